// The motion kinds (src/model/segment_kind.h, src/motion/segment_kinds.cpp):
// every segment a scene can hold has exactly the kind that holds it, the
// names are unique, and each kind's exact ends and enclosures agree with
// the segment's own definition.
#include "src/motion/segment_kinds.h"

#include "src/io/parse.h"

#include <boost/test/unit_test.hpp>

#include <set>
#include <string>

using tmcert::Exact;
using tmcert::MotionSegment;

namespace {

// The segments of every body of a scene with a rational keyframe segment,
// an rpy (enclosed) one, a robot moving along a linear joint path and one
// along a cubic trajectory.
std::vector<MotionSegment> sample_segments() {
  const std::string text = R"({"format": "tmcert-scene/1",
    "bodies": [{"name": "a", "points": [[0, 0, 0]], "motion": {"type": "keyframes", "times": [0, 1, 2], "poses": [
      {}, {"translation": [1, 0, 0]}, {"translation": [1, 0, 0], "rotation": {"rpy": [0, 0, 1]}}]}}],
    "robots": [{"name": "arm", "urdf": "chain.urdf", "joints": ["j1", "j2", "j3", "j4"],
                "path": {"times": [0, 2], "positions": [[0, 0, 0, 0], [0.5, 0.1, 0.25, 1]]}},
               {"name": "arm2", "urdf": "chain.urdf", "joints": ["j1", "j2", "j3", "j4"],
                "path": {"times": [0, 2], "interpolation": "cubic", "positions": [[0, 0, 0, 0], [0.5, 0.1, 0.25, 1]],
                         "velocities": [[0, 0, 0, 0], [0, 0, 0, 0]]}}]})";
  std::vector<tmcert::SceneRobot> robots;
  const tmcert::Scene scene =
      tmcert::parse_scene_text(text, "kinds.json", std::string(TMCERT_TEST_DATA) + "/robots", robots);
  std::vector<MotionSegment> out;
  for (const tmcert::Body& b : scene.bodies)
    if (b.trajectory) out.insert(out.end(), b.trajectory->segments.begin(), b.trajectory->segments.end());
  return out;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(segment_kinds)

BOOST_AUTO_TEST_CASE(names_are_unique_and_every_segment_has_one_kind) {
  std::set<std::string> names;
  for (const tmcert::SegmentKind* kind : tmcert::segment_kinds()) BOOST_TEST(names.insert(std::string(kind->name())).second);
  BOOST_TEST(names == (std::set<std::string>{"rational_bezier", "keyframe", "robot_link", "robot_link_hermite"}));
  std::set<std::string> seen;
  for (const MotionSegment& seg : sample_segments()) {
    int holders = 0;
    for (const tmcert::SegmentKind* kind : tmcert::segment_kinds()) holders += kind->holds(seg) ? 1 : 0;
    BOOST_TEST(holders == 1);
    seen.insert(std::string(tmcert::kind_of(seg).name()));
    BOOST_TEST((tmcert::kind_of(seg).rational(seg) != nullptr) == seg.rational.has_value());
    BOOST_TEST((tmcert::kind_of(seg).interval(seg) == std::pair<Exact, Exact>{seg.t0, seg.t1}));
  }
  BOOST_TEST(seen == names);  // the sample covers every kind
}

BOOST_AUTO_TEST_CASE(exact_ends_lie_in_the_enclosures_and_agree_with_the_models) {
  for (const MotionSegment& seg : sample_segments()) {
    const tmcert::VerifiedSegmentKind& kind = tmcert::verified_kind_of(seg);
    const std::unique_ptr<tmcert::SegmentModel> model = kind.model(seg);
    for (const bool last : {false, true}) {
      const tmcert::PoseInterval box = kind.enclosed_end(seg, last);
      const std::optional<tmcert::Mat34E> exact = kind.exact_end(seg, last);
      if (seg.rational) {
        BOOST_REQUIRE(exact.has_value());
        BOOST_TEST((*exact == tmcert::motion_pose(*seg.rational, last ? seg.t1 : seg.t0)));
      }
      if (!exact) continue;
      BOOST_TEST((model->exact_pose(Exact(last ? 1 : 0)) == exact));
      for (int e = 0; e < 12; ++e) {
        BOOST_TEST(box[e].inf() <= CGAL::to_double((*exact)[e]));
        BOOST_TEST(CGAL::to_double((*exact)[e]) <= box[e].sup());
      }
    }
  }
}

BOOST_AUTO_TEST_SUITE_END()
