#include "kernels/distance.h"

#include "kernels/vec3.h"
namespace tmcert {

namespace {

using vec3::dot;
using vec3::sub;
Vec3E along(const Vec3E& a, const Vec3E& d, const Exact& t) { return {a[0] + t * d[0], a[1] + t * d[1], a[2] + t * d[2]}; }

ClosestPoints pair(const Vec3E& a, const Vec3E& b) {
  const Vec3E d = sub(a, b);
  return {dot(d, d), a, b};
}

void keep(std::optional<ClosestPoints>& best, ClosestPoints c) {
  if (!best || c.d2 < best->d2) best = std::move(c);
}

// Point p and segment [a, b] (a != b): the parameter clamped to [0, 1].
ClosestPoints point_segment(const Vec3E& p, const Vec3E& a, const Vec3E& b) {
  const Vec3E d = sub(b, a);
  Exact t = dot(sub(p, a), d) / dot(d, d);
  if (t < 0) t = 0;
  if (t > 1) t = 1;
  return pair(p, along(a, d, t));
}

// Point p and a non-degenerate triangle: the projection when it falls
// inside (barycentric coordinates from the 2x2 normal equations), else the
// nearest edge.
ClosestPoints point_triangle(const Vec3E& p, const std::array<Vec3E, 3>& t) {
  const Vec3E e1 = sub(t[1], t[0]), e2 = sub(t[2], t[0]), w = sub(p, t[0]);
  const Exact a11 = dot(e1, e1), a12 = dot(e1, e2), a22 = dot(e2, e2), b1 = dot(w, e1), b2 = dot(w, e2);
  const Exact det = a11 * a22 - a12 * a12;  // > 0: not collinear
  const Exact u = (b1 * a22 - b2 * a12) / det, v = (a11 * b2 - a12 * b1) / det;
  if (u >= 0 && v >= 0 && u + v <= 1) {
    Vec3E q;
    for (int i = 0; i < 3; ++i) q[i] = t[0][i] + u * e1[i] + v * e2[i];
    return pair(p, q);
  }
  std::optional<ClosestPoints> best;
  for (int k = 0; k < 3; ++k) keep(best, point_segment(p, t[k], t[(k + 1) % 3]));
  return *best;
}

ClosestPoints point_simplex(const Vec3E& p, const Simplex& s) {
  if (s.count == 1) return pair(p, s.p[0]);
  if (s.count == 2) return point_segment(p, s.p[0], s.p[1]);
  return point_triangle(p, s.p);
}

ClosestPoints swap(ClosestPoints c) {
  std::swap(c.a, c.b);
  return c;
}

// Two segments: the interior critical point of |P(s) - Q(t)|^2 when the
// segments are not parallel and it lies in the unit square, else the best
// of the four endpoint-to-segment distances (the minimum of a convex
// quadratic over the square is interior or on an edge of it).
ClosestPoints segment_segment(const Vec3E& p0, const Vec3E& p1, const Vec3E& q0, const Vec3E& q1) {
  const Vec3E d1 = sub(p1, p0), d2 = sub(q1, q0), r = sub(p0, q0);
  const Exact a = dot(d1, d1), b = dot(d1, d2), c = dot(d2, d2), d = dot(d1, r), e = dot(d2, r);
  const Exact den = a * c - b * b;
  if (den != 0) {
    const Exact s = (b * e - c * d) / den, t = (a * e - b * d) / den;
    if (s >= 0 && s <= 1 && t >= 0 && t <= 1) return pair(along(p0, d1, s), along(q0, d2, t));
  }
  std::optional<ClosestPoints> best;
  keep(best, point_segment(p0, q0, q1));
  keep(best, point_segment(p1, q0, q1));
  keep(best, swap(point_segment(q0, p0, p1)));
  keep(best, swap(point_segment(q1, p0, p1)));
  return *best;
}

}  // namespace

ClosestPoints closest_points(const Simplex& a_in, const Simplex& b_in) {
  const Simplex a = canonical(a_in), b = canonical(b_in);
  if (const auto p = common_point(a, b)) return {Exact(0), *p, *p};
  // Disjoint convex polytopes: the distance is attained between a vertex of
  // one and the other, or between two edges.
  std::optional<ClosestPoints> best;
  for (int k = 0; k < a.count; ++k) keep(best, point_simplex(a.p[k], b));
  for (int k = 0; k < b.count; ++k) keep(best, swap(point_simplex(b.p[k], a)));
  if (a.count >= 2 && b.count >= 2)
    for (int i = 0; i < a.count; ++i)
      for (int j = 0; j < b.count; ++j) {
        if (a.count == 2 && i == 1) continue;  // a segment has one edge
        if (b.count == 2 && j == 1) continue;
        keep(best, segment_segment(a.p[i], a.p[(i + 1) % a.count], b.p[j], b.p[(j + 1) % b.count]));
      }
  return *best;
}

}  // namespace tmcert
