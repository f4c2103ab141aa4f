// The certificate checker's motion kinds (src/certificate/motion_kinds.h):
// every kind the verifier knows (src/model/segment_kind.h) has a checker
// enclosure, and the checker, deciding the kind of a segment by itself,
// agrees with the verifier on every segment of a scene of every kind.
#include "src/certificate/motion_kinds.h"
#include "src/io/parse.h"
#include "src/model/segment_kind.h"

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <set>
#include <string>

BOOST_AUTO_TEST_SUITE(certificate_motion_kinds)

BOOST_AUTO_TEST_CASE(every_verifier_kind_has_a_checker_enclosure) {
  const std::vector<std::string> checker = tmcert::certificate::checker_kind_names();
  for (const tmcert::SegmentKind* kind : tmcert::segment_kinds()) {
    BOOST_TEST_INFO("kind " << kind->name());
    BOOST_TEST(std::count(checker.begin(), checker.end(), std::string(kind->name())) == 1);
  }
  BOOST_TEST(checker.size() == tmcert::segment_kinds().size());
}

BOOST_AUTO_TEST_CASE(checker_and_verifier_agree_on_each_segments_kind) {
  const std::string text = R"({"format": "tmcert-scene/1",
    "bodies": [{"name": "a", "points": [[0, 0, 0]], "motion": {"type": "keyframes", "times": [0, 1, 2], "poses": [
      {}, {"translation": [1, 0, 0]}, {"translation": [1, 0, 0], "rotation": {"rpy": [0, 0, 1]}}]}}],
    "robots": [{"name": "arm", "urdf": "chain.urdf", "joints": ["j1", "j2", "j3", "j4"],
                "path": {"times": [0, 2], "positions": [[0, 0, 0, 0], [0.5, 0.1, 0.25, 1]]}},
               {"name": "arm2", "urdf": "chain.urdf", "joints": ["j1", "j2", "j3", "j4"],
                "path": {"interpolation": "quintic", "times": [0, 1],
                         "positions": [[0, 0, 0, 0], [0.5, 0.1, 0.25, 1]],
                         "velocities": [[0, 0, 0, 0], [0.1, 0, 0, 0]],
                         "accelerations": [[0, 0, 0, 0], [0, 0, 0, 0]]}}]})";
  std::vector<tmcert::SceneRobot> robots;
  const tmcert::Scene scene =
      tmcert::parse_scene_text(text, "kinds.json", std::string(TMCERT_TEST_DATA) + "/robots", robots);
  int segments = 0;
  std::set<std::string> kinds;
  for (const tmcert::Body& b : scene.bodies)
    if (b.trajectory)
      for (const tmcert::MotionSegment& seg : b.trajectory->segments) {
        ++segments;
        kinds.insert(std::string(tmcert::kind_of(seg).name()));
        BOOST_TEST(tmcert::certificate::checker_kind_name(seg) == tmcert::kind_of(seg).name());
      }
  BOOST_TEST(segments >= 4);
  BOOST_TEST(kinds.size() == tmcert::segment_kinds().size());  // every kind met once at least
}

BOOST_AUTO_TEST_SUITE_END()
