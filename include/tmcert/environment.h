// Many motions of one body against the same fixed obstacles: the obstacles
// and the moving body are prepared once (features, metric, bounding-volume
// hierarchies), and each motion costs only its own certified search.
//
//   const tmcert::Scene scene = tmcert::Scene::from_file("cell.json");   // or SceneBuilder
//   const tmcert::Environment env(scene, "gripper");
//   const tmcert::MotionResult r = env.certify(tmcert::Motion::translation({0, 0, 2}, {0, 0, 1}));
//   if (r.verdict == tmcert::Verdict::Safe) ...   // proven free of contact
//
// The scene gives the geometry: the moving body (its geometry in its own
// frame; its motion in the scene is ignored) and the obstacles, every other
// body of the scene, which must be fixed (a one-pose motion places one).
// The scene's checks are ignored.  Not supported (InputError): tolerances,
// clearances, URDF robots' links as the moving body, and a solid obstacle
// next to other obstacles.  These are the rules of the certified OMPL
// validator (tmcert/ompl.h), which certifies a planner's edges the same way.
//
// Options: as VerifyOptions say, with epsilon given, else the scene's,
// else 1/1000 of the diagonal of the box of everything the scene's bodies
// sweep, refined (undecided parts searched again at epsilon/10, ... down
// to epsilon/10^6, within time_limit, else 30 s for the whole check); "auto" refines even when
// the scene gives an epsilon.  The fast kernel is refused (not certified);
// threads and certificate are not used (a motion is one search).
//
// Thread safety: certify() may be called from several threads at once (as
// OMPL calls a validator from parallel planners); the calls run
// concurrently and give the results of sequential calls.  Each thread that
// certifies while all prepared copies are busy gets a copy prepared for it
// (once: copies are reused), so memory grows with the largest number of
// concurrent calls, not with the number of calls.
#pragma once

#include "tmcert/errors.h"
#include "tmcert/export.h"
#include "tmcert/motion.h"
#include "tmcert/numbers.h"
#include "tmcert/result.h"
#include "tmcert/scene.h"
#include "tmcert/verify.h"

#include <array>
#include <memory>
#include <optional>
#include <string>

namespace tmcert::api {

// The certified outcome of one motion against an Environment.
struct MotionResult {
  // Safe: proven free of contact over the motion's whole interval;
  // collision: proven contact (witness); undecided: neither.
  Verdict verdict = Verdict::Undecided;
  // Every parameter t with t0 <= t < safe_until is certified free (t0 the
  // motion's start); absent when the verdict is safe.
  std::optional<Rational> safe_until;
  // Brackets the earliest possible contact (absent when safe).
  std::optional<std::array<Rational, 2>> first_contact;
  // Of a collision: the two bodies (the moving body, and "obstacles" for
  // the obstacles together) and the witness (features name the parts).
  std::array<std::string, 2> bodies;
  std::optional<Witness> witness;
};

// Per-call options of Environment::certify.
struct CertifyOptions {
  // Only "safe or not", decided at the first proof of contact (what a
  // planner's validator asks): the motion's configurations at sampled
  // parameters and the slices of its segments are tested first, then the
  // searches run up to the first that is not safe.  The verdict is safe
  // exactly when it is without `decide`, and a collision is always proven;
  // but safe_until may be lower and first_contact may start at the
  // motion's start (proofs/sample-first.md, proofs/edge-slices.md).
  bool decide = false;
};

class TMCERT_API Environment {
 public:
  // Prepares the body `moving_body` of `scene` and the obstacles (every
  // other body).  Throws InputError (naming the field) for an unknown
  // body, no obstacle, an obstacle that moves, a tolerance or clearance,
  // bad options.
  Environment(const Scene& scene, const std::string& moving_body, const VerifyOptions& options = {});
  ~Environment();
  Environment(Environment&&) noexcept;
  Environment& operator=(Environment&&) noexcept;
  Environment(const Environment&) = delete;
  Environment& operator=(const Environment&) = delete;

  // Certifies the moving body along `motion` (any motion type, read with
  // the scene reader's checks and messages).  Throws InputError for a bad
  // motion, ResourceLimit when a resource limit leaves no honest answer.
  // Thread-safe (above).
  MotionResult certify(const Motion& motion, const CertifyOptions& options = {}) const;

  // How many prepared copies exist (at least 1): the largest number of
  // concurrent certify() calls so far.
  std::size_t prepared_copies() const;

  struct Impl;
  // Internal (src/api/shared_environment.h: the OMPL validator's
  // environments of several movers).
  explicit Environment(std::unique_ptr<Impl> impl);
  const Impl& impl() const { return *impl_; }

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace tmcert::api

namespace tmcert {
using namespace api;
}
