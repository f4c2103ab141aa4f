#include "src/verify/solid_contact.h"

#include "src/model/solid.h"

#include <cmath>
#include <limits>
#include <map>

namespace tmcert {

namespace {

Vec3E apply_map(const Mat34E& m, const Vec3E& x) {
  Vec3E r;
  for (int i = 0; i < 3; ++i) r[i] = m[4 * i] * x[0] + m[4 * i + 1] * x[1] + m[4 * i + 2] * x[2] + m[4 * i + 3];
  return r;
}

}  // namespace

Mat34E fixed_pose(const Body& b) {
  if (b.motion) return b.motion->control_points[0];  // degree 0: its only pose
  return {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
}

std::unique_ptr<ClosedSurface> placed_surface(const Body& b, const Mat34E& m) {
  const Exact det = m[0] * (m[5] * m[10] - m[6] * m[9]) - m[1] * (m[4] * m[10] - m[6] * m[8]) +
                    m[2] * (m[4] * m[9] - m[5] * m[8]);
  if (det == 0) return nullptr;
  // The inside is the union of the shells' insides: parity per shell.
  const std::vector<int> polygon_shell = polygon_shells(b);
  std::vector<std::array<Vec3E, 3>> triangles;
  std::vector<int> shell;
  for (const ConvexPiece& piece : b.pieces)
    for (std::size_t k = 1; k + 1 < piece.vertices.size(); ++k) {
      triangles.push_back({apply_map(m, piece.vertices[0]), apply_map(m, piece.vertices[k]),
                           apply_map(m, piece.vertices[k + 1])});
      shell.push_back(polygon_shell[piece.polygon]);
    }
  return std::make_unique<ClosedSurface>(std::move(triangles), std::move(shell));
}

std::vector<std::pair<std::string, Vec3E>> component_representatives(const Body& b, const Mat34E& m) {
  std::vector<std::vector<Vec3E>> parts;
  std::vector<std::string> names;
  for (std::size_t i = 0; i < b.polygons.size(); ++i) {
    parts.push_back(b.polygons[i]);
    names.push_back("polygon " + std::to_string(i) + " vertex 0");
  }
  for (std::size_t i = 0; i < b.segments.size(); ++i) {
    parts.push_back({b.segments[i][0], b.segments[i][1]});
    names.push_back("segment " + std::to_string(i) + " end 0");
  }
  for (std::size_t i = 0; i < b.points.size(); ++i) {
    parts.push_back({b.points[i]});
    names.push_back("point " + std::to_string(i));
  }
  std::vector<std::size_t> parent(parts.size());
  for (std::size_t i = 0; i < parts.size(); ++i) parent[i] = i;
  auto find = [&](std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  std::map<Vec3E, std::size_t> owner;
  for (std::size_t i = 0; i < parts.size(); ++i)
    for (const Vec3E& v : parts[i]) {
      auto [it, fresh] = owner.emplace(v, i);
      if (!fresh) parent[find(i)] = find(it->second);
    }
  std::vector<std::pair<std::string, Vec3E>> out;
  for (std::size_t i = 0; i < parts.size(); ++i)
    if (find(i) == i) out.emplace_back(names[i], apply_map(m, parts[i][0]));
  return out;
}

std::vector<Vec3E> every_vertex(const Body& b) {
  std::vector<Vec3E> v;
  for (const auto& poly : b.polygons) v.insert(v.end(), poly.begin(), poly.end());
  for (const auto& seg : b.segments) v.insert(v.end(), seg.begin(), seg.end());
  v.insert(v.end(), b.points.begin(), b.points.end());
  return v;
}

namespace {

// The box of points placed by an interval map (NaN: false).
bool placed_box(const std::vector<Vec3E>& points, const std::array<Interval, 12>& m, std::array<double, 3>& lo,
                std::array<double, 3>& hi) {
  RoundingGuard guard;
  lo.fill(std::numeric_limits<double>::infinity());
  hi.fill(-std::numeric_limits<double>::infinity());
  for (const Vec3E& v : points) {
    const Interval x[3] = {to_interval(v[0]), to_interval(v[1]), to_interval(v[2])};
    for (int i = 0; i < 3; ++i) {
      const Interval y = m[4 * i] * x[0] + m[4 * i + 1] * x[1] + m[4 * i + 2] * x[2] + m[4 * i + 3];
      if (std::isnan(y.inf()) || std::isnan(y.sup())) return false;
      lo[i] = std::min(lo[i], y.inf());
      hi[i] = std::max(hi[i], y.sup());
    }
  }
  return true;
}

bool boxes_overlap(const std::array<double, 3>& alo, const std::array<double, 3>& ahi,
                   const std::array<double, 3>& blo, const std::array<double, 3>& bhi) {
  for (int c = 0; c < 3; ++c)
    if (ahi[c] < blo[c] || bhi[c] < alo[c]) return false;
  return true;
}

}  // namespace

Containment start_containment(const Body& solid, const std::vector<Vec3E>& solid_vertices, const StartPose& ps,
                              const Body& other, const std::vector<std::pair<std::string, Vec3E>>& other_reps,
                              const StartPose& po, bool solid_first) {
  Containment out;
  if (ps.exact && po.exact) {
    const std::unique_ptr<ClosedSurface> surface = placed_surface(solid, *ps.exact);
    if (!surface) return out;  // a singular pose: the solid is its surface there
    for (const auto& [part, rep] : other_reps) {
      const Vec3E point = apply_map(*po.exact, rep);
      if (surface->contains(point)) {
        const std::string inside = solid.name + " interior", at = other.name + " " + part;
        out.kind = Containment::Kind::Hit;
        out.witness = Witness{Exact(0), solid_first ? std::array{inside, at} : std::array{at, inside}, point,
                              std::nullopt, std::nullopt, std::nullopt, 0, std::nullopt};
        return out;
      }
    }
    return out;
  }
  std::array<double, 3> lo, hi;
  if (!placed_box(solid_vertices, ps.map, lo, hi)) {
    out.kind = Containment::Kind::Unknown;
    return out;
  }
  for (const auto& rep : other_reps) {
    std::array<double, 3> rlo, rhi;
    if (!placed_box({rep.second}, po.map, rlo, rhi) || boxes_overlap(lo, hi, rlo, rhi)) {
      out.kind = Containment::Kind::Unknown;
      return out;
    }
  }
  return out;
}

}  // namespace tmcert
