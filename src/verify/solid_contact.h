// A solid body's inside at one exact pose (proofs/containment.md §5): its
// surface placed as triangles tagged by shell, and the vertices that decide
// whether another body lies inside (one per connected component).  Used by
// the start check and by the witness candidates of the search.
#pragma once

#include "kernels/containment.h"
#include "src/model/model.h"

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace tmcert {

// The pose of a body that does not move: its one-point motion, or the
// identity.  (A moving body's pose comes from its curve.)
Mat34E fixed_pose(const Body& b);

// The surface of solid body `b` under the exact affine map m (fan triangles
// of its convex pieces, each tagged with its polygon's shell), or null when
// m is singular (then the solid is its surface: containment.md Lemma 2).
std::unique_ptr<ClosedSurface> placed_surface(const Body& b, const Mat34E& m);

// One vertex per connected component of b's polygons, segments and points
// (features sharing an exact vertex are connected), placed by m, with its
// feature name ("polygon 2 vertex 0", "segment 1 end 0", "point 3").
std::vector<std::pair<std::string, Vec3E>> component_representatives(const Body& b, const Mat34E& m);

}  // namespace tmcert
