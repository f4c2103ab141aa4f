#include "kernels/robust_crossing.h"

namespace tmcert {

namespace {

using V = std::array<Interval, 3>;

V sub(const V& a, const V& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

// The sign of det(b - a, c - a, d - a), when certain: +1, -1; 0 when not
// certainly nonzero.
int orient(const V& a, const V& b, const V& c, const V& d) {
  const V u = sub(b, a), v = sub(c, a), w = sub(d, a);
  const Interval det = u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
                       u[2] * (v[0] * w[1] - v[1] * w[0]);
  if (det.inf() > 0) return 1;
  if (det.sup() < 0) return -1;
  return 0;
}

Interval volume(const V& a, const V& b, const V& c, const V& d) {
  const V u = sub(b, a), v = sub(c, a), w = sub(d, a);
  return u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0]);
}

// Segment pq crossing triangle t's interior transversally, for certain.
std::optional<V> crossing(const V& p, const V& q, const std::array<V, 3>& t) {
  const int sp = orient(t[0], t[1], t[2], p), sq = orient(t[0], t[1], t[2], q);
  if (sp == 0 || sq == 0 || sp == sq) return std::nullopt;
  const int s0 = orient(p, q, t[0], t[1]), s1 = orient(p, q, t[1], t[2]), s2 = orient(p, q, t[2], t[0]);
  if (s0 == 0 || s0 != s1 || s1 != s2) return std::nullopt;
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
