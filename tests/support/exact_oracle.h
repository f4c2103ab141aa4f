// An exact oracle shared by the randomized tests (no rapidcheck): vector
// helpers, rational Bezier evaluation and point-on-feature tests, written
// independently of src/motion and kernels/static_intersection.
#pragma once

#include "kernels/number_types.h"
#include "src/model/model.h"

#include <array>
#include <vector>

namespace tmcert::testing {

inline Vec3E sub(const Vec3E& a, const Vec3E& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline Exact dot(const Vec3E& a, const Vec3E& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec3E cross(const Vec3E& a, const Vec3E& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline bool is_zero(const Vec3E& a) { return a[0] == 0 && a[1] == 0 && a[2] == 0; }

// The rational Bezier motion at scene parameter t, exactly: de Casteljau on
// the homogeneous points (w_k P_k, w_k).
inline Mat34E eval_motion(const Motion& m, const Exact& t) {
  if (m.control_points.size() == 1) return m.control_points[0];
  const Exact u = (t - m.t0) / (m.t1 - m.t0);
  const std::size_t n = m.control_points.size();
  std::vector<std::array<Exact, 13>> h(n);
  for (std::size_t k = 0; k < n; ++k) {
    for (int e = 0; e < 12; ++e) h[k][e] = m.weights[k] * m.control_points[k][e];
    h[k][12] = m.weights[k];
  }
  for (std::size_t level = 1; level < n; ++level)
    for (std::size_t k = 0; k + level < n; ++k)
      for (int e = 0; e < 13; ++e) h[k][e] = (1 - u) * h[k][e] + u * h[k + 1][e];
  Mat34E out;
  for (int e = 0; e < 12; ++e) out[e] = h[0][e] / h[0][12];
  return out;
}

// p on the closed segment ab (a point when a = b).
inline bool on_segment(const Vec3E& p, const Vec3E& a, const Vec3E& b) {
  if (a == b) return p == a;
  const Vec3E ab = sub(b, a), ap = sub(p, a);
  return is_zero(cross(ab, ap)) && dot(ap, ab) >= 0 && dot(sub(p, b), sub(a, b)) >= 0;
}

// p in the closed triangle abc, which may be degenerate (a singular affine
// map flattens it to a segment or a point).
inline bool in_triangle(const Vec3E& p, const Vec3E& a, const Vec3E& b, const Vec3E& c) {
  const Vec3E n = cross(sub(b, a), sub(c, a));
  if (is_zero(n)) return on_segment(p, a, b) || on_segment(p, b, c) || on_segment(p, a, c);
  if (dot(n, sub(p, a)) != 0) return false;
  return dot(cross(sub(b, a), sub(p, a)), n) >= 0 && dot(cross(sub(c, b), sub(p, b)), n) >= 0 &&
         dot(cross(sub(a, c), sub(p, c)), n) >= 0;
}

// Replaces every coordinate of the body in its own frame (polygons, convex
// pieces, segments, points) by f(coordinate).
template <class F>
void map_coordinates(Body& b, F f) {
  for (auto& poly : b.polygons)
    for (Vec3E& v : poly) v = f(v);
  for (ConvexPiece& piece : b.pieces)
    for (Vec3E& v : piece.vertices) v = f(v);
  for (auto& seg : b.segments)
    for (Vec3E& v : seg) v = f(v);
  for (Vec3E& v : b.points) v = f(v);
}

}  // namespace tmcert::testing
