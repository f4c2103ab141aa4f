// FixedEnvironment (src/verify/fixed_environment.h): bodies prepared once
// for many motions, with its own start test over a box tree of the
// environment, must agree with the Verifier on a scene holding the same
// motion, and its static test with the exact static test of the search
// (proofs/ompl-validator.md "Checked by"); a solid's inside counts.  Seeded; replay a failure with
// the seed printed.
#include "src/motion/segment.h"
#include "src/io/parse.h"
#include "src/verify/fixed_environment.h"
#include "src/verify/prepared.h"
#include "src/verify/search.h"

#include <boost/test/unit_test.hpp>

#include <cstdint>
#include <random>
#include <vector>
#include <string>

using namespace tmcert;

namespace {

// A cube of side 2/5 (the mover) and a slab |x| <= 1/10 with a square hole
// |y|, |z| <= 3/10 (the environment), in one scene.
Scene cube_and_slab() {
  auto rect = [](int axis, const std::string& c, const std::string& a0, const std::string& a1, const std::string& b0,
                 const std::string& b1) {
    auto point = [&](const std::string& a, const std::string& b) {
      std::string p[3];
      p[axis] = c;
      p[(axis + 1) % 3] = a;
      p[(axis + 2) % 3] = b;
      return "[\"" + p[0] + "\",\"" + p[1] + "\",\"" + p[2] + "\"]";
    };
    return "[" + point(a0, b0) + "," + point(a1, b0) + "," + point(a1, b1) + "," + point(a0, b1) + "]";
  };
  std::string slab, cube;
  for (const std::string x : {"-1/10", "1/10"}) {
    for (const std::string& r : {rect(0, x, "-2", "-3/10", "-2", "2"), rect(0, x, "3/10", "2", "-2", "2"),
                                 rect(0, x, "-3/10", "3/10", "-2", "-3/10"), rect(0, x, "-3/10", "3/10", "3/10", "2")})
      slab += (slab.empty() ? "" : ",") + r;
  }
  slab += "," + rect(1, "-3/10", "-3/10", "3/10", "-1/10", "1/10") + "," + rect(1, "3/10", "-3/10", "3/10", "-1/10", "1/10");
  slab += "," + rect(2, "-3/10", "-1/10", "1/10", "-3/10", "3/10") + "," + rect(2, "3/10", "-1/10", "1/10", "-3/10", "3/10");
  for (int axis = 0; axis < 3; ++axis)
    for (const std::string c : {"-1/5", "1/5"}) cube += (cube.empty() ? "" : ",") + rect(axis, c, "-1/5", "1/5", "-1/5", "1/5");
  return parse_scene_text("{\"format\": \"tmcert-scene/1\", \"bodies\": [{\"name\": \"slab\", \"polygons\": [" + slab +
                              "]}, {\"name\": \"cube\", \"polygons\": [" + cube + "]}]}",
                          "fixed_environment");
}

// A pose with a small-integer quaternion and a translation in sixteenths.
Pose random_pose(std::mt19937& rng) {
  std::uniform_int_distribution<int> q(-4, 4), t(-16, 16);
  Pose p;
  p.translation = {Exact(t(rng), 16), Exact(t(rng), 16), Exact(t(rng), 16)};
  p.rotation.kind = Rotation::Kind::Quaternion;
  do p.rotation.quaternion = {Exact(q(rng)), Exact(q(rng)), Exact(q(rng)), Exact(q(rng))};
  while (p.rotation.quaternion[0] == 0 && p.rotation.quaternion[1] == 0 && p.rotation.quaternion[2] == 0 &&
         p.rotation.quaternion[3] == 0);
  return p;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(fixed_environment)

BOOST_AUTO_TEST_CASE(static_contact_agrees_with_the_exact_static_test) {
  const Scene scene = cube_and_slab();
  VerifyOptions options;
  options.epsilon = Exact(1, 1000);
  const FixedEnvironment env(scene.bodies[0], {scene.bodies[1]}, {}, options);
  const PreparedBody slab(scene.bodies[0]);
  Body cube_moving = scene.bodies[1];
  Motion still;
  still.control_points = {Mat34E{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0}, Mat34E{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0}};
  still.weights = {Exact(1), Exact(1)};
  cube_moving.motion = still;  // prepared in its own frame
  const PreparedBody cube(cube_moving);
  const unsigned seed = 20261125;
  std::mt19937 rng(seed);
  int hits = 0;
  for (int k = 0; k < 200; ++k) {
    const Pose p = random_pose(rng);
    const Mat34E m = *exact_pose(p);
    CheckStats stats;
    const bool expected = detail::first_hit(transformed_parts(cube, m), slab.parts, nullptr, stats).has_value();
    const std::optional<Witness> got = env.static_contact({m});
    BOOST_TEST(got.has_value() == expected, "seed " << seed << ", pose " << k);
    hits += expected;
  }
  BOOST_TEST(hits > 20);   // both outcomes are exercised
  BOOST_TEST(hits < 180);
}

BOOST_AUTO_TEST_CASE(motions_agree_with_the_verifier) {
  const Scene base = cube_and_slab();
  VerifyOptions options;
  options.epsilon = Exact(1, 1000);
  const FixedEnvironment env(base.bodies[0], {base.bodies[1]}, {}, options);
  const unsigned seed = 20261126;
  std::mt19937 rng(seed);
  int verdicts[3] = {0, 0, 0};
  for (int k = 0; k < 24; ++k) {
    MotionSegment seg;
    seg.t0 = 0;
    seg.t1 = 1;
    seg.from = random_pose(rng);
    seg.to = random_pose(rng);
    seg.from.translation[0] = Exact(-3, 4);  // from one side of the slab towards the other
    seg.to.translation[0] = Exact(3, 4);
    if (k % 2 == 0) {
      // Through the hole, turning a little: mostly safe.
      std::uniform_int_distribution<int> small(-1, 1);
      for (Pose* p : {&seg.from, &seg.to}) {
        p->translation[1] = p->translation[2] = 0;
        p->rotation.quaternion = {Exact(8), Exact(small(rng)), Exact(small(rng)), Exact(small(rng))};
      }
    }
    seg.interpolation = Interpolation::Slerp;
    try {
      require_interpolable(seg.from, seg.to, seg.interpolation);
    } catch (const InputError&) {
      continue;
    }
    seg.rational = rational_keyframe_segment(seg.from, seg.to, seg.interpolation, seg.t0, seg.t1);
    const Trajectory motion{{seg}};
    const MotionCheck got = env.check({motion});

    Scene scene = base;
    scene.bodies[1].trajectory = motion;
    scene.checks = {{1, 0}};
    const CheckResult expected = Verifier(scene, options).check(1, 0);
    BOOST_TEST(got.verdict == expected.verdict, "seed " << seed << ", motion " << k);
    if (expected.verdict != Verdict::Safe && expected.first_contact) {
      // Both brackets hold the first contact and certify everything before
      // their lower ends, so they overlap.  They need not be equal: the
      // environment searches only the slices its boxes do not clear
      // (proofs/edge-slices.md), whose pieces start elsewhere.
      BOOST_REQUIRE(got.safe_until);
      BOOST_REQUIRE(got.first_contact);
      BOOST_TEST(*got.safe_until == got.first_contact->first);
      BOOST_TEST(got.first_contact->first <= expected.first_contact->second, "seed " << seed << ", motion " << k);
      BOOST_TEST(expected.first_contact->first <= got.first_contact->second, "seed " << seed << ", motion " << k);
      BOOST_TEST_MESSAGE("motion " << k << ": bracket [" << CGAL::to_double(got.first_contact->first) << ", "
                                   << CGAL::to_double(got.first_contact->second) << "], the Verifier's ["
                                   << CGAL::to_double(expected.first_contact->first) << ", "
                                   << CGAL::to_double(expected.first_contact->second) << "]");
    }
    ++verdicts[static_cast<int>(expected.verdict)];
  }
  BOOST_TEST(verdicts[static_cast<int>(Verdict::Safe)] > 0);
  BOOST_TEST(verdicts[static_cast<int>(Verdict::Collision)] > 0);
}

BOOST_AUTO_TEST_CASE(searches_reuse_their_caches_across_checks) {
  // Each thread's search keeps its sphere caches for the next check
  // (src/verify/ordered_tasks.h; proofs/search-and-pruning.md section 2b):
  // an entry from an earlier check must never be taken as current.  The
  // same motions checked again in the opposite order, with checks of
  // other bodies (other cache sizes) in between, give the same results
  // entry for entry, statistics included.
  const Scene base = cube_and_slab();
  VerifyOptions options;
  options.epsilon = Exact(1, 1000);
  options.threads = 1;
  const FixedEnvironment env(base.bodies[0], {base.bodies[1]}, {}, options);
  const FixedEnvironment swapped(base.bodies[1], {base.bodies[0]}, {}, options);
  std::mt19937 rng(20261129);
  std::vector<Trajectory> motions;
  while (motions.size() < 12) {
    MotionSegment seg;
    seg.t0 = 0;
    seg.t1 = 1;
    seg.from = random_pose(rng);
    seg.to = random_pose(rng);
    seg.from.translation[0] = Exact(-3, 4);
    seg.to.translation[0] = Exact(3, 4);
    seg.interpolation = Interpolation::Slerp;
    try {
      require_interpolable(seg.from, seg.to, seg.interpolation);
    } catch (const InputError&) {
      continue;
    }
    seg.rational = rational_keyframe_segment(seg.from, seg.to, seg.interpolation, seg.t0, seg.t1);
    motions.push_back(Trajectory{{seg}});
  }
  std::vector<MotionCheck> first;
  for (const Trajectory& m : motions) first.push_back(env.check({m}));
  std::uint64_t searched = 0;
  for (std::size_t k = motions.size(); k-- > 0;) {
    (void)swapped.check({motions[(k + 5) % motions.size()]});  // the other bodies' search in between
    const MotionCheck again = env.check({motions[k]});
    const MotionCheck& was = first[k];
    BOOST_TEST(again.verdict == was.verdict, "motion " << k);
    BOOST_TEST((again.first_contact == was.first_contact), "motion " << k);
    BOOST_REQUIRE_EQUAL(again.checks.size(), was.checks.size());
    for (std::size_t c = 0; c < was.checks.size(); ++c) {
      BOOST_TEST(again.checks[c].stats.nodes == was.checks[c].stats.nodes, "motion " << k);
      BOOST_TEST(again.checks[c].stats.sphere_tests == was.checks[c].stats.sphere_tests, "motion " << k);
      BOOST_REQUIRE_EQUAL(again.checks[c].undecided.size(), was.checks[c].undecided.size());
      for (std::size_t u = 0; u < was.checks[c].undecided.size(); ++u) {
        BOOST_TEST(again.checks[c].undecided[u].t0 == was.checks[c].undecided[u].t0);
        BOOST_TEST(again.checks[c].undecided[u].t1 == was.checks[c].undecided[u].t1);
      }
      searched += was.checks[c].stats.nodes;
    }
  }
  BOOST_TEST(searched > 0u);  // some motions needed the search
}

BOOST_AUTO_TEST_CASE(a_solid_inside_counts_as_contact) {
  // A small cube standing still inside a closed box, touching nothing: a
  // collision when the box is solid (at the start, with the interior as
  // the witness's feature), safe when it is a surface.
  auto box = [](const std::string& r) {
    const std::string m = "-" + r;
    auto p = [&](int x, int y, int z) {
      return "[\"" + (x ? r : m) + "\",\"" + (y ? r : m) + "\",\"" + (z ? r : m) + "\"]";
    };
    return "[" + p(0, 0, 0) + "," + p(0, 1, 0) + "," + p(0, 1, 1) + "," + p(0, 0, 1) + "],[" + p(1, 0, 0) + "," +
           p(1, 0, 1) + "," + p(1, 1, 1) + "," + p(1, 1, 0) + "],[" + p(0, 0, 0) + "," + p(0, 0, 1) + "," + p(1, 0, 1) +
           "," + p(1, 0, 0) + "],[" + p(0, 1, 0) + "," + p(1, 1, 0) + "," + p(1, 1, 1) + "," + p(0, 1, 1) + "],[" +
           p(0, 0, 0) + "," + p(1, 0, 0) + "," + p(1, 1, 0) + "," + p(0, 1, 0) + "],[" + p(0, 0, 1) + "," + p(0, 1, 1) +
           "," + p(1, 1, 1) + "," + p(1, 0, 1) + "]";
  };
  for (const bool solid : {true, false}) {
    const Scene scene = parse_scene_text(
        std::string("{\"format\": \"tmcert-scene/1\", \"bodies\": [{\"name\": \"room\", \"solid\": ") +
            (solid ? "true" : "false") + ", \"polygons\": [" + box("1") + "]}, {\"name\": \"cube\", \"polygons\": [" +
            box("1/10") + "]}]}",
        "solid_room");
    VerifyOptions options;
    options.epsilon = Exact(1, 1000);
    const FixedEnvironment env(scene.bodies[0], {scene.bodies[1]}, {}, options);
    MotionSegment seg;
    seg.t0 = 0;
    seg.t1 = 1;
    seg.from.translation = {Exact(-1, 2), Exact(0), Exact(0)};
    seg.to.translation = {Exact(1, 2), Exact(0), Exact(0)};
    seg.rational = rational_keyframe_segment(seg.from, seg.to, Interpolation::Slerp, seg.t0, seg.t1);
    const MotionCheck got = env.check({Trajectory{{seg}}});
    BOOST_TEST(got.verdict == (solid ? Verdict::Collision : Verdict::Safe));
    const std::optional<Witness> still = env.static_contact({*exact_pose(seg.from)});
    BOOST_TEST(still.has_value() == solid);
    if (solid) {
      BOOST_REQUIRE(got.witness);
      BOOST_TEST(got.witness->features[1] == "room interior");
      BOOST_REQUIRE(got.safe_until);
      BOOST_TEST(*got.safe_until == 0);
    }
  }
}

BOOST_AUTO_TEST_CASE(rejects_what_it_cannot_certify) {
  const Scene scene = cube_and_slab();
  VerifyOptions options;
  options.epsilon = Exact(1, 1000);
  Body tolerant = scene.bodies[1];
  tolerant.tolerance = Exact(1, 100);
  BOOST_CHECK_THROW(FixedEnvironment(scene.bodies[0], {tolerant}, {}, options), InputError);
  BOOST_CHECK_THROW(FixedEnvironment(scene.bodies[0], {}, {}, options), InputError);
  VerifyOptions no_epsilon;
  BOOST_CHECK_THROW(FixedEnvironment(scene.bodies[0], {scene.bodies[1]}, {}, no_epsilon), InputError);
  const FixedEnvironment env(scene.bodies[0], {scene.bodies[1]}, {}, options);
  BOOST_CHECK_THROW(env.check({}), InputError);
}

BOOST_AUTO_TEST_SUITE_END()
