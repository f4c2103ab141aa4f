// Helpers shared by the seeded randomized tests (tests/kernels/test_contact.cpp,
// tests/motion/test_bezier.cpp, tests/crosscheck/test_kernels.cpp): a small
// reproducible random source, triangle bodies and an exact collinearity test.
#pragma once

#include "kernels/number_types.h"
#include "src/metric/metric.h"
#include "src/model/model.h"

#include <array>
#include <random>
#include <string>

namespace tmcert::testing {

// A seeded source of small random numbers: the same seed gives the same
// sequence (std::mt19937, a fresh uniform distribution per draw).
struct Rng {
  std::mt19937 gen;
  explicit Rng(unsigned seed) : gen(seed) {}
  // The rational n / den, n uniform in [lo, hi].
  Exact q(int lo, int hi, int den) { return Exact(std::uniform_int_distribution<int>(lo, hi)(gen), den); }
  // The same as a double.
  double d(int lo, int hi, int den) { return std::uniform_int_distribution<int>(lo, hi)(gen) / double(den); }
  // An integer uniform in [lo, hi].
  int i(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(gen); }
  // A double uniform in [-1, 1).
  double noise() { return std::uniform_real_distribution<double>(-1, 1)(gen); }
};

// A fixed body made of the one triangle t, with the default mass of its
// vertices.
inline Body triangle_body(const std::string& name, const std::array<Vec3E, 3>& t) {
  Body b;
  b.name = name;
  b.polygons = {{t[0], t[1], t[2]}};
  b.pieces = {ConvexPiece{0, {t[0], t[1], t[2]}}};
  b.mass = default_mass({t[0], t[1], t[2]}, Exact(1));
  return b;
}

// Do a, b and c lie on one line (exactly)?
inline bool collinear(const Vec3E& a, const Vec3E& b, const Vec3E& c) {
  const Vec3E u{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  return u[1] * v[2] - u[2] * v[1] == 0 && u[2] * v[0] - u[0] * v[2] == 0 && u[0] * v[1] - u[1] * v[0] == 0;
}

inline bool collinear(const std::array<Vec3E, 3>& t) { return collinear(t[0], t[1], t[2]); }

}  // namespace tmcert::testing
