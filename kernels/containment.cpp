// Exact ray parity (containment.h, proofs/containment.md).
//
// For a query p:
//  1. p on a triangle (exact) -> true.  Only triangles whose box meets p's
//     interval box can hold p.
//  2. For the directions d_0, d_1, ... (all with x component 1): the part of
//     the ray p + s d (s > 0) that can meet the surface has p.x <= x <= xmax,
//     so it lies in the box [p.x, xmax] x (p.y + d.y [0, S]) x (p.z + d.z
//     [0, S]) with S = xmax - p.x, computed with outward rounding.  Only
//     triangles whose box meets that tube are classified.  Each is a proper
//     crossing, a miss, or degenerate (the ray touches an edge or vertex, or
//     runs in its plane while meeting it); one degenerate triangle discards
//     the direction.  Otherwise p is inside iff the crossings of some shell
//     are odd in number.
// Every sign is taken from an interval evaluation when that is certain and
// recomputed exactly otherwise.
#include "kernels/containment.h"

#include "kernels/uncertain.h"
#include "kernels/vec3.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

namespace tmcert {

namespace {

template <class T>
using V3 = std::array<T, 3>;

using vec3::cross;
using vec3::dot;
using vec3::sub;

int sign(const Exact& x) { return x > 0 ? 1 : (x < 0 ? -1 : 0); }

UncertainSign sign(const Interval& x) { return uncertain_sign(x); }

using vec3::is_zero;

// Is p on the closed segment ef (e == f allowed)?
bool on_segment(const Vec3E& p, const Vec3E& e, const Vec3E& f) {
  const Vec3E g = sub(f, e), w = sub(p, e);
  if (!is_zero(cross(w, g))) return false;
  if (is_zero(g)) return is_zero(w);
  const Exact along = dot(w, g);
  return along >= 0 && along <= dot(g, g);
}

// Does the ray p + s d, s >= 0 (d != 0), meet the closed segment ef?
bool ray_meets_segment(const Vec3E& p, const Vec3E& d, const Vec3E& e, const Vec3E& f) {
  const Vec3E g = sub(f, e), w = sub(e, p);
  const Vec3E dg = cross(d, g);
  if (!is_zero(dg)) {
    // Lines not parallel: they meet iff coplanar, at the unique solution of
    // s d - r g = w.
    if (dot(w, dg) != 0) return false;
    const Exact n2 = dot(dg, dg);
    const Exact s = dot(cross(w, g), dg) / n2, r = dot(cross(w, d), dg) / n2;
    return s >= 0 && r >= 0 && r <= 1;
  }
  // Parallel (or e == f): the segment must lie on the ray's line, and then
  // reach s >= 0.
  if (!is_zero(cross(w, d))) return false;
  return dot(w, d) >= 0 || dot(sub(f, p), d) >= 0;
}

// Encloses an exact direction component-wise.
V3<Interval> enclose(const Vec3E& v) { return {to_interval(v[0]), to_interval(v[1]), to_interval(v[2])}; }

}  // namespace

Vec3E ClosedSurface::ray_direction(std::size_t k) {
  const Exact t(1, static_cast<long>(1031 + k));
  return {Exact(1), t, t * t};
}

ClosedSurface::ClosedSurface(std::vector<std::array<Vec3E, 3>> triangles, std::vector<int> shell)
    : triangles_(std::move(triangles)), shell_(std::move(shell)) {
  const std::size_t n = triangles_.size();
  if (shell_.empty()) shell_.assign(n, 0);
  if (shell_.size() != n) throw std::invalid_argument("ClosedSurface: one shell index per triangle is needed");
  for (int s : shell_) {
    if (s < 0) throw std::invalid_argument("ClosedSurface: negative shell index");
    shells_ = std::max(shells_, s + 1);
  }
  intervals_.resize(n);
  flat_.assign(n, false);
  xlo_.resize(n), xhi_.resize(n), ylo_.resize(n), yhi_.resize(n), zlo_.resize(n), zhi_.resize(n);
  std::vector<std::size_t> unsure;
  {
    RoundingGuard guard;
    for (std::size_t i = 0; i < n; ++i) {
      std::array<Interval, 9>& c = intervals_[i];
      for (int v = 0; v < 3; ++v)
        for (int k = 0; k < 3; ++k) c[3 * v + k] = to_interval(triangles_[i][v][k]);
      std::array<double*, 6> bounds{&xlo_[i], &xhi_[i], &ylo_[i], &yhi_[i], &zlo_[i], &zhi_[i]};
      for (int k = 0; k < 3; ++k) {
        *bounds[2 * k] = std::min({c[k].inf(), c[3 + k].inf(), c[6 + k].inf()});
        *bounds[2 * k + 1] = std::max({c[k].sup(), c[3 + k].sup(), c[6 + k].sup()});
      }
      xmax_ = i == 0 ? xhi_[i] : std::max(xmax_, xhi_[i]);
      const V3<Interval> a{c[0], c[1], c[2]}, b{c[3], c[4], c[5]}, e{c[6], c[7], c[8]};
      const V3<Interval> normal = cross(sub(b, a), sub(e, a));
      if (certainly_not(sign(normal[0]), CGAL::ZERO)) continue;
      if (certainly_not(sign(normal[1]), CGAL::ZERO)) continue;
      if (certainly_not(sign(normal[2]), CGAL::ZERO)) continue;
      unsure.push_back(i);
    }
  }
  for (std::size_t i : unsure) {
    const auto& t = triangles_[i];
    flat_[i] = is_zero(cross(sub(t[1], t[0]), sub(t[2], t[0])));
  }
}

bool ClosedSurface::on_triangle(std::size_t i, const Vec3E& p) const {
  const auto& t = triangles_[i];
  if (flat_[i]) return on_segment(p, t[0], t[1]) || on_segment(p, t[1], t[2]) || on_segment(p, t[2], t[0]);
  const Vec3E n = cross(sub(t[1], t[0]), sub(t[2], t[0]));
  if (dot(n, sub(p, t[0])) != 0) return false;
  // In the plane: inside or on every edge, seen along the normal.
  for (int k = 0; k < 3; ++k)
    if (dot(cross(sub(t[(k + 1) % 3], t[k]), sub(p, t[k])), n) < 0) return false;
  return true;
}

ClosedSurface::Ray ClosedSurface::classify(std::size_t i, const Vec3E& p, const Vec3E& d) const {
  const auto& t = triangles_[i];
  auto meets_boundary = [&] {
    return ray_meets_segment(p, d, t[0], t[1]) || ray_meets_segment(p, d, t[1], t[2]) ||
           ray_meets_segment(p, d, t[2], t[0]);
  };
  // A flat triangle is the union of its edges: a ray meeting it is degenerate.
  if (flat_[i]) return meets_boundary() ? Ray::Degenerate : Ray::Miss;
  const Vec3E n = cross(sub(t[1], t[0]), sub(t[2], t[0]));
  const int op = sign(dot(n, sub(p, t[0]))), nd = sign(dot(n, d));
  if (nd == 0) {
    if (op != 0) return Ray::Miss;  // parallel to the plane, off it
    // In the plane, starting outside the triangle (p is on no triangle):
    // it meets the closed triangle iff it meets the boundary.
    return meets_boundary() ? Ray::Degenerate : Ray::Miss;
  }
  // The line meets the plane once, at s = -op/nd; s <= 0 is no hit (s = 0
  // would be p itself, which is on no triangle).
  if (op == 0 || op == nd) return Ray::Miss;
  const Vec3E a = sub(t[0], p), b = sub(t[1], p), c = sub(t[2], p);
  const int o[3] = {sign(dot(d, cross(a, b))), sign(dot(d, cross(b, c))), sign(dot(d, cross(c, a)))};
  const bool pos = o[0] > 0 || o[1] > 0 || o[2] > 0, neg = o[0] < 0 || o[1] < 0 || o[2] < 0;
  if (pos && neg) return Ray::Miss;
  if (o[0] != 0 && o[1] != 0 && o[2] != 0) return Ray::Cross;
  return Ray::Degenerate;  // through an edge or a vertex
}

bool ClosedSurface::contains(const Vec3E& p) const {
  int tried = 0;
  return contains(p, tried);
}

bool ClosedSurface::contains(const Vec3E& p, int& directions_tried) const {
  directions_tried = 0;
  const std::size_t n = triangles_.size();
  if (n == 0) return false;
  const V3<Interval> pi = enclose(p);
  const double pxlo = pi[0].inf(), pxhi = pi[0].sup(), pylo = pi[1].inf(), pyhi = pi[1].sup();
  const double pzlo = pi[2].inf(), pzhi = pi[2].sup();

  // 1. On the surface?  Interval filter: off the plane for sure -> not on.
  std::vector<std::size_t> exact;
  {
    RoundingGuard guard;
    for (std::size_t i = 0; i < n; ++i) {
      if (xhi_[i] < pxlo || xlo_[i] > pxhi || yhi_[i] < pylo || ylo_[i] > pyhi || zhi_[i] < pzlo || zlo_[i] > pzhi)
        continue;
      if (!flat_[i]) {
        const auto& c = intervals_[i];
        const V3<Interval> a{c[0], c[1], c[2]}, b{c[3], c[4], c[5]}, e{c[6], c[7], c[8]};
        if (certainly_not(sign(dot(cross(sub(b, a), sub(e, a)), sub(pi, a))), CGAL::ZERO)) continue;
      }
      exact.push_back(i);
    }
  }
  for (std::size_t i : exact)
    if (on_triangle(i, p)) return true;
  if (pxlo > xmax_) return false;  // nothing on the +x side: every ray misses

  // 2. Ray parity.
  const std::size_t max_directions = 11 * n + 1;
  for (std::size_t k = 0; k < max_directions; ++k) {
    ++directions_tried;
    const Vec3E d = ray_direction(k);
    std::vector<char> odd(static_cast<std::size_t>(shells_), 0);  // crossings per shell, mod 2
    bool degenerate = false;
    exact.clear();
    {
      RoundingGuard guard;
      const V3<Interval> di = enclose(d);
      // Hit parameters lie in [0, reach]; a NaN bound (from infinite
      // enclosures of huge coordinates) becomes +infinity, never 0.
      double reach = (Interval(xmax_) - pi[0]).sup();
      reach = std::isnan(reach) ? std::numeric_limits<double>::infinity() : std::max(0.0, reach);
      const Interval s(0, reach);
      const Interval ty = pi[1] + di[1] * s, tz = pi[2] + di[2] * s;
      const double tylo = ty.inf(), tyhi = ty.sup(), tzlo = tz.inf(), tzhi = tz.sup();
      for (std::size_t i = 0; i < n && !degenerate; ++i) {
        if (xhi_[i] < pxlo || yhi_[i] < tylo || ylo_[i] > tyhi || zhi_[i] < tzlo || zlo_[i] > tzhi) continue;
        if (flat_[i]) {
          exact.push_back(i);
          continue;
        }
        // The same decisions as classify(), on intervals.
        const auto& c = intervals_[i];
        const V3<Interval> a{c[0], c[1], c[2]}, b{c[3], c[4], c[5]}, e{c[6], c[7], c[8]};
        const V3<Interval> normal = cross(sub(b, a), sub(e, a));
        const UncertainSign op = sign(dot(normal, sub(pi, a))), nd = sign(dot(normal, di));
        if (!op.is_certain() || !certainly_not(nd, CGAL::ZERO)) {
          if (certainly_is(nd, CGAL::ZERO) && certainly_not(op, CGAL::ZERO)) continue;  // parallel, off the plane
          exact.push_back(i);
          continue;
        }
        if (certainly_is(op, CGAL::ZERO) || op.inf() == nd.inf()) continue;  // both certain here
        const V3<Interval> ra = sub(a, pi), rb = sub(b, pi), rc = sub(e, pi);
        const UncertainSign o[3] = {sign(dot(di, cross(ra, rb))), sign(dot(di, cross(rb, rc))),
                                    sign(dot(di, cross(rc, ra)))};
        const bool pos = certainly_is(o[0], CGAL::POSITIVE) || certainly_is(o[1], CGAL::POSITIVE) ||
                         certainly_is(o[2], CGAL::POSITIVE);
        const bool neg = certainly_is(o[0], CGAL::NEGATIVE) || certainly_is(o[1], CGAL::NEGATIVE) ||
                         certainly_is(o[2], CGAL::NEGATIVE);
        if (pos && neg) continue;  // certainly a miss
        if (!o[0].is_certain() || !o[1].is_certain() || !o[2].is_certain()) {
          exact.push_back(i);
          continue;
        }
        if (o[0].inf() != CGAL::ZERO && o[1].inf() != CGAL::ZERO && o[2].inf() != CGAL::ZERO)
          odd[shell_[i]] ^= 1;
        else
          degenerate = true;
      }
    }
    for (std::size_t j = 0; j < exact.size() && !degenerate; ++j) {
      const Ray r = classify(exact[j], p, d);
      if (r == Ray::Cross) odd[shell_[exact[j]]] ^= 1;
      if (r == Ray::Degenerate) degenerate = true;
    }
    // Inside the union iff inside some shell.
    if (!degenerate) return std::find(odd.begin(), odd.end(), 1) != odd.end();
  }
  // proofs/containment.md §3: at most 11 directions per triangle are spoilt.
  throw std::logic_error("ClosedSurface::contains: no ray direction in general position found");
}

}  // namespace tmcert
