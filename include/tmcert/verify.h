// Certified verification of a scene's checks.
#pragma once

#include "tmcert/export.h"
#include "tmcert/numbers.h"
#include "tmcert/result.h"
#include "tmcert/scene.h"

#include <optional>

namespace tmcert::api {

// Options of verify(), as the command line's (tmcert verify --help).
struct VerifyOptions {
  Kernel kernel = Kernel::Filtered;
  // Termination tolerance, a positive length (none: the scene's, else the
  // default epsilon).
  std::optional<Number> epsilon;
  // Subdivision depth limit, 1 to 200 (none: the scene's).
  std::optional<int> max_depth;
  // Worker threads, 1 to 256 (the result does not depend on it).
  int threads = 1;
  // Seconds per check, > 0 and at most 1e9 (none: no limit).  Past it the
  // rest of a check's interval is undecided (reason Limit), never safe; the
  // result then depends on the machine's speed.
  std::optional<double> time_limit;
  // Carry every feature pair from the start instead of the bounding-volume
  // hierarchies (the reference they are tested against; slow).
  bool all_pairs = false;
  // Keep what Result::certificate() needs (a certified kernel, and a scene
  // that certificates cover; otherwise verify() throws InputError).
  bool certificate = false;
};

// Verifies every check of `scene`.  Throws InputError for bad options or a
// scene that cannot be verified (a solid that is not closed, nothing to
// check), ResourceLimit when a resource limit leaves no honest answer,
// std::bad_alloc when memory runs out.
TMCERT_API Result verify(const Scene& scene, const VerifyOptions& options = {});

}  // namespace tmcert::api

namespace tmcert {
using namespace api;
}
