// Quaternion algebra over any number type (Exact, Interval, Jet): the
// rotation a quaternion stands for and the products the keyframe
// interpolations need.  proofs/enclosures.md, proofs/input-exactness.md.
#pragma once

#include <array>

namespace tmcert::quaternion {

template <class T>
using Quat = std::array<T, 4>;  // (w, x, y, z)

// R(q) for a unit quaternion q = (w, x, y, z) times |q|^2: the quadratic
// form whose value at a unit quaternion is its rotation matrix (rows).
template <class T>
std::array<T, 9> rotation_form(const Quat<T>& q) {
  const T &w = q[0], &x = q[1], &y = q[2], &z = q[3];
  const T two(2);
  return {w * w + x * x - y * y - z * z, two * (x * y - w * z), two * (x * z + w * y),
          two * (x * y + w * z), w * w - x * x + y * y - z * z, two * (y * z - w * x),
          two * (x * z - w * y), two * (y * z + w * x), w * w - x * x - y * y + z * z};
}

// The symmetric bilinear form of rotation_form: B(q, q) = rotation_form(q).
template <class T>
std::array<T, 9> rotation_bilinear(const Quat<T>& p, const Quat<T>& q) {
  Quat<T> s;
  for (int i = 0; i < 4; ++i) s[i] = p[i] + q[i];
  const std::array<T, 9> a = rotation_form(s), b = rotation_form(p), c = rotation_form(q);
  std::array<T, 9> out;
  for (int i = 0; i < 9; ++i) out[i] = (a[i] - b[i] - c[i]) / T(2);
  return out;
}

template <class T>
T qdot(const Quat<T>& a, const Quat<T>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
}

// Hamilton product: R(a b) = R(a) R(b).
template <class T>
Quat<T> qmul(const Quat<T>& a, const Quat<T>& b) {
  return {a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
          a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
          a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
          a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0]};
}

}  // namespace tmcert::quaternion
