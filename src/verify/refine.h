// Internal to src/verify: refinement by default (SCENE_FORMAT.md, "Decisive
// by default"; proofs/refinement.md).  A check that ends undecided at its
// epsilon has only its undecided intervals searched again, each as a check
// of its own on that part of the parameter interval, with epsilon divided
// by 10, level after level, down to the floor (the starting epsilon / 10^6:
// 1e-9 of the check's box for the default epsilon), within the check's time
// limit (options.deadline, from check_time_limit: VerifyOptions::time_limit,
// else kDefaultTimeLimit from the check's start, shared with its first
// search).  The re-searched parts replace the intervals they cover, in
// parameter order.
#pragma once

#include "src/verify/verify.h"

#include <chrono>
#include <functional>

namespace tmcert::detail {

// Levels of refinement: epsilon / 10, ..., epsilon / 10^kRefineLevels.
constexpr int kRefineLevels = 6;

// The time limit of a check refined by default when no time limit is given
// (SCENE_FORMAT.md "Decisive by default"), in seconds from the check's
// start, for its first search at the starting epsilon and its refinement
// together.
constexpr double kDefaultTimeLimit = 30;

// A check's time limit in seconds (0: none): VerifyOptions::time_limit when
// given, else with refinement (no epsilon given, or "auto")
// kDefaultTimeLimit, else none (a given epsilon is fixed and has no default
// limit, so that its result does not depend on the machine's speed).
double check_time_limit(const VerifyOptions& options);

// The deadline of a check started at `start` (check_time_limit; max():
// none), for VerifyOptions::deadline.
std::chrono::steady_clock::time_point check_deadline(const VerifyOptions& options,
                                                     std::chrono::steady_clock::time_point start);

// Tests only: the default limit in place of kDefaultTimeLimit (0: back to
// it), so that a test need not wait 30 s.
void set_default_time_limit_for_tests(double seconds);

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
