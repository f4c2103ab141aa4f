// The certificate checker's ray parity test (check.h, check_ray.h;
// proofs/certificates.md "Start claims"): exact signs of orientation
// determinants, every degenerate case reported as such.
#include "src/certificate/check_ray.h"
#include "src/certificate/check.h"
#include "src/model/solid.h"

#include <algorithm>

namespace tmcert::certificate {

namespace check_internal {

bool ray_meets_segment(const Vec3E& p, const Vec3E& d, const Vec3E& a, const Vec3E& b) {
  const Vec3E e = sub(b, a), w = sub(a, p), c = cross(d, e);
  if (!is_zero(c)) {
    if (sgn(dot(w, c)) != 0) return false;  // skew lines
    // s d - r e = w: s c = w x e, r c = w x d.
    const Exact cc = dot(c, c);
    const Exact s = dot(cross(w, e), c) / cc, r = dot(cross(w, d), c) / cc;
    return sgn(s) >= 0 && sgn(r) >= 0 && r <= 1;
  }
  // d parallel to e (or e = 0): only on the ray's line.
  if (!is_zero(cross(w, d))) return false;
  return sgn(dot(w, d)) >= 0 || sgn(dot(sub(b, p), d)) >= 0;
}

std::vector<int> piece_shells(const Body& body) {
  const std::vector<int> polygon_shell = polygon_shells(body);
  std::vector<int> out;
  out.reserve(body.pieces.size());
  for (const ConvexPiece& piece : body.pieces) out.push_back(polygon_shell[piece.polygon]);
  return out;
}

std::string counts_text(const std::vector<int>& counts) {
  std::string out;
  for (std::size_t k = 0; k < counts.size(); ++k)
    out += (k ? ", " : "") + std::to_string(counts[k]);
  return out;
}

}  // namespace check_internal

using namespace check_internal;

std::optional<int> ray_crossings(const std::vector<std::vector<Vec3E>>& placed_polygons, const Vec3E& p,
                                 const Vec3E& d) {
  const std::optional<std::vector<int>> per = ray_crossings(placed_polygons, std::vector<int>(placed_polygons.size(), 0), p, d);
  if (!per) return std::nullopt;
  return per->empty() ? 0 : (*per)[0];
}

std::optional<std::vector<int>> ray_crossings(const std::vector<std::vector<Vec3E>>& placed_polygons,
                                              const std::vector<int>& shell, const Vec3E& p, const Vec3E& d) {
  if (is_zero(d) || shell.size() != placed_polygons.size()) return std::nullopt;
  std::vector<int> count(placed_polygons.empty() ? 0 : static_cast<std::size_t>(*std::max_element(shell.begin(), shell.end())) + 1, 0);
  for (std::size_t index = 0; index < placed_polygons.size(); ++index) {
    const std::vector<Vec3E>& poly = placed_polygons[index];
    const std::size_t k = poly.size();
    if (k == 0) continue;
    // Area vector: nonzero exactly when the convex polygon is not flat.
    Vec3E n{Exact(0), Exact(0), Exact(0)};
    for (std::size_t i = 1; i + 1 < k; ++i) {
      const Vec3E c = cross(sub(poly[i], poly[0]), sub(poly[i + 1], poly[0]));
      for (int j = 0; j < 3; ++j) n[j] += c[j];
    }
    if (is_zero(n)) {
      // Flat (a segment or a point): degenerate when the ray meets it.
      for (std::size_t i = 0; i < k; ++i)
        if (ray_meets_segment(p, d, poly[i], poly[(i + 1) % k])) return std::nullopt;
      continue;
    }
    // Edge functions: e_i(x) = ((v_{i+1} - v_i) x (x - v_i)) . n >= 0 on the
    // polygon (vertices turn counter-clockwise about their area vector n).
    auto inside_closed = [&](const Vec3E& x) {
      for (std::size_t i = 0; i < k; ++i)
        if (sgn(dot(cross(sub(poly[(i + 1) % k], poly[i]), sub(x, poly[i])), n)) < 0) return false;
      return true;
    };
    const int nd = sgn(dot(n, d));
    const int h = sgn(dot(n, sub(p, poly[0])));  // side of p
    if (nd == 0) {
      if (h != 0) continue;  // parallel to the plane, off it
      // The ray lies in the plane: degenerate if it meets the polygon.
      // Along the ray e_i(p + s d) = c0 + s c1; feasible s >= 0?
      Exact lo(0);
      std::optional<Exact> hi;
      bool feasible = true;
      for (std::size_t i = 0; i < k && feasible; ++i) {
        const Vec3E edge = sub(poly[(i + 1) % k], poly[i]);
        const Exact c0 = dot(cross(edge, sub(p, poly[i])), n);
        const Exact c1 = dot(cross(edge, d), n);
        if (sgn(c1) == 0) {
          if (sgn(c0) < 0) feasible = false;
        } else if (sgn(c1) > 0) {
          lo = std::max(lo, -c0 / c1);
        } else {
          const Exact bound = -c0 / c1;
          hi = hi ? std::min(*hi, bound) : bound;
        }
      }
      if (feasible && (!hi || lo <= *hi)) return std::nullopt;
      continue;
    }
    if (h == 0) {
      // p in the plane, the ray leaves it at once.
      if (inside_closed(p)) return std::nullopt;
      continue;
    }
    if (h == nd) continue;  // the plane is behind p (s = -h/nd < 0)
    // The ray crosses the plane at s > 0, at q.  With v - p = (v - q) + s d,
    // o_i = d . ((v_i - p) x (v_{i+1} - p)) = mu_i (d . n), where mu_i > 0
    // iff q is strictly on the inner side of edge i.
    bool miss = false, boundary = false;
    for (std::size_t i = 0; i < k && !miss; ++i) {
      const int o = sgn(dot(d, cross(sub(poly[i], p), sub(poly[(i + 1) % k], p)))) * nd;
      if (o < 0) miss = true;
      else if (o == 0) boundary = true;
    }
    if (miss) continue;
    if (boundary) return std::nullopt;  // through an edge or a vertex
    ++count[shell[index]];
  }
  return count;
}

}  // namespace tmcert::certificate
