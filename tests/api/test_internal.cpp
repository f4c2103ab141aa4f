// src/api/internal: what the public API wraps.  Internal exceptions become
// the public ones with the same messages; exact numbers become Rationals
// with their nearest double; a scene splits into the mover and its
// obstacles, which are merged into one fixed body placed by their poses,
// and refused, naming the body and field, where they cannot be one.  (Part
// of the unit tests, which link the library's internals; tests/api/
// test_api.cpp tests the public library as users link it.)
#include "src/api/internal.h"

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>

namespace {

namespace api = tmcert::api;

const api::ObstacleWords kWords{"the test scene", "the test", "every body but the mover", "no fast kernel here"};

// Three bodies: "mover" (moving), "a" (a unit triangle moved to x = 10 by a
// one-pose motion) and "b" (fixed).
tmcert::Scene three_bodies(const std::string& extra_b = "") {
  const std::string tri = R"("polygons": [[[0,0,0],[1,0,0],[0,1,0]]])";
  return tmcert::parse_scene_text(
      R"({"format": "tmcert-scene/1", "bodies": [)"
      R"({"name": "mover", )" + tri + R"(, "motion": {"type": "rational_bezier", "control_points": [)"
      R"([[1,0,0,0],[0,1,0,0],[0,0,1,0]], [[1,0,0,1],[0,1,0,0],[0,0,1,0]]]}},)"
      R"({"name": "a", )" + tri + R"(, "motion": {"type": "rational_bezier", "control_points": [[[1,0,0,10],[0,1,0,0],[0,0,1,0]]]}},)"
      R"({"name": "b", )" + tri + extra_b + "}]}",
      "three.json");
}

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

BOOST_AUTO_TEST_SUITE(api_internal)

BOOST_AUTO_TEST_CASE(internal_errors_become_public_ones) {
  BOOST_CHECK_EXCEPTION(api::public_errors([]() -> int { throw tmcert::InputError("bad field"); }), api::InputError,
                        [](const api::InputError& e) { return std::string(e.what()) == "bad field"; });
  BOOST_CHECK_EXCEPTION(api::public_errors([]() -> int { throw tmcert::ResourceLimit("too big"); }),
                        api::ResourceLimit, [](const api::ResourceLimit& e) { return std::string(e.what()) == "too big"; });
  BOOST_CHECK_THROW(api::public_errors([]() -> int { throw std::bad_alloc(); }), std::bad_alloc);
  BOOST_TEST(api::public_errors([] { return 7; }) == 7);
}

BOOST_AUTO_TEST_CASE(rationals_exact_with_their_nearest_double) {
  const api::Rational third = api::to_rational(tmcert::Exact(-2, 6));
  BOOST_TEST(third.text == "-1/3");
  BOOST_TEST(third.numerator == "-1");
  BOOST_TEST(third.denominator == "3");
  BOOST_TEST(third.approx == -1.0 / 3.0);
  const api::Rational five = api::to_rational(tmcert::Exact(5));
  BOOST_TEST(five.text == "5");
  BOOST_TEST(five.denominator == "1");
  BOOST_TEST(five.approx_text == "5");
}

BOOST_AUTO_TEST_CASE(mover_and_obstacles) {
  const tmcert::Scene scene = three_bodies();
  const api::MoverAndObstacles split = api::split_mover(scene, "mover", kWords);
  BOOST_TEST(split.mover == 0u);
  BOOST_TEST((split.obstacles == std::vector<std::size_t>{1, 2}));
  BOOST_TEST(has(message_of([&] { api::split_mover(scene, "nobody", kWords); }), "three.json: bodies: no body named"));
  // The obstacles as one fixed body, each placed by its pose.
  const tmcert::Body merged = api::obstacle_body(scene, split.obstacles, kWords);
  BOOST_TEST(!merged.moves());
  BOOST_REQUIRE(merged.polygons.size() == 2u);
  BOOST_TEST(merged.polygons[0][0][0] == tmcert::Exact(10));  // "a" at x = 10
  BOOST_TEST(merged.polygons[1][0][0] == tmcert::Exact(0));   // "b" where it is
  // A moving obstacle is refused, naming it.
  const std::string moving = message_of([&] { api::obstacle_body(scene, {0, 2}, kWords); });
  BOOST_TEST(has(moving, "bodies[0] (\"mover\").motion: the obstacles of the test scene must be fixed"));
}

BOOST_AUTO_TEST_CASE(tolerance_and_clearance_refused) {
  const tmcert::Scene tolerant = three_bodies(R"(, "tolerance": "1/10")");
  const std::string tolerance = message_of([&] { api::obstacle_body(tolerant, {1, 2}, kWords); });
  BOOST_TEST(has(tolerance, "bodies[2] (\"b\").tolerance: tolerances are not supported by the test"));
  tmcert::Scene clear = three_bodies();
  BOOST_TEST(message_of([&] { api::require_no_clearance(clear, kWords); }).empty());
  clear.clearance = tmcert::Exact(1, 10);
  BOOST_TEST(message_of([&] { api::require_no_clearance(clear, kWords); }) == "three.json: clearance: not supported by the test");
}

BOOST_AUTO_TEST_SUITE_END()
