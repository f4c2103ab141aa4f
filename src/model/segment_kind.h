// The open motion model: the kinds of motion segment (README
// "Architecture", "Motion kinds").
//
// A segment of a body's trajectory (model.h MotionSegment) is of one kind:
// a rational Bezier curve, a keyframe interpolation (slerp, screw, nlerp),
// a robot link on a linear joint path, a robot link on a cubic or quintic
// joint trajectory (robot_link_hermite).  Each kind implements SegmentKind;
// the registry lists them, and whatever depends on the kind asks it
// instead of testing the segment's fields:
//   * here (model/): its name, whether a segment is of it, its scene
//     interval, its exact rational Bezier form when it is one, and its
//     exact pose at the segment's ends when that is known;
//   * the verifier's enclosures of the kind (jets over a parameter
//     interval, the pose at the ends enclosed) extend it in
//     src/motion/segment_kinds.h;
//   * the certificate checker has its own enclosure of every kind, found
//     by the kind's name (src/certificate/motion_kinds.h), and a test that
//     none is missing (tests/certificate/test_motion_kinds.cpp).
// The registry's entries are defined beside their enclosures
// (src/motion/segment_kinds.cpp): code of model/ and io/ reaches them
// through this declaration only.
#pragma once

#include "src/model/model.h"

#include <optional>
#include <string_view>
#include <utility>
#include <vector>

namespace tmcert {

class SegmentKind {
 public:
  virtual ~SegmentKind() = default;
  // The kind's name, unique; the checker finds its own enclosure by it.
  virtual std::string_view name() const = 0;
  // Whether `seg` is of this kind (the registry asks the kinds in order).
  virtual bool holds(const MotionSegment& seg) const = 0;
  // The segment's scene interval [t0, t1].
  std::pair<Exact, Exact> interval(const MotionSegment& seg) const { return {seg.t0, seg.t1}; }
  // The segment's exact rational Bezier form (over its scene interval),
  // when it is one; null otherwise.
  virtual const Motion* rational(const MotionSegment& seg) const = 0;
  // The exact pose at the segment's end (`last`) or start, when it is
  // known exactly there; nullopt otherwise.
  virtual std::optional<Mat34E> exact_end(const MotionSegment& seg, bool last) const = 0;
  // The pose at the segment's end (`last`) or start as the scene writes
  // it (a keyframe's pose), when the kind is given by such poses; null
  // otherwise.  Two ends written the same way are the same pose even
  // where neither is exact (rpy).
  virtual const Pose* written_end(const MotionSegment&, bool) const { return nullptr; }
};

// Every kind, in the order they are asked (src/motion/segment_kinds.cpp).
const std::vector<const SegmentKind*>& segment_kinds();

// The kind of a segment: the first of segment_kinds() that holds it.
const SegmentKind& kind_of(const MotionSegment& seg);

}  // namespace tmcert
