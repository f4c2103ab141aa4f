// The exact pose algebra (src/model/pose_algebra.h).
#include "src/model/pose_algebra.h"

#include "kernels/decimal.h"
#include "kernels/validated.h"
#include "src/model/quaternion.h"

#include <CGAL/number_utils.h>

#include <algorithm>
#include <climits>

namespace tmcert {

using quaternion::Quat;
using quaternion::qdot;
using quaternion::qmul;
using quaternion::rotation_bilinear;
using quaternion::rotation_form;

namespace {

const Mat34E kIdentity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};

// L with |x| in (2^(L-1), 2^(L+1)), for x != 0: the bit lengths of the
// numerator and denominator (n in [2^(a-1), 2^a), d in [2^(b-1), 2^b)).
long log2_magnitude(const Exact& x) {
  return static_cast<long>(mpz_sizeinbase(mpq_numref(x.mpq()), 2)) -
         static_cast<long>(mpz_sizeinbase(mpq_denref(x.mpq()), 2));
}

// 2^e exactly.
Exact power_of_two(long e) {
  Exact out(1);
  if (e >= 0) mpq_mul_2exp(out.mpq(), out.mpq(), static_cast<mp_bitcnt_t>(e));
  else mpq_div_2exp(out.mpq(), out.mpq(), static_cast<mp_bitcnt_t>(-e));
  return out;
}

bool all_zero(const std::array<Exact, 3>& a) { return a[0] == 0 && a[1] == 0 && a[2] == 0; }

}  // namespace

// ------------------------------------------------------------------ poses

// Two rotations are equal, proven exactly (false also when unknown).
bool same_rotation(const Rotation& a, const Rotation& b) {
  if (a.kind == Rotation::Kind::Rpy && b.kind == Rotation::Kind::Rpy) return a.rpy == b.rpy;
  const auto qa = exact_quaternion(a), qb = exact_quaternion(b);
  if (!qa || !qb) return false;
  // Proportional quaternions (either sign): every 2x2 minor vanishes.  A
  // minor whose interval enclosure excludes 0 is not zero (the common
  // case of two different rotations, decided without rational products);
  // the others are decided exactly (proofs/enclosures.md section 3b).
  {
    RoundingGuard guard;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) {
        const Interval m = to_interval((*qa)[i]) * to_interval((*qb)[j]) - to_interval((*qa)[j]) * to_interval((*qb)[i]);
        if (m.inf() > 0 || m.sup() < 0) return false;
      }
  }
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j)
      if ((*qa)[i] * (*qb)[j] != (*qa)[j] * (*qb)[i]) return false;
  return true;
}

std::optional<std::array<Exact, 4>> exact_quaternion(const Rotation& r) {
  switch (r.kind) {
    case Rotation::Kind::Identity: return std::array<Exact, 4>{1, 0, 0, 0};
    case Rotation::Kind::Quaternion: return r.quaternion;
    case Rotation::Kind::Rpy:
      if (all_zero(r.rpy)) return std::array<Exact, 4>{1, 0, 0, 0};
      return std::nullopt;
    case Rotation::Kind::Matrix: {
      // A nonzero multiple of the quaternion, rationally: (1 + tr, m21 - m12,
      // m02 - m20, m10 - m01) = 4w q, or the branch of the largest diagonal
      // entry when 1 + tr = 0 (a half turn).
      const auto& m = r.matrix;
      const Exact tr = m[0] + m[4] + m[8];
      if (1 + tr > 0) return std::array<Exact, 4>{1 + tr, m[7] - m[5], m[2] - m[6], m[3] - m[1]};
      if (m[0] >= m[4] && m[0] >= m[8]) return std::array<Exact, 4>{m[7] - m[5], 1 + m[0] - m[4] - m[8], m[1] + m[3], m[2] + m[6]};
      if (m[4] >= m[8]) return std::array<Exact, 4>{m[2] - m[6], m[1] + m[3], 1 - m[0] + m[4] - m[8], m[5] + m[7]};
      return std::array<Exact, 4>{m[3] - m[1], m[2] + m[6], m[5] + m[7], 1 - m[0] - m[4] + m[8]};
    }
  }
  return std::nullopt;
}

Exact quaternion_scale(const std::array<Exact, 4>& q) {
  long top = LONG_MIN;
  for (const Exact& x : q)
    if (x != 0) top = std::max(top, log2_magnitude(x));
  return top == LONG_MIN ? Exact(1) : power_of_two(-top);
}

std::array<Interval, 4> unit_quaternion(const Rotation& r) {
  if (auto q = exact_quaternion(r)) {
    // Scaled exactly first (the same rotation), so that a quaternion of
    // 1e-400 or 1e400 is not enclosed by [0, tiny] or [huge, inf].
    const Exact f = quaternion_scale(*q);
    for (Exact& x : *q) x *= f;
    const Interval n = validated::sqrt(qdot(*q, *q));
    return {to_interval((*q)[0]) / n, to_interval((*q)[1]) / n, to_interval((*q)[2]) / n, to_interval((*q)[3]) / n};
  }
  // R = Rz(yaw) Ry(pitch) Rx(roll): q = qz qy qx with half angles.
  auto half = [](const Exact& a) { return to_interval(a) / Interval(2); };
  const Interval hr = half(r.rpy[0]), hp = half(r.rpy[1]), hy = half(r.rpy[2]);
  const Quat<Interval> qx{validated::cos(hr), validated::sin(hr), Interval(0), Interval(0)};
  const Quat<Interval> qy{validated::cos(hp), Interval(0), validated::sin(hp), Interval(0)};
  const Quat<Interval> qz{validated::cos(hy), Interval(0), Interval(0), validated::sin(hy)};
  return qmul(qmul(qz, qy), qx);
}

std::optional<Mat34E> exact_pose(const Pose& p) {
  Mat34E m = kIdentity;
  if (p.rotation.kind == Rotation::Kind::Matrix) {
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) m[4 * r + c] = p.rotation.matrix[3 * r + c];
  } else {
    const auto q = exact_quaternion(p.rotation);
    if (!q) return std::nullopt;
    const Exact n2 = qdot(*q, *q);
    const std::array<Exact, 9> R = rotation_form(*q);
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) m[4 * r + c] = R[3 * r + c] / n2;
  }
  for (int r = 0; r < 3; ++r) m[4 * r + 3] = p.translation[r];
  return m;
}

std::string rotation_matrix_problem(const std::array<Exact, 9>& m) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const Exact d = m[3 * i] * m[3 * j] + m[3 * i + 1] * m[3 * j + 1] + m[3 * i + 2] * m[3 * j + 2];
      if (d != (i == j ? 1 : 0)) return "the rows are not exactly orthonormal (row " + std::to_string(i) + " . row " +
                                        std::to_string(j) + " = " + decimal_text(d) + ")";
    }
  const Exact det = m[0] * (m[4] * m[8] - m[5] * m[7]) - m[1] * (m[3] * m[8] - m[5] * m[6]) +
                    m[2] * (m[3] * m[7] - m[4] * m[6]);
  if (det != 1) return "the determinant is " + decimal_text(det) + ", not +1 (a reflection)";
  return {};
}

// ------------------------------------------------------------------ exact segments

namespace {

Motion translation_motion(const Mat34E& from, const Vec3E& to, const Exact& t0, const Exact& t1) {
  Motion m;
  m.t0 = t0;
  m.t1 = t1;
  Mat34E end = from;
  for (int r = 0; r < 3; ++r) end[4 * r + 3] = to[r];
  m.control_points = {from, end};
  m.weights = {1, 1};
  return m;
}

}  // namespace

std::optional<Motion> rational_keyframe_segment(const Pose& a, const Pose& b, Interpolation how, const Exact& t0,
                                                const Exact& t1) {
  // Different rotations under slerp or screw: no rational segment, and no
  // exact pose is needed to say so.
  const bool same = same_rotation(a.rotation, b.rotation);
  if (!same && how != Interpolation::Nlerp) return std::nullopt;
  const auto pa = exact_pose(a);
  if (same && pa) return translation_motion(*pa, b.translation, t0, t1);
  const auto pb = exact_pose(b);
  if (how != Interpolation::Nlerp || !pa || !pb) return std::nullopt;
  // q(s) = (1 - s) q0 + s q1 (q1 negated when q0 . q1 < 0): the rotation
  // form R(q(s)) is quadratic with Bernstein controls B(q0,q0), B(q0,q1),
  // B(q1,q1), and so is the weight |q(s)|^2; the translation times the
  // weight is cubic.  Everything is raised to degree 3.
  const std::array<Exact, 4> q0 = *exact_quaternion(a.rotation);
  std::array<Exact, 4> q1 = *exact_quaternion(b.rotation);
  if (qdot(q0, q1) < 0)
    for (Exact& x : q1) x = -x;
  const std::array<std::array<Exact, 9>, 3> R = {rotation_form(q0), rotation_bilinear(q0, q1), rotation_form(q1)};
  const std::array<Exact, 3> w = {qdot(q0, q0), qdot(q0, q1), qdot(q1, q1)};
  const Vec3E &T0 = a.translation, &T1 = b.translation;
  Motion m;
  m.t0 = t0;
  m.t1 = t1;
  // Degree elevation 2 -> 3: c'0 = c0, c'1 = (c0 + 2 c1) / 3, c'2 = (2 c1 + c2) / 3, c'3 = c2.
  auto elevate = [](const Exact& c0, const Exact& c1, const Exact& c2) {
    return std::array<Exact, 4>{c0, (c0 + 2 * c1) / 3, (2 * c1 + c2) / 3, c2};
  };
  const std::array<Exact, 4> weights = elevate(w[0], w[1], w[2]);
  m.weights.assign(weights.begin(), weights.end());
  m.control_points.assign(4, Mat34E{});
  for (int e = 0; e < 9; ++e) {
    const std::array<Exact, 4> c = elevate(R[0][e], R[1][e], R[2][e]);
    for (int k = 0; k < 4; ++k) m.control_points[k][4 * (e / 3) + e % 3] = c[k] / weights[k];
  }
  for (int r = 0; r < 3; ++r) {
    // (w T) as the product of a quadratic (w) and a linear (T) Bernstein form.
    const std::array<Exact, 4> wt = {w[0] * T0[r], (2 * w[1] * T0[r] + w[0] * T1[r]) / 3,
                                     (w[2] * T0[r] + 2 * w[1] * T1[r]) / 3, w[2] * T1[r]};
    for (int k = 0; k < 4; ++k) m.control_points[k][4 * r + 3] = wt[k] / weights[k];
  }
  normalise_weights(m);  // |q|^2 of a quaternion of 1e300 is 1e600
  m.nlerp = true;
  return m;
}

void require_interpolable(const Pose& a, const Pose& b, Interpolation how) {
  if (same_rotation(a.rotation, b.rotation)) return;
  const auto qa = exact_quaternion(a.rotation), qb = exact_quaternion(b.rotation);
  if (qa && qb) {
    // nlerp's sign rule (negate when the dot product is negative) is
    // decided exactly; a zero dot product leaves nlerp well defined.  An
    // interval enclosure of the dot product that excludes 0 proves it
    // nonzero (proofs/enclosures.md section 3c); exact only otherwise.
    if (how == Interpolation::Nlerp) return;
    {
      RoundingGuard guard;
      Quat<Interval> ia, ib;
      for (int i = 0; i < 4; ++i) {
        ia[i] = to_interval((*qa)[i]);
        ib[i] = to_interval((*qb)[i]);
      }
      const Interval d = qdot(ia, ib);
      if (d.inf() > 0 || d.sup() < 0) return;
    }
    if (qdot(*qa, *qb) == 0)
      throw InputError("the two rotations are exactly 180 degrees apart: the interpolation has no shorter arc");
    return;
  }
  // An enclosed (rpy) end: the sign of the dot product, which picks the arc
  // for every interpolation (nlerp's negation rule too), must be certain.
  RoundingGuard guard;
  const Interval d = qdot(unit_quaternion(a.rotation), unit_quaternion(b.rotation));
  if (!(d.inf() > 0) && !(d.sup() < 0))
    throw InputError("cannot prove which arc between the two rotations is shorter (they are 180 degrees apart or "
                     "within rounding of it)");
}

void normalise_weights(Motion& m) {
  if (m.weights.empty()) return;
  auto comfortable = [](const Exact& w) {
    const long e = log2_magnitude(w);
    return e > -32 && e < 32;  // w in (2^-32, 2^32)
  };
  if (std::all_of(m.weights.begin(), m.weights.end(), comfortable)) return;
  // Coprime integers: times the lcm of the denominators, over the gcd of
  // the numerators (both positive; the weights are positive).
  CGAL::Gmpz g(0), l(1);
  for (const Exact& w : m.weights) {
    mpz_gcd(g.mpz(), g.mpz(), mpq_numref(w.mpq()));
    mpz_lcm(l.mpz(), l.mpz(), mpq_denref(w.mpq()));
  }
  const Exact factor(l, g);
  Exact top(0);
  for (Exact& w : m.weights) {
    w *= factor;
    if (w > top) top = w;
  }
  if (comfortable(top) || log2_magnitude(top) < 0) return;
  const Exact shift = power_of_two(-log2_magnitude(top));
  for (Exact& w : m.weights) w *= shift;
}

}  // namespace tmcert
