// The scene reader's poses and motions (src/io/motion_reader.cpp): rigid
// poses in their three rotation forms, a rational Bezier curve kept as one
// motion, keyframes as segments (rational where exact), piecewise joins,
// and the messages of each kind of bad motion.
#include "src/io/scene_reader.h"

#include <boost/test/unit_test.hpp>

#include <string>
#include <utility>

using tmcert::Body;
using tmcert::Exact;
using tmcert::InputError;
namespace reader = tmcert::reader;

namespace {

// Reads `json` as a motion into a body.
Body motion_of(const std::string& json) {
  const reader::Tree tree = reader::parse_json(json, "m.json");
  const reader::SceneReader r("m.json", "", tree);
  Body b;
  r.motion(b, tree.root, reader::Path().member("motion"));
  return b;
}

std::string error_of(const std::string& json) {
  try {
    motion_of(json);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

BOOST_AUTO_TEST_SUITE(motion_reader)

BOOST_AUTO_TEST_CASE(poses_in_each_rotation_form) {
  const reader::Tree tree = reader::parse_json(
      R"([{"translation": [1, 2, "1/3"]}, {"rotation": {"quaternion": [1, 0, 0, 1]}},
          {"rotation": {"rpy": [0, 0, 0.5]}}, {"rotation": {"matrix": [[0,-1,0],[1,0,0],[0,0,1]]}},
          {"rotation": {"rpy": [0, 0, 90]}}])",
      "p.json");
  reader::SceneReader r("p.json", "", tree);
  const reader::Path doc;
  const auto items = r.array(tree.root, doc);
  const tmcert::Pose t = r.pose(items[0], doc.index(0));
  BOOST_TEST(t.translation[2] == Exact(1) / Exact(3));
  BOOST_TEST((t.rotation.kind == tmcert::Rotation::Kind::Identity));
  BOOST_TEST((r.pose(items[1], doc.index(1)).rotation.kind == tmcert::Rotation::Kind::Quaternion));
  BOOST_TEST((r.pose(items[2], doc.index(2)).rotation.kind == tmcert::Rotation::Kind::Rpy));
  BOOST_TEST((r.pose(items[3], doc.index(3)).rotation.kind == tmcert::Rotation::Kind::Matrix));
  BOOST_TEST(r.take_warnings().empty());
  r.pose(items[4], doc.index(4));  // 90 > 2 pi: read as radians, with a warning
  const std::vector<std::string> warnings = r.take_warnings();
  BOOST_REQUIRE(warnings.size() == 1u);
  BOOST_TEST(warnings[0].rfind("p.json: [4].rotation.rpy[2]: the angle 90 is more than 2 pi", 0) == 0);
}

BOOST_AUTO_TEST_CASE(rational_bezier_stays_one_motion) {
  const Body b = motion_of(R"({"type": "rational_bezier", "interval": [0, 2],
      "control_points": [[[1,0,0,0],[0,1,0,0],[0,0,1,0]], [[1,0,0,1],[0,1,0,0],[0,0,1,0]]]})");
  BOOST_REQUIRE(b.motion.has_value());
  BOOST_TEST(!b.trajectory.has_value());
  BOOST_TEST(b.motion->t1 == Exact(2));
  BOOST_TEST(b.motion->weights.size() == 2u);
}

BOOST_AUTO_TEST_CASE(keyframes_become_segments) {
  // Three poses: two segments; the translation-only first one is rational.
  const Body b = motion_of(R"({"type": "keyframes", "times": [0, 1, 3], "poses": [
      {}, {"translation": [1, 0, 0]}, {"translation": [1, 0, 0], "rotation": {"rpy": [0, 0, 1]}}]})");
  BOOST_REQUIRE(b.trajectory.has_value());
  BOOST_REQUIRE(b.trajectory->segments.size() == 2u);
  BOOST_TEST(b.trajectory->segments[0].rational.has_value());
  BOOST_TEST(!b.trajectory->segments[1].rational.has_value());  // slerp to an rpy rotation
  BOOST_TEST(b.trajectory->t1() == Exact(3));
  // Two poses with exact rotations under nlerp: one rational curve.
  const Body n = motion_of(R"({"type": "keyframes", "interpolation": "nlerp", "poses": [
      {}, {"rotation": {"quaternion": [1, 0, 0, 1]}}]})");
  BOOST_TEST(n.motion.has_value());
}

BOOST_AUTO_TEST_CASE(bad_motions_say_why) {
  BOOST_TEST(error_of(R"({"type": "spline"})") ==
             "m.json: motion.type: unknown motion type \"spline\" (supported: \"rational_bezier\", \"keyframes\", "
             "\"piecewise\")");
  BOOST_TEST(error_of(R"({"type": "keyframes", "interpolation": "linear", "poses": [{}, {}]})") ==
             "m.json: motion.interpolation: unknown interpolation \"linear\" (supported: \"slerp\", \"screw\", "
             "\"nlerp\")");
  BOOST_TEST(error_of(R"({"type": "keyframes", "times": [0, 0], "poses": [{}, {}]})") ==
             "m.json: motion.times[1]: times must be strictly increasing");
  const std::string piece = R"({"type": "keyframes", "times": [%0, %1], "poses": [{}, {"translation": [%2, 0, 0]}]})";
  auto keyframe_piece = [&](const char* t0, const char* t1, const char* x) {
    std::string s = piece;
    s.replace(s.find("%0"), 2, t0);
    s.replace(s.find("%1"), 2, t1);
    s.replace(s.find("%2"), 2, x);
    return s;
  };
  BOOST_TEST(error_of(R"({"type": "piecewise", "pieces": [)" + keyframe_piece("0", "1", "1") + ", " +
                      keyframe_piece("2", "3", "0") + "]}") ==
             "m.json: motion.pieces[1]: join with pieces[0]: the intervals do not abut (the previous piece ends at "
             "1, this one starts at 2)");
  BOOST_TEST(error_of(R"({"type": "piecewise", "pieces": [)" + keyframe_piece("0", "1", "1") + ", " +
                      keyframe_piece("1", "2", "0") + "]}") ==
             "m.json: motion.pieces[1]: join with pieces[0]: the poses differ at t = 1 (a jump)");
}

// A piecewise join where neither pose is exact (rpy): accepted when the
// segments' kinds give the poses as written and they are written the same,
// refused otherwise (SegmentKind::written_end).
BOOST_AUTO_TEST_CASE(rpy_joins_are_compared_as_written) {
  const std::string piece = R"({"type": "keyframes", "times": [%0, %1], "poses": [
      {"rotation": {"rpy": [%2, 0, 0]}}, {"rotation": {"rpy": [%3, 0, 0]}}]})";
  auto make = [&](const std::string& t0, const std::string& t1, const std::string& a, const std::string& b) {
    std::string out = piece;
    const std::pair<std::string, std::string> subs[] = {{"%0", t0}, {"%1", t1}, {"%2", a}, {"%3", b}};
    for (const auto& [key, value] : subs) out.replace(out.find(key), 2, value);
    return out;
  };
  const Body ok = motion_of(R"({"type": "piecewise", "pieces": [)" + make("0", "1", "0.1", "0.5") + ", " +
                            make("1", "2", "0.5", "0.2") + "]}");
  BOOST_TEST_REQUIRE(ok.trajectory.has_value());
  BOOST_TEST(ok.trajectory->segments.size() == 2);
  BOOST_TEST(error_of(R"({"type": "piecewise", "pieces": [)" + make("0", "1", "0.1", "0.5") + ", " +
                      make("1", "2", "0.4", "0.2") + "]}") ==
             "m.json: motion.pieces[1]: join with pieces[0]: the poses at t = 1 cannot be proven equal (an rpy pose "
             "must be written the same way on both sides)");
}

BOOST_AUTO_TEST_SUITE_END()
