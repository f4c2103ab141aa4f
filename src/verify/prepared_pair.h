// One check of two bodies that were prepared beforehand, by the general
// search (keyframe and piecewise motions, tolerances, clearances;
// src/verify/general.cpp).  Verifier uses it for such checks; callers that
// certify many motions of the same bodies (src/verify/fixed_environment.h)
// prepare the bodies once and call it per motion.
#pragma once

#include "src/verify/verify.h"

#include <array>
#include <optional>
#include <utility>

namespace tmcert {

class PreparedBody;

namespace detail {

// `pa`, `pb`: the two bodies (PreparedBody::body points at each one's Body,
// whose motion is read at the time of the call); `ids` go to
// CheckResult::bodies.  No prefilter, no solid containment: Verifier::check
// does those before it gets here.  `start_proven_free`: the caller has
// proven the configuration at the start of the interval free of contact
// (an exact static test, proofs/static-test.md), so the search skips its
// own start test.  `window`: search only this part [t0, t1] of the check's
// interval (the refinement's re-search, src/verify/refine.h), cut at the
// joins inside it; its start is tested unless `start_proven_free`.
CheckResult check_prepared_pair(const PreparedBody& pa, const PreparedBody& pb, std::array<int, 2> ids,
                                const Exact& clearance, const VerifyOptions& options,
                                bool start_proven_free = false,
                                const std::optional<std::pair<Exact, Exact>>& window = std::nullopt);

}  // namespace detail
}  // namespace tmcert
