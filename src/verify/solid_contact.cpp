#include "src/verify/solid_contact.h"

#include "src/model/solid.h"

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

}  // namespace tmcert
