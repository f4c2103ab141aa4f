// Internal to src/verify: refinement by default (SCENE_FORMAT.md, "Decisive
// by default"; proofs/refinement.md).  A check that ends undecided at its
// epsilon has only its undecided intervals searched again, each as a check
// of its own on that part of the parameter interval, with epsilon divided
// by 10, level after level, down to the floor (the starting epsilon / 10^6:
// 1e-9 of the check's box for the default epsilon), within the check's time
// limit (VerifyOptions::time_limit, else kRefineSeconds from the check's
// start).  The re-searched parts replace the intervals they cover, in
// parameter order.
#pragma once

#include "src/verify/verify.h"

#include <chrono>
#include <functional>

namespace tmcert::detail {

// The refinement's time limit per check when none is given (seconds,
// counted from the check's start).
constexpr double kRefineSeconds = 30;
// Levels of refinement: epsilon / 10, ..., epsilon / 10^kRefineLevels.
constexpr int kRefineLevels = 6;

// Searches the check on the part [t0, t1] of its interval with the options
// given (their epsilon set); `start_proven_free`: the configuration at t0 is
// proven free of contact.
using WindowSearch =
    std::function<CheckResult(const Exact& t0, const Exact& t1, bool start_proven_free, const VerifyOptions& options)>;

// Refines `result` (the check's result at *options.epsilon) in place when
// options.refine is set and it is undecided.  `check_t0`: the start of the
// check's interval (the start there was tested by the first search, not
// proven free beforehand).  `dyadic`: the check is searched on one
// rational curve over its whole interval [check_t0, check_t1] (not a
// general check), whose cleared pieces a certificate names by index and
// depth: the re-searched parts are then aligned dyadic pieces of it, and
// their cleared pieces are given back in that form.
void refine_check(CheckResult& result, const Exact& check_t0, const Exact& check_t1, bool dyadic,
                  const VerifyOptions& options, std::chrono::steady_clock::time_point started,
                  const WindowSearch& search);

}  // namespace tmcert::detail
