// Contacts found at sampled parameters before any search
// (src/verify/sample_first.h, FixedEnvironment::decide; proofs/sample-first.md):
// the sample order, a witness at a sampled parameter that the exact static
// test confirms (exact and enclosed poses), the partition such a result
// claims (nothing before the witness, nothing after it), the search when
// every sample misses, and the same "safe" as check().
#include "src/io/parse.h"
#include "src/motion/segment.h"
#include "src/verify/fixed_environment.h"
#include "src/verify/sample_first.h"

#include <boost/test/unit_test.hpp>

#include <string>
#include <vector>

using namespace tmcert;

namespace {

std::string square(const std::string& x, const std::string& h) {
  // The square |y|, |z| <= h in the plane x.
  const std::string m = "-" + h;
  return "[[\"" + x + "\",\"" + m + "\",\"" + m + "\"],[\"" + x + "\",\"" + h + "\",\"" + m + "\"],[\"" + x + "\",\"" + h +
         "\",\"" + h + "\"],[\"" + x + "\",\"" + m + "\",\"" + h + "\"]]";
}

// A cube of side 2/5 (the mover) and a wall: the square |y|, |z| <= 1 in
// the plane x = `wall` (zero thickness).
Scene cube_and_wall(const std::string& wall) {
  std::string cube;
  const std::string c[2] = {"-1/5", "1/5"};
  for (int axis = 0; axis < 3; ++axis)
    for (const std::string& v : c) {
      auto p = [&](const std::string& a, const std::string& b) {
        std::string q[3];
        q[axis] = v;
        q[(axis + 1) % 3] = a;
        q[(axis + 2) % 3] = b;
        return "[\"" + q[0] + "\",\"" + q[1] + "\",\"" + q[2] + "\"]";
      };
      cube += std::string(cube.empty() ? "" : ",") + "[" + p(c[0], c[0]) + "," + p(c[1], c[0]) + "," + p(c[1], c[1]) +
              "," + p(c[0], c[1]) + "]";
    }
  return parse_scene_text("{\"format\": \"tmcert-scene/1\", \"bodies\": [{\"name\": \"wall\", \"polygons\": [" +
                              square(wall, "1") + "]}, {\"name\": \"cube\", \"polygons\": [" + cube + "]}]}",
                          "sample_first");
}

// The cube moving from x = x0 to x = x1 (y = z = 0), turning about x by
// the quaternion (w, 1, 0, 0) at the end when w != 0 (a slerp: enclosed
// poses between the keyframes).
Trajectory along_x(const Exact& x0, const Exact& x1, int turn = 0) {
  MotionSegment seg;
  seg.t0 = 0;
  seg.t1 = 1;
  seg.from.translation = {x0, Exact(0), Exact(0)};
  seg.to.translation = {x1, Exact(0), Exact(0)};
  if (turn != 0) {
    seg.to.rotation.kind = Rotation::Kind::Quaternion;
    seg.to.rotation.quaternion = {Exact(turn), Exact(1), Exact(0), Exact(0)};
  }
  seg.interpolation = Interpolation::Slerp;
  seg.rational = rational_keyframe_segment(seg.from, seg.to, seg.interpolation, seg.t0, seg.t1);
  return Trajectory{{seg}};
}

VerifyOptions options() {
  VerifyOptions o;
  o.epsilon = Exact(1, 1000);
  return o;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(sample_first)

BOOST_AUTO_TEST_CASE(sample_order) {
  const std::vector<Exact> got = sample_times(Exact(0), Exact(1), 9);
  const std::vector<Exact> want = {Exact(1),    Exact(1, 2), Exact(1, 4), Exact(3, 4), Exact(1, 8),
                                   Exact(3, 8), Exact(5, 8), Exact(7, 8), Exact(1, 16)};
  BOOST_TEST(got == want, boost::test_tools::per_element());
  const std::vector<Exact> shifted = sample_times(Exact(2), Exact(4), 3);
  BOOST_TEST(shifted == (std::vector<Exact>{Exact(4), Exact(3), Exact(5, 2)}), boost::test_tools::per_element());
  BOOST_TEST(sample_times(Exact(1), Exact(1), 5).empty());
}

BOOST_AUTO_TEST_CASE(a_contact_at_the_end_decides_without_a_search) {
  // The cube ends across the wall at x = 0: the end state is in contact.
  const Scene scene = cube_and_wall("0");
  const FixedEnvironment env(scene.bodies[0], {scene.bodies[1]}, {}, options());
  const Trajectory motion = along_x(Exact(-1), Exact(0));
  const MotionCheck got = env.decide({motion});
  BOOST_TEST(got.verdict == Verdict::Collision);
  BOOST_REQUIRE(got.witness);
  BOOST_TEST(got.witness->t == Exact(1));
  // An exact pose, but the edges of the cube cross the wall transversally:
  // the certain crossing of the enclosures is found first (no exact test),
  // and the witness is its box.
  BOOST_REQUIRE(got.witness->point_box);
  BOOST_REQUIRE_EQUAL(got.checks.size(), 1u);
  const CheckResult& c = got.checks[0];
  BOOST_TEST(c.stats.nodes == 0u);  // no search
  BOOST_TEST(c.stats.static_configurations == 1u);
  // Nothing claimed before the witness: undecided "limit" over [0, 1).
  BOOST_REQUIRE_EQUAL(c.undecided.size(), 1u);
  BOOST_TEST(c.undecided[0].t0 == Exact(0));
  BOOST_TEST(c.undecided[0].t1 == Exact(1));
  BOOST_TEST((c.undecided[0].reason == StopReason::Limit));
  BOOST_REQUIRE(got.first_contact);
  BOOST_TEST(got.first_contact->first == Exact(0));
  BOOST_TEST(got.first_contact->second == Exact(1));
  BOOST_TEST(!c.first_contact_exact);
  BOOST_REQUIRE(got.safe_until);
  BOOST_TEST(*got.safe_until == Exact(0));
  // The exact static test confirms a contact at that pose, and the box
  // holds a point of the wall (x = 0) within the cube's reach.
  const Pose end = motion.segments[0].to;
  BOOST_TEST(env.static_contact({*exact_pose(end)}).has_value());
  const auto& box = *got.witness->point_box;
  BOOST_TEST(box[0][0] <= Exact(0));
  BOOST_TEST(box[0][1] >= Exact(0));
  for (int i = 1; i < 3; ++i) {  // within the cube's reach, up to rounding
    BOOST_TEST(box[i][0] >= Exact(-1, 5) - Exact(1, 1000000));
    BOOST_TEST(box[i][1] <= Exact(1, 5) + Exact(1, 1000000));
  }
  // check() searches for the first contact: the cube's face reaches the
  // wall at x = -1/5, t = 4/5.
  const MotionCheck full = env.check({motion});
  BOOST_TEST(full.verdict == Verdict::Collision);
  BOOST_REQUIRE(full.first_contact);
  BOOST_TEST(full.first_contact->first <= Exact(4, 5));
  BOOST_TEST(full.first_contact->second >= Exact(4, 5));
  BOOST_TEST(full.checks[0].stats.nodes > 0u);
}

BOOST_AUTO_TEST_CASE(the_end_of_one_mover_is_tested_before_its_slices) {
  // One mover (proofs/sample-first.md section 3): its end configuration is
  // tested first; an end across the wall decides, an end short of it
  // (boxes apart) is skipped and the edge is certified as before.
  const Scene scene = cube_and_wall("0");
  const FixedEnvironment env(scene.bodies[0], {scene.bodies[1]}, {}, options());
  const MotionCheck across = env.decide({along_x(Exact(-1), Exact(1, 10), 2)});
  BOOST_TEST(across.verdict == Verdict::Collision);
  BOOST_REQUIRE(across.witness);
  BOOST_TEST(across.witness->t == Exact(1));
  BOOST_TEST(across.checks[0].stats.static_configurations == 1u);
  BOOST_TEST(across.checks[0].stats.nodes == 0u);
  for (const Trajectory& m : {along_x(Exact(-1), Exact(-1, 4)), along_x(Exact(-1), Exact(-1, 4), 2)}) {
    const MotionCheck short_of = env.decide({m});
    BOOST_TEST(short_of.verdict == Verdict::Safe);
    BOOST_TEST(env.check({m}).verdict == Verdict::Safe);
  }
}

BOOST_AUTO_TEST_CASE(with_several_movers_the_sample_pass_tests_the_end) {
  // Two movers: no end test before the slices; the sample pass finds the
  // contact at the end for whichever mover has it.
  const Scene scene = cube_and_wall("0");
  Body other = scene.bodies[1];
  other.name = "cube2";
  const FixedEnvironment env(scene.bodies[0], {scene.bodies[1], other}, {}, options());
  MotionSegment away;
  away.t0 = 0;
  away.t1 = 1;
  away.from.translation = {Exact(-5), Exact(5), Exact(0)};
  away.to.translation = {Exact(-4), Exact(5), Exact(0)};
  away.interpolation = Interpolation::Slerp;
  away.rational = rational_keyframe_segment(away.from, away.to, away.interpolation, away.t0, away.t1);
  const Trajectory far{{away}};
  const Trajectory across = along_x(Exact(-1), Exact(0));
  for (int which = 0; which < 2; ++which) {
    const MotionCheck got = env.decide(which == 0 ? std::vector<Trajectory>{across, far} : std::vector<Trajectory>{far, across});
    BOOST_TEST(got.verdict == Verdict::Collision);
    BOOST_REQUIRE(got.witness);
    BOOST_TEST(got.witness->t == Exact(1));
    BOOST_REQUIRE_EQUAL(got.checks.size(), 1u);
    BOOST_TEST(got.checks[0].bodies[0] == 1 + which);
    BOOST_TEST(got.checks[0].bodies[1] == 0);
    BOOST_TEST(got.checks[0].stats.nodes == 0u);
  }
}

BOOST_AUTO_TEST_CASE(a_touching_end_pose_gets_the_exact_point) {
  // The cube's face ends on the wall (x = -1/5 + 1/5 = 0): a touching
  // contact, no transversal crossing for the interval test to prove, so
  // the exact test decides and the witness is an exact point on the wall.
  const Scene scene = cube_and_wall("0");
  const FixedEnvironment env(scene.bodies[0], {scene.bodies[1]}, {}, options());
  const MotionCheck got = env.decide({along_x(Exact(-1), Exact(-1, 5))});
  BOOST_TEST(got.verdict == Verdict::Collision);
  BOOST_REQUIRE(got.witness);
  BOOST_TEST(got.witness->t == Exact(1));
  BOOST_TEST(!got.witness->point_box);
  BOOST_TEST(got.witness->point[0] == Exact(0));
  BOOST_TEST(got.checks[0].stats.nodes == 0u);
}

BOOST_AUTO_TEST_CASE(an_exact_end_pose_is_computed_only_for_candidate_pairs) {
  // Turning a quarter about x (the quaternion (1, 1, 0, 0): the same cube)
  // while moving: the end test gets the slerp model's enclosure of the end
  // pose, and the exact end pose only for the candidate pairs the
  // enclosures do not decide (proofs/sample-first.md section 2c).  A face
  // ending on the wall (touching, no certain crossing) is still the exact
  // contact at t = 1; a face ending 10^-20 short of it (closer than the
  // enclosures' width: candidate pairs) is free there by the exact test,
  // so no collision is claimed: the search then stops undecided near the
  // end (a gap far below epsilon), as check() does.
  const Scene scene = cube_and_wall("0");
  const FixedEnvironment env(scene.bodies[0], {scene.bodies[1]}, {}, options());
  const MotionCheck touching = env.decide({along_x(Exact(-1), Exact(-1, 5), 1)});
  BOOST_TEST(touching.verdict == Verdict::Collision);
  BOOST_REQUIRE(touching.witness);
  BOOST_TEST(touching.witness->t == Exact(1));
  BOOST_TEST(!touching.witness->point_box);
  BOOST_TEST(touching.witness->point[0] == Exact(0));
  BOOST_TEST(touching.checks[0].stats.nodes == 0u);
  const Exact e5(1, 100000);
  const Exact tiny = e5 * e5 * e5 * e5;  // 10^-20
  const Trajectory short_of = along_x(Exact(-1), Exact(-1, 5) - tiny, 1);
  const MotionCheck near = env.decide({short_of});
  BOOST_TEST(near.verdict != Verdict::Collision);
  BOOST_TEST(near.verdict == env.check({short_of}).verdict);
}

BOOST_AUTO_TEST_CASE(an_enclosed_pose_gives_a_certain_crossing) {
  // Turning while it moves (slerp): the poses at the samples are enclosed,
  // and a contact there is a certain transversal crossing with a box.
  const Scene scene = cube_and_wall("0");
  const FixedEnvironment env(scene.bodies[0], {scene.bodies[1]}, {}, options());
  const Trajectory motion = along_x(Exact(-1), Exact(1), 3);
  const MotionCheck got = env.decide({motion});
  BOOST_TEST(got.verdict == Verdict::Collision);
  BOOST_REQUIRE(got.witness);
  BOOST_TEST(got.witness->t == Exact(1, 2));  // the end (x = 1) is clear of the wall, the middle crosses it
  BOOST_REQUIRE(got.witness->point_box);
  const auto& box = *got.witness->point_box;
  BOOST_TEST(box[0][0] <= Exact(0));  // the crossing lies on the wall
  BOOST_TEST(box[0][1] >= Exact(0));
  BOOST_TEST(got.checks[0].stats.nodes == 0u);
  BOOST_TEST(env.check({motion}).verdict == Verdict::Collision);
}

BOOST_AUTO_TEST_CASE(samples_that_miss_leave_the_search) {
  // The wall at x = 1/3 is touched only for t in [76/150, 79/150] of the
  // motion from x = -10 to 10 (|x - 1/3| <= 1/5): between the samples
  // 1/2 and 5/8 (the nine samples: 1, 1/2, 1/4, 3/4, 1/8, ..., 7/8, 1/16),
  // so the search finds it.
  const Scene scene = cube_and_wall("1/3");
  const FixedEnvironment env(scene.bodies[0], {scene.bodies[1]}, {}, options());
  const Trajectory motion = along_x(Exact(-10), Exact(10));
  const MotionCheck got = env.decide({motion});
  BOOST_TEST(got.verdict == Verdict::Collision);
  BOOST_REQUIRE(got.witness);
  BOOST_TEST(got.witness->t >= Exact(76, 150));
  BOOST_TEST(got.witness->t <= Exact(79, 150));
  BOOST_TEST(got.checks[0].stats.nodes > 0u);
  BOOST_REQUIRE(got.first_contact);
  BOOST_TEST(got.first_contact->first <= Exact(76, 150));
}

BOOST_AUTO_TEST_CASE(safe_exactly_when_check_is_safe) {
  const Scene scene = cube_and_wall("0");
  const FixedEnvironment env(scene.bodies[0], {scene.bodies[1]}, {}, options());
  // Beside the wall (y = 2), then through it, then stopping short of it.
  MotionSegment beside;
  beside.t0 = 0;
  beside.t1 = 1;
  beside.from.translation = {Exact(-1), Exact(2), Exact(0)};
  beside.to.translation = {Exact(1), Exact(2), Exact(1, 2)};
  beside.interpolation = Interpolation::Slerp;
  beside.rational = rational_keyframe_segment(beside.from, beside.to, beside.interpolation, beside.t0, beside.t1);
  for (const Trajectory& m : {Trajectory{{beside}}, along_x(Exact(-1), Exact(1)), along_x(Exact(-1), Exact(-1, 4)),
                              along_x(Exact(-1), Exact(-1, 5)), along_x(Exact(-1), Exact(-1, 4), 5)}) {
    const MotionCheck d = env.decide({m});
    const MotionCheck c = env.check({m});
    BOOST_TEST((d.verdict == Verdict::Safe) == (c.verdict == Verdict::Safe));
    if (d.verdict == Verdict::Collision) BOOST_TEST(c.verdict != Verdict::Safe);
  }
}

BOOST_AUTO_TEST_SUITE_END()
