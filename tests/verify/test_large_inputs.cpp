// Valid inputs that used to take minutes: two motionless 5 000-triangle
// surfaces (the fixed-fixed start test ran an exact test on each of the 25
// million simplex pairs, 160-320 s; now the interval filter and sweep of the
// moving start test), and a non-convex polygon of 10 000 vertices (ear
// clipping and the pairwise simplicity test, 52 s; now a constrained
// Delaunay triangulation).  The time bounds are generous (a loaded 2-core
// machine); the old code exceeded them many times over.
#include "src/io/parse.h"
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

BOOST_AUTO_TEST_CASE(a_star_polygon_of_10000_vertices) {
  // Radii 1 and 1/2 alternating, coordinates rounded to 1e-7 (rational).
  const int n = 10000;
  std::string polygon = "[";
  std::vector<std::array<long, 2>> xy;
  for (int k = 0; k < n; ++k) {
    const double angle = 2 * M_PI * k / n, r = k % 2 ? 0.5 : 1.0;
    xy.push_back({std::lround(r * std::cos(angle) * 1e7), std::lround(r * std::sin(angle) * 1e7)});
    polygon += (k ? ",[\"" : "[\"") + std::to_string(xy.back()[0]) + "/10000000\",\"" + std::to_string(xy.back()[1]) +
               "/10000000\",0]";
  }
  polygon += "]";
  const auto start = std::chrono::steady_clock::now();
  const Scene scene = tmcert::parse_scene_text(
      R"({"format": "tmcert-scene/1", "bodies": [{"name": "star", "polygons": [)" + polygon +
          R"(]}, {"name": "p", "points": [[0, 0, 5]], "motion": {"type": "rational_bezier", "control_points": )"
          R"([[[1,0,0,-3],[0,1,0,0],[0,0,1,0]], [[1,0,0,3],[0,1,0,0],[0,0,1,0]]]}}]})",
      "star.json");
  const double took = seconds_since(start);
  BOOST_TEST(took < 10.0, "reading a 10000-vertex polygon took " << took << " s");
  // n - 2 triangles of polygon vertices whose areas add up to the polygon's.
  const auto& pieces = scene.bodies[0].pieces;
  BOOST_TEST(pieces.size() == static_cast<std::size_t>(n - 2));
  std::set<Vec3E> vertices(scene.bodies[0].polygons[0].begin(), scene.bodies[0].polygons[0].end());
  Exact polygon_area2 = 0, pieces_area2 = 0;
  const auto& poly = scene.bodies[0].polygons[0];
  for (std::size_t i = 0; i < poly.size(); ++i)
    polygon_area2 += poly[i][0] * poly[(i + 1) % poly.size()][1] - poly[i][1] * poly[(i + 1) % poly.size()][0];
  for (const auto& piece : pieces) {
    BOOST_REQUIRE(piece.vertices.size() == 3u);
    for (const Vec3E& v : piece.vertices) BOOST_TEST(vertices.count(v) == 1u);
    const Vec3E &a = piece.vertices[0], &b = piece.vertices[1], &c = piece.vertices[2];
    const Exact area2 = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    BOOST_TEST(CGAL::sign(area2) == CGAL::sign(polygon_area2));  // the polygon's orientation
    pieces_area2 += area2;
  }
  BOOST_TEST(pieces_area2 == polygon_area2);
  BOOST_TEST(verify(scene).verdict == tmcert::Verdict::Safe);
}

BOOST_AUTO_TEST_SUITE_END()
