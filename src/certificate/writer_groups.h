// The certificate writer's groups (docs/certificate-format.md "Groups"):
// a body's elements, their vertices numbered once, and a binary tree of
// groups over them.
#pragma once

#include "src/certificate/writer_common.h"

#include <cstdint>
#include <vector>

namespace tmcert::certificate::writer_internal {


// A body's elements, their vertices numbered once, and a binary tree of
// groups over them (median splits of the element centroids, preorder
// numbering: children after their parent).
struct BodyGroups {
  std::vector<std::vector<Vec3E>> elements;
  PointIds ids;
  std::vector<std::vector<std::uint32_t>> element_vertices;
  std::vector<std::array<int, 2>> children;          // {-1, -1} for a leaf
  std::vector<int> element;                          // a leaf's element, else -1
  std::vector<std::vector<std::uint32_t>> vertices;  // sorted vertex ids under the group


  explicit BodyGroups(const Body& body);

  // The subtree over order[lo, hi) (median split along the centroids'
  // longest axis); returns its root.
  int build(std::vector<int>& order, std::size_t lo, std::size_t hi, const std::vector<std::array<double, 3>>& c);

  // The "groups" array of the certificate.
  json to_json() const;
};

}  // namespace tmcert::certificate::writer_internal
