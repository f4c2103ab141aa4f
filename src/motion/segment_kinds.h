// The verifier's side of the motion kinds (src/model/segment_kind.h): each
// kind's enclosures, for the search.  The kinds themselves are defined in
// segment_kinds.cpp, one class per kind beside its enclosure
// (proofs/enclosures.md):
//   rational_bezier  BezierModel (segment.cpp)
//   keyframe         KeyframeModel (segment.cpp)
//   robot_link       the link's chain model (chain.cpp)
//   robot_link_hermite  the link's chain model on Hermite joint polynomials (chain.cpp)
#pragma once

#include "src/model/segment_kind.h"
#include "src/motion/segment.h"

#include <memory>

namespace tmcert {

class VerifiedSegmentKind : public SegmentKind {
 public:
  // The model of the segment over its own parameter s in [0, 1]: jets of
  // the pose, exact poses where known.
  virtual std::unique_ptr<SegmentModel> model(const MotionSegment& seg) const = 0;
  // The pose at the segment's end (`last`) or start, enclosed (a point
  // interval where it is exact).  Call outside any rounding guard.
  virtual PoseInterval enclosed_end(const MotionSegment& seg, bool last) const = 0;
};

// The kind of a segment (kind_of), with its enclosures.
const VerifiedSegmentKind& verified_kind_of(const MotionSegment& seg);

// The model of a keyframe interpolation from `a` to `b` (not rational).
std::unique_ptr<SegmentModel> make_keyframe_model(const Pose& a, const Pose& b, Interpolation how);

}  // namespace tmcert
