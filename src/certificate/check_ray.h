// The certificate checker's ray parity test (the public ray_crossings is
// declared in check.h): its helpers, shared with the start claims and the
// interior witnesses.
#pragma once

#include "src/certificate/check_numbers.h"

#include <vector>

namespace tmcert::certificate::check_internal {

// Does the closed ray {p + s d : s >= 0} meet the segment [a, b]?
bool ray_meets_segment(const Vec3E& p, const Vec3E& d, const Vec3E& a, const Vec3E& b);

// The shell of each convex piece of a solid body (SCENE_FORMAT.md "Solids":
// polygons linked by shared edges; the scene reader found them closed).
std::vector<int> piece_shells(const Body& body);

// "1, 0, 3": per-shell crossing counts in messages.
std::string counts_text(const std::vector<int>& counts);

}  // namespace tmcert::certificate::check_internal
