// The certificate checker's start claims at enclosed poses (check_enclosed.h,
// proofs/certificates.md "Start claims at enclosed poses").  Exact interval
// arithmetic on rationals: every bound is a rational, every product of two
// intervals the min and max of the four endpoint products.
#include "src/certificate/check_enclosed.h"

#include <algorithm>

namespace tmcert::certificate::check_internal {

namespace {

RInterval point(const Exact& x) { return {x, x}; }

RInterval add(const RInterval& a, const RInterval& b) { return {a.lo + b.lo, a.hi + b.hi}; }

RInterval minus(const RInterval& a, const RInterval& b) { return {a.lo - b.hi, a.hi - b.lo}; }

RInterval mul(const RInterval& a, const RInterval& b) {
  const Exact p[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
  return {*std::min_element(p, p + 4), *std::max_element(p, p + 4)};
}

RInterval entry(const PoseBox& box, int e) { return {box.center[e] - box.radius[e], box.center[e] + box.radius[e]}; }

}  // namespace

std::optional<RBox> solid_frame_box(const PoseBox& solid, const std::optional<Mat34E>& exact_solid,
                                    const PoseBox& other, const Vec3E& x) {
  const RBox q = place_box(other, x);
  RBox y;
  if (exact_solid) {
    // y = A^-1 (q - a), A^-1 = adj(A) / det(A).
    const Mat34E& m = *exact_solid;
    const Exact det = determinant(m);
    if (sgn(det) == 0) return std::nullopt;
    auto a = [&](int r, int c) -> const Exact& { return m[4 * r + c]; };
    Exact inv[3][3];
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) {
        // inv[r][c] = cofactor(c, r) / det.
        const int r1 = (c + 1) % 3, r2 = (c + 2) % 3, c1 = (r + 1) % 3, c2 = (r + 2) % 3;
        inv[r][c] = (a(r1, c1) * a(r2, c2) - a(r1, c2) * a(r2, c1)) / det;
      }
    for (int r = 0; r < 3; ++r) {
      RInterval s = point(Exact(0));
      for (int c = 0; c < 3; ++c) s = add(s, mul(point(inv[r][c]), minus(q[c], point(a(c, 3)))));
      y[r] = s;
    }
    return y;
  }
  // Rigid: y = R^T (q - t), R and t anywhere in their boxes.
  for (int r = 0; r < 3; ++r) {
    RInterval s = point(Exact(0));
    for (int c = 0; c < 3; ++c) s = add(s, mul(entry(solid, 4 * c + r), minus(q[c], entry(solid, 4 * c + 3))));
    y[r] = s;
  }
  return y;
}

namespace {

// Strictly disjoint projections of the box and the polygon onto axis d.
bool separated_along(const Vec3E& d, const RBox& box, const std::vector<Vec3E>& polygon) {
  if (is_zero(d)) return false;
  Exact blo(0), bhi(0);
  for (int i = 0; i < 3; ++i) {
    if (sgn(d[i]) >= 0) {
      blo += d[i] * box[i].lo;
      bhi += d[i] * box[i].hi;
    } else {
      blo += d[i] * box[i].hi;
      bhi += d[i] * box[i].lo;
    }
  }
  Exact plo = dot(d, polygon[0]), phi = plo;
  for (std::size_t k = 1; k < polygon.size(); ++k) {
    const Exact p = dot(d, polygon[k]);
    if (p < plo) plo = p;
    if (phi < p) phi = p;
  }
  return phi < blo || bhi < plo;
}

}  // namespace

bool box_clear_of_polygon(const RBox& box, const std::vector<Vec3E>& polygon) {
  if (polygon.empty()) return true;
  const Vec3E axes[3] = {{Exact(1), Exact(0), Exact(0)}, {Exact(0), Exact(1), Exact(0)}, {Exact(0), Exact(0), Exact(1)}};
  for (const Vec3E& e : axes)
    if (separated_along(e, box, polygon)) return true;
  const std::size_t k = polygon.size();
  Vec3E n{Exact(0), Exact(0), Exact(0)};
  for (std::size_t i = 1; i + 1 < k; ++i) {
    const Vec3E c = cross(sub(polygon[i], polygon[0]), sub(polygon[i + 1], polygon[0]));
    for (int j = 0; j < 3; ++j) n[j] += c[j];
  }
  if (separated_along(n, box, polygon)) return true;
  for (std::size_t i = 0; i < k; ++i) {
    const Vec3E edge = sub(polygon[(i + 1) % k], polygon[i]);
    for (const Vec3E& e : axes)
      if (separated_along(cross(edge, e), box, polygon)) return true;
  }
  return false;
}

Vec3E box_center(const RBox& box) {
  Vec3E c;
  for (int i = 0; i < 3; ++i) c[i] = (box[i].lo + box[i].hi) / 2;
  return c;
}

}  // namespace tmcert::certificate::check_internal
