// src/verify/true_shape: a contact with a URDF cylinder or sphere counts
// only with a point proven to lie in both true bodies.  A point inside the
// circumscribed polyhedron but outside the cylinder is no contact; one
// inside the cylinder is, exactly; the sides' order is kept.
#include "src/verify/true_shape.h"
#include "src/io/parse.h"
#include "src/verify/prepared.h"
#include "tests/verify/check_testing.h"

#include <boost/test/unit_test.hpp>

#include <string>

using namespace tmcert;

namespace {

// Body 0 "can": the cube [-1, 1]^3, the circumscribed polyhedron of the
// cylinder of radius 1 and length 2 about z (set as its primitive); body 1
// "dot": one point at `at` (JSON).
Scene can_and_dot(const std::string& at) {
  Scene s = parse_scene_text("{\"format\": \"tmcert-scene/1\", \"bodies\": [{\"name\": \"can\", \"polygons\": " +
                                 testing::cube_polygons("-1", "1") + "}, {\"name\": \"dot\", \"points\": [" + at + "]}]}",
                             "can_and_dot");
  Body::Primitive p;
  p.kind = Body::Primitive::Kind::Cylinder;
  p.radius = 1;
  p.length = 2;
  s.bodies[0].primitive = p;
  return s;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(true_shape)

BOOST_AUTO_TEST_CASE(point_in_the_cylinder_is_a_proven_contact) {
  const Scene scene = can_and_dot("[\"1/2\", \"1/2\", \"9/10\"]");
  const PreparedBody can(scene.bodies[0]), dot(scene.bodies[1]);
  CheckStats stats;
  const std::optional<TrueContact> c = true_contact(fixed_side(can), fixed_side(dot), stats);
  BOOST_REQUIRE(c);
  BOOST_REQUIRE(c->point);
  BOOST_TEST((*c->point == Vec3E{Exact(1, 2), Exact(1, 2), Exact(9, 10)}));
  BOOST_TEST(c->features[1].find("point 0") != std::string::npos);
  // The other order: features swapped, the local side is the first.
  const std::optional<TrueContact> d = true_contact(fixed_side(dot), fixed_side(can), stats);
  BOOST_REQUIRE(d);
  BOOST_TEST(d->features[0] == c->features[1]);
  BOOST_TEST(d->features[1] == c->features[0]);
  BOOST_TEST(d->local_side == 0);
  const Witness w = witness_of(Exact(1, 5), *c);
  BOOST_TEST(w.t == Exact(1, 5));
  BOOST_TEST(w.true_shape);
  BOOST_TEST(w.features[0] == c->features[0]);
  const Witness swapped = witness_of(Exact(1, 5), *c, true);
  BOOST_TEST(swapped.features[0] == c->features[1]);
}

BOOST_AUTO_TEST_CASE(point_in_the_polyhedron_only_is_no_contact) {
  // (19/20)^2 + (19/20)^2 > 1: outside the cylinder, inside the cube.
  const Scene scene = can_and_dot("[\"19/20\", \"19/20\", \"0\"]");
  const PreparedBody can(scene.bodies[0]), dot(scene.bodies[1]);
  CheckStats stats;
  BOOST_TEST(!true_contact(fixed_side(can), fixed_side(dot), stats));
  BOOST_TEST(!true_contact(fixed_side(dot), fixed_side(can), stats));
  // Past the cylinder's end: no contact either.
  const Scene beyond = can_and_dot("[\"0\", \"0\", \"11/10\"]");
  const PreparedBody can2(beyond.bodies[0]), dot2(beyond.bodies[1]);
  BOOST_TEST(!true_contact(fixed_side(can2), fixed_side(dot2), stats));
}

BOOST_AUTO_TEST_CASE(sphere_primitive) {
  Scene scene = can_and_dot("[\"1/2\", \"1/2\", \"1/2\"]");  // |x|^2 = 3/4 <= 1
  scene.bodies[0].primitive->kind = Body::Primitive::Kind::Sphere;
  const PreparedBody ball(scene.bodies[0]), dot(scene.bodies[1]);
  CheckStats stats;
  BOOST_TEST(true_contact(fixed_side(ball), fixed_side(dot), stats).has_value());
  Scene outside = can_and_dot("[\"3/5\", \"3/5\", \"3/5\"]");  // |x|^2 = 27/25 > 1
  outside.bodies[0].primitive->kind = Body::Primitive::Kind::Sphere;
  const PreparedBody ball2(outside.bodies[0]), dot2(outside.bodies[1]);
  BOOST_TEST(!true_contact(fixed_side(ball2), fixed_side(dot2), stats));
}

BOOST_AUTO_TEST_CASE(enlarged_pairs_are_those_with_a_primitive) {
  const Scene scene = can_and_dot("[\"0\", \"0\", \"0\"]");
  BOOST_TEST(enlarged_pair(scene.bodies[0], scene.bodies[1]));
  BOOST_TEST(enlarged_pair(scene.bodies[1], scene.bodies[0]));
  BOOST_TEST(!enlarged_pair(scene.bodies[1], scene.bodies[1]));
}

BOOST_AUTO_TEST_SUITE_END()
