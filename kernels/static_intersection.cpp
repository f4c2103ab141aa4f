#include "kernels/static_intersection.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/intersections.h>

#include <variant>

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
  if (!result) return std::nullopt;  // cannot happen after do_intersect
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

std::optional<Vec3E> common_point(const Simplex& a_in, const Simplex& b_in) {
  const Simplex a = canonical(a_in), b = canonical(b_in);
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

}  // namespace tmcert
