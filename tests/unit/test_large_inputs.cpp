// Valid inputs that used to take minutes: two motionless 5 000-triangle
// surfaces (the fixed-fixed start test ran an exact test on each of the 25
// million simplex pairs, 160-320 s; now the interval filter and sweep of the
// moving start test).  The time bounds are generous (a loaded 2-core
// machine); the old code exceeded them many times over.
#include "src/scene/parse.h"
#include "src/verify/verify.h"

#include <boost/test/unit_test.hpp>

#include <chrono>
#include <cmath>
#include <set>
#include <string>

using tmcert::Exact;
using tmcert::Scene;
using tmcert::Vec3E;

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// A bumpy surface over the n x n grid: height (7 i + 13 j mod 11) / 10 at
// grid point (i, j), plus `lift` / 20; two triangles per square.
std::string surface(int n, int lift, std::pair<int, int> dent = {-1, -1}) {
  std::string out = "[";
  auto v = [&](int i, int j) {
    int h = 2 * ((7 * i + 13 * j) % 11) + lift;
    if (std::pair{i, j} == dent) h -= lift;  // this vertex on the lower surface
    return "[" + std::to_string(i) + "," + std::to_string(j) + ",\"" + std::to_string(h) + "/20\"]";
  };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      if (out.size() > 1) out += ",";
      out += "[" + v(i, j) + "," + v(i + 1, j) + "," + v(i + 1, j + 1) + "],";
      out += "[" + v(i, j) + "," + v(i + 1, j + 1) + "," + v(i, j + 1) + "]";
    }
  return out + "]";
}

tmcert::SceneResult verify(const Scene& scene) {
  tmcert::VerifyOptions options;
  options.epsilon = tmcert::default_epsilon(scene);
  return tmcert::verify_scene(scene, options);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(large_inputs)

BOOST_AUTO_TEST_CASE(two_motionless_5000_triangle_surfaces) {
  auto scene_of = [](std::pair<int, int> dent) {
    return tmcert::parse_scene_text(R"({"format": "tmcert-scene/1", "bodies": [{"name": "lower", "polygons": )" +
                                        surface(50, 0) + R"(}, {"name": "upper", "polygons": )" + surface(50, 1, dent) +
                                        R"(}], "checks": [["lower", "upper"]]})",
                                    "grid.json");
  };
  const Scene apart = scene_of({-1, -1});
  BOOST_TEST(apart.bodies[0].pieces.size() == 5000u);
  const auto start = std::chrono::steady_clock::now();
  const tmcert::SceneResult safe = verify(apart);
  const double took = seconds_since(start);
  BOOST_TEST(safe.verdict == tmcert::Verdict::Safe);
  BOOST_TEST(took < 30.0, "two motionless 5000-triangle surfaces took " << took << " s");
  // One vertex of the upper surface dented down onto the lower one: the
  // witness is that vertex, found in the order of parts and simplices.
  const tmcert::SceneResult touch = verify(scene_of({20, 30}));
  BOOST_TEST(touch.verdict == tmcert::Verdict::Collision);
  BOOST_REQUIRE(touch.checks[0].witness);
  const Vec3E expected{Exact(20), Exact(30), Exact(2 * ((7 * 20 + 13 * 30) % 11), 20)};
  BOOST_TEST((touch.checks[0].witness->point == expected));
}

BOOST_AUTO_TEST_SUITE_END()
