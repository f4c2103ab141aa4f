#include "src/model/mass.h"

#include "kernels/number_types.h"
#include "kernels/vec3.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace tmcert {

Mat44E moment_matrix(const MassDistribution& mass) {
  Mat44E g;
  // G = sum w h h^T, h = (p, 1): the 10 distinct entries as integer
  // products over running denominators (ExactSum), no per-term gcd.
  // Repeated points (a default mass lists a vertex once per polygon) are
  // merged first, their weights summed: the same G, fewer terms.
  PointIds ids;
  std::vector<Exact> weight;
  for (std::size_t i = 0; i < mass.points.size(); ++i) {
    const std::uint32_t k = ids.id(mass.points[i]);
    if (k == weight.size()) weight.push_back(mass.weights[i]);
    else weight[k] += mass.weights[i];
  }
  std::array<ExactSum, 16> sums;
  CGAL::Gmpz one(1), num, den;
  for (std::size_t i = 0; i < ids.size(); ++i) {
    const Vec3E& p = ids.point(static_cast<std::uint32_t>(i));
    const Exact& w = weight[i];
    mpz_srcptr hn[4] = {mpq_numref(p[0].mpq()), mpq_numref(p[1].mpq()), mpq_numref(p[2].mpq()), one.mpz()};
    mpz_srcptr hd[4] = {mpq_denref(p[0].mpq()), mpq_denref(p[1].mpq()), mpq_denref(p[2].mpq()), one.mpz()};
    for (int r = 0; r < 4; ++r)
      for (int c = r; c < 4; ++c) {
        mpz_mul(num.mpz(), mpq_numref(w.mpq()), hn[r]);
        mpz_mul(num.mpz(), num.mpz(), hn[c]);
        mpz_mul(den.mpz(), mpq_denref(w.mpq()), hd[r]);
        mpz_mul(den.mpz(), den.mpz(), hd[c]);
        sums[4 * r + c].add(num, den);
      }
  }
  for (int r = 0; r < 4; ++r)
    for (int c = r; c < 4; ++c) g[4 * r + c] = g[4 * c + r] = sums[4 * r + c].value();
  return g;
}

bool invert_positive_definite(const Mat44E& a, Mat44E& inv) {
  Exact m[4][8];
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) {
      m[r][c] = a[4 * r + c];
      m[r][c + 4] = (r == c) ? 1 : 0;
    }
  for (int k = 0; k < 4; ++k) {
    // No pivoting: for a symmetric positive definite matrix every leading
    // pivot is positive; a non-positive pivot proves it is not definite.
    if (!(m[k][k] > 0)) return false;
    const Exact pivot = m[k][k];
    for (int c = 0; c < 8; ++c) m[k][c] /= pivot;
    for (int r = 0; r < 4; ++r) {
      if (r == k || m[r][k] == 0) continue;
      const Exact f = m[r][k];
      for (int c = 0; c < 8; ++c) m[r][c] -= f * m[k][c];
    }
  }
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) inv[4 * r + c] = m[r][c + 4];
  return true;
}

void require_positive_definite(const MassDistribution& mass) {
  {
    RoundingGuard guard;
    std::array<Interval, 16> g;
    g.fill(Interval(0));
    bool finite = true;
    for (std::size_t i = 0; i < mass.points.size() && finite; ++i) {
      const Interval h[4] = {to_interval(mass.points[i][0]), to_interval(mass.points[i][1]),
                             to_interval(mass.points[i][2]), Interval(1)};
      const Interval w = to_interval(mass.weights[i]);
      for (int r = 0; r < 4; ++r)
        for (int c = r; c < 4; ++c) g[4 * r + c] += w * h[r] * h[c];
    }
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < r; ++c) g[4 * r + c] = g[4 * c + r];
    for (const Interval& x : g) finite = finite && std::isfinite(x.inf()) && std::isfinite(x.sup());
    // Sylvester: G is positive definite iff its leading principal minors are
    // positive; enclosures of the exact minors that are all certainly
    // positive prove it.
    auto at = [&](int r, int c) -> const Interval& { return g[4 * r + c]; };
    auto det3 = [&](int a, int b, int c, int x, int y, int z) {  // rows a b c, columns x y z
      return at(a, x) * (at(b, y) * at(c, z) - at(b, z) * at(c, y)) -
             at(a, y) * (at(b, x) * at(c, z) - at(b, z) * at(c, x)) +
             at(a, z) * (at(b, x) * at(c, y) - at(b, y) * at(c, x));
    };
    if (finite) {
      const Interval m1 = at(0, 0);
      const Interval m2 = at(0, 0) * at(1, 1) - at(0, 1) * at(1, 0);
      const Interval m3 = det3(0, 1, 2, 0, 1, 2);
      const Interval m4 = at(0, 0) * det3(1, 2, 3, 1, 2, 3) - at(0, 1) * det3(1, 2, 3, 0, 2, 3) +
                          at(0, 2) * det3(1, 2, 3, 0, 1, 3) - at(0, 3) * det3(1, 2, 3, 0, 1, 2);
      if (m1.inf() > 0 && m2.inf() > 0 && m3.inf() > 0 && m4.inf() > 0) return;
    }
  }
  // The exact decision.
  Mat44E inverse;
  if (!invert_positive_definite(moment_matrix(mass), inverse))
    throw InputError("moment matrix of the mass distribution is not positive definite "
                     "(mass points must not lie in one plane)");
}

namespace {

using vec3::cross;
using vec3::is_zero;
using vec3::sub;
Exact abs(const Exact& a) { return a < 0 ? -a : a; }

// Index of the coordinate axis with the largest |component| of v.
int dominant_axis(const Vec3E& v) {
  int k = 0;
  for (int i = 1; i < 3; ++i)
    if (abs(v[i]) > abs(v[k])) k = i;
  return k;
}

}  // namespace

MassDistribution default_mass(const std::vector<Vec3E>& vertices, const Exact& fallback_size) {
  MassDistribution mass;
  mass.points = vertices;
  mass.weights.assign(vertices.size(), Exact(1));
  if (vertices.empty()) return mass;

  Vec3E lo = vertices[0], hi = vertices[0], centroid;
  std::array<ExactSum, 3> sum;
  for (const Vec3E& v : vertices)
    for (int i = 0; i < 3; ++i) {
      if (v[i] < lo[i]) lo[i] = v[i];
      if (hi[i] < v[i]) hi[i] = v[i];
      sum[i].add(v[i]);
    }
  for (int i = 0; i < 3; ++i) centroid[i] = sum[i].value() / Exact(static_cast<long>(vertices.size()));
  Exact size = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
  if (size == 0) size = fallback_size > 0 ? fallback_size : Exact(1);
  const Exact offset = size / 10;

  // Affine rank of the vertex set, exactly (over the distinct vertices).
  PointIds distinct;
  for (const Vec3E& v : vertices) distinct.id(v);
  const Vec3E& p0 = vertices[0];
  std::optional<Vec3E> dir;      // first nonzero difference
  std::optional<Vec3E> normal;   // first nonzero cross product
  bool full = false;
  for (std::uint32_t i = 0; i < distinct.size(); ++i) {
    const Vec3E& v = distinct.point(i);
    const Vec3E d = sub(v, p0);
    if (is_zero(d)) continue;
    if (!dir) { dir = d; continue; }
    if (!normal) {
      const Vec3E n = cross(*dir, d);
      if (!is_zero(n)) normal = n;
      continue;
    }
    const Exact off = (*normal)[0] * d[0] + (*normal)[1] * d[1] + (*normal)[2] * d[2];
    if (off != 0) { full = true; break; }
  }
  auto add = [&](int axis, const Exact& sign) {
    Vec3E p = centroid;
    p[axis] += sign * offset;
    mass.points.push_back(p);
    mass.weights.push_back(Exact(1));
  };
  if (full) return mass;
  if (normal) {                       // coplanar: offset along the axis most normal to the plane
    int k = dominant_axis(*normal);
    add(k, 1);
    add(k, -1);
  } else if (dir) {                   // collinear: offset along the two axes least along the line
    int k = dominant_axis(*dir);
    for (int a = 0; a < 3; ++a)
      if (a != k) { add(a, 1); add(a, -1); }
  } else {                            // a single point: offset along every axis
    for (int a = 0; a < 3; ++a) { add(a, 1); add(a, -1); }
  }
  return mass;
}

Exact default_mass_fallback_size(const std::vector<Body>& bodies) {
  std::optional<Vec3E> lo, hi;
  auto extend = [&](const Vec3E& p) {
    if (!lo) { lo = p; hi = p; }
    for (int a = 0; a < 3; ++a) {
      (*lo)[a] = std::min((*lo)[a], p[a]);
      (*hi)[a] = std::max((*hi)[a], p[a]);
    }
  };
  for (const Body& b : bodies) {
    for (const auto& polygon : b.polygons)
      for (const Vec3E& p : polygon) extend(p);
    for (const auto& segment : b.segments)
      for (const Vec3E& p : segment) extend(p);
    for (const Vec3E& p : b.points) extend(p);
  }
  Exact size = 0;
  if (lo)
    for (int a = 0; a < 3; ++a) size = std::max(size, (*hi)[a] - (*lo)[a]);
  if (size == 0) size = 1;
  return size;
}

}  // namespace tmcert
