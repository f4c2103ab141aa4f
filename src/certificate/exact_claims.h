// The exact "no contact in this piece" claim of certificates
// (docs/certificate-format.md, "Exact claims"; proofs/exact-resolution.md
// §6): two elements, one of each body of a check, share no point at any
// curve parameter of a piece.  Decided from the scene alone in exact
// arithmetic: the elements apart at the piece's start (a static exact
// test), and no vertex-element or edge-edge contact anywhere in the closed
// piece (the contact polynomials of the sub-features, their roots isolated
// by Sturm, the containment predicates' signs at each root, identically
// vanishing polynomials reduced exactly: kernels/moving_contact.h).  Used by
// the checker (check.cpp) and by the writer (writer.cpp) where separating
// planes do not prove a piece.
#pragma once

#include "src/certificate/algebraic_witness.h"

#include <string>
#include <vector>

namespace tmcert::certificate {

// Do two elements share a point?  Each is a list of exact vertices: one (a
// point), two (a segment) or at least three (a convex polygon, in order,
// possibly collapsed onto a segment or a point).
bool elements_meet(const std::vector<Vec3E>& a, const std::vector<Vec3E>& b);

// The claim for element `a` of the check's body a (vertices in its frame)
// and element `b` of body b, over the curve parameters [u0, u1] (closed,
// u0 <= u1), or, with `before` (a root, u0 < before <= u1 and u1 at or after
// the root's interval), over [u0, before) (half-open: the elements may touch
// at `before` itself).  Empty when it holds; otherwise why not.  Throws
// ResourceLimit when an exact loop passes its cap (never a verdict).
std::string no_contact_error(const CheckMotions& motions, const std::vector<Vec3E>& a, const std::vector<Vec3E>& b,
                             const Exact& u0, const Exact& u1, const RealRoot* before = nullptr);

}  // namespace tmcert::certificate
