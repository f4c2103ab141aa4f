// The certificate checker's own small exact vocabulary (independent of
// src/motion and src/verify): a GMP integer with value semantics, access to
// a rational's numerator and denominator, 3-vector and 3x4-pose operations,
// and the texts of numbers in messages.
#pragma once

#include "kernels/number_types.h"
#include "src/model/model.h"

#include <gmp.h>

#include <cstddef>
#include <string>
#include <vector>

namespace tmcert::certificate::check_internal {

// ---------------------------------------------------------------- integers

// A GMP integer with value semantics (CGAL::Gmpz shares its representation
// between copies, which in-place GMP calls must not touch).
struct Z {
  mpz_t v;
  Z() { mpz_init(v); }
  explicit Z(long x) { mpz_init_set_si(v, x); }
  Z(const Z& o) { mpz_init_set(v, o.v); }
  Z(Z&& o) noexcept {
    mpz_init(v);
    mpz_swap(v, o.v);
  }
  Z& operator=(const Z& o) {
    if (this != &o) mpz_set(v, o.v);
    return *this;
  }
  Z& operator=(Z&& o) noexcept {
    mpz_swap(v, o.v);
    return *this;
  }
  ~Z() { mpz_clear(v); }
};

inline mpz_srcptr num(const Exact& q) { return mpq_numref(q.mpq()); }
inline mpz_srcptr den(const Exact& q) { return mpq_denref(q.mpq()); }
inline int sgn(const Exact& q) { return mpq_sgn(q.mpq()); }

inline Exact from_z(mpz_srcptr n, mpz_srcptr d) {
  return Exact(CGAL::Gmpz(n), CGAL::Gmpz(d));
}

// ---------------------------------------------------------------- vectors

inline Vec3E sub(const Vec3E& a, const Vec3E& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline Exact dot(const Vec3E& a, const Vec3E& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec3E cross(const Vec3E& a, const Vec3E& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline bool is_zero(const Vec3E& a) { return sgn(a[0]) == 0 && sgn(a[1]) == 0 && sgn(a[2]) == 0; }

inline Vec3E place_point(const Mat34E& m, const Vec3E& x) {
  Vec3E out;
  for (int r = 0; r < 3; ++r) out[r] = m[4 * r] * x[0] + m[4 * r + 1] * x[1] + m[4 * r + 2] * x[2] + m[4 * r + 3];
  return out;
}

inline Exact determinant(const Mat34E& m) {
  return m[0] * (m[5] * m[10] - m[6] * m[9]) - m[1] * (m[4] * m[10] - m[6] * m[8]) +
         m[2] * (m[4] * m[9] - m[5] * m[8]);
}

inline Mat34E identity_pose() {
  Mat34E m;
  for (Exact& x : m) x = Exact(0);
  m[0] = m[5] = m[10] = Exact(1);
  return m;
}

inline std::string str(const Exact& q) { return to_string(q); }
inline std::string str(const Vec3E& v) {
  std::string out = "(";
  for (int i = 0; i < 3; ++i) {
    if (i) out += ", ";
    out += str(v[i]);
  }
  out += ")";
  return out;
}

// ---------------------------------------------------------------- de Casteljau

// The checker's one exact de Casteljau subdivision (the verifier has its
// own, src/model/de_casteljau.h): the control points of the curve's part
// over [0, s] (keep_left) or [s, 1], for control points that are arrays of
// exact rationals and s in [0, 1].  `p` has at least one point.
template <class Point>
std::vector<Point> split_controls(std::vector<Point> p, const Exact& s, bool keep_left) {
  const std::size_t n = p.size() - 1;
  std::vector<Point> out(n + 1);
  if (keep_left) out[0] = p[0];
  else out[n] = p[n];
  for (std::size_t r = 1; r <= n; ++r) {
    for (std::size_t i = 0; i + r <= n; ++i)
      for (std::size_t e = 0; e < p[i].size(); ++e) p[i][e] += s * (p[i + 1][e] - p[i][e]);
    if (keep_left) out[r] = p[0];
    else out[n - r] = p[n - r];
  }
  return out;
}

}  // namespace tmcert::certificate::check_internal
