// The small exact-geometry vocabulary of the verifier (kernels/ and every
// layer above it but the certificate checker, which keeps its own copy in
// src/certificate/check_numbers.h): 3-vectors as std::array<T, 3> and
// affine maps x -> A x + a as std::array<T, 12> holding the rows [A | a],
// over any number type T (Exact, Interval, double).  Each function spells
// the one order of operations every caller used, so that interval and
// floating-point results are the same as those callers' own copies gave.
#pragma once

#include <array>

namespace tmcert::vec3 {

template <class T>
std::array<T, 3> sub(const std::array<T, 3>& a, const std::array<T, 3>& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

template <class T>
std::array<T, 3> cross(const std::array<T, 3>& a, const std::array<T, 3>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

template <class T>
T dot(const std::array<T, 3>& a, const std::array<T, 3>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

template <class T>
bool is_zero(const std::array<T, 3>& a) {
  return a[0] == 0 && a[1] == 0 && a[2] == 0;
}

// m applied to the point x: A x + a, row by row.
template <class T>
std::array<T, 3> apply(const std::array<T, 12>& m, const std::array<T, 3>& x) {
  std::array<T, 3> out;
  for (int r = 0; r < 3; ++r) out[r] = m[4 * r] * x[0] + m[4 * r + 1] * x[1] + m[4 * r + 2] * x[2] + m[4 * r + 3];
  return out;
}

// m's linear part A applied to the vector v: A v, row by row.
template <class T>
std::array<T, 3> apply_linear(const std::array<T, 12>& m, const std::array<T, 3>& v) {
  std::array<T, 3> out;
  for (int r = 0; r < 3; ++r) out[r] = m[4 * r] * v[0] + m[4 * r + 1] * v[1] + m[4 * r + 2] * v[2];
  return out;
}

// The identity map [I | 0].
template <class T>
std::array<T, 12> identity() {
  return {T(1), T(0), T(0), T(0), T(0), T(1), T(0), T(0), T(0), T(0), T(1), T(0)};
}

// The composition a o b (b first, then a): [A B | A b + a], row by row.
template <class T>
std::array<T, 12> compose(const std::array<T, 12>& a, const std::array<T, 12>& b) {
  std::array<T, 12> out;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 4; ++c) {
      T sum = a[4 * r] * b[c] + a[4 * r + 1] * b[4 + c] + a[4 * r + 2] * b[8 + c];
      if (c == 3) sum = sum + a[4 * r + 3];
      out[4 * r + c] = sum;
    }
  }
  return out;
}

}  // namespace tmcert::vec3
