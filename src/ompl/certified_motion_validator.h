// A certified motion validator for OMPL (ompl::base::MotionValidator):
// checkMotion(s1, s2) is true only when tmcert proves the straight segment
// from s1 to s2, the motion OMPL interpolates, free of contact with a fixed
// environment.  A segment that is undecided (within epsilon of contact, or
// out of budget), that tmcert cannot interpolate (two SE(3) rotations
// exactly 180 degrees apart: no shorter arc) or whose states are not finite
// counts as invalid: an edge is accepted only when it is proven safe.
// See README.md "Plugging tmcert into an OMPL planner" and
// proofs/ompl-validator.md for what exactly is certified.
//
// The environment is a public tmcert::Environment (include/tmcert/
// environment.h) made of the obstacles and the movers (src/api/
// shared_environment.h: the public one of any movers and mover pairs).
//
// Thread safety: the validator may be called from several threads at once;
// each call certifies on a prepared copy of the environment no other call
// uses (as Environment::certify), with the results of sequential calls.
// OMPL's own valid/invalid counters are plain integers.
#pragma once

#include "src/api/shared_environment.h"

#include <ompl/base/MotionValidator.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/StateValidityChecker.h>

#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace tmcert {

// How the states of one OMPL state space become motions of tmcert bodies.
class StateMotions {
 public:
  virtual ~StateMotions() = default;
  // The movers' motions over [0, 1] along OMPL's straight segment from
  // `s1` (t = 0) to `s2` (t = 1), with every number of the states taken
  // exactly.  Throws InputError when the segment has no certified meaning
  // (non-finite numbers, a zero quaternion, no shorter arc).
  virtual std::vector<Trajectory> segment(const ompl::base::State* s1, const ompl::base::State* s2) const = 0;
  // The movers' exact poses at a state, when they are exact (SE(3)
  // states); nullopt otherwise (then a state is certified as the segment
  // from it to itself).  Throws InputError as segment().
  virtual std::optional<std::vector<Mat34E>> exact_poses(const ompl::base::State* s) const = 0;
};

// Rigid bodies in ompl::base::SE3StateSpace (one mover): the state's
// translation (x, y, z) and its quaternion (w, x, y, z) are read exactly as
// the doubles they are (no rounding, no normalization: the rotation is
// that of q / |q|, computed exactly); the segment is translation linear,
// rotation slerp of the unit quaternions along the shorter arc at constant
// angular speed, as SO3StateSpace::interpolate computes it (in doubles).
class SE3Motions final : public StateMotions {
 public:
  std::vector<Trajectory> segment(const ompl::base::State* s1, const ompl::base::State* s2) const override;
  std::optional<std::vector<Mat34E>> exact_poses(const ompl::base::State* s) const override;
  // The pose of an SE(3) state, exactly.  Throws InputError.
  static Pose pose(const ompl::base::State* s);
};

// The outcome of certifying one state or segment.
struct EdgeCertificate {
  // Safe: proven free; collision: proven contact (witness); undecided:
  // neither (also when the segment has no certified meaning: `problem`).
  MotionCheck check;
  std::string problem;  // why the segment could not be certified at all
};

class CertifiedMotionValidator final : public ompl::base::MotionValidator {
 public:
  // `environment` holds the fixed obstacles and the movers' geometry
  // (shared_environment); `motions` maps the states of si's space to the
  // movers' motions.
  CertifiedMotionValidator(const ompl::base::SpaceInformationPtr& si,
                           std::shared_ptr<const api::Environment> environment,
                           std::shared_ptr<const StateMotions> motions);

  // True only when the segment from s1 to s2 is certified safe (both end
  // states included: the search covers the closed interval [0, 1] and
  // starts with an exact static test at t = 0).
  bool checkMotion(const ompl::base::State* s1, const ompl::base::State* s2) const override;
  // As above; when false, lastValid gets a state and its fraction such
  // that the segment from s1 to that state (as OMPL computed it) is itself
  // certified safe: the fraction starts below the certified first-contact
  // bracket and is halved until that shorter segment certifies; if none
  // does, s1 and 0 (s1 is then certified free unless the contact is at
  // t = 0 itself, where OMPL's precondition "s1 is valid" was violated).
  bool checkMotion(const ompl::base::State* s1, const ompl::base::State* s2,
                   std::pair<ompl::base::State*, double>& lastValid) const override;

  // The full result for the segment (or, with s1 == s2 as states, the state).
  EdgeCertificate certify(const ompl::base::State* s1, const ompl::base::State* s2) const;
  // What checkMotion(s1, s2) runs: safe exactly when certify() is, but a
  // collision is decided at the first proof of contact
  // (CertifyOptions::decide: sampled configurations first), so its
  // first-contact bracket may start at 0 and its checks stop at the first
  // that is not safe.
  EdgeCertificate decide(const ompl::base::State* s1, const ompl::base::State* s2) const;
  // A state certified free (exact static test, or the segment to itself).
  EdgeCertificate certify_state(const ompl::base::State* s) const;

  const api::Environment& environment() const { return *environment_; }
  // Its prepared copies (the bodies' names: pool().labels()).
  const EnvironmentPool& pool() const { return pool_; }

 private:
  EdgeCertificate run(const ompl::base::State* s1, const ompl::base::State* s2, bool decide) const;

  std::shared_ptr<const api::Environment> environment_;
  const EnvironmentPool& pool_;  // environment_'s
  std::shared_ptr<const StateMotions> motions_;
};

// A state validity checker with the same guarantee: isValid(s) only when
// the movers at s are certified free of the environment.
class CertifiedStateValidityChecker final : public ompl::base::StateValidityChecker {
 public:
  CertifiedStateValidityChecker(const ompl::base::SpaceInformationPtr& si,
                                std::shared_ptr<const CertifiedMotionValidator> validator);
  bool isValid(const ompl::base::State* s) const override;

 private:
  std::shared_ptr<const CertifiedMotionValidator> validator_;
};

// Installs the certified validity checker and motion validator for a rigid
// body `robot` (geometry in its own frame) among the fixed `obstacles` in
// si's SE3StateSpace (throws InputError for any other space), and returns
// the motion validator.  Call before si->setup().
std::shared_ptr<CertifiedMotionValidator> use_certified_se3(const ompl::base::SpaceInformationPtr& si, Body robot,
                                                            Body obstacles, const VerifyOptions& options);

}  // namespace tmcert
