// The motion kinds (src/model/segment_kind.h, src/motion/segment_kinds.h):
// one class per kind, and the registry.  Adding a kind: its data in
// MotionSegment (model.h), a class here with its model (the enclosure of
// proofs/enclosures.md), its reader (src/io/motion_reader.cpp), its
// checker enclosure (src/certificate/motions.cpp); README "Architecture".
#include "src/motion/segment_kinds.h"

#include "src/motion/chain.h"
#include "src/motion/enclosure.h"

namespace tmcert {

namespace {

// A rational Bezier curve (Motion): exact everywhere.
class RationalBezierKind final : public VerifiedSegmentKind {
 public:
  std::string_view name() const override { return "rational_bezier"; }
  bool holds(const MotionSegment& seg) const override { return seg.rational.has_value(); }
  const Motion* rational(const MotionSegment& seg) const override { return &*seg.rational; }
  // The curve's values at its ends are its first and last control points.
  std::optional<Mat34E> exact_end(const MotionSegment& seg, bool last) const override {
    return last ? seg.rational->control_points.back() : seg.rational->control_points.front();
  }
  std::unique_ptr<SegmentModel> model(const MotionSegment& seg) const override {
    return make_bezier_model(*seg.rational);
  }
  PoseInterval enclosed_end(const MotionSegment& seg, bool last) const override {
    const Mat34E m = *exact_end(seg, last);
    PoseInterval out;
    for (int e = 0; e < 12; ++e) out[e] = to_interval(m[e]);
    return out;
  }
};

// The interpolation of two keyframe poses that is not rational (slerp and
// screw between different rotations, nlerp between rotations not given
// exactly): exact at its ends where their rotations are exact.
class KeyframeKind final : public VerifiedSegmentKind {
 public:
  std::string_view name() const override { return "keyframe"; }
  bool holds(const MotionSegment& seg) const override { return !seg.rational && !seg.link; }
  const Motion* rational(const MotionSegment&) const override { return nullptr; }
  std::optional<Mat34E> exact_end(const MotionSegment& seg, bool last) const override {
    return exact_pose(last ? seg.to : seg.from);
  }
  const Pose* written_end(const MotionSegment& seg, bool last) const override { return last ? &seg.to : &seg.from; }
  std::unique_ptr<SegmentModel> model(const MotionSegment& seg) const override {
    return make_keyframe_model(seg.from, seg.to, seg.interpolation);
  }
  PoseInterval enclosed_end(const MotionSegment& seg, bool last) const override {
    RoundingGuard guard;
    return interval_pose(last ? seg.to : seg.from);
  }
};

// A robot link (src/motion/chain.h LinkMotion) that is not rational: exact
// at a waypoint where its chain is.  The two kinds below differ only in
// the degree of the joints' polynomials.
class RobotLinkKindBase : public VerifiedSegmentKind {
 public:
  const Motion* rational(const MotionSegment&) const override { return nullptr; }
  std::optional<Mat34E> exact_end(const MotionSegment& seg, bool last) const override {
    return make_link_model(*seg.link)->exact_pose(Exact(last ? 1 : 0));
  }
  std::unique_ptr<SegmentModel> model(const MotionSegment& seg) const override {
    return make_link_model(*seg.link);
  }
  PoseInterval enclosed_end(const MotionSegment& seg, bool last) const override {
    return enclose_pose(*make_link_model(*seg.link), Exact(last ? 1 : 0));
  }
};

// On a linear joint path.
class RobotLinkKind final : public RobotLinkKindBase {
 public:
  std::string_view name() const override { return "robot_link"; }
  bool holds(const MotionSegment& seg) const override {
    return !seg.rational && seg.link != nullptr && seg.link->degree() == 1;
  }
};

// On cubic or quintic Hermite polynomials in time (a trajectory as
// controllers execute it); never rational.
class RobotLinkHermiteKind final : public RobotLinkKindBase {
 public:
  std::string_view name() const override { return "robot_link_hermite"; }
  bool holds(const MotionSegment& seg) const override {
    return !seg.rational && seg.link != nullptr && seg.link->degree() > 1;
  }
};

const RationalBezierKind kRationalBezier;
const KeyframeKind kKeyframe;
const RobotLinkKind kRobotLink;
const RobotLinkHermiteKind kRobotLinkHermite;

const std::vector<const VerifiedSegmentKind*>& verified_kinds() {
  static const std::vector<const VerifiedSegmentKind*> kinds = {&kRationalBezier, &kRobotLink, &kRobotLinkHermite, &kKeyframe};
  return kinds;
}

}  // namespace

const std::vector<const SegmentKind*>& segment_kinds() {
  static const std::vector<const SegmentKind*> kinds(verified_kinds().begin(), verified_kinds().end());
  return kinds;
}

const VerifiedSegmentKind& verified_kind_of(const MotionSegment& seg) {
  for (const VerifiedSegmentKind* kind : verified_kinds())
    if (kind->holds(seg)) return *kind;
  return kKeyframe;  // not reached: the keyframe kind holds what the others do not
}

const SegmentKind& kind_of(const MotionSegment& seg) { return verified_kind_of(seg); }

}  // namespace tmcert
