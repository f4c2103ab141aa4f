// The motions planners produce, as one interface the search needs: the
// pose at a parameter (exactly where it is rational, else enclosed) and
// second-order jets of the pose from which a piece's Taylor enclosure is
// built (src/motion/enclosure.h).  A new motion type is one class here.
// proofs/enclosures.md.
#pragma once

#include "kernels/jet.h"
#include "src/model/model.h"
#include "src/model/pose_algebra.h"

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

// The pose enclosed.  Call under RoundingGuard.
PoseInterval interval_pose(const Pose& p);

// The restriction of a rational Bezier motion to [t0, t1] inside its
// interval, exactly (de Casteljau at rational parameters).
Motion restrict_motion(const Motion& m, const Exact& t0, const Exact& t1);

// Exact pose of a rational Bezier motion at scene parameter t.
Mat34E motion_pose(const Motion& m, const Exact& t);

}  // namespace tmcert
