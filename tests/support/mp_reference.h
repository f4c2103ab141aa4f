// An independent high-precision reference for the planner motions
// (tests/motion/test_planner_motions.cpp, tests/property/test_planner_motions.cpp):
// MPFR numbers at 256 bits (CGAL ships MPFR; tmcert's validated functions
// use Arb, so the two share no code), and slerp, screw and nlerp written
// from their textbook definitions (SCENE_FORMAT.md "Motion type keyframes"),
// not from src/motion/segment.cpp's formulas:
//   * slerp: the angle by acos of the dot product of the unit quaternions,
//   * screw: the SE(3) logarithm (axis-angle of the relative rotation, then
//     v = V(phi)^-1 t) and exponential, T(s) = T0 exp(s log(T0^-1 T1)),
//   * nlerp: R(q(s)) / |q(s)|^2 with the quaternions as written,
//   * rpy: the product of the three elementary matrices Rz Ry Rx.
// An MPFR value at 256 bits is within 2^-240 (relative) of the real number
// for these short formulas; the tests compare it with double enclosures,
// whose widths are at least 2^-60 or so, with the margin kMpSlack.
#pragma once

#include "kernels/number_types.h"
#include "src/model/model.h"

#include <mpfr.h>

#include <array>
#include <cmath>
#include <string>

namespace tmcert::testing {

constexpr mpfr_prec_t kMpBits = 256;
// Allowed error of a reference value against an enclosure: far above the
// reference's own error, far below any enclosure's width.
constexpr double kMpSlack = 1e-60;

class Mp {
 public:
  Mp() { mpfr_init2(v_, kMpBits); mpfr_set_zero(v_, 1); }
  Mp(double d) { mpfr_init2(v_, kMpBits); mpfr_set_d(v_, d, MPFR_RNDN); }
  Mp(int d) : Mp(static_cast<double>(d)) {}
  Mp(const Exact& q) { mpfr_init2(v_, kMpBits); mpfr_set_q(v_, q.mpq(), MPFR_RNDN); }
  Mp(const Mp& o) { mpfr_init2(v_, kMpBits); mpfr_set(v_, o.v_, MPFR_RNDN); }
  Mp& operator=(const Mp& o) { mpfr_set(v_, o.v_, MPFR_RNDN); return *this; }
  ~Mp() { mpfr_clear(v_); }
  mpfr_ptr get() { return v_; }
  mpfr_srcptr get() const { return v_; }
  double to_double() const { return mpfr_get_d(v_, MPFR_RNDN); }

  template <class F>
  static Mp apply(const Mp& a, F f) { Mp r; f(r.v_, a.v_, MPFR_RNDN); return r; }
  template <class F>
  static Mp apply(const Mp& a, const Mp& b, F f) { Mp r; f(r.v_, a.v_, b.v_, MPFR_RNDN); return r; }

 private:
  mpfr_t v_;
};

inline Mp operator+(const Mp& a, const Mp& b) { return Mp::apply(a, b, mpfr_add); }
inline Mp operator-(const Mp& a, const Mp& b) { return Mp::apply(a, b, mpfr_sub); }
inline Mp operator*(const Mp& a, const Mp& b) { return Mp::apply(a, b, mpfr_mul); }
inline Mp operator/(const Mp& a, const Mp& b) { return Mp::apply(a, b, mpfr_div); }
inline Mp operator-(const Mp& a) { return Mp::apply(a, mpfr_neg); }
inline Mp sin(const Mp& a) { return Mp::apply(a, mpfr_sin); }
inline Mp cos(const Mp& a) { return Mp::apply(a, mpfr_cos); }
inline Mp tan(const Mp& a) { return Mp::apply(a, mpfr_tan); }
inline Mp acos(const Mp& a) { return Mp::apply(a, mpfr_acos); }
inline Mp atan(const Mp& a) { return Mp::apply(a, mpfr_atan); }
inline Mp sqrt(const Mp& a) { return Mp::apply(a, mpfr_sqrt); }
inline Mp atan2(const Mp& y, const Mp& x) { return Mp::apply(y, x, mpfr_atan2); }
inline Mp abs(const Mp& a) { return Mp::apply(a, mpfr_abs); }
inline bool operator<(const Mp& a, const Mp& b) { return mpfr_less_p(a.get(), b.get()); }
inline Mp mp_pi() { Mp r; mpfr_const_pi(r.get(), MPFR_RNDN); return r; }

// Is the reference value inside [lo, hi] (up to kMpSlack)?
// The slack is applied in MPFR (lo - 1e-60 would round back to lo in double).
inline bool mp_inside(const Mp& v, double lo, double hi) {
  const Mp slack(kMpSlack);
  return !(slack < Mp(lo) - v) && !(slack < v - Mp(hi));
}
inline bool mp_inside(const Mp& v, const Interval& x) { return mp_inside(v, x.inf(), x.sup()); }

using MpQuat = std::array<Mp, 4>;
using MpMat3 = std::array<Mp, 9>;   // rows
using MpPose = std::array<Mp, 12>;  // [A | a], row-major

inline MpMat3 mat_mul(const MpMat3& a, const MpMat3& b) {
  MpMat3 r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r[3 * i + j] = a[3 * i] * b[j] + a[3 * i + 1] * b[3 + j] + a[3 * i + 2] * b[6 + j];
  return r;
}
inline std::array<Mp, 3> mat_vec(const MpMat3& a, const std::array<Mp, 3>& x) {
  return {a[0] * x[0] + a[1] * x[1] + a[2] * x[2], a[3] * x[0] + a[4] * x[1] + a[5] * x[2],
          a[6] * x[0] + a[7] * x[1] + a[8] * x[2]};
}
inline MpMat3 transpose(const MpMat3& a) { return {a[0], a[3], a[6], a[1], a[4], a[7], a[2], a[5], a[8]}; }

// The rotation matrix of a unit quaternion (w, x, y, z), textbook form
// (1 - 2(y^2 + z^2), ...).
inline MpMat3 quat_matrix_unit(const MpQuat& q) {
  const Mp &w = q[0], &x = q[1], &y = q[2], &z = q[3];
  const Mp one(1), two(2);
  return {one - two * (y * y + z * z), two * (x * y - z * w), two * (x * z + y * w),
          two * (x * y + z * w), one - two * (x * x + z * z), two * (y * z - x * w),
          two * (x * z - y * w), two * (y * z + x * w), one - two * (x * x + y * y)};
}
inline MpQuat normalized(const MpQuat& q) {
  const Mp n = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  return {q[0] / n, q[1] / n, q[2] / n, q[3] / n};
}

// Rz(yaw) Ry(pitch) Rx(roll), from the elementary matrices.
inline MpMat3 rpy_matrix(const Mp& roll, const Mp& pitch, const Mp& yaw) {
  const Mp z(0), one(1);
  const MpMat3 rx = {one, z, z, z, cos(roll), -sin(roll), z, sin(roll), cos(roll)};
  const MpMat3 ry = {cos(pitch), z, sin(pitch), z, one, z, -sin(pitch), z, cos(pitch)};
  const MpMat3 rz = {cos(yaw), -sin(yaw), z, sin(yaw), cos(yaw), z, z, z, one};
  return mat_mul(rz, mat_mul(ry, rx));
}

// The unit quaternion of a rotation matrix (Shepperd's method, largest
// pivot), any sign.
inline MpQuat matrix_quat(const MpMat3& m) {
  const Mp one(1), quarter(0.25);
  const Mp tr = m[0] + m[4] + m[8];
  Mp best = tr;
  int which = -1;
  for (int i = 0; i < 3; ++i)
    if (best < m[4 * i]) { best = m[4 * i]; which = i; }
  if (which < 0) {
    const Mp w = sqrt(one + tr) / Mp(2);
    const Mp f = quarter / w;
    return {w, (m[7] - m[5]) * f, (m[2] - m[6]) * f, (m[3] - m[1]) * f};
  }
  const int i = which, j = (i + 1) % 3, k = (i + 2) % 3;
  const Mp a = sqrt(one + m[4 * i] - m[4 * j] - m[4 * k]) / Mp(2);
  const Mp f = quarter / a;
  MpQuat q;
  q[0] = (m[3 * k + j] - m[3 * j + k]) * f;
  q[1 + i] = a;
  q[1 + j] = (m[3 * j + i] + m[3 * i + j]) * f;
  q[1 + k] = (m[3 * k + i] + m[3 * i + k]) * f;
  return q;
}

// The rotation of a pose, as a matrix.
inline MpMat3 rotation_matrix(const Rotation& r) {
  switch (r.kind) {
    case Rotation::Kind::Identity: return {Mp(1), Mp(0), Mp(0), Mp(0), Mp(1), Mp(0), Mp(0), Mp(0), Mp(1)};
    case Rotation::Kind::Quaternion: {
      MpQuat q;
      for (int i = 0; i < 4; ++i) q[i] = Mp(r.quaternion[i]);
      return quat_matrix_unit(normalized(q));
    }
    case Rotation::Kind::Rpy: return rpy_matrix(Mp(r.rpy[0]), Mp(r.rpy[1]), Mp(r.rpy[2]));
    case Rotation::Kind::Matrix: {
      MpMat3 m;
      for (int i = 0; i < 9; ++i) m[i] = Mp(r.matrix[i]);
      return m;
    }
  }
  return {};
}

// The quaternion nlerp interpolates: as written for a quaternion, the unit
// one otherwise (rpy; identity (1,0,0,0)); a matrix's rational multiple
// (1 + tr, m21 - m12, m02 - m20, m10 - m01) (SCENE_FORMAT / docs), or the
// largest-diagonal branch (x, y or z times 4) for half turns.
inline MpQuat nlerp_quaternion(const Rotation& r) {
  switch (r.kind) {
    case Rotation::Kind::Identity: return {Mp(1), Mp(0), Mp(0), Mp(0)};
    case Rotation::Kind::Quaternion: return {Mp(r.quaternion[0]), Mp(r.quaternion[1]), Mp(r.quaternion[2]), Mp(r.quaternion[3])};
    case Rotation::Kind::Rpy:
      if (r.rpy[0] == 0 && r.rpy[1] == 0 && r.rpy[2] == 0) return {Mp(1), Mp(0), Mp(0), Mp(0)};
      return matrix_quat(rotation_matrix(r));
    case Rotation::Kind::Matrix: {
      const auto& m = r.matrix;
      const Exact tr = m[0] + m[4] + m[8];
      if (1 + tr > 0) return {Mp(1 + tr), Mp(m[7] - m[5]), Mp(m[2] - m[6]), Mp(m[3] - m[1])};
      return matrix_quat(rotation_matrix(r));  // the unit multiple: same rotations, another (constant) factor
    }
  }
  return {};
}

inline MpPose make_pose(const MpMat3& R, const std::array<Mp, 3>& t) {
  MpPose p;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) p[4 * i + j] = R[3 * i + j];
    p[4 * i + 3] = t[i];
  }
  return p;
}

inline std::array<Mp, 3> mp_vec(const Vec3E& v) { return {Mp(v[0]), Mp(v[1]), Mp(v[2])}; }

// Translation linear in s.
inline std::array<Mp, 3> lerp_translation(const Pose& a, const Pose& b, const Mp& s) {
  std::array<Mp, 3> t;
  for (int i = 0; i < 3; ++i) t[i] = Mp(a.translation[i]) + s * (Mp(b.translation[i]) - Mp(a.translation[i]));
  return t;
}

// Slerp along the shorter arc, angle by acos.
inline MpPose slerp_pose(const Pose& a, const Pose& b, const Mp& s) {
  const MpQuat p0 = matrix_quat(rotation_matrix(a.rotation));
  MpQuat p1 = matrix_quat(rotation_matrix(b.rotation));
  Mp d = p0[0] * p1[0] + p0[1] * p1[1] + p0[2] * p1[2] + p0[3] * p1[3];
  if (d < Mp(0)) {
    for (Mp& x : p1) x = -x;
    d = -d;
  }
  MpQuat q;
  if (Mp(1) - d < Mp(1e-70)) {
    q = p0;
  } else {
    const Mp theta = acos(d);
    const Mp c0 = sin((Mp(1) - s) * theta) / sin(theta), c1 = sin(s * theta) / sin(theta);
    for (int i = 0; i < 4; ++i) q[i] = c0 * p0[i] + c1 * p1[i];
  }
  return make_pose(quat_matrix_unit(q), lerp_translation(a, b, s));
}

// Nlerp with the quaternions as written (the second negated when the dot
// product is negative): R(q(s)) for the normalised q(s).
inline MpPose nlerp_pose(const Pose& a, const Pose& b, const Mp& s) {
  const MpQuat q0 = nlerp_quaternion(a.rotation);
  MpQuat q1 = nlerp_quaternion(b.rotation);
  if (q0[0] * q1[0] + q0[1] * q1[1] + q0[2] * q1[2] + q0[3] * q1[3] < Mp(0))
    for (Mp& x : q1) x = -x;
  MpQuat q;
  for (int i = 0; i < 4; ++i) q[i] = (Mp(1) - s) * q0[i] + s * q1[i];
  return make_pose(quat_matrix_unit(normalized(q)), lerp_translation(a, b, s));
}

// Screw: T(s) = T0 exp(s log(T0^-1 T1)) with the SE(3) log/exp of the
// twist (phi k, v): rotation Rot(k, s phi), translation V(s phi) s v with
// V(alpha) = I + (1 - cos alpha)/alpha [k]x + (alpha - sin alpha)/alpha [k]x^2.
inline MpPose screw_pose(const Pose& a, const Pose& b, const Mp& s) {
  const MpMat3 R0 = rotation_matrix(a.rotation), R1 = rotation_matrix(b.rotation);
  const MpMat3 Rd = mat_mul(transpose(R0), R1);
  std::array<Mp, 3> dt;
  for (int i = 0; i < 3; ++i) dt[i] = Mp(b.translation[i]) - Mp(a.translation[i]);
  const std::array<Mp, 3> td = mat_vec(transpose(R0), dt);
  const Mp phi = acos((Rd[0] + Rd[4] + Rd[8] - Mp(1)) / Mp(2));
  const Mp two_sin = Mp(2) * sin(phi);
  const std::array<Mp, 3> k = {(Rd[7] - Rd[5]) / two_sin, (Rd[2] - Rd[6]) / two_sin, (Rd[3] - Rd[1]) / two_sin};
  const Mp z(0), one(1);
  const MpMat3 K = {z, -k[2], k[1], k[2], z, -k[0], -k[1], k[0], z};
  const MpMat3 K2 = mat_mul(K, K);
  auto V = [&](const Mp& alpha) {
    MpMat3 v;
    const Mp c1 = (one - cos(alpha)) / alpha, c2 = (alpha - sin(alpha)) / alpha;
    for (int i = 0; i < 9; ++i) v[i] = (i % 4 == 0 ? one : z) + c1 * K[i] + c2 * K2[i];
    return v;
  };
  // v = V(phi)^-1 td (Cramer's rule).
  const MpMat3 m = V(phi);
  auto det3 = [](const MpMat3& x) {
    return x[0] * (x[4] * x[8] - x[5] * x[7]) - x[1] * (x[3] * x[8] - x[5] * x[6]) + x[2] * (x[3] * x[7] - x[4] * x[6]);
  };
  const Mp dm = det3(m);
  std::array<Mp, 3> v;
  for (int c = 0; c < 3; ++c) {
    MpMat3 mc = m;
    for (int r = 0; r < 3; ++r) mc[3 * r + c] = td[r];
    v[c] = det3(mc) / dm;
  }
  // exp(s (phi k, v)).
  const Mp alpha = s * phi;
  MpMat3 Rs;
  for (int i = 0; i < 9; ++i) Rs[i] = (i % 4 == 0 ? one : z) + sin(alpha) * K[i] + (one - cos(alpha)) * K2[i];
  std::array<Mp, 3> ts = {z, z, z};
  if (!(abs(alpha) < Mp(1e-70))) {
    std::array<Mp, 3> sv = {s * v[0], s * v[1], s * v[2]};
    ts = mat_vec(V(alpha), sv);
  }
  const MpMat3 R = mat_mul(R0, Rs);
  std::array<Mp, 3> t = mat_vec(R0, ts);
  for (int i = 0; i < 3; ++i) t[i] = t[i] + Mp(a.translation[i]);
  return make_pose(R, t);
}

inline MpPose reference_pose(const Pose& a, const Pose& b, Interpolation how, const Mp& s) {
  switch (how) {
    case Interpolation::Slerp: return slerp_pose(a, b, s);
    case Interpolation::Screw: return screw_pose(a, b, s);
    case Interpolation::Nlerp: return nlerp_pose(a, b, s);
  }
  return {};
}

inline std::array<Mp, 3> apply_pose(const MpPose& p, const Vec3E& x) {
  std::array<Mp, 3> r;
  for (int i = 0; i < 3; ++i)
    r[i] = p[4 * i] * Mp(x[0]) + p[4 * i + 1] * Mp(x[1]) + p[4 * i + 2] * Mp(x[2]) + p[4 * i + 3];
  return r;
}

}  // namespace tmcert::testing
