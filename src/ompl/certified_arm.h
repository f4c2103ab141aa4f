// The certified OMPL motion validator for a URDF arm planned in joint
// space (ompl::base::RealVectorStateSpace, one dimension per moving joint):
// the straight segment between two states is the linear joint motion
// MoveIt and OMPL execute, and every link with collision geometry is
// certified against the fixed obstacles (and, with self-collision, against
// the other links) along it.  src/ompl/certified_motion_validator.h has
// the validator itself; proofs/ompl-validator.md the argument.
#pragma once

#include "src/ompl/certified_motion_validator.h"
#include "src/io/robot.h"

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace tmcert {

// Joint-space states of a placed robot: dimension k of a state is the
// position of joint `joints[k]` (every moving joint but the mimic joints,
// each once; a mimic joint follows its joint), read
// exactly as the double it is.  A segment's joint values are linear in the
// segment parameter (SCENE_FORMAT.md "Robots from URDF"); values outside a
// joint's <limit> make the segment uncertifiable (InputError: invalid).
class JointMotions final : public StateMotions {
 public:
  JointMotions(std::shared_ptr<const PlacedRobot> robot, std::vector<std::string> joints);
  std::vector<Trajectory> segment(const ompl::base::State* s1, const ompl::base::State* s2) const override;
  std::optional<std::vector<Mat34E>> exact_poses(const ompl::base::State* s) const override;

  // The movers: every part of every link with collision geometry (robot.h
  // LinkPart), as (link index, part index), and their bodies
  // "<robot>/<link>" (and "<robot>/<link>/collision[i]" for further parts).
  const std::vector<std::pair<int, std::size_t>>& movers() const { return movers_; }
  std::vector<Body> link_bodies() const;
  // Pairs of movers checked against each other: with `self_collision`, the
  // robot's default self-collision pairs (not parent and child, not in
  // `allowed_pairs`); else none.
  std::vector<std::pair<int, int>> self_pairs(
      bool self_collision, const std::vector<std::pair<std::string, std::string>>& allowed_pairs) const;

 private:
  std::vector<Exact> values(const ompl::base::State* s) const;  // per column, exactly

  std::shared_ptr<const PlacedRobot> robot_;
  std::vector<std::string> joints_;
  std::vector<std::pair<int, std::size_t>> movers_;
  std::vector<int> column_joints_;  // per column: its joint (index into the model's joints)
};

// Installs the certified validity checker and motion validator for `robot`
// among the fixed `obstacles` in si's RealVectorStateSpace, whose dimension
// k is joint `joints[k]` (throws InputError for any other space or a
// dimension mismatch), and returns the motion validator.  Call before
// si->setup().
std::shared_ptr<CertifiedMotionValidator> use_certified_arm(
    const ompl::base::SpaceInformationPtr& si, std::shared_ptr<const PlacedRobot> robot,
    std::vector<std::string> joints, Body obstacles, bool self_collision,
    const std::vector<std::pair<std::string, std::string>>& allowed_pairs, const VerifyOptions& options);

}  // namespace tmcert
