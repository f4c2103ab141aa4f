// src/verify/solid_contact: a solid body's inside at one exact pose.  The
// fixed pose of a body, its placed surface (none under a singular map), one
// representative vertex per connected component, and the start containment
// test: exact ray parity with exact poses (a witness at t = 0), boxes only
// otherwise, never "free" when the boxes cannot tell.
#include "src/verify/solid_contact.h"
#include "tests/verify/check_testing.h"

#include <boost/test/unit_test.hpp>

#include <set>
#include <string>

using namespace tmcert;
using tmcert::testing::two_cubes;

namespace {

const Mat34E kId = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};

Mat34E shift(const Exact& x) { return {1, 0, 0, x, 0, 1, 0, 0, 0, 0, 1, 0}; }

StartPose exact_pose(const Mat34E& m) {
  StartPose p;
  p.exact = m;
  for (int e = 0; e < 12; ++e) p.map[e] = to_interval(m[e]);
  return p;
}

// k of a representative's name "polygon k vertex 0" (else a large number).
std::size_t polygon_of(const std::string& name) {
  const std::string head = "polygon ", tail = " vertex 0";
  if (name.rfind(head, 0) != 0 || name.size() <= head.size() + tail.size() ||
      name.compare(name.size() - tail.size(), tail.size(), tail) != 0)
    return static_cast<std::size_t>(-1);
  return std::stoul(name.substr(head.size(), name.size() - head.size() - tail.size()));
}

StartPose enclosed_pose(const Mat34E& m) {
  StartPose p = exact_pose(m);
  p.exact.reset();
  return p;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(solid_contact)

BOOST_AUTO_TEST_CASE(fixed_pose_is_the_one_point_motion_or_the_identity) {
  const Scene scene = two_cubes("0 0 0", "1 0 0");
  BOOST_TEST((fixed_pose(scene.bodies[1]) == kId));
  Body still = scene.bodies[1];
  Motion m;
  m.control_points = {shift(Exact(3, 7))};
  m.weights = {1};
  still.motion = m;
  BOOST_TEST((fixed_pose(still) == shift(Exact(3, 7))));
}

BOOST_AUTO_TEST_CASE(vertices_and_components) {
  const Scene scene = two_cubes("0 0 0", "1 0 0");
  const Body& cube = scene.bodies[1];
  const std::vector<Vec3E> all = every_vertex(cube);
  const std::set<Vec3E> distinct(all.begin(), all.end());
  BOOST_TEST(distinct.size() == 8u);
  for (const Vec3E& v : distinct)
    for (int i = 0; i < 3; ++i) BOOST_TEST((v[i] == Exact(1, 2) || v[i] == Exact(-1, 2)));
  // One component: one representative, vertex 0 of one of its polygons, placed by the map.
  const auto reps = component_representatives(cube, shift(10));
  BOOST_REQUIRE(reps.size() == 1u);
  const std::size_t k = polygon_of(reps[0].first);
  BOOST_REQUIRE(k < cube.polygons.size());
  BOOST_TEST((reps[0].second == Vec3E{cube.polygons[k][0][0] + 10, cube.polygons[k][0][1], cube.polygons[k][0][2]}));
  // A second cube apart, a segment touching nothing and a point on the cube: three components.
  Body more = cube;
  for (const auto& polygon : cube.polygons) {
    std::vector<Vec3E> moved = polygon;
    for (Vec3E& v : moved) v[0] += 5;
    more.polygons.push_back(moved);
  }
  more.segments.push_back({Vec3E{20, 0, 0}, Vec3E{21, 0, 0}});
  more.points.push_back(cube.polygons[2][1]);
  const auto three = component_representatives(more, kId);
  BOOST_REQUIRE(three.size() == 3u);
  const std::size_t n = cube.polygons.size();
  BOOST_TEST(polygon_of(three[0].first) < n);                                                // the first cube
  BOOST_TEST((polygon_of(three[1].first) >= n && polygon_of(three[1].first) < 2 * n));      // the second
  BOOST_TEST(three[2].first == "segment 0 end 0");
  BOOST_TEST((three[2].second == Vec3E{20, 0, 0}));
  for (int c = 0; c < 2; ++c) BOOST_TEST((three[c].second == more.polygons[polygon_of(three[c].first)][0]));
}

BOOST_AUTO_TEST_CASE(placed_surface_is_null_under_a_singular_map) {
  const Scene scene = two_cubes("0 0 0", "1 0 0", "-2", "2", true);
  const Body& post = scene.bodies[1];
  const auto surface = placed_surface(post, kId);
  BOOST_REQUIRE(surface);
  BOOST_TEST(surface->contains(Vec3E{0, 0, 0}));
  BOOST_TEST(!surface->contains(Vec3E{3, 0, 0}));
  const auto shifted = placed_surface(post, shift(10));
  BOOST_REQUIRE(shifted);
  BOOST_TEST(shifted->contains(Vec3E{10, 0, 0}));
  BOOST_TEST(!shifted->contains(Vec3E{0, 0, 0}));
  const Mat34E flat = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0};
  BOOST_TEST(!placed_surface(post, flat));
}

BOOST_AUTO_TEST_CASE(start_containment_exact_and_enclosed) {
  // The mover [-1/2, 1/2]^3 and the solid post [-2, 2]^3.
  const Scene scene = two_cubes("0 0 0", "1 0 0", "-2", "2", true);
  const Body& mover = scene.bodies[0];
  const Body& post = scene.bodies[1];
  const std::vector<Vec3E> post_vertices = every_vertex(post);
  const auto mover_reps = component_representatives(mover, kId);
  const StartPose at_post = exact_pose(kId);

  const Containment inside = start_containment(post, post_vertices, at_post, mover, mover_reps, exact_pose(kId), true);
  BOOST_TEST((inside.kind == Containment::Kind::Hit));
  BOOST_REQUIRE(inside.witness);
  BOOST_TEST(inside.witness->t == 0);
  BOOST_TEST(inside.witness->features[0] == "post interior");
  BOOST_TEST(inside.witness->features[1] == "mover " + mover_reps[0].first);
  BOOST_TEST((inside.witness->point == mover_reps[0].second));
  // solid_first = false: the features in the other order.
  const Containment swapped = start_containment(post, post_vertices, at_post, mover, mover_reps, exact_pose(kId), false);
  BOOST_REQUIRE(swapped.witness);
  BOOST_TEST(swapped.witness->features[1] == "post interior");

  const Containment apart = start_containment(post, post_vertices, at_post, mover, mover_reps, exact_pose(shift(5)), true);
  BOOST_TEST((apart.kind == Containment::Kind::Free));
  BOOST_TEST(!apart.witness);

  // Enclosed poses only: boxes outside the solid's box are free; a box
  // within it cannot be decided (never "free").
  const Containment far = start_containment(post, post_vertices, at_post, mover, mover_reps, enclosed_pose(shift(5)), true);
  BOOST_TEST((far.kind == Containment::Kind::Free));
  const Containment near = start_containment(post, post_vertices, at_post, mover, mover_reps, enclosed_pose(kId), true);
  BOOST_TEST((near.kind == Containment::Kind::Unknown));
  BOOST_TEST(!near.witness);
}

BOOST_AUTO_TEST_SUITE_END()
