// Exact point-in-solid test for a union of closed triangulated shells
// (proofs/containment.md).
//
// contains(p) is true iff p lies on the surface or in the region enclosed by
// some shell, i.e. a ray from p in general position crosses some shell an
// odd number of times (the mod-2 winding number of each shell; overlapping
// and nested shells form a union, SCENE_FORMAT.md "Solids").
// Every decision is exact: an interval filter decides only what it proves,
// everything else is recomputed with rationals.  A ray that touches an edge
// or a vertex, or runs in the plane of a triangle it meets, is discarded and
// the next direction of a fixed sequence is tried; there is no guessing.
#pragma once

#include "kernels/number_types.h"

#include <array>
#include <cstddef>
#include <vector>

namespace tmcert {

class ClosedSurface {
 public:
  // `triangles` must form closed shells: `shell[i]` (>= 0) is the shell of
  // triangle i, and within each shell every undirected edge (pair of
  // endpoints) belongs to an even number of triangles - two for a solid
  // accepted by the scene parser.  Triangles with collinear or equal
  // vertices are allowed.  The caller guarantees closedness; it is not
  // re-checked.  Without `shell`, all triangles form one shell.
  explicit ClosedSurface(std::vector<std::array<Vec3E, 3>> triangles, std::vector<int> shell = {});

  // p inside the enclosed solid or on the surface; exact.  Thread-safe.
  bool contains(const Vec3E& p) const;
  // The same; `directions_tried` is the number of ray directions cast (0
  // when p was found on the surface or no triangle lies on the +x side).
  bool contains(const Vec3E& p, int& directions_tried) const;

  // The k-th ray direction (1, t, t^2) with t = 1/(1031 + k): no three of
  // them are coplanar, so each triangle spoils at most 11 of them and the
  // search ends after at most 11 * size() + 1 directions.
  static Vec3E ray_direction(std::size_t k);

  std::size_t size() const { return triangles_.size(); }

 private:
  enum class Ray { Miss, Cross, Degenerate };

  bool on_triangle(std::size_t i, const Vec3E& p) const;
  Ray classify(std::size_t i, const Vec3E& p, const Vec3E& d) const;

  std::vector<std::array<Vec3E, 3>> triangles_;
  std::vector<std::array<Interval, 9>> intervals_;  // enclosures of the coordinates
  std::vector<bool> flat_;                          // collinear (or equal) vertices
  std::vector<int> shell_;                          // per triangle
  int shells_ = 0;
  // Outward-rounded bounding boxes, one array per bound (for a fast scan).
  std::vector<double> xlo_, xhi_, ylo_, yhi_, zlo_, zhi_;
  double xmax_ = 0;  // >= every x coordinate of the surface
};

}  // namespace tmcert
