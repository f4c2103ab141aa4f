// A robot link's kinematic chain as data (SCENE_FORMAT.md "Robots from
// URDF"): the pose of the link frame is the product
//     C_0 J_1(q_1) C_1 J_2(q_2) ... J_n(q_n) C_n
// of constant poses C_k (each the product of a list of Poses) and joint
// motions J_j (a rotation by q about a unit axis, or a translation by q
// along it).  Both the verifier (src/motion/chain.h, which prepares the
// chain's enclosures) and the certificate checker (src/certificate/
// motions.cpp, its own evaluation) read it.  proofs/robot-links.md.
#pragma once

#include "src/model/model.h"

#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

namespace tmcert {

struct ChainJoint {
  enum class Kind { Revolute, Prismatic };
  Kind kind = Kind::Revolute;
  Vec3E axis;  // as written, nonzero; normalized (exactly or enclosed)
};

// The constants and joints of a chain, as given.
class ChainDescription {
 public:
  // constants.size() == joints.size() + 1 (LinkChain checks).
  ChainDescription(std::vector<std::vector<Pose>> constants, std::vector<ChainJoint> joints)
      : constant_poses_(std::move(constants)), chain_joints_(std::move(joints)) {}
  virtual ~ChainDescription() = default;

  std::size_t joint_count() const { return chain_joints_.size(); }
  // The constant poses as given (C_k is the product of its list, left to
  // right), for independent evaluations (the certificate checker).
  const std::vector<std::vector<Pose>>& constant_poses() const { return constant_poses_; }
  const ChainJoint& joint(std::size_t j) const { return chain_joints_[j]; }

 private:
  std::vector<std::vector<Pose>> constant_poses_;
  std::vector<ChainJoint> chain_joints_;
};

// One segment of a link's motion: the chain, and the joint values (one per
// chain joint, in chain order) at s = 0 and s = 1.  The verifier's chains
// are LinkChains (src/motion/chain.h), prepared once per link.
struct LinkMotion {
  std::shared_ptr<const ChainDescription> chain;
  std::vector<Exact> from, to;
};

}  // namespace tmcert
