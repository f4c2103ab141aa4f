// The certificate checker's witnesses on the true shape of a robot link's
// URDF cylinder or sphere (docs/certificate-format.md "Cylinders and
// spheres", proofs/certificates.md §8).  The scene reader gives such a body
// its circumscribed polyhedron P as polygons and the true shape S
// (Body::primitive: a cylinder about the z axis or a ball, centred at the
// body's origin); pieces proven apart for P are apart for S (S ⊆ P,
// proofs/robot-links.md §3), but a collision needs a point of S itself:
// the witness side {"true_shape": true}.  The point is brought into the
// primitive's own frame as a box of rationals holding it for every pose of
// the checker's own pose enclosures at t (check_enclosed.h; a point box
// when both poses are exact), and the box must lie in S, decided exactly:
// the largest square of each coordinate over the box against r^2 (and |z|
// against length/2 for a cylinder).  The writer uses the same function to
// confirm its witness.
#pragma once

#include "src/certificate/motions.h"
#include "src/model/model.h"

#include <string>

namespace tmcert::certificate::check_internal {

// True when every point of the box (the primitive's frame) lies in the
// true shape: sum of the largest squares <= r^2 (ball), or the largest
// squares of x and y summing to <= r^2 and the largest |z| <= length/2
// (cylinder).
bool box_in_primitive(const Body::Primitive& p, const RBox& x);

// Empty when M_p^-1 M_o x lies in the true shape of `prim` (which must have
// Body::primitive) for every pose M_p of `prim` at t (exact, or enclosed by
// pose_box_at: a rigid pose, inverted as R^T (y - c)) and every M_o in
// `other` (a point box for an exact pose or a world point); otherwise why
// not, in words.
std::string true_shape_error(const Body& prim, const Exact& t, const PoseBox& other, const Vec3E& x);

// The exact pose box of the identity (a world point as the `other` above).
PoseBox identity_box();

}  // namespace tmcert::certificate::check_internal
