// Exact closest points of two closed simplices (points, segments,
// triangles) in world coordinates: the witnesses of a clearance violation
// and of a toleranced contact (SCENE_FORMAT.md "Tolerance and clearance",
// proofs/enclosures.md section 6).  Squared distances between rational
// features are rational, and so are the closest points: nothing is rounded.
#pragma once

#include "kernels/static_intersection.h"

namespace tmcert {

struct ClosestPoints {
  Exact d2;      // squared distance, exact
  Vec3E a, b;    // a point of each simplex with |a - b|^2 = d2
};

ClosestPoints closest_points(const Simplex& a, const Simplex& b);

}  // namespace tmcert
