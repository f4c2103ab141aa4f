#include "src/certificate/motions.h"

#include "src/certificate/check_numbers.h"
#include "src/certificate/motion_kinds.h"

#include "src/model/chain.h"

#include <gmp.h>
#include <arb.h>
#include <flint/fmpq.h>
#include <flint/fmpz.h>

#include <algorithm>
#include <cmath>

namespace tmcert::certificate {

namespace {

// ---------------------------------------------------------------- balls

constexpr slong kPrec = 192;
// Parts of a piece enclosed separately (piece_motion).
constexpr int kSubBalls = 32;

// An Arb ball with value semantics, enough arithmetic for the formulas.
class B {
 public:
  B() { arb_init(v); }
  B(long x) { arb_init(v), arb_set_si(v, x); }
  explicit B(const Exact& q) {
    arb_init(v);
    fmpq_t f;
    fmpq_init(f);
    fmpz_set_mpz(fmpq_numref(f), mpq_numref(q.mpq()));
    fmpz_set_mpz(fmpq_denref(f), mpq_denref(q.mpq()));
    arb_set_fmpq(v, f, kPrec);
    fmpq_clear(f);
  }
  B(const B& o) { arb_init(v), arb_set(v, o.v); }
  B& operator=(const B& o) {
    arb_set(v, o.v);
    return *this;
  }
  ~B() { arb_clear(v); }
  arb_t v;
};

B operator+(const B& a, const B& b) { B r; arb_add(r.v, a.v, b.v, kPrec); return r; }
B operator-(const B& a, const B& b) { B r; arb_sub(r.v, a.v, b.v, kPrec); return r; }
B operator-(const B& a) { B r; arb_neg(r.v, a.v); return r; }
B operator*(const B& a, const B& b) { B r; arb_mul(r.v, a.v, b.v, kPrec); return r; }
B operator/(const B& a, const B& b) { B r; arb_div(r.v, a.v, b.v, kPrec); return r; }
B bsqrt(const B& a) { B r; arb_sqrt(r.v, a.v, kPrec); return r; }
// The square root of a sum of squares: arb_sqrtpos drops the negative part
// that the ball of such a sum may have near 0 (arb_sqrt would give an
// indeterminate ball there).
B bsqrt_nonnegative(const B& a) { B r; arb_sqrtpos(r.v, a.v, kPrec); return r; }
B bsin(const B& a) { B r; arb_sin(r.v, a.v, kPrec); return r; }
B bcos(const B& a) { B r; arb_cos(r.v, a.v, kPrec); return r; }
B bsinc(const B& a) { B r; arb_sinc(r.v, a.v, kPrec); return r; }
B batan2(const B& y, const B& x) { B r; arb_atan2(r.v, y.v, x.v, kPrec); return r; }
// The ball holding [lo, hi].
B interval(const Exact& lo, const Exact& hi) {
  B a(lo), b(hi), r;
  arb_union(r.v, a.v, b.v, kPrec);
  return r;
}

using Q = std::array<B, 4>;  // quaternion (w, x, y, z)
using V3 = std::array<B, 3>;
using M3 = std::array<B, 9>;  // rows

B qdot(const Q& a, const Q& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3]; }
Q qmul(const Q& a, const Q& b) {
  return {a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3], a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
          a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1], a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0]};
}
// The rotation matrix of q / |q| times |q|^2.
M3 rotation_times_norm2(const Q& q) {
  const B &w = q[0], &x = q[1], &y = q[2], &z = q[3];
  const B two(2);
  return {w * w + x * x - y * y - z * z, two * (x * y - w * z), two * (x * z + w * y),
          two * (x * y + w * z), w * w - x * x + y * y - z * z, two * (y * z - w * x),
          two * (x * z - w * y), two * (y * z + w * x), w * w - x * x - y * y + z * z};
}
V3 mul(const M3& m, const V3& x) {
  return {m[0] * x[0] + m[1] * x[1] + m[2] * x[2], m[3] * x[0] + m[4] * x[1] + m[5] * x[2],
          m[6] * x[0] + m[7] * x[1] + m[8] * x[2]};
}
V3 cross(const V3& a, const V3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// ---------------------------------------------------------------- series

// The largest magnitude of a ball, rounded up (a double; infinite when the
// ball is not finite).
double magnitude(const B& x) {
  arf_t m;
  arf_init(m);
  arb_get_abs_ubound_arf(m, x.v, kPrec);
  const double d = arf_get_d(m, ARF_RND_UP);
  arf_clear(m);
  return d;
}

// f_m(x) = sum_{k>=0} (-1)^k x^(2k) / (2k+m)! (m = 2: (1 - cos x)/x^2,
// m = 3: (x - sin x)/x^3), for every x in the ball, regular at 0: 60 terms
// and the bound of the rest, twice its first term (the terms fall by a
// factor below 1/1000 from there for |x| <= 4); the whole line for a wider
// ball.
B factorial_series(const B& x, int m) {
  B out;
  if (!(magnitude(x) <= 4)) {
    arb_indeterminate(out.v);
    return out;
  }
  constexpr int kTerms = 60;
  const B x2 = x * x;
  B power(1), fact;
  arb_fac_ui(fact.v, static_cast<ulong>(m), kPrec);
  arb_zero(out.v);
  for (int k = 0; k < kTerms; ++k) {
    if (k > 0) {
      power = power * x2;
      arb_mul_ui(fact.v, fact.v, static_cast<ulong>((2 * k + m - 1) * (2 * k + m)), kPrec);
    }
    const B term = power / fact;
    out = k % 2 ? out - term : out + term;
  }
  B rest;
  arb_set_d(rest.v, magnitude(x));
  arb_pow_ui(rest.v, rest.v, 2 * kTerms, kPrec);
  B nf;
  arb_fac_ui(nf.v, static_cast<ulong>(2 * kTerms + m), kPrec);
  rest = B(2) * rest / nf;
  arf_t bound;
  arf_init(bound);
  arb_get_abs_ubound_arf(bound, rest.v, kPrec);
  arb_add_error_arf(out.v, bound);
  arf_clear(bound);
  return out;
}

// C(phi) = (1 - (phi/2) cot(phi/2)) / phi^2 for every phi in the ball:
// for |phi| <= 1 the series sum_{n>=1} 2 zeta(2n) phi^(2n-2) / (2 pi)^(2n)
// (positive terms falling by phi^2 / (2 pi)^2 < 1/39 each, zeta < 2: the
// rest after N terms is below 4 (39/38) |phi|^(2N) / (2 pi)^(2N+2)),
// otherwise the closed form.
B screw_inverse_coefficient(const B& phi) {
  const double P = magnitude(phi);
  if (!(P <= 1)) {
    const B h = phi / B(2);
    return (B(1) - h * bcos(h) / bsin(h)) / (phi * phi);
  }
  constexpr int kTerms = 40;
  B two_pi;
  arb_const_pi(two_pi.v, kPrec);
  two_pi = B(2) * two_pi;
  const B inv2 = B(1) / (two_pi * two_pi);
  const B ph2 = phi * phi;
  B power = inv2, out(0), z;
  for (int n = 1; n <= kTerms; ++n) {
    if (n > 1) power = power * ph2 * inv2;
    arb_zeta_ui(z.v, static_cast<ulong>(2 * n), kPrec);
    out = out + B(2) * z * power;
  }
  B rest;
  arb_set_d(rest.v, P);
  arb_pow_ui(rest.v, rest.v, 2 * kTerms, kPrec);
  B inv_pow;
  arb_pow_ui(inv_pow.v, inv2.v, kTerms + 1, kPrec);
  rest = B(4 * 39) * rest * inv_pow / B(38);
  arf_t bound;
  arf_init(bound);
  arb_get_abs_ubound_arf(bound, rest.v, kPrec);
  arb_add_error_arf(out.v, bound);
  arf_clear(bound);
  return out;
}

// ---------------------------------------------------------------- rotations

// The quaternion the scene format interpolates for an exact rotation (as
// written; a matrix's rational multiple (1 + tr, m21 - m12, m02 - m20,
// m10 - m01) or its half-turn branch, docs/scene-format.md), nullopt for rpy.
std::optional<std::array<Exact, 4>> written_quaternion(const Rotation& r) {
  switch (r.kind) {
    case Rotation::Kind::Identity: return std::array<Exact, 4>{1, 0, 0, 0};
    case Rotation::Kind::Quaternion: return r.quaternion;
    case Rotation::Kind::Rpy:
      if (r.rpy[0] == 0 && r.rpy[1] == 0 && r.rpy[2] == 0) return std::array<Exact, 4>{1, 0, 0, 0};
      return std::nullopt;
    case Rotation::Kind::Matrix: {
      const auto& m = r.matrix;
      const Exact tr = m[0] + m[4] + m[8];
      if (1 + tr > 0) return std::array<Exact, 4>{1 + tr, m[7] - m[5], m[2] - m[6], m[3] - m[1]};
      if (m[0] >= m[4] && m[0] >= m[8])
        return std::array<Exact, 4>{m[7] - m[5], 1 + m[0] - m[4] - m[8], m[1] + m[3], m[2] + m[6]};
      if (m[4] >= m[8]) return std::array<Exact, 4>{m[2] - m[6], m[1] + m[3], 1 - m[0] + m[4] - m[8], m[5] + m[7]};
      return std::array<Exact, 4>{m[3] - m[1], m[2] + m[6], m[5] + m[7], 1 - m[0] - m[4] + m[8]};
    }
  }
  return std::nullopt;
}

Q ball_quaternion(const std::array<Exact, 4>& q) { return {B(q[0]), B(q[1]), B(q[2]), B(q[3])}; }

// The unit quaternion of the rotation (either sign).
Q ball_unit_quaternion(const Rotation& r) {
  if (const auto q = written_quaternion(r)) {
    const Q b = ball_quaternion(*q);
    const B n = bsqrt(qdot(b, b));
    return {b[0] / n, b[1] / n, b[2] / n, b[3] / n};
  }
  // R = Rz(yaw) Ry(pitch) Rx(roll): q = qz qy qx with half angles.
  auto half = [](const Exact& a) { return B(a) / B(2); };
  const B hr = half(r.rpy[0]), hp = half(r.rpy[1]), hy = half(r.rpy[2]);
  const Q qx{bcos(hr), bsin(hr), B(0), B(0)};
  const Q qy{bcos(hp), B(0), bsin(hp), B(0)};
  const Q qz{bcos(hy), B(0), B(0), bsin(hy)};
  return qmul(qmul(qz, qy), qx);
}

// The pose of a keyframe segment at every s in the ball `s`.
struct BallPose {
  M3 rotation;
  V3 translation;
};

bool certain_negative(const B& x) { return arb_is_negative(x.v); }
bool certain_positive(const B& x) { return arb_is_positive(x.v); }

std::optional<BallPose> keyframe_pose(const MotionSegment& seg, const B& s) {
  const Pose& a = seg.from;
  const Pose& b = seg.to;
  const Interpolation how = seg.interpolation;
  V3 p0, p1;
  for (int i = 0; i < 3; ++i) {
    p0[i] = B(a.translation[i]);
    p1[i] = B(b.translation[i]);
  }
  const B one(1);
  const B r = one - s;
  BallPose out;
  for (int i = 0; i < 3; ++i) out.translation[i] = p0[i] + (p1[i] - p0[i]) * s;  // linear (not for screw)

  // Equal rpy rotations (the only ones not made rational by the scene
  // reader): the rotation stands still and the translation is linear for
  // every interpolation (the screw's too: log of a pure translation).
  const bool same = a.rotation.kind == Rotation::Kind::Rpy && b.rotation.kind == Rotation::Kind::Rpy &&
                    a.rotation.rpy == b.rotation.rpy;
  const auto wa = written_quaternion(a.rotation), wb = written_quaternion(b.rotation);
  Q q0, q1;
  if (how == Interpolation::Nlerp) {
    q0 = wa ? ball_quaternion(*wa) : ball_unit_quaternion(a.rotation);
    q1 = wb ? ball_quaternion(*wb) : ball_unit_quaternion(b.rotation);
  } else {
    q0 = ball_unit_quaternion(a.rotation);
    q1 = ball_unit_quaternion(b.rotation);
  }
  // The shorter arc (nlerp's negation rule too): the sign of q0 . q1, exact
  // when both quaternions are, else certain from the balls.
  bool negate;
  if (wa && wb) {
    const Exact d = (*wa)[0] * (*wb)[0] + (*wa)[1] * (*wb)[1] + (*wa)[2] * (*wb)[2] + (*wa)[3] * (*wb)[3];
    negate = d < 0;
  } else {
    const B d = qdot(q0, q1);
    if (!same && !certain_negative(d) && !certain_positive(d)) return std::nullopt;
    negate = certain_negative(d);
  }
  if (negate)
    for (B& x : q1) x = -x;

  if (same) {
    out.rotation = rotation_times_norm2(q0);
    const B n2 = qdot(q0, q0);
    for (B& x : out.rotation) x = x / n2;
    return out;
  }
  if (how == Interpolation::Nlerp) {
    Q q;
    for (int i = 0; i < 4; ++i) q[i] = q0[i] + (q1[i] - q0[i]) * s;  // s once: no dependency blow-up
    out.rotation = rotation_times_norm2(q);
    const B n2 = qdot(q, q);
    for (B& x : out.rotation) x = x / n2;
    return out;
  }
  // Slerp (the rotation of the screw too): with the angle w between the
  // unit quaternions, q(s) = (sin((1-s) w) q0 + sin(s w) q1) / sin(w),
  // written with sinc (sin(u w) / sin(w) = u sinc(u w) / sinc(w)), which
  // stays finite when w is tiny or its ball holds 0.
  Q diff, sum;
  for (int i = 0; i < 4; ++i) {
    diff[i] = q0[i] - q1[i];
    sum[i] = q0[i] + q1[i];
  }
  const B w = B(2) * batan2(bsqrt_nonnegative(qdot(diff, diff)), bsqrt_nonnegative(qdot(sum, sum)));
  const B sw = bsinc(w);
  const B ca = r * bsinc(r * w) / sw, cb = s * bsinc(s * w) / sw;
  Q q;
  for (int i = 0; i < 4; ++i) q[i] = q0[i] * ca + q1[i] * cb;
  out.rotation = rotation_times_norm2(q);  // |q| = 1
  if (how == Interpolation::Slerp) return out;

  // Screw: T(s) = T0 exp(s xi), xi = log(T0^-1 T1) = (phi k, v) with the
  // relative rotation's angle phi and unit axis k, K = [k]x:
  //   v = V(phi)^-1 t,  V(phi)^-1 = I - (phi/2) K + (1 - (phi/2) cot(phi/2)) K^2,
  //   translation of exp(s xi) = s v + (1 - cos(s phi))/phi K v + (s - sin(s phi)/phi) K^2 v,
  // with t = R0^T (p1 - p0) the relative translation; the pose's
  // translation is p0 + R0 (that).  For phi away from 0 (above 2^-10).
  // Near 0, or 0 within the balls (rotations equal up to rounding), the
  // same with omega = phi k = 2 (d1, d2, d3) / sinc(phi/2) in forms regular
  // at 0 (C(phi), f2, f3 by their series):
  //   v = t - omega x t / 2 + C(phi) omega x (omega x t),
  //   translation of exp(s xi) = s v + s^2 f2(s phi) omega x v + s^3 f3(s phi) omega x (omega x v).
  const Q conj0{q0[0], -q0[1], -q0[2], -q0[3]};
  const Q d = qmul(conj0, q1);  // d[0] = q0 . q1 >= 0
  const B vnorm = bsqrt_nonnegative(d[1] * d[1] + d[2] * d[2] + d[3] * d[3]);
  const B phi = B(2) * batan2(vnorm, d[0]);
  const M3 R0 = rotation_times_norm2(q0);  // unit q0
  V3 t;
  for (int i = 0; i < 3; ++i)
    t[i] = R0[i] * (p1[0] - p0[0]) + R0[3 + i] * (p1[1] - p0[1]) + R0[6 + i] * (p1[2] - p0[2]);
  arf_t phi_lo;
  arf_init(phi_lo);
  arb_get_lbound_arf(phi_lo, phi.v, kPrec);
  const bool away = arf_cmp_2exp_si(phi_lo, -10) > 0;
  arf_clear(phi_lo);
  if (!away) {
    const B sinc_half = bsinc(phi / B(2));
    const V3 omega{B(2) * d[1] / sinc_half, B(2) * d[2] / sinc_half, B(2) * d[3] / sinc_half};
    const B c = screw_inverse_coefficient(phi);
    const V3 wt = cross(omega, t), wwt = cross(omega, wt);
    V3 v;
    for (int i = 0; i < 3; ++i) v[i] = t[i] - wt[i] / B(2) + c * wwt[i];
    const B x = s * phi;
    const B a = s * s * factorial_series(x, 2), b3 = s * s * s * factorial_series(x, 3);
    const V3 wv = cross(omega, v), wwv = cross(omega, wv);
    V3 local;
    for (int i = 0; i < 3; ++i) local[i] = s * v[i] + a * wv[i] + b3 * wwv[i];
    const V3 moved = mul(R0, local);
    for (int i = 0; i < 3; ++i) out.translation[i] = p0[i] + moved[i];
    return out;
  }
  const V3 k{d[1] / vnorm, d[2] / vnorm, d[3] / vnorm};
  const B half = phi / B(2);
  const B c2 = one - half * bcos(half) / bsin(half);
  const V3 kt = cross(k, t), kkt = cross(k, kt);
  V3 v;
  for (int i = 0; i < 3; ++i) v[i] = t[i] - half * kt[i] + c2 * kkt[i];
  const B sh = bsin(s * phi / B(2));
  const B c1 = B(2) * sh * sh / phi;  // (1 - cos(s phi)) / phi
  const B c3 = s - bsin(s * phi) / phi;
  const V3 kv = cross(k, v), kkv = cross(k, kv);
  V3 local;
  for (int i = 0; i < 3; ++i) local[i] = s * v[i] + c1 * kv[i] + c3 * kkv[i];
  const V3 moved = mul(R0, local);
  for (int i = 0; i < 3; ++i) out.translation[i] = p0[i] + moved[i];
  return out;
}

// ---------------------------------------------------------------- robot links

// [R | p] as balls.
struct BallMat {
  M3 r;
  V3 p;
};

BallMat compose(const BallMat& a, const BallMat& b) {
  BallMat out;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) out.r[3 * i + j] = a.r[3 * i] * b.r[j] + a.r[3 * i + 1] * b.r[3 + j] + a.r[3 * i + 2] * b.r[6 + j];
    out.p[i] = a.r[3 * i] * b.p[0] + a.r[3 * i + 1] * b.p[1] + a.r[3 * i + 2] * b.p[2] + a.p[i];
  }
  return out;
}

BallMat pose_matrix(const Pose& pose) {
  BallMat m;
  if (pose.rotation.kind == Rotation::Kind::Matrix) {
    for (int e = 0; e < 9; ++e) m.r[e] = B(pose.rotation.matrix[e]);
  } else {
    const Q q = ball_unit_quaternion(pose.rotation);
    m.r = rotation_times_norm2(q);  // |q| = 1
  }
  for (int i = 0; i < 3; ++i) m.p[i] = B(pose.translation[i]);
  return m;
}

// The link's pose C_0 J_1(q_1) C_1 ... J_n(q_n) C_n (src/motion/chain.h,
// proofs/robot-links.md) with q_j = from_j + (to_j - from_j) s: each
// constant the product of its poses, a revolute joint Rodrigues' rotation
// I + sin(q) K + (1 - cos q) K^2 about the unit axis (K = [u]x), a
// prismatic joint the translation q u.
BallPose chain_pose(const ChainDescription& chain, const std::vector<B>& values) {
  const auto& constants = chain.constant_poses();
  auto constant = [&](std::size_t k) {
    BallMat c{{B(1), B(0), B(0), B(0), B(1), B(0), B(0), B(0), B(1)}, {B(0), B(0), B(0)}};
    for (const Pose& p : constants[k]) c = compose(c, pose_matrix(p));
    return c;
  };
  BallMat m = constant(0);
  for (std::size_t j = 0; j < chain.joint_count(); ++j) {
    const ChainJoint& joint = chain.joint(j);
    const B& q = values[j];
    const B n = bsqrt(B(joint.axis[0]) * B(joint.axis[0]) + B(joint.axis[1]) * B(joint.axis[1]) +
                      B(joint.axis[2]) * B(joint.axis[2]));
    const V3 u{B(joint.axis[0]) / n, B(joint.axis[1]) / n, B(joint.axis[2]) / n};
    BallMat J{{B(1), B(0), B(0), B(0), B(1), B(0), B(0), B(0), B(1)}, {B(0), B(0), B(0)}};
    if (joint.kind == ChainJoint::Kind::Prismatic) {
      for (int i = 0; i < 3; ++i) J.p[i] = q * u[i];
    } else {
      const M3 K{B(0), -u[2], u[1], u[2], B(0), -u[0], -u[1], u[0], B(0)};
      M3 K2;
      for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k) K2[3 * i + k] = u[i] * u[k] - B(i == k ? 1 : 0);  // [u]x^2 = u u^T - I
      const B sn = bsin(q), vc = B(1) - bcos(q);
      for (int e = 0; e < 9; ++e) J.r[e] = J.r[e] + sn * K[e] + vc * K2[e];
    }
    m = compose(compose(m, J), constant(j + 1));
  }
  return BallPose{m.r, m.p};
}

BallPose link_pose(const LinkMotion& link, const B& s) {
  std::vector<B> q;
  for (std::size_t j = 0; j < link.chain->joint_count(); ++j)
    q.push_back(B(link.from[j]) + (B(link.to[j]) - B(link.from[j])) * s);
  return chain_pose(*link.chain, q);
}

// The Hermite basis polynomials at s (or, with `derivative`, their
// derivatives), each weighing one datum of a joint on a cubic or quintic
// segment (LinkMotion), with the ends' derivatives in s (duration times the
// rates, duration^2 times the accelerations):
//   cubic   q = p0 + (3s^2 - 2s^3) h + (s^3 - 2s^2 + s) D0 + (s^3 - s^2) D1,
//   quintic q = p0 + (10s^3 - 15s^4 + 6s^5) h + (s - 6s^3 + 8s^4 - 3s^5) D0
//             + (s^2 - 3s^3 + 3s^4 - s^5)/2 A0 + (s^3 - 2s^4 + s^5)/2 A1
//             + (-4s^3 + 7s^4 - 3s^5) D1,
// h = p1 - p0 (the checker's own form: the verifier goes through the power
// basis; proofs/trajectories.md section 4).  Order: h, D0, D1, A0, A1.
std::array<B, 5> hermite_basis(const B& s, bool quintic, bool derivative) {
  const B s2 = s * s, s3 = s2 * s, s4 = s3 * s, s5 = s4 * s;
  if (!quintic) {
    if (derivative)
      return {B(6) * s - B(6) * s2, B(3) * s2 - B(4) * s + B(1), B(3) * s2 - B(2) * s, B(0), B(0)};
    return {B(3) * s2 - B(2) * s3, s3 - B(2) * s2 + s, s3 - s2, B(0), B(0)};
  }
  if (derivative)
    return {B(30) * s2 - B(60) * s3 + B(30) * s4, B(1) - B(18) * s2 + B(32) * s3 - B(15) * s4,
            B(28) * s3 - B(12) * s2 - B(15) * s4, (B(2) * s - B(9) * s2 + B(12) * s3 - B(5) * s4) / B(2),
            (B(3) * s2 - B(8) * s3 + B(5) * s4) / B(2)};
  return {B(10) * s3 - B(15) * s4 + B(6) * s5, s - B(6) * s3 + B(8) * s4 - B(3) * s5, B(7) * s4 - B(4) * s3 - B(3) * s5,
          (s2 - B(3) * s3 + B(3) * s4 - s5) / B(2), (s3 - B(2) * s4 + s5) / B(2)};
}

// The link's pose on a cubic or quintic segment over the ball s: each q_j
// in the mean value form q(m) + q'(s) (s - m) about the ball's midpoint m
// (q' on the ball from the basis' derivatives), so that its radius is about
// max|q'| times the ball's, as for linear joints; then the chain.
BallPose hermite_link_pose(const LinkMotion& link, const B& s) {
  const bool quintic = link.degree() == 5;
  B m, offset;
  arb_get_mid_arb(m.v, s.v);
  offset = s - m;  // a ball about 0 holding s - m
  const std::array<B, 5> at_m = hermite_basis(m, quintic, false), slope = hermite_basis(s, quintic, true);
  const B T(link.duration), T2 = T * T;
  std::vector<B> q;
  for (std::size_t j = 0; j < link.chain->joint_count(); ++j) {
    const B p0(link.from[j]);
    const std::array<B, 5> data = {B(link.to[j]) - p0, T * B(link.from_rate[j]), T * B(link.to_rate[j]),
                                   quintic ? T2 * B(link.from_accel[j]) : B(0), quintic ? T2 * B(link.to_accel[j]) : B(0)};
    B value = p0, rate(0);
    for (int k = 0; k < 5; ++k) {
      value = value + at_m[k] * data[k];
      rate = rate + slope[k] * data[k];
    }
    q.push_back(value + rate * offset);
  }
  return chain_pose(*link.chain, q);
}

// The box of a ball pose: the ends rounded outward to doubles, the center
// their midpoint (short rationals for the checker's integer arithmetic).
std::optional<PoseBox> to_box(const BallPose& p) {
  PoseBox box;
  arf_t lo, hi;
  arf_init(lo);
  arf_init(hi);
  bool ok = true;
  for (int e = 0; e < 12 && ok; ++e) {
    const B& x = e % 4 == 3 ? p.translation[e / 4] : p.rotation[3 * (e / 4) + e % 4];
    if (!arb_is_finite(x.v)) {
      ok = false;
      break;
    }
    arb_get_interval_arf(lo, hi, x.v, kPrec);
    const double l = arf_get_d(lo, ARF_RND_FLOOR), h = arf_get_d(hi, ARF_RND_CEIL);
    if (!std::isfinite(l) || !std::isfinite(h)) {
      ok = false;
      break;
    }
    const Exact L(l), H(h);
    box.center[e] = (L + H) / 2;
    box.radius[e] = (H - L) / 2;
  }
  arf_clear(lo);
  arf_clear(hi);
  if (!ok) return std::nullopt;
  return box;
}

// ---------------------------------------------------------------- rational motions

const Mat34E kIdentity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};

// The restriction of a rational Bezier motion to [ta, tb] (de Casteljau on
// the homogeneous control points (w A, w)).
Motion restrict(const Motion& m, const Exact& ta, const Exact& tb) {
  Motion out;
  out.t0 = ta;
  out.t1 = tb;
  const std::size_t n = m.control_points.size();
  std::vector<std::array<Exact, 13>> c(n);
  for (std::size_t k = 0; k < n; ++k) {
    for (int e = 0; e < 12; ++e) c[k][e] = m.weights[k] * m.control_points[k][e];
    c[k][12] = m.weights[k];
  }
  const Exact span = m.t1 - m.t0;
  const Exact ua = (ta - m.t0) / span, ub = (tb - m.t0) / span;
  if (n > 1) {
    if (ub != 1) c = check_internal::split_controls(std::move(c), ub, true);
    if (ua != 0) c = check_internal::split_controls(std::move(c), ua / ub, false);
  }
  for (const auto& p : c) {
    Mat34E a;
    for (int e = 0; e < 12; ++e) a[e] = p[e] / p[12];
    out.control_points.push_back(a);
    out.weights.push_back(p[12]);
  }
  return out;
}

Mat34E evaluate(const Motion& m, const Exact& t) {
  if (m.control_points.size() == 1) return m.control_points[0];
  const Motion at = restrict(m, m.t0, t);  // its last control point is the pose at t
  return at.control_points.back();
}

Motion still(const Mat34E& pose, const Exact& ta, const Exact& tb) {
  Motion m;
  m.t0 = ta;
  m.t1 = tb;
  m.control_points = {pose};
  m.weights = {Exact(1)};
  return m;
}

std::optional<Mat34E> exact_keyframe(const Pose& p) {
  Mat34E m = kIdentity;
  if (p.rotation.kind == Rotation::Kind::Matrix) {
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) m[4 * r + c] = p.rotation.matrix[3 * r + c];
  } else {
    const auto q = written_quaternion(p.rotation);
    if (!q) return std::nullopt;
    const Exact &w = (*q)[0], &x = (*q)[1], &y = (*q)[2], &z = (*q)[3];
    const Exact n2 = w * w + x * x + y * y + z * z;
    const std::array<Exact, 9> R = {w * w + x * x - y * y - z * z, 2 * (x * y - w * z), 2 * (x * z + w * y),
                                    2 * (x * y + w * z), w * w - x * x + y * y - z * z, 2 * (y * z - w * x),
                                    2 * (x * z - w * y), 2 * (y * z + w * x), w * w - x * x - y * y + z * z};
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) m[4 * r + c] = R[3 * r + c] / n2;
  }
  for (int r = 0; r < 3; ++r) m[4 * r + 3] = p.translation[r];
  return m;
}

// a b for 3x4 affine maps, exactly.
Mat34E compose_exact(const Mat34E& a, const Mat34E& b) {
  Mat34E out;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) {
      Exact sum = a[4 * r] * b[c] + a[4 * r + 1] * b[4 + c] + a[4 * r + 2] * b[8 + c];
      if (c == 3) sum += a[4 * r + 3];
      out[4 * r + c] = sum;
    }
  return out;
}

// The rational square root of q >= 0, when there is one.
std::optional<Exact> exact_sqrt(const Exact& q) {
  if (q < 0) return std::nullopt;
  mpz_srcptr num = mpq_numref(q.mpq());
  mpz_srcptr den = mpq_denref(q.mpq());
  if (!mpz_perfect_square_p(num) || !mpz_perfect_square_p(den)) return std::nullopt;
  CGAL::Gmpz n, d;
  mpz_sqrt(n.mpz(), num);
  mpz_sqrt(d.mpz(), den);
  return Exact(n, d);
}

// The link's pose C_0 J_1(q_1) C_1 ... J_n(q_n) C_n at joint values q, when
// it is rational: every constant's poses exact, every revolute joint at
// q = 0 (sin and cos of a nonzero rational are irrational), every prismatic
// joint at 0 or with an axis of rational length.  nullopt otherwise.
std::optional<Mat34E> exact_link_pose(const ChainDescription& chain, const std::vector<Exact>& q) {
  const auto constant = [&](std::size_t k) -> std::optional<Mat34E> {
    Mat34E c = kIdentity;
    for (const Pose& p : chain.constant_poses()[k]) {
      const std::optional<Mat34E> m = exact_keyframe(p);
      if (!m) return std::nullopt;
      c = compose_exact(c, *m);
    }
    return c;
  };
  std::optional<Mat34E> m = constant(0);
  if (!m) return std::nullopt;
  for (std::size_t j = 0; j < chain.joint_count(); ++j) {
    const ChainJoint& joint = chain.joint(j);
    if (joint.kind == ChainJoint::Kind::Revolute) {
      if (q[j] != 0) return std::nullopt;
    } else if (q[j] != 0) {
      const Vec3E& k = joint.axis;
      const std::optional<Exact> n = exact_sqrt(k[0] * k[0] + k[1] * k[1] + k[2] * k[2]);
      if (!n) return std::nullopt;
      Mat34E shift = kIdentity;
      for (int i = 0; i < 3; ++i) shift[4 * i + 3] = k[i] / *n * q[j];
      m = compose_exact(*m, shift);
    }
    const std::optional<Mat34E> c = constant(j + 1);
    if (!c) return std::nullopt;
    m = compose_exact(*m, *c);
  }
  return m;
}

const MotionSegment* segment_over(const Trajectory& tr, const Exact& ta, const Exact& tb) {
  for (const MotionSegment& seg : tr.segments)
    if (seg.t0 <= ta && tb <= seg.t1) return &seg;
  return nullptr;
}

PoseBox exact_box(const Mat34E& m) {
  PoseBox b;
  b.center = m;
  for (Exact& x : b.radius) x = 0;
  return b;
}

// ---------------------------------------------------------------- kinds

// The checker's own view of one kind of motion segment (motion_kinds.h,
// src/model/segment_kind.h): which segments are of it, the exact pose at
// a segment's ends where it is known, its exact rational Bezier form when
// it is one (null otherwise), and the pose over a ball of segment
// parameters s (null for the rational kind, whose pieces are restricted
// exactly instead).
struct CheckerKind {
  const char* name;
  bool (*holds)(const MotionSegment& seg);
  const Motion* (*rational)(const MotionSegment& seg);
  std::optional<Mat34E> (*exact_end)(const MotionSegment& seg, bool last);
  std::optional<BallPose> (*pose)(const MotionSegment& seg, const B& s);
  // Over how many equal parts of a piece `pose` is taken (the union of
  // their enclosures holds the piece's poses): a keyframe segment kSubBalls,
  // each ball narrower, so less of the dependency blow-up of the
  // interpolation's formula; a robot link one (its chain costs about ten
  // times a slerp, and parts did not make its pieces fewer).
  int parts;
};

const CheckerKind kCheckerKinds[] = {
    {"rational_bezier", [](const MotionSegment& seg) { return seg.rational.has_value(); },
     [](const MotionSegment& seg) -> const Motion* { return &*seg.rational; },
     [](const MotionSegment& seg, bool last) -> std::optional<Mat34E> {
       return evaluate(*seg.rational, last ? seg.t1 : seg.t0);
     },
     nullptr, 1},
    {"robot_link", [](const MotionSegment& seg) { return !seg.rational && seg.link != nullptr && seg.link->degree() == 1; },
     [](const MotionSegment&) -> const Motion* { return nullptr; },
     [](const MotionSegment& seg, bool last) {  // exact at a waypoint where it is (revolute joints at 0, exact constants)
       return exact_link_pose(*seg.link->chain, last ? seg.link->to : seg.link->from);
     },
     [](const MotionSegment& seg, const B& s) { return std::optional<BallPose>(link_pose(*seg.link, s)); }, 1},
    {"robot_link_hermite",
     [](const MotionSegment& seg) { return !seg.rational && seg.link != nullptr && seg.link->degree() > 1; },
     [](const MotionSegment&) -> const Motion* { return nullptr; },
     [](const MotionSegment& seg, bool last) {  // the waypoint's joint values, as for linear joints
       return exact_link_pose(*seg.link->chain, last ? seg.link->to : seg.link->from);
     },
     [](const MotionSegment& seg, const B& s) { return std::optional<BallPose>(hermite_link_pose(*seg.link, s)); },
     1},
    {"keyframe", [](const MotionSegment& seg) { return !seg.rational && !seg.link; },
     [](const MotionSegment&) -> const Motion* { return nullptr; },
     [](const MotionSegment& seg, bool last) { return exact_keyframe(last ? seg.to : seg.from); },
     [](const MotionSegment& seg, const B& s) { return keyframe_pose(seg, s); }, kSubBalls},
};

const CheckerKind& checker_kind(const MotionSegment& seg) {
  for (const CheckerKind& kind : kCheckerKinds)
    if (kind.holds(seg)) return kind;
  return kCheckerKinds[3];  // not reached: the keyframe kind holds what the others do not
}

}  // namespace

// ---------------------------------------------------------------- public

std::optional<PieceMotion> piece_motion(const Body& body, const Exact& ta, const Exact& tb, std::string& why) {
  PieceMotion out;
  if (body.trajectory) {
    const MotionSegment* seg = segment_over(*body.trajectory, ta, tb);
    if (!seg) {
      why = "the piece [" + to_string(ta) + ", " + to_string(tb) + "] is not inside one segment of the motion of \"" +
            body.name + "\"";
      return std::nullopt;
    }
    const CheckerKind& kind = checker_kind(*seg);
    if (const Motion* rational = kind.rational(*seg)) {
      out.exact = restrict(*rational, ta, tb);
      return out;
    }
    // The union of the enclosures over the kind's number of equal parts of
    // the piece (a box over a cover of the piece holds its poses).
    const int parts = kind.parts;
    const Exact span = seg->t1 - seg->t0;
    const Exact u0 = (ta - seg->t0) / span, du = (tb - ta) / span / parts;
    std::optional<PoseBox> box;
    Mat34E lo, hi;
    for (int k = 0; k < parts; ++k) {
      const B s = interval(u0 + du * k, u0 + du * (k + 1));
      const auto pose = kind.pose(*seg, s);
      std::optional<PoseBox> part;
      if (pose) part = to_box(*pose);
      if (!part) {
        box.reset();
        break;
      }
      for (int e = 0; e < 12; ++e) {
        const Exact l = part->center[e] - part->radius[e], h = part->center[e] + part->radius[e];
        if (k == 0 || l < lo[e]) lo[e] = l;
        if (k == 0 || h > hi[e]) hi[e] = h;
      }
      box = part;
    }
    if (box)
      for (int e = 0; e < 12; ++e) {
        box->center[e] = (lo[e] + hi[e]) / 2;
        box->radius[e] = (hi[e] - lo[e]) / 2;
      }
    if (!box) {
      why = "the pose of \"" + body.name + "\" on [" + to_string(ta) + ", " + to_string(tb) +
            "] has no finite enclosure";
      return std::nullopt;
    }
    out.box = *box;
    return out;
  }
  if (body.motion && body.motion->degree() >= 1) {
    if (ta < body.motion->t0 || tb > body.motion->t1) {
      why = "the piece [" + to_string(ta) + ", " + to_string(tb) + "] is outside the motion of \"" + body.name + "\"";
      return std::nullopt;
    }
    out.exact = restrict(*body.motion, ta, tb);
    return out;
  }
  out.exact = still(body.motion ? body.motion->control_points[0] : kIdentity, ta, tb);
  return out;
}

std::optional<std::pair<Exact, Exact>> rational_span(const Body& a, const Body& b, const Exact& lo, const Exact& hi,
                                                     const Exact& t0, const Exact& t1) {
  std::pair<Exact, Exact> span{t0, t1};
  for (const Body* body : {&a, &b}) {
    if (!body->trajectory) continue;
    const MotionSegment* seg = segment_over(*body->trajectory, lo, hi);
    if (!seg || !checker_kind(*seg).rational(*seg)) return std::nullopt;
    span.first = std::max(span.first, seg->t0);
    span.second = std::min(span.second, seg->t1);
  }
  return span;
}

std::optional<Mat34E> exact_pose_at(const Body& body, const Exact& t) {
  if (body.trajectory) {
    const MotionSegment* seg = segment_over(*body.trajectory, t, t);
    if (!seg) return std::nullopt;
    const CheckerKind& kind = checker_kind(*seg);
    if (const Motion* rational = kind.rational(*seg)) return evaluate(*rational, t);
    if (t == seg->t0) return kind.exact_end(*seg, false);
    if (t == seg->t1) return kind.exact_end(*seg, true);
    return std::nullopt;
  }
  if (!body.motion) return kIdentity;
  if (body.motion->degree() >= 1 && (t < body.motion->t0 || t > body.motion->t1)) return std::nullopt;
  return evaluate(*body.motion, t);
}

std::optional<PoseBox> pose_box_at(const Body& body, const Exact& t) {
  if (const auto m = exact_pose_at(body, t)) return exact_box(*m);
  if (!body.trajectory) return std::nullopt;
  const MotionSegment* seg = segment_over(*body.trajectory, t, t);
  if (!seg) return std::nullopt;
  const CheckerKind& kind = checker_kind(*seg);
  if (kind.rational(*seg)) return std::nullopt;
  const Exact s = (t - seg->t0) / (seg->t1 - seg->t0);
  const auto pose = kind.pose(*seg, B(s));
  if (!pose) return std::nullopt;
  return to_box(*pose);
}

std::vector<std::string> checker_kind_names() {
  std::vector<std::string> out;
  for (const CheckerKind& kind : kCheckerKinds) out.emplace_back(kind.name);
  return out;
}

std::string_view checker_kind_name(const MotionSegment& seg) { return checker_kind(seg).name; }

PoseBox control_box(const Motion& m) {
  PoseBox b;
  for (int e = 0; e < 12; ++e) {
    Exact lo = m.control_points[0][e], hi = lo;
    for (const Mat34E& c : m.control_points) {
      lo = std::min(lo, c[e]);
      hi = std::max(hi, c[e]);
    }
    b.center[e] = (lo + hi) / 2;
    b.radius[e] = (hi - lo) / 2;
  }
  return b;
}

std::array<Exact, 4> coordinate_bounds(const std::vector<std::vector<Vec3E>>& elements) {
  std::array<Exact, 4> out{Exact(0), Exact(0), Exact(0), Exact(1)};
  for (const auto& el : elements)
    for (const Vec3E& x : el)
      for (int j = 0; j < 3; ++j) out[j] = std::max(out[j], CGAL::abs(x[j]));
  return out;
}

Exact sqrt_up(const Exact& x) {
  if (x <= 0) return Exact(0);
  double d = std::sqrt(CGAL::to_double(x));
  if (!std::isfinite(d)) throw std::overflow_error("sqrt_up: out of the range of doubles");
  while (Exact(d) * Exact(d) < x) d = std::nextafter(d, HUGE_VAL);
  return Exact(d);
}

Exact displacement_bound(const Body& body, const std::vector<std::vector<Vec3E>>& elements) {
  // G = sum_i w_i m_i m_i^T (4x4, m_i = (m, 1)), inverted exactly by
  // Gauss-Jordan (the scene reader requires affinely spanning mass points:
  // G is positive definite).
  std::array<std::array<Exact, 8>, 4> g;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 8; ++c) g[r][c] = c - 4 == r ? Exact(1) : Exact(0);
  for (std::size_t i = 0; i < body.mass.points.size(); ++i) {
    const Vec3E& p = body.mass.points[i];
    const std::array<Exact, 4> m{p[0], p[1], p[2], Exact(1)};
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) g[r][c] += body.mass.weights[i] * m[r] * m[c];
  }
  for (int col = 0; col < 4; ++col) {
    int pivot = col;
    while (pivot < 4 && g[pivot][col] == 0) ++pivot;
    if (pivot == 4) throw std::domain_error("the mass points of \"" + body.name + "\" do not span space");
    std::swap(g[col], g[pivot]);
    const Exact inv = 1 / g[col][col];
    for (Exact& x : g[col]) x *= inv;
    for (int r = 0; r < 4; ++r) {
      if (r == col || g[r][col] == 0) continue;
      const Exact f = g[r][col];
      for (int c = 0; c < 8; ++c) g[r][c] -= f * g[col][c];
    }
  }
  Exact best = 0;
  for (const auto& el : elements)
    for (const Vec3E& x : el) {
      const std::array<Exact, 4> h{x[0], x[1], x[2], Exact(1)};
      Exact q = 0;
      for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) q += h[r] * g[r][4 + c] * h[c];
      best = std::max(best, q);
    }
  return sqrt_up(best);
}

// ---------------------------------------------------------------- crossings

namespace {

RInterval operator+(const RInterval& a, const RInterval& b) { return {a.lo + b.lo, a.hi + b.hi}; }
RInterval operator-(const RInterval& a, const RInterval& b) { return {a.lo - b.hi, a.hi - b.lo}; }
RInterval operator*(const RInterval& a, const RInterval& b) {
  const Exact p[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
  return {*std::min_element(p, p + 4), *std::max_element(p, p + 4)};
}

// The sign of det[b - a, c - a, d - a] when it is certain and nonzero over
// the boxes; nullopt otherwise (unsure, or possibly zero).
std::optional<CGAL::Sign> orientation(const RBox& a, const RBox& b, const RBox& c, const RBox& d) {
  RBox u, v, w;
  for (int i = 0; i < 3; ++i) {
    u[i] = b[i] - a[i];
    v[i] = c[i] - a[i];
    w[i] = d[i] - a[i];
  }
  const RInterval det = u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
                        u[2] * (v[0] * w[1] - v[1] * w[0]);
  if (det.lo > 0) return CGAL::POSITIVE;
  if (det.hi < 0) return CGAL::NEGATIVE;
  return std::nullopt;
}

}  // namespace

RBox place_box(const PoseBox& pose, const Vec3E& x) {
  RBox out;
  for (int i = 0; i < 3; ++i) {
    Exact c = pose.center[4 * i + 3], r = pose.radius[4 * i + 3];
    for (int j = 0; j < 3; ++j) {
      c += pose.center[4 * i + j] * x[j];
      r += pose.radius[4 * i + j] * CGAL::abs(x[j]);
    }
    out[i] = {c - r, c + r};
  }
  return out;
}

bool certain_crossing(const RBox& p, const RBox& q, const RBox& a, const RBox& b, const RBox& c) {
  // p and q strictly on opposite sides of the triangle's plane, and the
  // line pq passing strictly inside the triangle: the three orientations
  // of (p, q) with the triangle's edges share one certain sign.
  const std::optional<CGAL::Sign> sp = orientation(a, b, c, p), sq = orientation(a, b, c, q);
  if (!sp || !sq || *sp == *sq) return false;
  const std::optional<CGAL::Sign> e0 = orientation(p, q, a, b), e1 = orientation(p, q, b, c), e2 = orientation(p, q, c, a);
  return e0 && e1 && e2 && *e0 == *e1 && *e1 == *e2;
}

}  // namespace tmcert::certificate
