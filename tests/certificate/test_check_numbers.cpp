// src/certificate/check_numbers.h: the checker's own exact vocabulary
// (vectors, poses, its one de Casteljau subdivision, GMP integers with
// value semantics).
#include "src/certificate/check_numbers.h"

#include <boost/test/unit_test.hpp>

#include <array>
#include <vector>

using namespace tmcert;
using namespace tmcert::certificate::check_internal;

BOOST_AUTO_TEST_SUITE(certificate_check_numbers)

BOOST_AUTO_TEST_CASE(vectors_and_poses) {
  const Vec3E a{Exact(1, 3), Exact(2), Exact(-1)}, b{Exact(1), Exact(1, 2), Exact(0)};
  BOOST_TEST((sub(a, b) == Vec3E{Exact(-2, 3), Exact(3, 2), Exact(-1)}));
  BOOST_TEST((cross(a, b) == Vec3E{Exact(1, 2), Exact(-1), Exact(1, 6) - 2}));
  BOOST_TEST(sgn(dot(a, cross(a, b))) == 0);
  BOOST_TEST(is_zero(cross(a, a)));
  BOOST_TEST(!is_zero(a));
  // A quarter turn about z with translation (1, 2, 3): det +1, a point placed.
  const Mat34E m{0, -1, 0, 1, 1, 0, 0, 2, 0, 0, 1, 3};
  BOOST_TEST(determinant(m) == 1);
  BOOST_TEST((place_point(m, a) == Vec3E{Exact(-1), Exact(7, 3), Exact(2)}));
  BOOST_TEST((place_point(identity_pose(), a) == a));
  BOOST_TEST(determinant(identity_pose()) == 1);
  BOOST_TEST(str(Vec3E{Exact(1, 2), Exact(0), Exact(-3)}) == "(" + str(Exact(1, 2)) + ", 0, -3)");
}

BOOST_AUTO_TEST_CASE(rationals_from_their_parts) {
  const Exact q(-6, 4);  // canonical -3/2
  BOOST_TEST(mpz_get_si(num(q)) == -3);
  BOOST_TEST(mpz_get_si(den(q)) == 2);
  BOOST_TEST(sgn(q) == -1);
  BOOST_TEST(from_z(num(q), den(q)) == q);
}

BOOST_AUTO_TEST_CASE(integers_have_value_semantics) {
  Z a(5);
  Z b = a;
  mpz_add_ui(b.v, b.v, 1);  // in place on the copy only
  BOOST_TEST(mpz_get_si(a.v) == 5);
  BOOST_TEST(mpz_get_si(b.v) == 6);
  a = b;
  mpz_add_ui(a.v, a.v, 1);
  BOOST_TEST(mpz_get_si(b.v) == 6);
  BOOST_TEST(mpz_get_si(a.v) == 7);
}

BOOST_AUTO_TEST_CASE(de_casteljau_parts_meet_on_the_curve) {
  using P = std::array<Exact, 2>;
  // The quadratic with controls (0,0), (1,2), (2,0): at s = 1/4 the point (1/2, 3/4).
  const std::vector<P> c = {{Exact(0), Exact(0)}, {Exact(1), Exact(2)}, {Exact(2), Exact(0)}};
  const std::vector<P> left = split_controls(c, Exact(1, 4), true), right = split_controls(c, Exact(1, 4), false);
  const P at{Exact(1, 2), Exact(3, 4)};
  BOOST_TEST((left == std::vector<P>{c[0], P{Exact(1, 4), Exact(1, 2)}, at}));
  BOOST_TEST((right == std::vector<P>{at, P{Exact(5, 4), Exact(3, 2)}, c[2]}));
  // Splitting at 0 and 1 gives the curve back (and a point).
  BOOST_TEST((split_controls(c, Exact(0), false) == c));
  BOOST_TEST((split_controls(c, Exact(1), true) == c));
  BOOST_TEST((split_controls(std::vector<P>{c[1]}, Exact(1, 3), true) == std::vector<P>{c[1]}));
}

BOOST_AUTO_TEST_SUITE_END()
