// Link motions of a kinematic chain under linear joint interpolation (URDF
// arms moving in joint space, SCENE_FORMAT.md "Robots from URDF"): the pose
// of a link frame is the product
//     C_0 J_1(q_1) C_1 J_2(q_2) ... J_n(q_n) C_n
// of constant poses C_k (base pose, joint origins, fixed joints, the
// collision origin; each a product of Poses with exact translations and
// exact or rpy rotations) and joint motions J_j: a rotation by q about a
// unit axis (revolute, continuous) or a translation by q along it
// (prismatic).  On a motion segment every q_j is linear in the segment
// parameter s between two waypoint values.  The pose is enclosed as jets
// (kernels/jet.h) in one pass from the base: every link's frame is its
// parent's times one joint, so the parent's enclosure is reused for the
// child within the pass.  proofs/robot-links.md section 4.
#pragma once

#include "src/model/chain.h"
#include "src/motion/segment.h"

#include <memory>
#include <optional>
#include <vector>

namespace tmcert {

// The verifier's preparation of a chain description: its constants and
// joint axes enclosed, once per description (of()), for the pose jets of
// every segment that uses the chain.  The exact questions (the rational
// pose, rational segments) are the description's (src/model/chain.h).
class LinkChain {
 public:
  explicit LinkChain(const ChainDescription& description);

  // The preparation of `description`, made on the first call and kept in
  // the description (ChainDescription::prepared).
  static std::shared_ptr<const LinkChain> of(const ChainDescription& description);

  // Jets of the pose for joint values q_j = from_j + (to_j - from_j) s,
  // given as intervals (from, delta).  Call under RoundingGuard.
  PoseJet pose(const std::vector<Interval>& from, const std::vector<Interval>& delta, const Jet& s) const;
  // The value parts of pose(from, delta, Jet(s)), bit for bit: the same
  // interval operations in the same order, without the derivatives (a
  // slice's box, a sampled pose).  Call under RoundingGuard.
  PoseInterval pose_values(const std::vector<Interval>& from, const std::vector<Interval>& delta,
                           const Interval& s) const;
  // Jets of the pose for joint values given as jets (one per joint, each
  // enclosing q_j and its derivatives in the segment parameter).  Call
  // under RoundingGuard.
  PoseJet pose(const std::vector<Jet>& values) const;

 private:
  struct Constant {
    PoseInterval enclosed;
    bool identity = false;
  };
  struct Prepared {
    ChainJoint joint;
    std::array<Interval, 3> unit;         // axis / |axis|, enclosed
    std::array<Interval, 9> cross;        // [u]x, rows
    std::array<Interval, 9> cross2;       // [u]x^2 = u u^T - I, from exact axis data
  };
  std::vector<Constant> constants_;
  std::vector<Prepared> joints_;
};

// The model of a link segment: linear joints, or cubic / quintic Hermite
// polynomials (LinkMotion::degree()).
std::unique_ptr<SegmentModel> make_link_model(const LinkMotion& motion);

}  // namespace tmcert
