// The public C++ API (include/tmcert/), used as a user would: linked
// against the shared library only, with only <tmcert/...> headers.
//  * builder vs reader: the same scene built in code and read from its
//    tmcert-scene/1 text gives the same result, for every motion type;
//  * doubles are exact: 0.1 as a double is not 1/10;
//  * every builder and option error is a tmcert::InputError naming the field;
//  * the doubles of a result agree with its exact values (nearest double);
//  * Result::to_json is the document `tmcert verify --json` prints, and a
//    certificate of a result holds.
#define BOOST_TEST_MODULE tmcert_api
#include <boost/test/unit_test.hpp>

#include <tmcert/tmcert.h>

#include <gmp.h>

#include <cmath>
#include <stdexcept>
#include <cstdio>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <functional>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace {

const std::string kExamples = TMCERT_EXAMPLES;

// A result document without its "seconds" lines (the one thing in it that
// is not deterministic).
std::string without_seconds(const std::string& json) {
  std::istringstream in(json);
  std::string line, out;
  while (std::getline(in, line))
    if (line.find("\"seconds\"") == std::string::npos) out += line + "\n";
  return out;
}

// Verifies the builder's scene and the scene read from `json`; both must
// give the same result document, with verdict `expected`.
void same_result(const tmcert::SceneBuilder& builder, const std::string& json, tmcert::Verdict expected) {
  const tmcert::Scene built = builder.build();
  const tmcert::Scene read = tmcert::Scene::from_json(json);
  BOOST_TEST(built.body_names() == read.body_names(), boost::test_tools::per_element());
  BOOST_TEST((built.checks() == read.checks()));
  const tmcert::Result a = tmcert::verify(built);
  const tmcert::Result b = tmcert::verify(read);
  BOOST_TEST(tmcert::to_string(a.verdict()) == tmcert::to_string(expected));
  BOOST_TEST(without_seconds(a.to_json()) == without_seconds(b.to_json()));
}

// The wall x = 3/2, |y|, |z| <= 1, as the JSON of one body.
const char* kWallJson = R"({ "name": "wall", "polygons": [ [["1.5",-1,-1],["1.5",1,-1],["1.5",1,1],["1.5",-1,1]] ] })";

void add_wall(tmcert::SceneBuilder& b) {
  const std::vector<double> xyz = {1.5, -1, -1, 1.5, 1, -1, 1.5, 1, 1, 1.5, -1, 1};
  b.add_body("wall").polygons(xyz, {{0, 1, 2, 3}});
}

// The bar |x| <= 2, |y| <= 1/10 in the plane z = 0.
void add_bar(tmcert::SceneBuilder& b, tmcert::Motion motion) {
  b.add_body("bar").polygon({{-2, "-0.1", 0}, {2, "-0.1", 0}, {2, "0.1", 0}, {-2, "0.1", 0}}).motion(std::move(motion));
}
const char* kBarPolygon = R"("polygons": [ [[-2,"-0.1",0],[2,"-0.1",0],[2,"0.1",0],[-2,"0.1",0]] ])";

// A scene document: `before` (members ending in a comma) ahead of the
// bodies, `after` (members starting with a comma) behind them.
std::string scene_json(const std::string& bodies, const std::string& before = "", const std::string& after = "") {
  return R"({ "format": "tmcert-scene/1", )" + before + R"( "bodies": [ )" + bodies + " ]" + after + " }";
}

// Is `approx` the double nearest to the rational num/den (ties to even)?
bool nearest(const tmcert::Rational& r) {
  mpq_t q, d, below, above, tmp;
  mpq_inits(q, d, below, above, tmp, nullptr);
  const std::string text = r.numerator + "/" + r.denominator;
  bool ok = mpq_set_str(q, text.c_str(), 10) == 0;
  mpq_canonicalize(q);
  if (ok && std::isfinite(r.approx)) {
    // |q - approx| <= |q - neighbour| for both neighbours.
    mpq_set_d(d, r.approx);
    mpq_sub(tmp, q, d);
    mpq_abs(tmp, tmp);
    for (double n : {std::nextafter(r.approx, -INFINITY), std::nextafter(r.approx, INFINITY)}) {
      if (!std::isfinite(n)) continue;
      mpq_set_d(below, n);
      mpq_sub(above, q, below);
      mpq_abs(above, above);
      if (mpq_cmp(tmp, above) > 0) ok = false;
    }
    // Text and numerator/denominator agree.
    mpq_set_str(below, r.text.c_str(), 10);
    mpq_canonicalize(below);
    if (!mpq_equal(below, q)) ok = false;
  }
  mpq_clears(q, d, below, above, tmp, nullptr);
  return ok;
}

void check_doubles(const tmcert::Result& result) {
  BOOST_TEST(nearest(result.epsilon()));
  for (const tmcert::CheckResult& c : result.checks()) {
    for (const tmcert::UndecidedInterval& u : c.undecided) {
      BOOST_TEST(nearest(u.t0));
      BOOST_TEST(nearest(u.t1));
    }
    if (c.first_contact)
      for (const tmcert::Time& t : *c.first_contact)
        if (const tmcert::Rational* r = t.rational()) BOOST_TEST(nearest(*r));
    if (!c.witness) continue;
    const tmcert::Witness& w = *c.witness;
    if (const tmcert::Rational* r = w.t.rational()) {
      BOOST_TEST(nearest(*r));
      BOOST_TEST(w.t.approx() == r->approx);
    } else {
      const tmcert::AlgebraicNumber& a = *w.t.algebraic();
      BOOST_TEST(nearest(a.lower));
      BOOST_TEST(nearest(a.upper));
      // The 15-digit decimal of a root inside (lower, upper).
      const double slack = 1e-14 * std::max(1.0, std::fabs(a.approx));
      BOOST_TEST(a.approx >= a.lower.approx - slack);
      BOOST_TEST(a.approx <= a.upper.approx + slack);
    }
    if (w.point) {
      for (int k = 0; k < 3; ++k) {
        BOOST_TEST(nearest((*w.point)[k]));
        BOOST_TEST(w.point_approx[k] == (*w.point)[k].approx);
      }
    } else {
      BOOST_REQUIRE(w.point_box.has_value());
      for (int k = 0; k < 3; ++k) {
        BOOST_TEST(nearest((*w.point_box)[k][0]));
        BOOST_TEST(nearest((*w.point_box)[k][1]));
        BOOST_TEST(w.point_approx[k] >= (*w.point_box)[k][0].approx);
        BOOST_TEST(w.point_approx[k] <= (*w.point_box)[k][1].approx);
      }
    }
  }
}

// Runs f and requires a tmcert::InputError whose message holds every one
// of `parts`.
void input_error(const std::function<void()>& f, const std::vector<std::string>& parts) {
  try {
    f();
    BOOST_ERROR("no InputError; expected one naming " + parts.front());
  } catch (const tmcert::InputError& e) {
    const std::string message = e.what();
    for (const std::string& part : parts)
      BOOST_TEST(message.find(part) != std::string::npos, "\"" << message << "\" names " << part);
  }
}

}  // namespace

BOOST_AUTO_TEST_SUITE(builder_vs_reader)

// A triangle with a segment and a point, translated along a weighted
// (rational) degree-2 curve into the wall, with a mass, epsilon, max_depth
// and an explicit check.
BOOST_AUTO_TEST_CASE(rational_bezier) {
  tmcert::SceneBuilder b;
  b.epsilon("1/500").max_depth(30);
  add_wall(b);
  tmcert::RationalBezier curve;
  curve.control_points = {{1, 0, 0, -1, 0, 1, 0, 0, 0, 0, 1, 0},
                          {1, 0, 0, 0.5, 0, 1, 0, 0.25, 0, 0, 1, 0},
                          {1, 0, 0, 2, 0, 1, 0, 0, 0, 0, 1, "1/3"}};
  curve.weights = {1, 2, 1};
  curve.interval = {0, 2};
  const std::vector<double> xyz = {0, 0, 0, 0.25, 0, 0, 0, 0.25, 0};
  b.add_body("tri")
      .polygons(xyz, std::vector<std::size_t>{0, 1, 2}, std::vector<std::size_t>{3})
      .segments(std::vector<double>{0, 0, 0, 0, 0, 0.5})
      .points(std::vector<double>{-0.5, 0, 0})
      .mass({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {1, 1, 1, "1/2"})
      .motion(curve);
  b.check("tri", "wall");
  const std::string json = scene_json(std::string(kWallJson) + R"(,
    { "name": "tri", "polygons": [ [[0,0,0],[0.25,0,0],[0,0.25,0]] ], "segments": [ [[0,0,0],[0,0,0.5]] ],
      "points": [ [-0.5,0,0] ],
      "mass": { "points": [[0,0,0],[1,0,0],[0,1,0],[0,0,1]], "weights": [1,1,1,"1/2"] },
      "motion": { "type": "rational_bezier", "interval": [0, 2],
        "control_points": [ [[1,0,0,-1],[0,1,0,0],[0,0,1,0]], [[1,0,0,0.5],[0,1,0,0.25],[0,0,1,0]],
                            [[1,0,0,2],[0,1,0,0],[0,0,1,"1/3"]] ],
        "weights": [1, 2, 1] } })", R"("epsilon": "1/500", "max_depth": 30,)", R"(, "checks": [["tri", "wall"]])");
  same_result(b, json, tmcert::Verdict::Collision);
}

BOOST_AUTO_TEST_CASE(keyframes_slerp_quaternion) {
  tmcert::SceneBuilder b;
  add_bar(b, tmcert::Keyframes{{{{0, 0, 0}, tmcert::Rotation::quaternion(1, 0, 0, 1)},
                                {{0, 0, 0}, tmcert::Rotation::quaternion(1, 0, 0, 0)}},
                               {0, 1},
                               tmcert::Interpolation::Slerp});
  add_wall(b);
  const std::string json = scene_json(std::string(R"({ "name": "bar", )") + kBarPolygon + R"(,
      "motion": { "type": "keyframes", "interpolation": "slerp", "times": [0, 1],
                  "poses": [ { "rotation": {"quaternion": [1,0,0,1]} }, { "rotation": {"quaternion": [1,0,0,0]} } ] } },
    )" + kWallJson);
  same_result(b, json, tmcert::Verdict::Collision);
}

BOOST_AUTO_TEST_CASE(keyframes_screw_rpy) {
  tmcert::SceneBuilder b;
  add_bar(b, tmcert::Keyframes{{{{0, 0, 2}, tmcert::Rotation::rpy(0, 0, "1.5")},
                                {{0, 0, 1}, tmcert::Rotation::rpy(0, 0, "0.75")},
                                {{0, 0, 0}, tmcert::Rotation::identity()}},
                               {0, "1/2", 1},
                               tmcert::Interpolation::Screw});
  add_wall(b);
  const std::string json = scene_json(std::string(R"({ "name": "bar", )") + kBarPolygon + R"(,
      "motion": { "type": "keyframes", "interpolation": "screw", "times": [0, "1/2", 1],
                  "poses": [ { "translation": [0,0,2], "rotation": {"rpy": [0,0,"1.5"]} },
                             { "translation": [0,0,1], "rotation": {"rpy": [0,0,"0.75"]} },
                             { "translation": [0,0,0] } ] } },
    )" + kWallJson);
  same_result(b, json, tmcert::Verdict::Collision);
}

BOOST_AUTO_TEST_CASE(keyframes_nlerp_matrix) {
  tmcert::SceneBuilder b;
  // Quarter turn about z as a matrix, then the identity; times evenly spaced.
  add_bar(b, tmcert::Keyframes{{{{0, 0, 0}, tmcert::Rotation::matrix({0, -1, 0, 1, 0, 0, 0, 0, 1})},
                                {{"0.5", 0, 0}, tmcert::Rotation::identity()}},
                               {},
                               tmcert::Interpolation::Nlerp});
  add_wall(b);
  const std::string json = scene_json(std::string(R"({ "name": "bar", )") + kBarPolygon + R"(,
      "motion": { "type": "keyframes", "interpolation": "nlerp",
                  "poses": [ { "rotation": {"matrix": [[0,-1,0],[1,0,0],[0,0,1]]} },
                             { "translation": ["0.5",0,0] } ] } },
    )" + kWallJson);
  same_result(b, json, tmcert::Verdict::Collision);
}

// A translation on [0, 1] and a slerp on [1, 2] meeting at the identity.
BOOST_AUTO_TEST_CASE(piecewise) {
  tmcert::SceneBuilder b;
  add_bar(b, tmcert::Piecewise{{tmcert::Motion::translation({0, 0, -3}, {0, 0, 0}),
                                tmcert::Keyframes{{{{0, 0, 0}, tmcert::Rotation::identity()},
                                                   {{0, 0, 0}, tmcert::Rotation::quaternion(1, 0, 0, 1)}},
                                                  {1, 2}}}});
  add_wall(b);
  const std::string json = scene_json(std::string(R"({ "name": "bar", )") + kBarPolygon + R"(,
      "motion": { "type": "piecewise", "pieces": [
        { "type": "rational_bezier", "interval": [0, 1],
          "control_points": [ [[1,0,0,0],[0,1,0,0],[0,0,1,-3]], [[1,0,0,0],[0,1,0,0],[0,0,1,0]] ] },
        { "type": "keyframes", "times": [1, 2],
          "poses": [ {}, { "rotation": {"quaternion": [1,0,0,1]} } ] } ] } },
    )" + kWallJson);
  same_result(b, json, tmcert::Verdict::Collision);
}

// A solid box (triangles) with a tolerance, a point passing it, a clearance
// on the check.
BOOST_AUTO_TEST_CASE(solid_tolerance_clearance) {
  tmcert::SceneBuilder b;
  std::vector<double> xyz;
  for (int k = 0; k < 8; ++k) xyz.insert(xyz.end(), {k & 1 ? 1.0 : 0.0, k & 2 ? 1.0 : 0.0, k & 4 ? 1.0 : 0.0});
  const std::vector<std::size_t> faces = {0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4,
                                          2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5};
  b.add_body("box").triangles(xyz, faces).solid().tolerance("1/100");
  b.add_body("p").point({"0.5", 2, "0.5"}).motion(tmcert::Motion::translation({0, 0, 0}, {0, 0, 1}));
  b.check("p", "box", "1/2");
  std::string json_faces;
  auto corner = [](std::size_t k) {
    return "[" + std::string(k & 1 ? "1" : "0") + "," + (k & 2 ? "1" : "0") + "," + (k & 4 ? "1" : "0") + "]";
  };
  for (std::size_t i = 0; i < faces.size(); i += 3)
    json_faces += std::string(i ? "," : "") + "[" + corner(faces[i]) + "," + corner(faces[i + 1]) + "," + corner(faces[i + 2]) + "]";
  const std::string json = scene_json(R"({ "name": "box", "polygons": [)" + json_faces + R"(], "solid": true, "tolerance": "1/100" },
      { "name": "p", "points": [ ["0.5", 2, "0.5"] ],
        "motion": { "type": "rational_bezier", "control_points": [ [[1,0,0,0],[0,1,0,0],[0,0,1,0]], [[1,0,0,0],[0,1,0,0],[0,0,1,1]] ] } })",
      "", R"(, "checks": [ { "bodies": ["p", "box"], "clearance": "1/2" } ])");
  same_result(b, json, tmcert::Verdict::Safe);
}

// A URDF arm whose forearm sweeps through a panel; the post as a mesh file.
BOOST_AUTO_TEST_CASE(robot_and_mesh) {
  tmcert::SceneBuilder b;
  b.add_robot("arm", kExamples + "/robot/arm.urdf")
      .base({{0, 0, 0}, tmcert::Rotation::identity()})
      .path({"shoulder", "elbow", "wrist"}, {0, 1}, {{0, 0, 0}, {-1, 0, 0}})
      .self_collision()
      .allow("upper_arm", "tool");
  b.add_body("panel").polygon({{0.25, "-0.3", "0.55"}, {0.25, "-0.1", "0.55"}, {0.25, "-0.1", "0.65"}, {0.25, "-0.3", "0.65"}});
  b.add_body("post").mesh(kExamples + "/robot/post.off");
  const std::string json = scene_json(R"(
      { "name": "panel", "polygons": [ [[0.25,"-0.3","0.55"],[0.25,"-0.1","0.55"],[0.25,"-0.1","0.65"],[0.25,"-0.3","0.65"]] ] },
      { "name": "post", "mesh": ")" + kExamples + R"(/robot/post.off" })", "", R"(,
      "robots": [ { "name": "arm", "urdf": ")" + kExamples + R"(/robot/arm.urdf", "base": { "translation": [0,0,0] },
                    "joints": ["shoulder", "elbow", "wrist"],
                    "path": { "times": [0, 1], "positions": [[0,0,0],[-1,0,0]] },
                    "self_collision": true, "allowed_pairs": [["upper_arm", "tool"]] } ])");
  same_result(b, json, tmcert::Verdict::Collision);
  const tmcert::Scene scene = b.build();
  BOOST_TEST(scene.body_names().front() == "panel");
  BOOST_TEST(scene.body_names().back().rfind("arm/", 0) == 0);
}

// Vertices moving linearly (continuous-collision queries): the scene of
// examples/vertex-face-linear.json.
BOOST_AUTO_TEST_CASE(linear_primitive) {
  tmcert::SceneBuilder b;
  b.add_body("p").linear_primitive({{"0.2", "0.2", 1}}, {{"0.2", "0.2", -1}});
  b.add_body("f").linear_primitive({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{"0.1", 0, 0}, {"1.1", 0, 0}, {"0.1", 1, 0}});
  const std::string json = R"({ "format": "tmcert-scene/1",
    "bodies": [
      { "name": "p", "points": [[0,0,0]],
        "motion": { "type": "rational_bezier", "control_points": [
          [[0,0,0,0.2],[0,0,0,0.2],[0,0,0,1]], [[0,0,0,0.2],[0,0,0,0.2],[0,0,0,-1]] ] } },
      { "name": "f", "polygons": [[[0,0,0],[1,0,0],[0,1,0]]],
        "motion": { "type": "rational_bezier", "control_points": [
          [[1,0,0,0],[0,1,0,0],[0,0,0,0]], [[1,0,0,0.1],[0,1,0,0],[0,0,0,0]] ] } } ] })";
  same_result(b, json, tmcert::Verdict::Collision);
  BOOST_TEST(tmcert::verify(b.build()).checks()[0].witness->t.text() == "1/2");
  input_error([] { tmcert::SceneBuilder().add_body("q").linear_primitive({{0, 0, 0}}, {}); }, {"body \"q\"", "linear_primitive"});
  input_error([] { tmcert::SceneBuilder().add_body("q").linear_primitive({{0, "x", 0}}, {{0, 0, 0}}); },
              {"body \"q\"", "start[0][1]", "not a number"});
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(exact_numbers)

BOOST_AUTO_TEST_CASE(doubles_are_taken_exactly) {
  BOOST_TEST(tmcert::Number(0.1).text() == "3602879701896397/36028797018963968");
  BOOST_TEST(tmcert::Number("0.1").text() == "0.1");
  BOOST_TEST(tmcert::Number(0.25).text() == "1/4");
  BOOST_TEST(tmcert::Number(-3).text() == "-3");
  BOOST_TEST(tmcert::Number(1e300).text().find('/') == std::string::npos);
  // A point moving from x = 0 to x = 1 over [0, 1] meets the plane of a
  // square at x = 0.1 at t = 0.1: the double's value or exactly 1/10.
  for (const bool as_double : {true, false}) {
    const tmcert::Number x = as_double ? tmcert::Number(0.1) : tmcert::Number("0.1");
    tmcert::SceneBuilder b;
    b.add_body("square").polygon({{x, -1, -1}, {x, 1, -1}, {x, 1, 1}, {x, -1, 1}});
    b.add_body("p").point({0, 0, 0}).motion(tmcert::Motion::translation({0, 0, 0}, {1, 0, 0}));
    const tmcert::Result r = tmcert::verify(b.build());
    BOOST_REQUIRE(r.checks().size() == 1);
    BOOST_REQUIRE(r.checks()[0].witness.has_value());
    const tmcert::Time& t = r.checks()[0].witness->t;
    BOOST_REQUIRE(t.is_rational());
    BOOST_TEST(t.rational()->text == (as_double ? "3602879701896397/36028797018963968" : "1/10"));
    BOOST_TEST(t.approx() == 0.1);  // both round to the same double
    const tmcert::Time& first = (*r.checks()[0].first_contact)[0];
    BOOST_TEST(first.text() == t.text());
  }
}

BOOST_AUTO_TEST_CASE(result_doubles_agree_with_exact_values) {
  // Rational witnesses, a transcendental one (point_box) and an algebraic time.
  for (const char* file : {"/octagons-collision.json", "/planner-bar-slerp.json", "/vertex-face-linear.json"})
    check_doubles(tmcert::verify(tmcert::Scene::from_file(kExamples + file)));
  const tmcert::Result cubic = tmcert::verify(tmcert::Scene::from_file(std::string(TMCERT_TEST_DATA) + "/scenes/cubic-crossing-irrational.json"));
  BOOST_REQUIRE(!cubic.checks().empty());
  BOOST_REQUIRE(cubic.checks()[0].witness.has_value());
  BOOST_TEST(!cubic.checks()[0].witness->t.is_rational());
  BOOST_TEST(cubic.checks()[0].witness->t.text().rfind("root of [", 0) == 0);
  check_doubles(cubic);
  tmcert::SceneBuilder b;
  b.epsilon("1/3");
  b.add_body("a").point({0, 0, 0}).motion(tmcert::Motion::translation({0, 0, 0}, {1, 0, 0}));
  b.add_body("b").point({5, 5, 5});
  const tmcert::Result r = tmcert::verify(b.build());
  BOOST_TEST(r.epsilon().text == "1/3");
  BOOST_TEST(r.epsilon().numerator == "1");
  BOOST_TEST(r.epsilon().denominator == "3");
  BOOST_TEST(r.epsilon().approx == 1.0 / 3.0);
  BOOST_REQUIRE(r.checks().size() == 1u);
  BOOST_TEST(r.checks()[0].epsilon.text == "1/3");
  BOOST_TEST(tmcert::to_string(r.verdict()) == std::string("safe"));
  // Without one, each check has its own default: 1/1000 of the box of its
  // two bodies (a (0,0,0)-(5,5,5) box here, a far third body changes nothing).
  tmcert::SceneBuilder d;
  d.add_body("a").point({0, 0, 0}).motion(tmcert::Motion::translation({0, 0, 0}, {1, 0, 0}));
  d.add_body("b").point({5, 5, 5});
  d.add_body("far").point({5000, 0, 0});
  d.check("a", "b");
  const tmcert::Scene ds = d.build();
  const tmcert::Result dr = tmcert::verify(ds);
  BOOST_REQUIRE(dr.checks().size() == 1u);
  BOOST_TEST(dr.checks()[0].epsilon.text == ds.default_epsilon("a", "b").text);
  BOOST_TEST(dr.checks()[0].epsilon.approx == std::sqrt(75.0) / 1000, boost::test_tools::tolerance(1e-5));
  BOOST_TEST(dr.epsilon().text == dr.checks()[0].epsilon.text);
  BOOST_CHECK_THROW(ds.default_epsilon("a", "nobody"), std::out_of_range);
}

// Decisive by default (issue 23): without an epsilon (or with "auto") the
// undecided parts are searched again at smaller epsilons; a given epsilon
// is fixed.
BOOST_AUTO_TEST_CASE(refines_without_an_epsilon) {
  const tmcert::Scene s = tmcert::Scene::from_file(std::string(TMCERT_TEST_DATA) + "/scenes/decisive-slerp-pass-above.json");
  const tmcert::Rational start = s.default_epsilon("probe", "plate");
  const tmcert::Result r = tmcert::verify(s);
  BOOST_TEST(tmcert::to_string(r.verdict()) == std::string("safe"));
  BOOST_REQUIRE(r.checks().size() == 1u);
  BOOST_TEST(r.checks()[0].refined);
  BOOST_TEST(r.checks()[0].epsilon.approx < start.approx);
  tmcert::VerifyOptions fixed;
  fixed.epsilon = start;
  const tmcert::Result f = tmcert::verify(s, fixed);
  BOOST_TEST(tmcert::to_string(f.verdict()) == std::string("undecided"));
  BOOST_TEST(!f.checks()[0].refined);
  BOOST_TEST(f.checks()[0].epsilon.text == start.text);
  tmcert::VerifyOptions automatic;
  automatic.epsilon = tmcert::Number("auto");
  const tmcert::Result a = tmcert::verify(s, automatic);
  BOOST_TEST(tmcert::to_string(a.verdict()) == std::string("safe"));
  BOOST_TEST(a.checks()[0].refined);
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(errors)

BOOST_AUTO_TEST_CASE(builder_errors_name_the_field) {
  // The scene of one triangle "wall" changed by `edit` must fail to build.
  auto build_error = [](const std::function<void(tmcert::SceneBuilder&)>& edit, const std::vector<std::string>& parts) {
    input_error([&] {
      tmcert::SceneBuilder b;
      b.add_body("wall").polygon({{1, 0, 0}, {1, 1, 0}, {1, 1, 1}});
      edit(b);
      b.build();
    }, parts);
  };
  input_error([] { tmcert::SceneBuilder().build(); }, {"SceneBuilder: bodies", "at least one body"});
  build_error([&](tmcert::SceneBuilder& b) {
    b.add_body("line").polygon({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}});
  }, {"bodies[1].polygons[0]", "(body \"line\")"});
  build_error([&](tmcert::SceneBuilder& b) {
    b.add_body("p").point({0, std::nan(""), 0});
  }, {"bodies[1].points[0][1]", "not a number", "(body \"p\")"});
  build_error([&](tmcert::SceneBuilder& b) {
    b.add_body("p").point({0, 0, "1/0"});
  }, {"bodies[1].points[0][2]"});
  build_error([&](tmcert::SceneBuilder& b) {
    b.add_body("wall").point({0, 0, 0});
  }, {"bodies[1].name", "duplicate body name"});
  build_error([&](tmcert::SceneBuilder& b) {
    b.add_body("");
  }, {"bodies[1].name"});
  build_error([&](tmcert::SceneBuilder& b) {
    tmcert::RationalBezier m;
    m.control_points = {{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0}, {1, 0, 0, 1, 0, 1, 0, 0, 0, 0, 1, 0}};
    m.weights = {1, -1};
    b.add_body("p").point({0, 0, 0}).motion(m);
  }, {"bodies[1].motion.weights", "(body \"p\")"});
  build_error([&](tmcert::SceneBuilder& b) {
    b.add_body("p").point({0, 0, 0}).motion(tmcert::Keyframes{{{{0, 0, 0}, tmcert::Rotation::quaternion(0, 0, 0, 0)}, {}}, {0, 1}});
  }, {"bodies[1].motion.poses[0].rotation"});
  build_error([&](tmcert::SceneBuilder& b) {
    b.add_body("p").point({0, 0, 0}).motion(tmcert::Keyframes{{{{0, 0, 0}, tmcert::Rotation::matrix({2, 0, 0, 0, 1, 0, 0, 0, 1})}, {}}, {0, 1}});
  }, {"bodies[1].motion.poses[0].rotation"});
  build_error([&](tmcert::SceneBuilder& b) {
    b.add_body("p").point({0, 0, 0}).motion(tmcert::Piecewise{{tmcert::Motion::translation({0, 0, 0}, {1, 0, 0}),
                                                              tmcert::Motion::translation({0, 0, 0}, {1, 0, 0}, 1, 2)}});
  }, {"bodies[1].motion.pieces"});
  build_error([&](tmcert::SceneBuilder& b) {
    b.add_body("p").point({0, 0, 0}).mass({{0, 0, 0}, {1, 0, 0}}, {1, 1});
  }, {"bodies[1].mass"});
  build_error([&](tmcert::SceneBuilder& b) {
    b.add_body("p").point({0, 0, 0}).tolerance(-1);
  }, {"bodies[1].tolerance"});
  build_error([&](tmcert::SceneBuilder& b) {
    b.add_body("open").polygon({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}).solid();
  }, {"bodies[1].solid"});
  build_error([&](tmcert::SceneBuilder& b) {
    b.add_body("m").mesh("/nonexistent/file.off");
  }, {"bodies[1].mesh", "file.off"});
  build_error([&](tmcert::SceneBuilder& b) {
    b.check("wall", "nobody");
  }, {"checks[0][1]", "unknown body"});
  build_error([&](tmcert::SceneBuilder& b) {
    b.add_body("p").point({0, 0, 0});
    b.check("wall", "p", -1);
  }, {"checks[0].clearance"});
  build_error([&](tmcert::SceneBuilder& b) {
    b.epsilon("abc");
  }, {"SceneBuilder: epsilon", "not a number"});
  build_error([&](tmcert::SceneBuilder& b) {
    b.max_depth(0);
  }, {"SceneBuilder: max_depth"});
  build_error([&](tmcert::SceneBuilder& b) {
    b.add_robot("arm", kExamples + "/robot/arm.urdf").path({"shoulder", "elbow", "wrist"}, {0, 1}, {{0, 0, 0}, {9, 0, 0}});
  }, {"robots[0].path.positions[1]", "(robot \"arm\")"});
  build_error([&](tmcert::SceneBuilder& b) {
    b.add_robot("arm", "/nonexistent/arm.urdf");
  }, {"robots[0].urdf"});
  // Array shapes are refused at once, naming the body.
  input_error([] { tmcert::SceneBuilder().add_body("t").triangles(std::vector<double>{0, 0, 0, 1}, std::vector<std::size_t>{}); },
              {"body \"t\"", "triangles", "not 3 per vertex"});
  input_error([] {
    tmcert::SceneBuilder().add_body("t").triangles(std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0}, std::vector<std::size_t>{0, 1, 3});
  }, {"body \"t\"", "vertex index 3 is out of range"});
  input_error([] { tmcert::SceneBuilder().add_body("s").segments(std::vector<double>{0, 0, 0, 1}); }, {"body \"s\"", "segments"});
  input_error([] {
    tmcert::SceneBuilder().add_body("q").polygons(std::vector<double>{0, 0, 0}, std::vector<std::size_t>{0, 0}, std::vector<std::size_t>{3});
  }, {"body \"q\"", "polygons"});
}

// build() reads the builder's document as a JSON value, not as text: its
// messages are the reader's for the text of to_json() (plus the body's or
// robot's name), and a deep piecewise motion meets the same nesting limit.
BOOST_AUTO_TEST_CASE(builder_errors_are_the_readers_of_its_document) {
  auto message = [](const std::function<void()>& f) -> std::string {
    try {
      f();
    } catch (const tmcert::InputError& e) {
      return e.what();
    }
    return "";
  };
  std::vector<tmcert::SceneBuilder> builders(4);
  builders[0].add_body("wall").polygon({{1, 0, 0}, {1, 1, 0}, {2, 2, 0}, {1, 1, 1}});
  builders[1].add_body("w").point({0, 0, 0}).tolerance(-1);
  builders[2].epsilon("0").add_body("w").point({0, 0, 0});
  tmcert::Motion deep = tmcert::Motion::translation({0, 0, 0}, {1, 0, 0});
  for (int k = 0; k < 40; ++k) deep = tmcert::Piecewise{{deep}};
  builders[3].add_body("deep").point({0, 0, 0}).motion(deep);
  builders[3].add_body("fixed").point({1, 1, 1});
  for (const tmcert::SceneBuilder& b : builders) {
    const std::string built = message([&] { b.build(); });
    const std::string read = message([&] { tmcert::Scene::from_json(b.to_json(), "SceneBuilder"); });
    BOOST_TEST(!read.empty());
    BOOST_TEST(built.rfind(read, 0) == 0, "\"" << built << "\" starts with \"" << read << "\"");
  }
  BOOST_TEST(message([&] { builders[3].build(); }).find("nesting deeper than") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(option_and_file_errors) {
  const tmcert::Scene scene = tmcert::Scene::from_file(kExamples + "/vertex-face-linear.json");
  tmcert::VerifyOptions o;
  o.epsilon = "-1";
  input_error([&] { tmcert::verify(scene, o); }, {"epsilon"});
  o = {};
  o.max_depth = 0;
  input_error([&] { tmcert::verify(scene, o); }, {"max_depth"});
  o = {};
  o.threads = 0;
  input_error([&] { tmcert::verify(scene, o); }, {"threads"});
  o = {};
  o.time_limit = -1;
  input_error([&] { tmcert::verify(scene, o); }, {"time_limit"});
  o = {};
  o.kernel = tmcert::Kernel::Fast;
  o.certificate = true;
  input_error([&] { tmcert::verify(scene, o); }, {"certificate"});
  input_error([&] { tmcert::verify(scene).certificate(); }, {"certificate"});
  input_error([] { tmcert::Scene::from_file("/nonexistent/scene.json"); }, {"/nonexistent/scene.json"});
  input_error([] { tmcert::Scene::from_json(R"({"format": "tmcert-scene/1", "bodies": 3})", "mine"); }, {"mine: bodies"});
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(results)

// Result::to_json is what `tmcert verify --json` prints (up to seconds).
BOOST_AUTO_TEST_CASE(to_json_is_the_command_line_document) {
  const std::string file = kExamples + "/octagons-collision.json";
  const std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen((std::string(TMCERT_CLI) + " verify --json " + file).c_str(), "r"), pclose);
  BOOST_REQUIRE(pipe);
  std::string printed;
  char buffer[4096];
  for (std::size_t n; (n = fread(buffer, 1, sizeof buffer, pipe.get())) > 0;) printed.append(buffer, n);
  const tmcert::Result r = tmcert::verify(tmcert::Scene::from_file(file));
  BOOST_TEST(without_seconds(r.to_json()) == without_seconds(printed));
  BOOST_TEST(r.summary().rfind("tmcert: collision", 0) == 0);
  BOOST_TEST(r.certified());
  BOOST_TEST(tmcert::to_string(r.kernel()) == std::string("filtered"));
}

BOOST_AUTO_TEST_CASE(certificate_round_trip) {
  const tmcert::Scene scene = tmcert::Scene::from_file(kExamples + "/octagons-near.json");
  tmcert::VerifyOptions o;
  o.certificate = true;
  const tmcert::Result r = tmcert::verify(scene, o);
  BOOST_TEST(tmcert::to_string(r.verdict()) == std::string("safe"));
  const tmcert::CertificateCheck ok = tmcert::check_certificate_text(scene, r.certificate());
  BOOST_TEST(ok.ok, ok.message);
  BOOST_TEST(!ok.proven.empty());
  // Through a file, as `tmcert check` reads it.
  const std::string path = std::filesystem::temp_directory_path() / "tmcert_api_test_certificate.json";
  r.write_certificate(path);
  const tmcert::CertificateCheck from_file = tmcert::check_certificate(scene, path);
  std::filesystem::remove(path);
  BOOST_TEST(from_file.ok, from_file.message);
  BOOST_TEST(from_file.proven == ok.proven, boost::test_tools::per_element());
  // The same claims about the colliding octagons do not hold.
  bool rejected = false;
  try {
    const tmcert::CertificateCheck other =
        tmcert::check_certificate_text(tmcert::Scene::from_file(kExamples + "/octagons-collision.json"), r.certificate());
    rejected = !other.ok && !other.message.empty();
  } catch (const tmcert::InputError&) {
    rejected = true;
  }
  BOOST_TEST(rejected);
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(progress)

// VerifyOptions::progress: reports while verify() runs, the fraction never
// falls and stays below 1 while a check is left; the last call has
// fraction 1 and every check done.
BOOST_AUTO_TEST_CASE(reports_are_honest) {
  const tmcert::Scene scene = tmcert::Scene::from_file(kExamples + "/gripper/gripper-safe.json");
  std::vector<tmcert::Progress> reports;
  tmcert::VerifyOptions o;
  o.progress_interval = 0.001;
  o.progress = [&](const tmcert::Progress& p) {
    reports.push_back(p);
    return true;
  };
  const tmcert::Result r = tmcert::verify(scene, o);
  BOOST_TEST(tmcert::to_string(r.verdict()) == std::string("safe"));
  BOOST_REQUIRE(!reports.empty());
  const tmcert::Progress& last = reports.back();
  BOOST_TEST(last.fraction == 1.0);
  BOOST_TEST(last.checks == r.checks().size());
  BOOST_TEST(last.checks_done == last.checks);
  for (std::size_t k = 0; k + 1 < reports.size(); ++k) {
    // 1 only once every check is done (verify() may still be finishing).
    BOOST_TEST((reports[k].fraction < 1.0 || reports[k].checks_done == reports[k].checks),
               "report " << k << ": " << reports[k].fraction << " with a check left");
    BOOST_TEST(reports[k].fraction <= reports[k + 1].fraction, "report " << k << " goes back");
    BOOST_TEST(reports[k].checks_done <= reports[k].checks);
    BOOST_TEST(reports[k].seconds <= reports[k + 1].seconds);
  }
  // Something is named while it runs (the check, or what comes before it).
  BOOST_TEST(std::any_of(reports.begin(), reports.end() - 1, [](const tmcert::Progress& p) { return !p.activity.empty(); }));
}

// Returning false cancels: verify() throws Cancelled, never a result.  An
// exception of the callback cancels and comes out of verify().
BOOST_AUTO_TEST_CASE(cancel_and_callback_errors) {
  const tmcert::Scene scene = tmcert::Scene::from_file(kExamples + "/gripper/gripper-safe.json");
  tmcert::VerifyOptions o;
  o.progress_interval = 0.001;
  int calls = 0;
  o.progress = [&](const tmcert::Progress&) {
    ++calls;
    return false;
  };
  BOOST_CHECK_THROW(tmcert::verify(scene, o), tmcert::Cancelled);
  BOOST_TEST(calls >= 1);
  o.progress = [](const tmcert::Progress&) -> bool { throw std::range_error("from the callback"); };
  BOOST_CHECK_THROW(tmcert::verify(scene, o), std::range_error);
  o.progress_interval = 0;
  BOOST_CHECK_THROW(tmcert::verify(scene, o), tmcert::InputError);
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(more_results)

// Notes and warnings of the reader (docs/scene-format.md, "Data from real
// pipelines") are in the scene and the result, as in the JSON document.
BOOST_AUTO_TEST_CASE(notes_and_warnings) {
  const tmcert::Scene plate = tmcert::Scene::from_file(std::string(TMCERT_TEST_DATA) + "/scenes/pipeline-quad-off-plane.json");
  BOOST_REQUIRE_EQUAL(plate.notes().size(), 1u);
  BOOST_TEST(plate.notes()[0].find("not exactly planar") != std::string::npos);
  BOOST_TEST(plate.warnings().empty());
  const tmcert::Result r = tmcert::verify(plate);
  BOOST_TEST(r.notes() == plate.notes(), boost::test_tools::per_element());
  BOOST_TEST(r.to_json().find("\"notes\": [") != std::string::npos);
  BOOST_TEST(r.summary().find("  note: ") != std::string::npos);
  const tmcert::Scene degrees = tmcert::Scene::from_file(std::string(TMCERT_TEST_DATA) + "/scenes/pipeline-rpy-degrees.json");
  BOOST_REQUIRE_EQUAL(degrees.warnings().size(), 1u);
  BOOST_TEST(degrees.warnings()[0].find("rotation.rpy[2]: the angle 90 is more than 2 pi") != std::string::npos);
  // A clean scene has neither, and its document no such keys.
  const tmcert::Result clean = tmcert::verify(tmcert::Scene::from_file(kExamples + "/octagons-near.json"));
  BOOST_TEST(clean.notes().empty());
  BOOST_TEST(clean.to_json().find("\"notes\"") == std::string::npos);
}

// The visual report from the API: the page --report writes.
BOOST_AUTO_TEST_CASE(report_page) {
  const tmcert::Result r = tmcert::verify(tmcert::Scene::from_file(kExamples + "/octagons-collision.json"));
  const std::string page = r.report_html();
  BOOST_TEST(page.rfind("<!DOCTYPE html>", 0) == 0);
  const std::string path = std::filesystem::temp_directory_path() / "tmcert_api_test_report.html";
  r.write_report(path);
  BOOST_TEST(std::filesystem::file_size(path) == page.size());
  std::filesystem::remove(path);
  BOOST_CHECK_THROW(r.write_report("/nonexistent-dir/x.html"), tmcert::InputError);
}

// batch() and batch_merge(): the example in 2 shards merges into the bytes
// of the unsharded run; the summary is tmcert batch's.
BOOST_AUTO_TEST_CASE(batch_and_merge) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "tmcert_api_test_batch";
  std::filesystem::create_directories(dir);
  tmcert::BatchOptions o;
  o.requests = kExamples + "/batch/requests.jsonl";
  o.scene = kExamples + "/batch/environment.json";
  o.output = dir / "all.jsonl";
  const tmcert::BatchSummary all = tmcert::batch(o);
  BOOST_TEST(all.requests == 5u);
  BOOST_TEST(all.safe == 4u);
  BOOST_TEST(all.collision == 1u);
  BOOST_TEST(all.exit_code == 1);
  std::vector<std::string> shards;
  for (int i = 0; i < 2; ++i) {
    o.shard = std::to_string(i) + "/2";
    o.output = dir / ("shard-" + std::to_string(i) + ".jsonl");
    shards.push_back(o.output);
    tmcert::batch(o);
  }
  BOOST_TEST(tmcert::batch_merge(shards, dir / "merged.jsonl") == 5u);
  auto bytes = [](const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  BOOST_TEST(bytes(dir / "merged.jsonl") == bytes(dir / "all.jsonl"));
  o.shard = "2/2";
  BOOST_CHECK_THROW(tmcert::batch(o), tmcert::InputError);
  // A progress callback that says no stops the run: Cancelled.
  o.shard.clear();
  o.progress_interval = 0.001;
  o.progress = [](const tmcert::BatchProgress&) { return false; };
  o.requests = kExamples + "/batch/requests.jsonl";
  bool cancelled_or_done = true;
  try {
    tmcert::batch(o);  // may end before the first report on a fast machine
  } catch (const tmcert::Cancelled&) {
  } catch (...) {
    cancelled_or_done = false;
  }
  BOOST_TEST(cancelled_or_done);
  std::filesystem::remove_all(dir);
}

BOOST_AUTO_TEST_SUITE_END()
