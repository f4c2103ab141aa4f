// Certified verification of a scene's checks.
#pragma once

#include "tmcert/export.h"
#include "tmcert/numbers.h"
#include "tmcert/result.h"
#include "tmcert/scene.h"

#include <cstddef>
#include <functional>
#include <optional>
#include <string>

namespace tmcert::api {

// What VerifyOptions::progress is given while verify() runs.
struct Progress {
  // The share of the checks' work done: each check counts as one part of
  // the whole, and within a running check, the share of its parameter
  // interval already decided.  Below 1 while any check is left; 1 once
  // every check is done, and in the last call.  What verify() does before
  // the checks (bounding the sweeps) and within them (preparing a large
  // body) is named by `activity`, not hidden behind the fraction.
  double fraction = 0;
  std::size_t checks_done = 0;
  std::size_t checks = 0;  // 0 until verify() knows them
  // What verify() does now, for people ("checking gripper x fixture",
  // "checking a x b: preparing body terrain (...)"); the wording is not
  // an interface.
  std::string activity;
  double seconds = 0;  // since verify() started
};

// Options of verify(), as the command line's (tmcert verify --help).
struct VerifyOptions {
  Kernel kernel = Kernel::Filtered;
  // Termination tolerance, a positive length, fixed (none: the scene's,
  // else each check's default epsilon, refined: its undecided parts
  // searched again at epsilon/10, ... down to epsilon/10^6, within the time
  // limit, else 30 s per check; "auto": refined from the default even when
  // the scene gives one).
  std::optional<Number> epsilon;
  // Subdivision depth limit, 1 to 200 (none: the scene's).
  std::optional<int> max_depth;
  // Worker threads, 1 to 256 (the result does not depend on it).
  int threads = 1;
  // Seconds per check, > 0 and at most 1e9 (none: 30 s for a refined check,
  // its first search included; none with a given epsilon).  Past it the rest
  // of a check's interval is undecided (reason Limit), never safe; the result then depends on the machine's speed.
  std::optional<double> time_limit;
  // Carry every feature pair from the start instead of the bounding-volume
  // hierarchies (the reference they are tested against; slow).
  bool all_pairs = false;
  // Keep what Result::certificate() needs (a certified kernel, and a scene
  // that certificates cover; otherwise verify() throws InputError).
  bool certificate = false;
  // Progress and cancellation.  When set, verify() calls it about every
  // `progress_interval` seconds from a thread of its own (never two calls
  // at once, none after verify() returns or throws), and once more from the
  // calling thread with fraction 1 just before it returns a result.
  // Returning false cancels the run: every check stops within about one
  // subdivision node's work (what it had not decided is never taken as
  // cleared) and verify() throws Cancelled instead of returning a result.
  // An exception thrown by the callback cancels the run the same way and
  // is rethrown by verify().  The callback runs while verify() works:
  // keep it short.
  std::function<bool(const Progress&)> progress;
  double progress_interval = 0.5;  // seconds, > 0 and at most 3600
};

// Verifies every check of `scene`.  Throws InputError for bad options or a
// scene that cannot be verified (a solid that is not closed, nothing to
// check), ResourceLimit when a resource limit leaves no honest answer,
// std::bad_alloc when memory runs out, Cancelled when the progress
// callback cancels the run.
TMCERT_API Result verify(const Scene& scene, const VerifyOptions& options = {});

}  // namespace tmcert::api

namespace tmcert {
using namespace api;
}
