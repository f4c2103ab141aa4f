// A solid body's inside at one exact pose (proofs/containment.md §5): its
// surface placed as triangles tagged by shell, and the vertices that decide
// whether another body lies inside (one per connected component).  Used by
// the start check and by the witness candidates of the search.
#pragma once

#include "kernels/containment.h"
#include "src/model/model.h"
#include "src/verify/verify.h"

#include <array>
#include <optional>

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

// Every vertex of b's polygons, segments and points, in its own frame.
std::vector<Vec3E> every_vertex(const Body& b);

// A body's pose at one instant: exact when known, always enclosed.
struct StartPose {
  std::optional<Mat34E> exact;
  std::array<Interval, 12> map;
};

// Whether some connected component of `other` lies inside the solid `solid`
// at one instant (proofs/containment.md: with no such component and no
// surface contact later, no point of one is ever inside the other).  With
// both poses exact: exact ray parity of one vertex per component (Hit: a
// witness at t = 0, features "<solid> interior" and the vertex, in the
// order `solid_first` says).  Else only the boxes decide: every component
// vertex's enclosure outside the solid's box means free; anything else is
// Unknown (never "free").  `solid_vertices`: every_vertex(solid);
// `other_reps`: component_representatives(other, identity).
struct Containment {
  enum class Kind { Free, Hit, Unknown } kind = Kind::Free;
  std::optional<Witness> witness;
};
Containment start_containment(const Body& solid, const std::vector<Vec3E>& solid_vertices, const StartPose& ps,
                              const Body& other, const std::vector<std::pair<std::string, Vec3E>>& other_reps,
                              const StartPose& po, bool solid_first);

}  // namespace tmcert
