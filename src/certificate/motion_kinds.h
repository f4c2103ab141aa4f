// The certificate checker's enclosures of the motion kinds
// (src/model/segment_kind.h), registered by the kind's name and defined in
// motions.cpp with the checker's own arithmetic (Arb balls from the
// defining formulas): every kind the verifier knows has one here
// (tests/certificate/test_motion_kinds.cpp).  The checker decides a
// segment's kind itself (`holds`), sharing nothing with the verifier but
// the scene model.
#pragma once

#include "src/model/model.h"

#include <string>
#include <string_view>
#include <vector>

namespace tmcert::certificate {

// The names of the kinds the checker encloses, in the order it asks them.
std::vector<std::string> checker_kind_names();

// The name of the checker's kind of `seg` (empty when none holds it).
std::string_view checker_kind_name(const MotionSegment& seg);

}  // namespace tmcert::certificate
