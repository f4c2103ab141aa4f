// The slices of an edge (src/verify/edge_slices.h; proofs/edge-slices.md):
// each slice's box holds the exact vertex images at rational parameters of
// the slice; a motion whose whole box meets an obstacle but whose slices'
// boxes do not is cleared without a search; a motion that meets the
// obstacle only in its middle is searched there, with the verdict and the
// first-contact bracket of the Verifier.
#include "src/io/parse.h"
#include "src/motion/segment.h"
#include "src/verify/edge_slices.h"
#include "src/verify/fixed_environment.h"

#include <boost/test/unit_test.hpp>

#include <string>
#include <vector>

using namespace tmcert;

namespace {

// A cube of side 2/5 (the mover) and a wall: the square |y|, |z| <= 1 in
// the plane x = 0 (zero thickness).
Scene cube_and_wall() {
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
  const std::string wall = "[[\"0\",\"-1\",\"-1\"],[\"0\",\"1\",\"-1\"],[\"0\",\"1\",\"1\"],[\"0\",\"-1\",\"1\"]]";
  return parse_scene_text("{\"format\": \"tmcert-scene/1\", \"bodies\": [{\"name\": \"wall\", \"polygons\": [" + wall +
                              "]}, {\"name\": \"cube\", \"polygons\": [" + cube + "]}]}",
                          "edge_slices");
}

Trajectory keyframes(const Vec3E& a, const Vec3E& b, int turn, Interpolation how) {
  MotionSegment seg;
  seg.t0 = 0;
  seg.t1 = 1;
  seg.from.translation = a;
  seg.to.translation = b;
  if (turn != 0) {
    seg.to.rotation.kind = Rotation::Kind::Quaternion;
    seg.to.rotation.quaternion = {Exact(turn), Exact(1), Exact(2), Exact(0)};
  }
  seg.interpolation = how;
  seg.rational = rational_keyframe_segment(seg.from, seg.to, seg.interpolation, seg.t0, seg.t1);
  return Trajectory{{seg}};
}

VerifyOptions options() {
  VerifyOptions o;
  o.epsilon = Exact(1, 1000);
  return o;
}

bool inside(const Exact& x, double lo, double hi) { return Exact(lo) <= x && x <= Exact(hi); }

}  // namespace

BOOST_AUTO_TEST_SUITE(sliced_edges)

BOOST_AUTO_TEST_CASE(slice_boxes_hold_the_exact_vertex_images) {
  const Scene scene = cube_and_wall();
  const Body& cube = scene.bodies[1];
  const auto vertices = enclosed_vertices(cube);
  BOOST_TEST(vertices.size() == 8u);  // distinct vertices only
  // An nlerp turn: a rational motion, exact at every rational parameter.
  const Trajectory motion = keyframes({Exact(-1), Exact(1, 3), Exact(0)}, {Exact(2), Exact(0), Exact(1, 7)}, 3,
                                      Interpolation::Nlerp);
  const MotionSegment& seg = motion.segments[0];
  BOOST_REQUIRE(seg.rational);
  const EdgeSlices s = tmcert::edge_slices(motion, vertices, 16);
  BOOST_REQUIRE_EQUAL(s.size(), 16u);
  BOOST_REQUIRE_EQUAL(s.t.size(), 17u);
  BOOST_TEST(s.whole.valid);
  const std::unique_ptr<SegmentModel> model = make_segment_model(seg);
  for (std::size_t k = 0; k < s.size(); ++k) {
    BOOST_TEST(s.t[k] == Exact(static_cast<int>(k), 16));
    BOOST_TEST(s.valid[k]);
    for (const Exact& u : {Exact(static_cast<int>(k), 16), Exact(2 * static_cast<int>(k) + 1, 32),
                           Exact(3 * static_cast<int>(k) + 1, 48), Exact(static_cast<int>(k) + 1, 16)}) {
      const std::optional<Mat34E> m = model->exact_pose(u);
      BOOST_REQUIRE(m);
      for (const auto& poly : cube.polygons)
        for (const Vec3E& x : poly)
          for (int i = 0; i < 3; ++i) {
            const Exact y = (*m)[4 * i] * x[0] + (*m)[4 * i + 1] * x[1] + (*m)[4 * i + 2] * x[2] + (*m)[4 * i + 3];
            BOOST_TEST(inside(y, s.lo[k][i], s.hi[k][i]), "slice " << k << " u " << u);
            BOOST_TEST(inside(y, s.whole.lo[i], s.whole.hi[i]));
          }
    }
  }
  // A slerp: exact at its keyframes, which lie in the first and last slices.
  const Trajectory slerp = keyframes({Exact(-1), Exact(1, 3), Exact(0)}, {Exact(2), Exact(0), Exact(1, 7)}, 3,
                                     Interpolation::Slerp);
  const EdgeSlices e = tmcert::edge_slices(slerp, vertices, 16);
  BOOST_REQUIRE_EQUAL(e.size(), 16u);
  for (const auto& [k, pose] : {std::pair{std::size_t{0}, slerp.segments[0].from}, std::pair{std::size_t{15}, slerp.segments[0].to}}) {
    const std::optional<Mat34E> m = exact_pose(pose);
    BOOST_REQUIRE(m);
    for (const auto& poly : cube.polygons)
      for (const Vec3E& x : poly)
        for (int i = 0; i < 3; ++i) {
          const Exact y = (*m)[4 * i] * x[0] + (*m)[4 * i + 1] * x[1] + (*m)[4 * i + 2] * x[2] + (*m)[4 * i + 3];
          BOOST_TEST(inside(y, e.lo[k][i], e.hi[k][i]));
        }
  }
}

BOOST_AUTO_TEST_CASE(slices_clear_what_the_whole_box_cannot) {
  // From (-1/2, 3, 0) to (3, -1/2, 0): the whole box meets the wall, but
  // where the cube is near x = 0 it is far up (y about 5/2), and where it
  // is down at |y| <= 6/5 it is far out (x >= 13/10).
  const Scene scene = cube_and_wall();
  const FixedEnvironment env(scene.bodies[0], {scene.bodies[1]}, {}, options());
  const Trajectory motion = keyframes({Exact(-1, 2), Exact(3), Exact(0)}, {Exact(3), Exact(-1, 2), Exact(0)}, 0,
                                      Interpolation::Slerp);
  const MotionCheck got = env.check({motion});
  BOOST_TEST(got.verdict == Verdict::Safe);
  BOOST_REQUIRE_EQUAL(got.checks.size(), 1u);
  BOOST_TEST(got.checks[0].stats.prefiltered);  // no search
  BOOST_TEST(got.checks[0].stats.nodes == 0u);
  BOOST_TEST(env.decide({motion}).verdict == Verdict::Safe);
  // The Verifier (whole-box prefilter, then the search) agrees.
  Scene s = scene;
  s.bodies[1].trajectory = motion;
  s.checks = {{1, 0}};
  BOOST_TEST(Verifier(s, options()).check(1, 0).verdict == Verdict::Safe);
}

BOOST_AUTO_TEST_CASE(only_the_slices_near_the_wall_are_searched) {
  // Through the wall at x = 0, turning (enclosed poses): the contact is in
  // the middle; the search runs on the slices around it only, with the
  // Verifier's verdict, and a bracket around the same first contact.
  const Scene scene = cube_and_wall();
  const FixedEnvironment env(scene.bodies[0], {scene.bodies[1]}, {}, options());
  for (const int turn : {0, 5}) {
    const Trajectory motion = keyframes({Exact(-4), Exact(0), Exact(0)}, {Exact(4), Exact(0), Exact(0)}, turn,
                                        Interpolation::Slerp);
    const MotionCheck got = env.check({motion});
    Scene s = scene;
    s.bodies[1].trajectory = motion;
    s.checks = {{1, 0}};
    const CheckResult want = Verifier(s, options()).check(1, 0);
    BOOST_TEST(got.verdict == Verdict::Collision);
    BOOST_TEST(want.verdict == Verdict::Collision);
    BOOST_REQUIRE(got.first_contact);
    BOOST_REQUIRE(want.first_contact);
    // Both brackets hold the true first contact and certify everything
    // before their lower ends: the intervals overlap.
    BOOST_TEST(got.first_contact->first <= want.first_contact->second);
    BOOST_TEST(want.first_contact->first <= got.first_contact->second);
    // The cube (reach at most sqrt(3)/5 < 7/20 from its centre) cannot
    // touch the wall before its centre is within 7/20 of x = 0: t >= 1/2 - 7/160.
    BOOST_TEST(got.first_contact->first >= Exact(3, 8));
    if (turn == 0) {
      // Rational: the exact first contact at x = -1/5, t = 19/40.
      BOOST_TEST(got.first_contact->first == Exact(19, 40));
      BOOST_TEST(got.first_contact->second == Exact(19, 40));
    }
  }
}

BOOST_AUTO_TEST_CASE(coarse_boxes_keep_the_slices_that_the_vertex_boxes_keep) {
  // section 1b: a slice whose coarse box (the slice's map on the box of the
  // vertices) the caller's test clears keeps that box; it holds the vertex
  // box, so the same slices are kept as with the vertex boxes alone.  The
  // caller's test: "misses the slab |x| <= 1/100" (a wall's box).
  const Scene scene = cube_and_wall();
  const auto vertices = enclosed_vertices(scene.bodies[1]);
  SliceFilter filter;
  filter.bounds = enclosed_bounds(vertices);
  for (int i = 0; i < 3; ++i) {
    BOOST_TEST(Exact(filter.bounds[i].inf()) <= Exact(-1, 5));  // holds every vertex, narrowly
    BOOST_TEST(filter.bounds[i].inf() > -0.20001);
    BOOST_TEST(Exact(filter.bounds[i].sup()) >= Exact(1, 5));
    BOOST_TEST(filter.bounds[i].sup() < 0.20001);
  }
  // The cube is its own vertex box, whose image is the vertex box; a larger
  // box holding every vertex (also a valid `bounds`) makes the coarse boxes
  // differ, so that the boxes kept can be told apart.
  for (int i = 0; i < 3; ++i) filter.bounds[i] = Interval(-0.5, 0.5);
  int calls = 0;
  auto misses = [](const std::array<double, 3>& lo, const std::array<double, 3>& hi) {
    return hi[0] < -0.01 || lo[0] > 0.01;
  };
  filter.clears = [&](const std::array<double, 3>& lo, const std::array<double, 3>& hi) {
    ++calls;
    return misses(lo, hi);
  };
  for (const int turn : {0, 3})
    for (const Interpolation how : {Interpolation::Slerp, Interpolation::Nlerp}) {
      const Trajectory motion = keyframes({Exact(-2), Exact(1, 3), Exact(0)}, {Exact(1), Exact(0), Exact(1, 7)}, turn, how);
      calls = 0;
      const EdgeSlices fine = tmcert::edge_slices(motion, vertices, 16);
      const EdgeSlices coarse = tmcert::edge_slices(motion, vertices, 16, &filter);
      BOOST_TEST(calls == 16);
      BOOST_REQUIRE_EQUAL(fine.size(), coarse.size());
      BOOST_TEST(fine.t == coarse.t, boost::test_tools::per_element());
      int kept_coarse = 0;
      for (std::size_t k = 0; k < fine.size(); ++k) {
        BOOST_TEST(coarse.valid[k] == fine.valid[k]);
        for (int i = 0; i < 3; ++i) {
          BOOST_TEST(coarse.lo[k][i] <= fine.lo[k][i]);  // the coarse box holds the vertex box
          BOOST_TEST(coarse.hi[k][i] >= fine.hi[k][i]);
        }
        const bool cleared = misses(coarse.lo[k], coarse.hi[k]);
        BOOST_TEST(cleared == misses(fine.lo[k], fine.hi[k]), "slice " << k);
        if (cleared && (coarse.lo[k] != fine.lo[k] || coarse.hi[k] != fine.hi[k])) ++kept_coarse;
        if (!cleared) {  // not cleared: the vertex box itself
          BOOST_TEST((coarse.lo[k] == fine.lo[k]));
          BOOST_TEST((coarse.hi[k] == fine.hi[k]));
        }
      }
      if (turn == 0) BOOST_TEST(kept_coarse > 0);  // a wide turn's coarse boxes may clear nothing
      auto keep_fine = [&](std::size_t k) { return !fine.valid[k] || !misses(fine.lo[k], fine.hi[k]); };
      auto keep_coarse = [&](std::size_t k) { return !coarse.valid[k] || !misses(coarse.lo[k], coarse.hi[k]); };
      BOOST_TEST((slice_runs(fine, keep_fine) == slice_runs(coarse, keep_coarse)));
      BOOST_TEST(!slice_runs(fine, keep_fine).empty());
    }
}

BOOST_AUTO_TEST_SUITE_END()
