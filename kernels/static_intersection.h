// Exact static intersection of points, segments and triangles in world
// coordinates (DESIGN.md section 4: the start check and collision witnesses,
// proofs/static-test.md).  Degenerate simplices (a triangle whose vertices
// are collinear, a segment of length zero: they arise under singular affine
// maps) are reduced exactly to the segment or point they are.
#pragma once

#include "kernels/number_types.h"

#include <optional>

namespace tmcert {

// Up to three points: count 1 = point, 2 = segment, 3 = triangle.
struct Simplex {
  int count = 1;
  std::array<Vec3E, 3> p;
};

// Reduces a degenerate simplex to the lower-dimensional one with the same
// point set (a collinear triangle becomes the segment between its two
// farthest vertices, equal points collapse).
Simplex canonical(const Simplex& s);

// Whether three points are collinear (or equal), exactly; an interval
// filter settles most non-degenerate triples.
bool collinear(const Vec3E& a, const Vec3E& b, const Vec3E& c);

// A point common to both closed simplices, computed exactly, or nothing when
// they are disjoint.  The point is re-checked to lie on both (exact has_on
// tests), so a reported point never rests on construction code alone.
std::optional<Vec3E> common_point(const Simplex& a, const Simplex& b);

// The same simplex with interval coordinates (enclosures).
struct SimplexI {
  int count = 1;
  std::array<std::array<Interval, 3>, 3> p;
};

// Filter for the static test: true only when the two simplices are proven
// disjoint by a separating axis (coordinate axes, triangle normals, cross
// products of edges, all rounded to doubles: any fixed axis will do) with
// interval projections.  false means "not proven", never "they touch".
// Call under RoundingGuard.
bool certainly_disjoint(const SimplexI& a, const SimplexI& b);

}  // namespace tmcert
