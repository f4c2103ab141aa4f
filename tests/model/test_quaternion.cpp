// src/model/quaternion.h: the rotation a quaternion stands for, exactly
// over rationals.
#include "src/model/quaternion.h"

#include "kernels/number_types.h"

#include <boost/test/unit_test.hpp>

#include <array>

using tmcert::Exact;
namespace quaternion = tmcert::quaternion;
using Q = quaternion::Quat<Exact>;
using M = std::array<Exact, 9>;

namespace {

M product(const M& a, const M& b) {
  M out;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) out[3 * r + c] = a[3 * r] * b[c] + a[3 * r + 1] * b[3 + c] + a[3 * r + 2] * b[6 + c];
  return out;
}

M scaled(const M& a, const Exact& f) {
  M out = a;
  for (Exact& x : out) x *= f;
  return out;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(model_quaternion)

BOOST_AUTO_TEST_CASE(rotation_form_is_the_rotation_times_the_squared_norm) {
  // A quarter turn about z: q = (1, 0, 0, 1) (|q|^2 = 2), R = [[0,-1,0],[1,0,0],[0,0,1]].
  const Q q{1, 0, 0, 1};
  BOOST_TEST(quaternion::qdot(q, q) == 2);
  BOOST_TEST((quaternion::rotation_form(q) == scaled(M{0, -1, 0, 1, 0, 0, 0, 0, 1}, 2)));
  // The identity, and -q the same rotation as q.
  BOOST_TEST((quaternion::rotation_form(Q{3, 0, 0, 0}) == M{9, 0, 0, 0, 9, 0, 0, 0, 9}));
  BOOST_TEST((quaternion::rotation_form(Q{-1, 0, 0, -1}) == quaternion::rotation_form(q)));
}

BOOST_AUTO_TEST_CASE(rotation_form_is_orthogonal) {
  // R(q) R(q)^T = |q|^4 I for any quaternion, exactly.
  const Q q{Exact(1, 2), Exact(-2), Exact(3, 7), Exact(5)};
  const M r = quaternion::rotation_form(q);
  M rt;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) rt[3 * i + j] = r[3 * j + i];
  const Exact n2 = quaternion::qdot(q, q);
  BOOST_TEST((product(r, rt) == M{n2 * n2, 0, 0, 0, n2 * n2, 0, 0, 0, n2 * n2}));
}

BOOST_AUTO_TEST_CASE(the_hamilton_product_composes_rotations) {
  const Q a{Exact(1), Exact(2), Exact(-1, 3), Exact(0)}, b{Exact(-3), Exact(1, 2), Exact(4), Exact(1)};
  BOOST_TEST((quaternion::rotation_form(quaternion::qmul(a, b)) ==
              product(quaternion::rotation_form(a), quaternion::rotation_form(b))));
  // Not commutative: b a is another rotation here.
  BOOST_TEST((quaternion::qmul(a, b) != quaternion::qmul(b, a)));
}

BOOST_AUTO_TEST_CASE(the_bilinear_form_is_the_polarisation) {
  const Q p{Exact(1), Exact(2), Exact(-1, 3), Exact(0)}, q{Exact(-3), Exact(1, 2), Exact(4), Exact(1)};
  BOOST_TEST((quaternion::rotation_bilinear(q, q) == quaternion::rotation_form(q)));
  BOOST_TEST((quaternion::rotation_bilinear(p, q) == quaternion::rotation_bilinear(q, p)));
  // R(p + q) = R(p) + 2 B(p, q) + R(q).
  Q s;
  for (int i = 0; i < 4; ++i) s[i] = p[i] + q[i];
  const M rp = quaternion::rotation_form(p), rq = quaternion::rotation_form(q), b = quaternion::rotation_bilinear(p, q);
  M sum;
  for (int i = 0; i < 9; ++i) sum[i] = rp[i] + 2 * b[i] + rq[i];
  BOOST_TEST((quaternion::rotation_form(s) == sum));
}

BOOST_AUTO_TEST_SUITE_END()
