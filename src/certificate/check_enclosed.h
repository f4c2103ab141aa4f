// The certificate checker's start claims at enclosed poses
// (docs/certificate-format.md "Start claims", proofs/certificates.md
// "Start claims at enclosed poses"): where a body's pose at a claim's
// instant is not exact (a URDF origin's rpy rotation, a revolute joint away
// from 0, a keyframe rotation), the vertex of the other body is brought into
// the solid's own frame as a box of rationals holding it for every pose of
// the two pose boxes (the checker's own enclosures, motions.h); the claim
// holds when that box meets no polygon of the solid (exact separating axes)
// and the ray from the box's centre crosses every shell an even number of
// times (the box is connected and misses the boundary, so all of it is on
// the centre's side).  The writer uses the same functions to choose its
// points and rays.
#pragma once

#include "src/certificate/check_numbers.h"
#include "src/certificate/motions.h"

#include <optional>
#include <vector>

namespace tmcert::certificate::check_internal {

// The box, in the solid's frame, of M_s^-1 M_o x over every M_o in `other`
// and M_s in `solid`.  `exact_solid`: the solid's pose when it is exact (any
// nonsingular affine map, inverted exactly); without it the solid's poses
// are rigid (a keyframe or robot link motion: rotation and translation, so
// M^-1 y = R^T (y - t)) and `solid` encloses them.  nullopt when the exact
// pose is singular.
std::optional<RBox> solid_frame_box(const PoseBox& solid, const std::optional<Mat34E>& exact_solid,
                                    const PoseBox& other, const Vec3E& x);

// True when an axis among the box's three, the polygon's normal and the
// cross products of its edges with the box's axes separates the closed box
// from the convex polygon (vertices in order) strictly: then they are
// disjoint.  False when none does (they may meet).
bool box_clear_of_polygon(const RBox& box, const std::vector<Vec3E>& polygon);

// The centre of the box (a rational point inside it).
Vec3E box_center(const RBox& box);

}  // namespace tmcert::certificate::check_internal
