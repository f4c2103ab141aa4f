#include "kernels/robust_crossing.h"

#include "kernels/uncertain.h"
#include "kernels/vec3.h"

namespace tmcert {

namespace {

using V = std::array<Interval, 3>;

using vec3::sub;

// The sign of det(b - a, c - a, d - a) over the intervals.
UncertainSign orient(const V& a, const V& b, const V& c, const V& d) {
  const V u = sub(b, a), v = sub(c, a), w = sub(d, a);
  const Interval det = u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
                       u[2] * (v[0] * w[1] - v[1] * w[0]);
  return uncertain_sign(det);
}

Interval volume(const V& a, const V& b, const V& c, const V& d) {
  const V u = sub(b, a), v = sub(c, a), w = sub(d, a);
  return u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0]);
}

// Segment pq crossing triangle t's interior transversally, for certain.
std::optional<V> crossing(const V& p, const V& q, const std::array<V, 3>& t) {
  // p and q certainly on opposite sides of the plane, off it.
  const UncertainSign sp = orient(t[0], t[1], t[2], p), sq = orient(t[0], t[1], t[2], q);
  if (!certainly_not(sp, CGAL::ZERO) || !certainly_not(sq, CGAL::ZERO) || sp.inf() == sq.inf()) return std::nullopt;
  // The line pq certainly on the same side of the three edges, off them.
  const UncertainSign s0 = orient(p, q, t[0], t[1]), s1 = orient(p, q, t[1], t[2]), s2 = orient(p, q, t[2], t[0]);
  if (!certainly_not(s0, CGAL::ZERO) || !certainly_is(s1, s0.inf()) || !certainly_is(s2, s0.inf()))
    return std::nullopt;
  // The crossing point p + (q - p) vp / (vp - vq), with vp, vq the signed
  // volumes (of certain, opposite signs: the denominator excludes 0).
  const Interval vp = volume(t[0], t[1], t[2], p), vq = volume(t[0], t[1], t[2], q);
  const Interval lambda = vp / (vp - vq);
  V x;
  for (int i = 0; i < 3; ++i) x[i] = p[i] + (q[i] - p[i]) * lambda;
  return x;
}

}  // namespace

std::optional<std::array<Interval, 3>> certain_crossing(const SimplexI& a, const SimplexI& b) {
  for (int side = 0; side < 2; ++side) {
    const SimplexI& e = side == 0 ? a : b;
    const SimplexI& t = side == 0 ? b : a;
    if (t.count != 3 || e.count < 2) continue;
    const int edges = e.count == 2 ? 1 : 3;
    for (int k = 0; k < edges; ++k)
      if (auto x = crossing(e.p[k], e.p[(k + 1) % e.count], t.p)) return x;
  }
  return std::nullopt;
}

}  // namespace tmcert
