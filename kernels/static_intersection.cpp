#include "kernels/static_intersection.h"

#include "kernels/vec3.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/intersections.h>

#include <cmath>
#include <stdexcept>
#include <limits>
#include <variant>
#include <vector>

namespace tmcert {

namespace {

using K = CGAL::Simple_cartesian<Exact>;
using Point = K::Point_3;
using Segment = K::Segment_3;

Point to_point(const Vec3E& v) { return Point(v[0], v[1], v[2]); }


Exact dist2(const Vec3E& a, const Vec3E& b) {
  return CGAL::squared_distance(to_point(a), to_point(b));
}

std::optional<Vec3E> point_in(const Vec3E& p, const Simplex& s) {
  for (int k = 0; k < s.count; ++k)  // a vertex of s (the common case of a witness)
    if (p == s.p[k]) return p;
  const Point q = to_point(p);
  switch (s.count) {
    case 1: return p == s.p[0] ? std::optional<Vec3E>(p) : std::nullopt;
    case 2: return Segment(to_point(s.p[0]), to_point(s.p[1])).has_on(q) ? std::optional<Vec3E>(p) : std::nullopt;
    default: {
      // CGAL's own predicates (not ours): in the triangle's plane, and on
      // the inner side of (or on) each edge.  The triangle is not
      // degenerate (canonical), as coplanar_orientation requires.  Cheaper
      // than Triangle_3::has_on, which constructs the plane and solves.
      const Point t[3] = {to_point(s.p[0]), to_point(s.p[1]), to_point(s.p[2])};
      if (!CGAL::coplanar(t[0], t[1], t[2], q)) return std::nullopt;
      for (int e = 0; e < 3; ++e)
        if (CGAL::coplanar_orientation(t[e], t[(e + 1) % 3], t[(e + 2) % 3], q) == CGAL::NEGATIVE) return std::nullopt;
      return p;
    }
  }
}

}  // namespace

bool collinear(const Vec3E& a, const Vec3E& b, const Vec3E& c) {
  {  // an interval filter proves most triangles non-degenerate
    RoundingGuard guard;
    const Interval ax = to_interval(a[0]), ay = to_interval(a[1]), az = to_interval(a[2]);
    const Interval ux = to_interval(b[0]) - ax, uy = to_interval(b[1]) - ay, uz = to_interval(b[2]) - az;
    const Interval wx = to_interval(c[0]) - ax, wy = to_interval(c[1]) - ay, wz = to_interval(c[2]) - az;
    for (const Interval& n : {uy * wz - uz * wy, uz * wx - ux * wz, ux * wy - uy * wx})
      if (n.inf() > 0 || n.sup() < 0) return false;
  }
  return CGAL::collinear(to_point(a), to_point(b), to_point(c));
}

Simplex canonical(const Simplex& s) {
  if (s.count == 1) return s;
  if (s.count == 2) {
    if (s.p[0] == s.p[1]) return Simplex{1, {s.p[0], s.p[0], s.p[0]}};
    return s;
  }
  if (!collinear(s.p[0], s.p[1], s.p[2])) return s;
  // Collinear: the segment between the farthest pair holds all three.
  int bi = 0, bj = 1;
  Exact best = dist2(s.p[0], s.p[1]);
  for (auto [i, j] : {std::pair{0, 2}, std::pair{1, 2}}) {
    Exact d = dist2(s.p[i], s.p[j]);
    if (d > best) { best = d; bi = i; bj = j; }
  }
  return canonical(Simplex{2, {s.p[bi], s.p[bj], s.p[bj]}});
}

namespace {

std::optional<Vec3E> construct_common_point(const Simplex& a, const Simplex& b);

}  // namespace

std::optional<Vec3E> common_point(const Simplex& a_in, const Simplex& b_in) {
  const Simplex a = canonical(a_in), b = canonical(b_in);
  std::optional<Vec3E> p = construct_common_point(a, b);
  // Independent confirmation with exact predicates; a disagreement is an
  // internal error (exit 4), never "no contact" and never a witness.
  if (p && (!point_in(*p, a) || !point_in(*p, b)))
    throw std::logic_error("exact static test: constructed common point is not on both simplices");
  return p;
}

bool certainly_disjoint(const SimplexI& a, const SimplexI& b) {
  using V = std::array<double, 3>;
  auto mid = [](const std::array<Interval, 3>& x) { return V{CGAL::to_double(x[0]), CGAL::to_double(x[1]), CGAL::to_double(x[2])}; };
  auto diff = [](const V& x, const V& y) { return V{x[0] - y[0], x[1] - y[1], x[2] - y[2]}; };
  auto cross = [](const V& x, const V& y) {
    return V{x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]};
  };
  // Candidate axes from approximate geometry (a fixed axis needs no rigour).
  V pa[3], pb[3];
  for (int i = 0; i < a.count; ++i) pa[i] = mid(a.p[i]);
  for (int i = 0; i < b.count; ++i) pb[i] = mid(b.p[i]);
  // Fixed arrays (no allocation per pair; the same axes in the same order).
  V edges_a[3], edges_b[3], axes[3 + 2 + 9] = {V{1, 0, 0}, V{0, 1, 0}, V{0, 0, 1}};
  int na = 0, nb = 0, n_axes = 3;
  for (int i = 0; i < a.count; ++i)
    for (int j = i + 1; j < a.count; ++j) edges_a[na++] = diff(pa[j], pa[i]);
  for (int i = 0; i < b.count; ++i)
    for (int j = i + 1; j < b.count; ++j) edges_b[nb++] = diff(pb[j], pb[i]);
  if (a.count == 3) axes[n_axes++] = cross(edges_a[0], edges_a[1]);
  if (b.count == 3) axes[n_axes++] = cross(edges_b[0], edges_b[1]);
  for (int i = 0; i < na; ++i)
    for (int j = 0; j < nb; ++j) axes[n_axes++] = cross(edges_a[i], edges_b[j]);
  for (int k = 0; k < n_axes; ++k) {
    const V& n = axes[k];
    if (!std::isfinite(n[0]) || !std::isfinite(n[1]) || !std::isfinite(n[2])) continue;
    // Projection range of a simplex; false when a bound is NaN (std::min
    // and std::max would silently drop it).
    auto range = [&](const SimplexI& s, double& lo, double& hi) {
      lo = std::numeric_limits<double>::infinity();
      hi = -lo;
      for (int i = 0; i < s.count; ++i) {
        const Interval d = s.p[i][0] * n[0] + s.p[i][1] * n[1] + s.p[i][2] * n[2];
        if (std::isnan(d.inf()) || std::isnan(d.sup())) return false;
        lo = std::min(lo, d.inf());
        hi = std::max(hi, d.sup());
      }
      return true;
    };
    double alo, ahi, blo, bhi;
    if (!range(a, alo, ahi) || !range(b, blo, bhi)) continue;
    if (ahi < blo || bhi < alo) return true;
  }
  return false;
}

namespace {

// ---------------------------------------------------------------- construction
// Exact predicates with an interval filter in front (the sign of an interval
// that excludes 0 is the sign of the exact value it encloses); exact
// rationals only when the filter cannot decide, and for the one point
// constructed.

using I3 = std::array<Interval, 3>;

// An exact point and its enclosure.
struct Pt {
  const Vec3E* e;
  I3 i;
};

Pt make_pt(const Vec3E& p) { return Pt{&p, {to_interval(p[0]), to_interval(p[1]), to_interval(p[2])}}; }

CGAL::Sign sign_of(const Interval& x) {
  if (x.inf() > 0) return CGAL::POSITIVE;
  if (x.sup() < 0) return CGAL::NEGATIVE;
  return CGAL::ZERO;  // undecided (0 also when exact zero: the caller re-runs exactly)
}
bool decided(const Interval& x) { return x.inf() > 0 || x.sup() < 0; }

using vec3::dot;
using vec3::sub;

// det[b - a, c - a, d - a]: positive when d is on the positive side of the
// plane abc (orientation).
template <class T>
T det3(const std::array<T, 3>& u, const std::array<T, 3>& v, const std::array<T, 3>& w) {
  return u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0]);
}
template <class T>
std::array<T, 3> minus(const std::array<T, 3>& a, const std::array<T, 3>& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

Exact orient_value(const Pt& a, const Pt& b, const Pt& c, const Pt& d) {
  return det3(sub(*b.e, *a.e), sub(*c.e, *a.e), sub(*d.e, *a.e));
}

CGAL::Sign orient(const Pt& a, const Pt& b, const Pt& c, const Pt& d) {
  {
    RoundingGuard guard;
    const Interval x = det3(minus(b.i, a.i), minus(c.i, a.i), minus(d.i, a.i));
    if (decided(x)) return sign_of(x);
  }
  return CGAL::sign(orient_value(a, b, c, d));
}

// Component k of (b - a) x (c - a): the orientation of abc projected along
// axis k (a fixed sign convention per k).
template <class T>
T cross_k(const std::array<T, 3>& u, const std::array<T, 3>& v, int k) {
  const int i = (k + 1) % 3, j = (k + 2) % 3;
  return u[i] * v[j] - u[j] * v[i];
}

Exact orient2_value(const Pt& a, const Pt& b, const Pt& c, int k) {
  return cross_k(sub(*b.e, *a.e), sub(*c.e, *a.e), k);
}

CGAL::Sign orient2(const Pt& a, const Pt& b, const Pt& c, int k) {
  {
    RoundingGuard guard;
    const Interval x = cross_k(minus(b.i, a.i), minus(c.i, a.i), k);
    if (decided(x)) return sign_of(x);
  }
  return CGAL::sign(orient2_value(a, b, c, k));
}

// An axis along which the projection of the plane of a, b, c (not
// collinear) is one to one: a component of the normal that is not 0.
int projection_axis(const Pt& a, const Pt& b, const Pt& c) {
  {
    RoundingGuard guard;
    const I3 u = minus(b.i, a.i), v = minus(c.i, a.i);
    int best = -1;
    double size = 0;
    for (int k = 0; k < 3; ++k) {
      const Interval n = cross_k(u, v, k);
      if (!decided(n)) continue;
      const double m = std::min(std::fabs(n.inf()), std::fabs(n.sup()));
      if (best < 0 || m > size) best = k, size = m;
    }
    if (best >= 0) return best;
  }
  const Vec3E u = sub(*b.e, *a.e), v = sub(*c.e, *a.e);
  for (int k = 0; k < 3; ++k)
    if (cross_k(u, v, k) != 0) return k;
  throw std::logic_error("exact static test: projection of a degenerate triangle");
}

// The sign of (b - a).(c - a).
CGAL::Sign dot_sign(const Pt& a, const Pt& b, const Pt& c) {
  {
    RoundingGuard guard;
    const I3 u = minus(b.i, a.i), v = minus(c.i, a.i);
    const Interval x = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
    if (decided(x)) return sign_of(x);
  }
  return CGAL::sign(dot(sub(*b.e, *a.e), sub(*c.e, *a.e)));
}

// p on the line ab (a != b): (b - a) x (p - a) = 0.
bool on_line(const Pt& a, const Pt& b, const Pt& p) {
  {
    RoundingGuard guard;
    const I3 u = minus(b.i, a.i), v = minus(p.i, a.i);
    for (int k = 0; k < 3; ++k)
      if (decided(cross_k(u, v, k))) return false;
  }
  const Vec3E u = sub(*b.e, *a.e), v = sub(*p.e, *a.e);
  for (int k = 0; k < 3; ++k)
    if (cross_k(u, v, k) != 0) return false;
  return true;
}

// p on the closed segment ab (a != b).
bool on_segment(const Pt& p, const Pt& a, const Pt& b) {
  return on_line(a, b, p) && dot_sign(a, b, p) != CGAL::NEGATIVE && dot_sign(b, a, p) != CGAL::NEGATIVE;
}

// p, in the plane of the triangle t (not degenerate), in the closed triangle.
bool in_triangle_coplanar(const Pt& p, const Pt* t, int axis) {
  const CGAL::Sign s = orient2(t[0], t[1], t[2], axis);
  for (int e = 0; e < 3; ++e) {
    const CGAL::Sign x = orient2(t[e], t[(e + 1) % 3], p, axis);
    if (x != CGAL::ZERO && x != s) return false;
  }
  return true;
}

bool in_triangle(const Pt& p, const Pt* t) {
  return orient(t[0], t[1], t[2], p) == CGAL::ZERO && in_triangle_coplanar(p, t, projection_axis(t[0], t[1], t[2]));
}

// a + (b - a) * num / (num - other), exactly.
Vec3E between(const Vec3E& a, const Vec3E& b, const Exact& num, const Exact& other) {
  const Exact s = num / (num - other);
  return {a[0] + (b[0] - a[0]) * s, a[1] + (b[1] - a[1]) * s, a[2] + (b[2] - a[2]) * s};
}

// Two coplanar segments (a0 != a1, b0 != b1) whose four points are not all
// on one line; `axis` projects their plane one to one.
std::optional<Vec3E> segments_in_plane(const Pt& a0, const Pt& a1, const Pt& b0, const Pt& b1, int axis) {
  const CGAL::Sign d1 = orient2(a0, a1, b0, axis), d2 = orient2(a0, a1, b1, axis);
  const CGAL::Sign d3 = orient2(b0, b1, a0, axis), d4 = orient2(b0, b1, a1, axis);
  // An end on the other segment (the only way to meet without crossing).
  if (d1 == CGAL::ZERO && on_segment(b0, a0, a1)) return *b0.e;
  if (d2 == CGAL::ZERO && on_segment(b1, a0, a1)) return *b1.e;
  if (d3 == CGAL::ZERO && on_segment(a0, b0, b1)) return *a0.e;
  if (d4 == CGAL::ZERO && on_segment(a1, b0, b1)) return *a1.e;
  // A proper crossing: each segment's ends strictly on both sides of the other.
  if (d1 * d2 < 0 && d3 * d4 < 0)
    return between(*b0.e, *b1.e, orient2_value(a0, a1, b0, axis), orient2_value(a0, a1, b1, axis));
  return std::nullopt;
}

std::optional<Vec3E> segment_segment(const Pt& a0, const Pt& a1, const Pt& b0, const Pt& b1) {
  if (orient(a0, a1, b0, b1) != CGAL::ZERO) return std::nullopt;  // not coplanar
  // Coplanar: a plane through a and a point of b off a's line, if any.
  const Pt* off = !on_line(a0, a1, b0) ? &b0 : !on_line(a0, a1, b1) ? &b1 : nullptr;
  if (!off) {  // all four on one line: an end of one on the other, if they overlap
    if (on_segment(b0, a0, a1)) return *b0.e;
    if (on_segment(b1, a0, a1)) return *b1.e;
    if (on_segment(a0, b0, b1)) return *a0.e;
    if (on_segment(a1, b0, b1)) return *a1.e;
    return std::nullopt;
  }
  return segments_in_plane(a0, a1, b0, b1, projection_axis(a0, a1, *off));
}

std::optional<Vec3E> segment_triangle(const Pt& s0, const Pt& s1, const Pt* t) {
  const CGAL::Sign o0 = orient(t[0], t[1], t[2], s0), o1 = orient(t[0], t[1], t[2], s1);
  if (o0 * o1 > 0) return std::nullopt;  // both ends strictly on one side
  const int axis = projection_axis(t[0], t[1], t[2]);
  if (o0 == CGAL::ZERO && o1 == CGAL::ZERO) {  // in the triangle's plane
    if (in_triangle_coplanar(s0, t, axis)) return *s0.e;
    if (in_triangle_coplanar(s1, t, axis)) return *s1.e;
    for (int e = 0; e < 3; ++e)  // neither end inside: it meets the boundary if anything
      if (auto p = segments_in_plane(s0, s1, t[e], t[(e + 1) % 3], axis)) return p;
    return std::nullopt;
  }
  if (o0 == CGAL::ZERO) return in_triangle_coplanar(s0, t, axis) ? std::optional<Vec3E>(*s0.e) : std::nullopt;
  if (o1 == CGAL::ZERO) return in_triangle_coplanar(s1, t, axis) ? std::optional<Vec3E>(*s1.e) : std::nullopt;
  // Strictly on both sides: the line s0 s1 meets the closed triangle iff it
  // passes on the same side of (or through) its three edges.
  const CGAL::Sign e0 = orient(s0, s1, t[0], t[1]), e1 = orient(s0, s1, t[1], t[2]), e2 = orient(s0, s1, t[2], t[0]);
  const bool has_pos = e0 > 0 || e1 > 0 || e2 > 0, has_neg = e0 < 0 || e1 < 0 || e2 < 0;
  if (has_pos && has_neg) return std::nullopt;
  return between(*s0.e, *s1.e, orient_value(t[0], t[1], t[2], s0), orient_value(t[0], t[1], t[2], s1));
}

std::optional<Vec3E> construct_common_point(const Simplex& a, const Simplex& b) {
  std::array<Pt, 3> pa, pb;
  for (int k = 0; k < a.count; ++k) pa[k] = make_pt(a.p[k]);
  for (int k = 0; k < b.count; ++k) pb[k] = make_pt(b.p[k]);
  auto point_on = [](const Pt& p, const Simplex& s, const std::array<Pt, 3>& ps) -> std::optional<Vec3E> {
    const bool on = s.count == 1 ? *p.e == s.p[0] : s.count == 2 ? on_segment(p, ps[0], ps[1]) : in_triangle(p, ps.data());
    return on ? std::optional<Vec3E>(*p.e) : std::nullopt;
  };
  if (a.count == 1) return point_on(pa[0], b, pb);
  if (b.count == 1) return point_on(pb[0], a, pa);
  if (a.count == 2 && b.count == 2) return segment_segment(pa[0], pa[1], pb[0], pb[1]);
  if (a.count == 2) return segment_triangle(pa[0], pa[1], pb.data());
  if (b.count == 2) return segment_triangle(pb[0], pb[1], pa.data());
  // Two triangles meet iff an edge of one meets the other: if they cross,
  // the ends of their common segment lie on edges; if they overlap in one
  // plane, an edge crosses or a whole triangle (with its edges) is inside.
  for (int e = 0; e < 3; ++e)
    if (auto p = segment_triangle(pa[e], pa[(e + 1) % 3], pb.data())) return p;
  for (int e = 0; e < 3; ++e)
    if (auto p = segment_triangle(pb[e], pb[(e + 1) % 3], pa.data())) return p;
  return std::nullopt;
}

}  // namespace

}  // namespace tmcert
