// kernels/vec3.h: the verifier's vector vocabulary, exact over rationals
// and the same interval enclosure as the expression it replaced.
#include "kernels/vec3.h"

#include "kernels/number_types.h"

#include <boost/test/unit_test.hpp>

using tmcert::Exact;
using tmcert::Interval;
using tmcert::Mat34E;
using tmcert::Vec3E;
namespace vec3 = tmcert::vec3;

BOOST_AUTO_TEST_SUITE(vec3_vocabulary)

BOOST_AUTO_TEST_CASE(exact_operations) {
  const Vec3E a{Exact(1, 3), Exact(2), Exact(-1)}, b{Exact(1), Exact(1, 2), Exact(0)};
  BOOST_TEST((vec3::sub(a, b) == Vec3E{Exact(-2, 3), Exact(3, 2), Exact(-1)}));
  // a x b = (2*0 - (-1)(1/2), (-1)(1) - (1/3)(0), (1/3)(1/2) - 2*1)
  BOOST_TEST((vec3::cross(a, b) == Vec3E{Exact(1, 2), Exact(-1), Exact(1, 6) - 2}));
  BOOST_TEST(vec3::dot(a, vec3::cross(a, b)) == 0);
  BOOST_TEST(vec3::dot(a, b) == Exact(1, 3) + 1);
  BOOST_TEST(vec3::is_zero(vec3::cross(a, a)));
  BOOST_TEST(!vec3::is_zero(a));
  // x -> A x + a with A a quarter turn about z and a = (1, 2, 3).
  const Mat34E m{0, -1, 0, 1, 1, 0, 0, 2, 0, 0, 1, 3};
  BOOST_TEST((vec3::apply(m, a) == Vec3E{Exact(-1), Exact(7, 3), Exact(2)}));
  // The linear part alone leaves out the translation (a vector, not a point).
  BOOST_TEST((vec3::apply_linear(m, a) == Vec3E{Exact(-2), Exact(1, 3), Exact(-1)}));
}

BOOST_AUTO_TEST_CASE(composition_applies_the_right_map_first) {
  // m: a quarter turn about z, then (1, 2, 3); s: a scaling by 2 along x,
  // then (0, 0, 1/3).  Neither commutes with the other.
  const Mat34E m{0, -1, 0, 1, 1, 0, 0, 2, 0, 0, 1, 3};
  const Mat34E s{2, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, Exact(1, 3)};
  const Vec3E x{Exact(1, 3), Exact(2), Exact(-1)};
  BOOST_TEST((vec3::apply(vec3::compose(m, s), x) == vec3::apply(m, vec3::apply(s, x))));
  BOOST_TEST((vec3::apply(vec3::compose(s, m), x) == vec3::apply(s, vec3::apply(m, x))));
  BOOST_TEST((vec3::compose(m, s) != vec3::compose(s, m)));
  const Mat34E id = vec3::identity<Exact>();
  BOOST_TEST((vec3::compose(id, m) == m));
  BOOST_TEST((vec3::compose(m, id) == m));
  BOOST_TEST((vec3::apply(id, x) == x));
}

BOOST_AUTO_TEST_CASE(interval_enclosures) {
  tmcert::RoundingGuard guard;
  const std::array<Interval, 3> a{Interval(0.1), Interval(1, 2), Interval(-1)}, b{Interval(3), Interval(0), Interval(1)};
  const Interval d = vec3::dot(a, b);  // 0.1 * 3 + [1, 2] * 0 - 1: about -0.7
  BOOST_TEST(d.inf() < -0.6999);
  BOOST_TEST(d.sup() > -0.7001);
  BOOST_TEST(d.sup() - d.inf() < 1e-12);
  const std::array<Interval, 3> c = vec3::cross(a, b);  // c[1] = a2 b0 - a0 b2 = -3 - 0.1
  BOOST_TEST(c[1].inf() < -3.0999);
  BOOST_TEST(c[1].sup() > -3.1001);
}

BOOST_AUTO_TEST_SUITE_END()
