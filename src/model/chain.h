// A robot link's kinematic chain as data (SCENE_FORMAT.md "Robots from
// URDF"): the pose of the link frame is the product
//     C_0 J_1(q_1) C_1 J_2(q_2) ... J_n(q_n) C_n
// of constant poses C_k (each the product of a list of Poses) and joint
// motions J_j (a rotation by q about a unit axis, or a translation by q
// along it).  The description answers the exact questions (the rational
// pose at given joint values, whether a segment is a rational motion); the
// verifier's enclosures are prepared from it once (src/motion/chain.h,
// kept in prepared()), and the certificate checker (src/certificate/
// motions.cpp) makes its own evaluation from constant_poses() and joint().
// proofs/robot-links.md.
#pragma once

#include "src/model/model.h"

#include <cstddef>
#include <memory>
#include <mutex>
#include <optional>
#include <utility>
#include <vector>

namespace tmcert {

struct ChainJoint {
  enum class Kind { Revolute, Prismatic };
  Kind kind = Kind::Revolute;
  Vec3E axis;  // as written, nonzero; normalized (exactly or enclosed)
};

// The constants and joints of a chain, as given, with their exact parts.
// Immutable (prepared() fills its slot once, thread-safely).
class ChainDescription {
 public:
  // Throws std::invalid_argument unless constants.size() == joints.size()
  // + 1 and every axis is nonzero (callers validate first).
  ChainDescription(std::vector<std::vector<Pose>> constants, std::vector<ChainJoint> joints);
  ChainDescription(const ChainDescription&) = delete;
  ChainDescription& operator=(const ChainDescription&) = delete;

  std::size_t joint_count() const { return chain_joints_.size(); }
  // The constant poses as given (C_k is the product of its list, left to
  // right), for independent evaluations (the certificate checker).
  const std::vector<std::vector<Pose>>& constant_poses() const { return constant_poses_; }
  const ChainJoint& joint(std::size_t j) const { return chain_joints_[j]; }

  // C_k exactly, when every pose of its list is exact (exact_pose(Pose)).
  const std::optional<Mat34E>& exact_constant(std::size_t k) const { return exact_constants_[k]; }
  // Joint j's axis / |axis| exactly, when |axis| is rational.
  const std::optional<Vec3E>& exact_unit_axis(std::size_t j) const { return unit_axes_[j]; }
  // |axis|^2 of joint j, exactly.
  const Exact& axis_norm2(std::size_t j) const { return axis_norms2_[j]; }

  // The exact pose at joint values q (one per joint), when it is exact:
  // every constant exact, every revolute joint at q = 0, every prismatic
  // axis of rational length (or the joint at 0).  nullopt otherwise.
  std::optional<Mat34E> exact_pose(const std::vector<Exact>& q) const;

  // True when the pose is affine in the joint values of a segment from
  // `from` to `to` and exact at both ends (every revolute joint stays at 0):
  // the segment is then the rational degree-1 motion between its end poses.
  bool rational_between(const std::vector<Exact>& from, const std::vector<Exact>& to) const;

  // A layer above keeps its preparation of this chain here, made by
  // make(*this) on the first call and shared by every later one (the
  // verifier's enclosures, src/motion/chain.cpp: one preparation per chain
  // however many segments use it).  T must be the same type at every call.
  template <class T, class Make>
  std::shared_ptr<const T> prepared(Make make) const {
    std::call_once(prepared_once_, [&] { prepared_ = std::shared_ptr<const void>(make(*this)); });
    return std::static_pointer_cast<const T>(prepared_);
  }

 private:
  std::vector<std::vector<Pose>> constant_poses_;
  std::vector<ChainJoint> chain_joints_;
  std::vector<std::optional<Mat34E>> exact_constants_;
  std::vector<std::optional<Vec3E>> unit_axes_;
  std::vector<Exact> axis_norms2_;
  mutable std::once_flag prepared_once_;
  mutable std::shared_ptr<const void> prepared_;
};

// One segment of a link's motion: the chain, and the joint values (one per
// chain joint, in chain order) at s = 0 and s = 1.  The verifier prepares
// the chain's enclosures once per description (src/motion/chain.h).
//
// Linear (no rates): every q_j is linear in s between `from` and `to`.
// Cubic (`from_rate`, `to_rate`) and quintic (also `from_accel`,
// `to_accel`): every q_j follows the Hermite polynomial in scene time t
// with these values, first derivatives dq/dt and second derivatives
// d^2q/dt^2 at the segment's ends, over `duration` = t1 - t0 of the
// segment, as ros_control's joint_trajectory_controller interpolates
// (SCENE_FORMAT.md "Real robots as they ship"; proofs/trajectories.md).
struct LinkMotion {
  std::shared_ptr<const ChainDescription> chain;
  std::vector<Exact> from, to;
  std::vector<Exact> from_rate, to_rate;    // cubic and quintic: dq/dt, one per chain joint
  std::vector<Exact> from_accel, to_accel;  // quintic: d^2q/dt^2, one per chain joint
  Exact duration = 1;                       // cubic and quintic: t1 - t0 > 0
  // 1 (linear), 3 (cubic) or 5 (quintic).
  int degree() const { return !from_accel.empty() ? 5 : !from_rate.empty() ? 3 : 1; }
};

// The coefficients (constant first, degree() + 1 of them) in the segment
// parameter s in [0, 1] of joint j's polynomial on a segment with values
// p0, p1, rates v0, v1 and accelerations a0, a1 (zero for cubic) in time
// over `duration`, exactly: with D = duration v and A = duration^2 a,
//   cubic:   p0 + D0 s + (3 h - 2 D0 - D1) s^2 + (-2 h + D0 + D1) s^3,
//   quintic: p0 + D0 s + A0/2 s^2 + (10 h - 6 D0 - 4 D1 - (3 A0 - A1)/2) s^3
//            + (-15 h + 8 D0 + 7 D1 + (3 A0 - 2 A1)/2) s^4
//            + (6 h - 3 D0 - 3 D1 - (A0 - A1)/2) s^5,
// h = p1 - p0: the polynomial with these values and derivatives at s = 0
// and s = 1 (tests/model/test_hermite.cpp checks both ends exactly).
inline std::vector<Exact> hermite_coefficients(int degree, const Exact& p0, const Exact& p1, const Exact& v0,
                                               const Exact& v1, const Exact& a0, const Exact& a1,
                                               const Exact& duration) {
  const Exact h = p1 - p0, D0 = duration * v0, D1 = duration * v1;
  if (degree == 1) return {p0, h};
  if (degree == 3) return {p0, D0, 3 * h - 2 * D0 - D1, -2 * h + D0 + D1};
  const Exact A0 = duration * duration * a0, A1 = duration * duration * a1;
  return {p0,
          D0,
          A0 / 2,
          10 * h - 6 * D0 - 4 * D1 - (3 * A0 - A1) / 2,
          -15 * h + 8 * D0 + 7 * D1 + (3 * A0 - 2 * A1) / 2,
          6 * h - 3 * D0 - 3 * D1 - (A0 - A1) / 2};
}

// Joint j's coefficients on the segment (hermite_coefficients).
inline std::vector<Exact> link_joint_coefficients(const LinkMotion& m, std::size_t j) {
  const int d = m.degree();
  const Exact zero(0);
  return hermite_coefficients(d, m.from[j], m.to[j], d > 1 ? m.from_rate[j] : zero, d > 1 ? m.to_rate[j] : zero,
                              d > 3 ? m.from_accel[j] : zero, d > 3 ? m.to_accel[j] : zero, m.duration);
}

}  // namespace tmcert
