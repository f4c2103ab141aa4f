// Many motions of the same bodies against the same fixed environment (a
// planner's edges): every body is prepared once (features, metric,
// hierarchy), and each motion costs only its own search.  The certified
// OMPL motion validator (src/ompl/) is built on it.
#pragma once

#include "kernels/static_intersection.h"
#include "src/verify/verify.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <optional>
#include <utility>
#include <vector>

namespace tmcert {

// The result of one motion of the movers: every mover against the
// environment, and the listed mover pairs against each other.
struct MotionCheck {
  // Safe only when every check is safe; collision when one is (with its
  // witness); else undecided.
  Verdict verdict = Verdict::Safe;
  // Every parameter t with t0 <= t < safe_until is certified free for every
  // check (t0: the motions' start); absent when the whole interval is
  // (verdict safe).  It is the smallest lower end of the checks'
  // first-contact brackets: t0 itself when the start is not certified.
  std::optional<Exact> safe_until;
  // Of the check that decided the verdict (the collision, or the first
  // undecided check).
  std::optional<Witness> witness;
  std::optional<std::pair<Exact, Exact>> first_contact;
  // CheckResult::bodies index FixedEnvironment::bodies(): 0 is the
  // environment, 1 + k is mover k.
  std::vector<CheckResult> checks;
};

class PreparedBody;
struct EnvironmentIndex;

// A body's simplices by their distinct vertices: each vertex's interval
// enclosure once, and per part, per simplex, its corners' indices.
struct LocalVertices {
  std::vector<std::array<Interval, 3>> vertices;
  std::vector<std::vector<std::array<std::uint32_t, 3>>> index;
};

class FixedEnvironment {
 public:
  // `environment`: the fixed obstacles as one body (no motion, or a
  // one-pose motion); `movers`: the moving bodies' geometry in their own
  // frames (their motions, if any, are ignored); `mover_pairs`: pairs of
  // movers (indices into `movers`) also checked against each other.
  // Solids as in scenes: a component of one body inside a solid one at the
  // start is a collision (exact when both start poses are exact; with an
  // enclosed start pose, e.g. a robot link, only disjoint boxes settle it,
  // else the check is undecided).  No tolerances.  options.epsilon must be
  // given and > 0.  Throws InputError otherwise.
  FixedEnvironment(Body environment, std::vector<Body> movers, std::vector<std::pair<int, int>> mover_pairs,
                   const VerifyOptions& options);
  ~FixedEnvironment();
  FixedEnvironment(const FixedEnvironment&) = delete;
  FixedEnvironment& operator=(const FixedEnvironment&) = delete;

  // Certifies the movers moving along `motions` (one per mover, all over
  // the same parameter interval).  Serialized: calls from several threads
  // wait for each other (the movers' motions are set in place).
  MotionCheck check(const std::vector<Trajectory>& motions) const;

  // The same question for a planner's validator, which needs only "safe"
  // or "not safe", decided at the first proof of contact
  // (proofs/sample-first.md): first the exact static test of each pair the
  // boxes do not clear at kSampledParameters sampled parameters
  // (src/verify/sample_first.h); a contact there is the verdict, with a
  // check that claims nothing before its witness (undecided "limit") nor
  // after it (not searched).  Else the checks of check(), in order, up to
  // the first that is not safe (the later ones are not run: `checks` holds
  // those run).  Safe exactly when check() is safe; a collision is always
  // proven; safe_until may be lower than check()'s.
  MotionCheck decide(const std::vector<Trajectory>& motions) const;
  static constexpr std::size_t kSampledParameters = 9;
  // The slices of each motion segment whose boxes are tested against the
  // environment before any search (proofs/edge-slices.md).
  static constexpr int kSlices = 16;

  // The exact static test of the movers at exact poses (one per mover):
  // a witness (t = 0) when a mover touches the environment or a listed
  // mover pair touches (a solid's inside included), else nothing (the
  // configuration is certified free).
  std::optional<Witness> static_contact(const std::vector<Mat34E>& poses) const;

  // Some body is a URDF cylinder or sphere (Body::primitive): its static
  // contacts are the polyhedron's (static_contact says nothing about the
  // true shape; check() proves a collision on it).
  bool has_primitives() const {
    for (const Body& b : bodies_)
      if (b.primitive) return true;
    return false;
  }

  // 0: the environment, 1 + k: mover k (for CheckResult::bodies).
  const std::vector<Body>& bodies() const { return bodies_; }
  const VerifyOptions& options() const { return options_; }

 private:
  MotionCheck run(const std::vector<Trajectory>& motions, bool decide) const;

  mutable std::vector<Body> bodies_;  // the movers' motions change per check (under mutex_)
  std::vector<std::pair<int, int>> pairs_;  // indices into bodies_
  VerifyOptions options_;
  std::vector<std::unique_ptr<PreparedBody>> prepared_;
  // The environment's simplices enclosed once, in a box tree: the exact
  // static test of a mover's configuration against it (the start of every
  // motion, static_contact) touches only the simplices near the mover.
  std::unique_ptr<EnvironmentIndex> index_;
  // Per body, in its own frame: its vertices, and one vertex per connected
  // component with its feature name (the containment of solids).
  std::vector<std::vector<Vec3E>> vertices_;
  // Per body, its distinct vertices enclosed once (the edge's slices,
  // src/verify/edge_slices.h).
  std::vector<std::vector<std::array<Interval, 3>>> enclosed_;
  // Per body, the interval box of those enclosures (the slices' coarse
  // boxes, edge_slices.h SliceFilter).
  std::vector<std::array<Interval, 3>> bounds_;
  // Per body, per part, its simplices' coordinates enclosed once (the
  // static test places them by the pose's interval map).
  std::vector<std::vector<std::vector<SimplexI>>> local_;
  std::vector<LocalVertices> shared_;  // the same enclosures, by distinct vertex
  std::vector<std::vector<std::pair<std::string, Vec3E>>> representatives_;
  mutable std::mutex mutex_;
};

}  // namespace tmcert
