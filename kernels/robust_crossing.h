// A collision proven on enclosed configurations (proofs/enclosures.md
// section 5): when a motion is transcendental its pose at a parameter is
// known only as an interval enclosure, so a witness must hold for every
// configuration in it.  An edge of one simplex (a segment, or a side of a
// triangle) that crosses the interior of a triangle of the other
// transversally does: both ends strictly on opposite sides of the
// triangle's plane and the edge's line strictly inside the three sides,
// every sign certain over the intervals.  Grazing contacts never qualify.
#pragma once

#include "kernels/static_intersection.h"

#include <optional>

namespace tmcert {

// A box holding the crossing point of every configuration in the
// enclosures, or nothing when no certain transversal crossing exists.
// Call under RoundingGuard.
std::optional<std::array<Interval, 3>> certain_crossing(const SimplexI& a, const SimplexI& b);

}  // namespace tmcert
