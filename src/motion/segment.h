// The motions planners produce, as one interface the search needs: the
// pose at a parameter (exactly where it is rational, else enclosed) and
// second-order jets of the pose from which a piece's Taylor enclosure is
// built (src/motion/enclosure.h).  A new motion type is one class here.
// proofs/enclosures.md.
#pragma once

#include "kernels/jet.h"
#include "src/model/model.h"

#include <array>
#include <memory>
#include <optional>

namespace tmcert {

using PoseJet = std::array<Jet, 12>;              // [A | a] row-major
using PoseInterval = std::array<Interval, 12>;

// One motion segment over its own parameter s in [0, 1].
class SegmentModel {
 public:
  virtual ~SegmentModel() = default;
  // Jets of the pose at s (a point jet) or over an interval of s; the
  // result encloses the exact pose and its first two derivatives.  Call
  // under RoundingGuard.
  virtual PoseJet pose(const Jet& s) const = 0;
  // The value parts of pose(Jet(s)) (a constant jet: s a point or an
  // interval), the same intervals bit for bit, computed without the
  // derivatives where a model overrides it (the link chains: the same
  // interval operations in the same order).  An enclosure of the pose at
  // every parameter in s.  Call under RoundingGuard.  proofs/enclosures.md
  // section 2 ("Value parts"), proofs/robot-links.md section 4.
  virtual PoseInterval pose_values(const Interval& s) const {
    const PoseJet j = pose(Jet(s));
    PoseInterval out;
    for (int e = 0; e < 12; ++e) out[e] = j[e].v;
    return out;
  }
  // The exact pose at a rational s, when it is known exactly there (a
  // rational motion anywhere, a keyframe with an exact rotation at its
  // keyframe); nullopt otherwise.
  virtual std::optional<Mat34E> exact_pose(const Exact& s) const = 0;
};

// The model of a segment (rational or keyframe interpolation).
std::unique_ptr<SegmentModel> make_segment_model(const MotionSegment& segment);

// The model of a rational Bezier motion over its curve parameter.
std::unique_ptr<SegmentModel> make_bezier_model(const Motion& motion);

// ---------------------------------------------------------------- poses

// A quaternion proportional to the rotation (w, x, y, z), exactly, when the
// rotation is exact (identity, quaternion as written, matrix); nullopt for
// rpy.
std::optional<std::array<Exact, 4>> exact_quaternion(const Rotation& r);

// The unit quaternion of the rotation, enclosed (any sign).  Call under
// RoundingGuard.
std::array<Interval, 4> unit_quaternion(const Rotation& r);

// The pose as an exact 3x4 map, when its rotation is exact.
std::optional<Mat34E> exact_pose(const Pose& p);

// The pose enclosed.  Call under RoundingGuard.
PoseInterval interval_pose(const Pose& p);

// Why a matrix is not a rotation (not orthonormal, det != 1), or empty.
std::string rotation_matrix_problem(const std::array<Exact, 9>& m);

// The exact rational Bezier motion of the keyframe segment from `a` to
// `b` over [t0, t1], when it is one: nlerp between exact rotations (the
// quaternions as written; a degree-3 rational curve), or any interpolation
// between equal rotations (a translation).  nullopt otherwise.
std::optional<Motion> rational_keyframe_segment(const Pose& a, const Pose& b, Interpolation how, const Exact& t0,
                                                const Exact& t1);

// Throws InputError (message without a path) when the interpolation from
// `a` to `b` is not defined: slerp and screw between rotations exactly 180
// degrees apart, or whose shorter arc cannot be proven (rpy).
void require_interpolable(const Pose& a, const Pose& b, Interpolation how);

// Divides a rational Bezier motion's weights by one positive factor, which
// leaves the curve unchanged, so that they stay well inside the double
// range: weights beyond [2^-32, 2^32] (e.g. 1e400 or 1e-400, or |q|^2 of an
// nlerp quaternion of 1e300) become coprime integers (divided by the gcd of
// their numerators over the lcm of their denominators), and then, when the
// largest is still above 2^32, are divided by a power of two that brings it
// into (1/2, 2).  Weights within that range are left as they are.
// proofs/input-exactness.md.
void normalise_weights(Motion& m);

// A positive power of two f with max |q_i| f in (1/2, 2): the quaternion
// scaled by it has the same rotation and stays inside the double range
// (q nonzero).
Exact quaternion_scale(const std::array<Exact, 4>& q);

// The restriction of a rational Bezier motion to [t0, t1] inside its
// interval, exactly (de Casteljau at rational parameters).
Motion restrict_motion(const Motion& m, const Exact& t0, const Exact& t1);

// Exact pose of a rational Bezier motion at scene parameter t.
Mat34E motion_pose(const Motion& m, const Exact& t);

}  // namespace tmcert
