// src/certificate/writer_common: the certificate writer's shared
// vocabulary.  Directions rounded to about 20 significant bits (relative to
// the largest component), exact poses of a body at a scene parameter, the
// identity for a body without motion, which checks the plain format cannot
// describe, and the JSON forms of exact numbers.
#include "src/certificate/writer_common.h"
#include "tests/verify/check_testing.h"

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <limits>

using namespace tmcert;
using namespace tmcert::certificate::writer_internal;
using tmcert::testing::two_cubes;

BOOST_AUTO_TEST_SUITE(writer_common)

BOOST_AUTO_TEST_CASE(rounded_keeps_about_twenty_bits) {
  const std::array<double, 3> n = {0.1, -0.7, 1e-9};
  const std::array<double, 3> r = rounded(n);
  // The unit is 2^(ilogb(0.7) - 20) = 2^-21: every component a multiple of
  // it, within half of it.
  const double unit = std::ldexp(1.0, -21);
  for (int i = 0; i < 3; ++i) {
    BOOST_TEST(std::fabs(r[i] - n[i]) <= unit / 2);
    BOOST_TEST(std::nearbyint(r[i] / unit) * unit == r[i]);
  }
  BOOST_TEST(r[2] == 0.0);  // far below the unit
  // Zero and non-finite directions are left as they are.
  const std::array<double, 3> zero = {0, 0, 0};
  BOOST_TEST((rounded(zero) == zero));
  const double inf = std::numeric_limits<double>::infinity();
  const std::array<double, 3> wild = {inf, 1.2345678901, 0};
  BOOST_TEST(rounded(wild)[1] == 1.2345678901);
  // Short already: unchanged.
  const std::array<double, 3> exact = {1, 0.5, -3};
  BOOST_TEST((rounded(exact) == exact));
}

BOOST_AUTO_TEST_CASE(poses_exact) {
  const Scene scene = two_cubes("-3 0 0", "3 0 0");
  const Body& mover = scene.bodies[0];
  const Body& post = scene.bodies[1];
  const Mat34E at_third = pose(mover, Exact(1, 3));
  BOOST_TEST((at_third == Mat34E{1, 0, 0, -1, 0, 1, 0, 0, 0, 0, 1, 0}));
  BOOST_TEST((pose(post, Exact(1, 3)) == kIdentity));
  BOOST_TEST((tmcert::certificate::writer_internal::apply(at_third, Vec3E{Exact(1, 2), 2, 3}) == Vec3E{Exact(-1, 2), 2, 3}));
  const Motion still = motion_or_identity(post);
  BOOST_REQUIRE(still.control_points.size() == 1u);
  BOOST_TEST((still.control_points[0] == kIdentity));
  BOOST_TEST((motion_or_identity(mover).control_points == mover.motion->control_points));
}

BOOST_AUTO_TEST_CASE(general_checks) {
  const Scene scene = two_cubes("-3 0 0", "3 0 0");
  Body a = scene.bodies[0], b = scene.bodies[1];
  BOOST_TEST(!general_check(a, b, 0));
  BOOST_TEST(general_check(a, b, Exact(1, 100)));  // a clearance
  b.tolerance = Exact(1, 1000);
  BOOST_TEST(general_check(a, b, 0));  // a tolerance
}

BOOST_AUTO_TEST_CASE(numbers_as_exact_strings) {
  BOOST_TEST(rational(Exact(-7, 3)) == json("-7/3"));
  BOOST_TEST(rational(Exact(4)) == json("4"));
  BOOST_TEST(vec(Vec3E{Exact(1, 2), 0, -5}) == json::array({"1/2", "0", "-5"}));
}

BOOST_AUTO_TEST_SUITE_END()
