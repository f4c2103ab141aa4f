#include "kernels/static_intersection.h"

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
using Triangle = K::Triangle_3;

Point to_point(const Vec3E& v) { return Point(v[0], v[1], v[2]); }
Vec3E to_vec(const Point& p) { return {p.x(), p.y(), p.z()}; }

bool collinear(const Vec3E& a, const Vec3E& b, const Vec3E& c) {
  return CGAL::collinear(to_point(a), to_point(b), to_point(c));
}

Exact dist2(const Vec3E& a, const Vec3E& b) {
  return CGAL::squared_distance(to_point(a), to_point(b));
}

// A point of an intersection result of any CGAL shape.
struct AnyPoint {
  Vec3E operator()(const Point& p) const { return to_vec(p); }
  Vec3E operator()(const Segment& s) const { return to_vec(s.source()); }
  Vec3E operator()(const Triangle& t) const { return to_vec(t.vertex(0)); }
  Vec3E operator()(const std::vector<Point>& v) const { return to_vec(v.front()); }
};

template <class A, class B>
std::optional<Vec3E> intersect(const A& a, const B& b) {
  if (!CGAL::do_intersect(a, b)) return std::nullopt;
  auto result = CGAL::intersection(a, b);
  // The predicate said they meet: a missing construction must not read as
  // "no contact" (at the start check that could end in a false "safe").
  if (!result) throw std::logic_error("exact static test: intersection predicate and construction disagree");
  return boost::apply_visitor(AnyPoint(), *result);
}

std::optional<Vec3E> point_in(const Vec3E& p, const Simplex& s) {
  const Point q = to_point(p);
  switch (s.count) {
    case 1: return p == s.p[0] ? std::optional<Vec3E>(p) : std::nullopt;
    case 2: return Segment(to_point(s.p[0]), to_point(s.p[1])).has_on(q) ? std::optional<Vec3E>(p) : std::nullopt;
    default:
      return Triangle(to_point(s.p[0]), to_point(s.p[1]), to_point(s.p[2])).has_on(q)
                 ? std::optional<Vec3E>(p) : std::nullopt;
  }
}

}  // namespace

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
  std::vector<V> edges_a, edges_b, axes = {V{1, 0, 0}, V{0, 1, 0}, V{0, 0, 1}};
  for (int i = 0; i < a.count; ++i)
    for (int j = i + 1; j < a.count; ++j) edges_a.push_back(diff(pa[j], pa[i]));
  for (int i = 0; i < b.count; ++i)
    for (int j = i + 1; j < b.count; ++j) edges_b.push_back(diff(pb[j], pb[i]));
  if (a.count == 3) axes.push_back(cross(edges_a[0], edges_a[1]));
  if (b.count == 3) axes.push_back(cross(edges_b[0], edges_b[1]));
  for (const V& e : edges_a)
    for (const V& f : edges_b) axes.push_back(cross(e, f));
  for (const V& n : axes) {
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

std::optional<Vec3E> construct_common_point(const Simplex& a, const Simplex& b) {
  if (a.count == 1) return point_in(a.p[0], b);
  if (b.count == 1) return point_in(b.p[0], a);
  const Segment sa(to_point(a.p[0]), to_point(a.p[1]));
  const Segment sb(to_point(b.p[0]), to_point(b.p[1]));
  if (a.count == 2 && b.count == 2) return intersect(sa, sb);
  if (a.count == 2) return intersect(sa, Triangle(to_point(b.p[0]), to_point(b.p[1]), to_point(b.p[2])));
  const Triangle ta(to_point(a.p[0]), to_point(a.p[1]), to_point(a.p[2]));
  if (b.count == 2) return intersect(sb, ta);
  return intersect(ta, Triangle(to_point(b.p[0]), to_point(b.p[1]), to_point(b.p[2])));
}

}  // namespace

}  // namespace tmcert
