// Scene parsing (src/io/parse.cpp): exact numbers, defaults, polygon
// cleaning and convex splitting, and one check per class of error.
#include "src/metric/metric.h"
#include "src/io/parse.h"

#include <boost/test/unit_test.hpp>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using tmcert::Exact;
using tmcert::InputError;
using tmcert::Scene;
using tmcert::Vec3E;

namespace {

const std::string kHead = R"({"format": "tmcert-scene/1", )";

Scene read_scene(const std::string& text) { return tmcert::parse_scene_text(text, "t.json"); }

// A scene holding the given bodies (JSON text of the array's contents).
std::string scene_of(const std::string& bodies, const std::string& extra = "") {
  return kHead + R"("bodies": [)" + bodies + "]" + (extra.empty() ? "" : ", " + extra) + "}";
}

// A fixed body named `name` with one polygon written as `polygon`.
std::string polygon_body(const std::string& polygon, const std::string& name = "a") {
  return R"({"name": ")" + name + R"(", "polygons": [)" + polygon + "]}";
}

// The message of the InputError that parsing `text` throws, or "" if none.
std::string error_of(const std::string& text) {
  try {
    read_scene(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// Checks that parsing fails with a one-line "t.json: <path>: ..." message
// that contains `expected`.
void expect_error(const std::string& text, const std::string& path, const std::string& expected = "") {
  const std::string message = error_of(text);
  BOOST_TEST_INFO("message: " << message);
  BOOST_TEST(!message.empty());
  BOOST_TEST(message.find('\n') == std::string::npos);
  BOOST_TEST(message.rfind("t.json: " + path + ": ", 0) == 0);
  BOOST_TEST(message.find(expected) != std::string::npos);
}

Exact q(const char* text) {
  Exact value;
  BOOST_REQUIRE(tmcert::parse_exact(text, value));
  return value;
}

Vec3E v(const char* x, const char* y, const char* z) { return {q(x), q(y), q(z)}; }

// Twice the signed area of a planar polygon projected along axis `drop`
// (exact; proportional to the true area for a fixed plane).
Exact twice_projected_area(const std::vector<Vec3E>& p, int drop) {
  const int a = drop == 0 ? 1 : 0, b = drop == 2 ? 1 : 2;
  Exact s = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3E &u = p[i], &w = p[(i + 1) % p.size()];
    s += u[a] * w[b] - u[b] * w[a];
  }
  return s;
}

Exact abs(const Exact& x) { return x < 0 ? -x : x; }

// Every piece of body 0 is strictly convex (all turns of one sign, none zero).
bool pieces_convex(const tmcert::Body& body, int drop) {
  const int a = drop == 0 ? 1 : 0, b = drop == 2 ? 1 : 2;
  for (const auto& piece : body.pieces) {
    const auto& p = piece.vertices;
    if (p.size() < 3) return false;
    int turn = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const Vec3E &u = p[i], &w = p[(i + 1) % p.size()], &x = p[(i + 2) % p.size()];
      const Exact o = (w[a] - u[a]) * (x[b] - u[b]) - (w[b] - u[b]) * (x[a] - u[a]);
      const int s = o > 0 ? 1 : (o < 0 ? -1 : 0);
      if (s == 0 || (turn != 0 && s != turn)) return false;
      turn = s;
    }
  }
  return true;
}

// Checks that the pieces of polygon 0 are convex, use only polygon vertices
// and have the same total (projected) area as the polygon.
void check_split(const tmcert::Body& body, int drop) {
  BOOST_TEST(pieces_convex(body, drop));
  Exact total = 0;
  for (const auto& piece : body.pieces) {
    BOOST_TEST(piece.polygon == 0);
    for (const Vec3E& p : piece.vertices)
      BOOST_TEST((std::find(body.polygons[0].begin(), body.polygons[0].end(), p) != body.polygons[0].end()));
    total += abs(twice_projected_area(piece.vertices, drop));
  }
  BOOST_TEST(total == abs(twice_projected_area(body.polygons[0], drop)));
}

}  // namespace

BOOST_AUTO_TEST_SUITE(parse)

// ---------------------------------------------------------------- exactness

BOOST_AUTO_TEST_CASE(numbers_are_exact) {
  const Scene s = read_scene(scene_of(
      R"({"name": "a", "points": [[0.1, "1/3", 1e-17], [123456789012345678901234567890, "-1.25e-3", -7],
                                  [18446744073709551616, -9223372036854775809, 2.5E+2]]})"));
  const auto& p = s.bodies[0].points;
  BOOST_REQUIRE(p.size() == 3u);
  BOOST_TEST(p[0][0] == Exact(1, 10));
  BOOST_TEST(p[0][1] == Exact(1, 3));
  BOOST_TEST(p[0][2] == Exact(1) / Exact(CGAL::Gmpz("100000000000000000")));
  BOOST_TEST(p[0][0] != tmcert::to_exact(0.1));  // not the nearest double
  BOOST_TEST(p[1][0] == Exact(CGAL::Gmpz("123456789012345678901234567890")));
  BOOST_TEST(p[1][1] == Exact(-1, 800));
  BOOST_TEST(p[1][2] == Exact(-7));
  BOOST_TEST(p[2][0] == Exact(CGAL::Gmpz("18446744073709551616")));
  BOOST_TEST(p[2][1] == Exact(CGAL::Gmpz("-9223372036854775809")));
  BOOST_TEST(p[2][2] == Exact(250));
}

BOOST_AUTO_TEST_CASE(scene_settings) {
  const Scene plain = read_scene(scene_of(R"({"name": "a", "points": [[0,0,0]]})"));
  BOOST_TEST(!plain.epsilon.has_value());
  BOOST_TEST(plain.max_depth == 40);
  BOOST_TEST(plain.source == "t.json");

  const Scene s = read_scene(scene_of(R"({"name": "a", "points": [[0,0,0]]})", R"("epsilon": "1/1000", "max_depth": "12")"));
  BOOST_REQUIRE(s.epsilon.has_value());
  BOOST_TEST(*s.epsilon == Exact(1, 1000));
  BOOST_TEST(s.max_depth == 12);
  BOOST_TEST(read_scene(scene_of(R"({"name": "a", "points": [[0,0,0]]})", R"("epsilon": 0.001, "max_depth": 200)")).max_depth ==
             200);
}

BOOST_AUTO_TEST_CASE(annotations_and_solid_false_are_accepted) {
  const Scene s = read_scene(kHead + R"("_note": 1, "comment": "x", "bodies": [
      {"name": "a", "comment": "c", "_id": [1], "solid": false, "points": [[0,0,0]],
       "mass": {"_m": 0, "points": [[0,0,0],[1,0,0],[0,1,0],[0,0,1]], "weights": [1,1,1,1]},
       "motion": {"type": "rational_bezier", "comment": "m", "control_points": [[[1,0,0,0],[0,1,0,0],[0,0,1,0]]]}}]})");
  BOOST_TEST(!s.bodies[0].solid);
  BOOST_TEST(!read_scene(scene_of(R"({"name": "a", "points": [[0,0,0]]})")).bodies[0].solid);
  // A solid is a closed surface: isolated points or segments cannot be part
  // of one.
  expect_error(scene_of(R"({"name": "a", "points": [[0,0,0]], "solid": true})"), "bodies[0].solid",
               "a solid body cannot have segments or points");
}

// ---------------------------------------------------------------- masses

BOOST_AUTO_TEST_CASE(default_mass_of_planar_body_is_positive_definite) {
  const Scene s = read_scene(scene_of(polygon_body("[[0,0,0],[2,0,0],[2,1,0],[0,1,0]]")));
  const auto& body = s.bodies[0];
  BOOST_TEST(body.mass_is_default);
  BOOST_TEST(body.mass.points.size() > 4u);  // the vertices plus off-plane points
  BOOST_TEST(body.mass.weights.size() == body.mass.points.size());
  BOOST_CHECK_NO_THROW(tmcert::Metric::from_mass(body.mass));
  // The coplanar vertices alone would not do.
  tmcert::MassDistribution flat{body.polygons[0], std::vector<Exact>(4, Exact(1))};
  BOOST_CHECK_THROW(tmcert::Metric::from_mass(flat), InputError);
}

BOOST_AUTO_TEST_CASE(default_mass_of_single_point_uses_scene_size) {
  // Body "p" is one point: its size comes from the scene (extent 6).
  const Scene s = read_scene(scene_of(R"({"name": "p", "points": [[1,1,1]]},)" +
                                 polygon_body("[[0,0,0],[6,0,0],[0,1,0]]", "b")));
  const auto& mass = s.bodies[0].mass;
  BOOST_CHECK_NO_THROW(tmcert::Metric::from_mass(mass));
  bool found = false;  // an offset point at a tenth of the scene size
  for (const Vec3E& p : mass.points) found = found || p == Vec3E{Exact(1) + Exact(6, 10), 1, 1};
  BOOST_TEST(found);
}

BOOST_AUTO_TEST_CASE(explicit_mass_is_kept) {
  const Scene s = read_scene(scene_of(
      R"({"name": "a", "points": [[0,0,0]], "mass": {"points": [[0,0,0],[1,0,0],[0,1,0],[0,0,"3/2"]], "weights": [1,2,"1/2",0.5]}})"));
  const auto& mass = s.bodies[0].mass;
  BOOST_TEST(!s.bodies[0].mass_is_default);
  BOOST_REQUIRE(mass.points.size() == 4u);
  BOOST_TEST(mass.points[3][2] == Exact(3, 2));
  BOOST_TEST(mass.weights[2] == Exact(1, 2));
  BOOST_TEST(mass.weights[3] == Exact(1, 2));
}

// ---------------------------------------------------------------- motion and checks

BOOST_AUTO_TEST_CASE(motion_fields) {
  const std::string moving = R"({"name": "m", "points": [[0,0,0]], "motion": {"type": "rational_bezier",
      "control_points": [[[1,0,0,0],[0,1,0,0],[0,0,1,0]], [[1,0,0,2],[0,1,0,"1/3"],[0,0,1,-1]]]}})";
  const Scene s = read_scene(scene_of(moving));
  BOOST_REQUIRE(s.bodies[0].motion.has_value());
  const auto& m = *s.bodies[0].motion;
  BOOST_TEST(m.degree() == 1);
  BOOST_TEST(m.t0 == Exact(0));
  BOOST_TEST(m.t1 == Exact(1));
  BOOST_TEST((m.weights == std::vector<Exact>{1, 1}));
  BOOST_TEST(m.control_points[1][3] == Exact(2));       // row 0, column 3
  BOOST_TEST(m.control_points[1][7] == Exact(1, 3));    // row 1, column 3
  BOOST_TEST(m.control_points[1][10] == Exact(1));      // row 2, column 2

  const Scene w = read_scene(scene_of(R"({"name": "m", "points": [[0,0,0]], "motion": {"type": "rational_bezier",
      "interval": ["1/2", 3], "weights": [2, "1/4"],
      "control_points": [[[1,0,0,0],[0,1,0,0],[0,0,1,0]], [[1,0,0,2],[0,1,0,0],[0,0,1,-1]]]}})"));
  BOOST_TEST(w.bodies[0].motion->t0 == Exact(1, 2));
  BOOST_TEST(w.bodies[0].motion->t1 == Exact(3));
  BOOST_TEST(w.bodies[0].motion->weights[1] == Exact(1, 4));
}

BOOST_AUTO_TEST_CASE(default_and_explicit_checks) {
  const std::string fixed_a = R"({"name": "a", "points": [[0,0,0]]})";
  const std::string moving_b = R"({"name": "b", "points": [[0,0,0]], "motion": {"type": "rational_bezier",
      "control_points": [[[1,0,0,0],[0,1,0,0],[0,0,1,0]]]}})";
  const std::string fixed_c = R"({"name": "c", "points": [[1,0,0]]})";
  const Scene s = read_scene(scene_of(fixed_a + "," + moving_b + "," + fixed_c));
  BOOST_TEST((s.checks == std::vector<std::pair<int, int>>{{0, 1}, {1, 2}}));

  const Scene none = read_scene(scene_of(fixed_a + "," + fixed_c));
  BOOST_TEST(none.checks.empty());  // the verifier refuses it (require_supported)

  const Scene e = read_scene(scene_of(fixed_a + "," + moving_b + "," + fixed_c, R"("checks": [["c", "a"], ["b", "c"]])"));
  BOOST_TEST((e.checks == std::vector<std::pair<int, int>>{{2, 0}, {1, 2}}));
}

// ---------------------------------------------------------------- polygons

BOOST_AUTO_TEST_CASE(convex_polygon_is_one_piece) {
  const Scene s = read_scene(scene_of(polygon_body("[[0,0,0],[1,0,0],[1,1,0],[0,1,0]]")));
  const auto& body = s.bodies[0];
  BOOST_REQUIRE(body.pieces.size() == 1u);
  BOOST_TEST((body.pieces[0].vertices == body.polygons[0]));
  BOOST_TEST(body.polygons[0].size() == 4u);
}

BOOST_AUTO_TEST_CASE(collinear_vertices_are_removed) {
  // Midpoints of a square's sides, and a run of two collinear vertices.
  const Scene s = read_scene(scene_of(
      polygon_body("[[0,0,0],[1,0,0],[2,0,0],[2,1,0],[2,2,0],[1,2,0],[0,2,0],[0,1,0]]") + "," +
      polygon_body("[[0,0,5],[1,0,5],[2,0,5],[3,0,5],[3,3,5]]", "b")));
  const auto& square = s.bodies[0].polygons[0];
  BOOST_TEST((square == std::vector<Vec3E>{v("0", "0", "0"), v("2", "0", "0"), v("2", "2", "0"), v("0", "2", "0")}));
  BOOST_TEST(s.bodies[0].pieces.size() == 1u);
  BOOST_TEST((s.bodies[1].polygons[0] == std::vector<Vec3E>{v("0", "0", "5"), v("3", "0", "5"), v("3", "3", "5")}));
}

BOOST_AUTO_TEST_CASE(nonconvex_polygon_is_split_exactly) {
  // An L shape in the xy plane, clockwise.
  const Scene l = read_scene(scene_of(polygon_body("[[0,0,0],[0,2,0],[1,2,0],[1,1,0],[2,1,0],[2,0,0]]")));
  BOOST_TEST(l.bodies[0].pieces.size() >= 2u);
  check_split(l.bodies[0], 2);

  // A comb with rational coordinates on the tilted plane z = x + 2y; it is
  // projected along z.
  std::vector<std::pair<std::string, std::string>> xy = {
      {"0", "0"}, {"5", "0"}, {"5", "3"}, {"4", "3"}, {"4", "1/3"}, {"3", "1/3"}, {"3", "3"},
      {"2", "3"}, {"2", "1/2"}, {"1", "1/2"}, {"1", "3"}, {"0", "3"}};
  std::string poly = "[";
  for (std::size_t i = 0; i < xy.size(); ++i) {
    const Exact z = q(xy[i].first.c_str()) + 2 * q(xy[i].second.c_str());
    poly += (i ? ",[\"" : "[\"") + xy[i].first + "\",\"" + xy[i].second + "\",\"" + tmcert::to_string(z) + "\"]";
  }
  poly += "]";
  const Scene c = read_scene(scene_of(polygon_body(poly)));
  BOOST_TEST(c.bodies[0].pieces.size() == xy.size() - 2);  // a triangulation
  check_split(c.bodies[0], 2);

  // A star (non-convex, counterclockwise) in the plane x = 1; removing the
  // collinear vertex (1, 1/2, 0) makes (1, 0, 0) collinear too.
  const Scene st = read_scene(scene_of(polygon_body(
      "[[1,0,0],[1,\"1/2\",0],[1,1,0],[1,\"1/2\",\"1/2\"],[1,1,1],[1,0,\"1/2\"],[1,-1,1],[1,\"-1/2\",\"1/2\"],[1,-1,0]]")));
  BOOST_TEST(st.bodies[0].polygons[0].size() == 7u);
  BOOST_TEST(st.bodies[0].pieces.size() == 5u);
  check_split(st.bodies[0], 0);
}

BOOST_AUTO_TEST_CASE(second_polygon_pieces_point_to_it) {
  const Scene s = read_scene(scene_of(R"({"name": "a", "polygons": [[[0,0,0],[1,0,0],[0,1,0]],
      [[0,0,1],[0,2,1],[1,2,1],[1,1,1],[2,1,1],[2,0,1]]]})"));
  int second = 0;
  for (const auto& piece : s.bodies[0].pieces) second += piece.polygon == 1;
  BOOST_TEST(s.bodies[0].pieces.front().polygon == 0);
  BOOST_TEST(second >= 2);
}

// ---------------------------------------------------------------- errors

BOOST_AUTO_TEST_CASE(json_errors) {
  const std::string message = error_of(R"({"format": "tmcert-scene/1", "bodies": [)");
  BOOST_TEST(message.rfind("t.json: invalid JSON at byte ", 0) == 0);
  BOOST_TEST(error_of("").rfind("t.json: invalid JSON at byte 0: ", 0) == 0);
  BOOST_TEST(error_of(R"({"a": })").rfind("t.json: invalid JSON at byte 6: ", 0) == 0);  // offset of '}'
  BOOST_TEST(error_of(R"({"format": NaN})").rfind("t.json: invalid JSON at byte ", 0) == 0);
  expect_error(kHead + R"("format": "tmcert-scene/1", "bodies": []})", "format", "duplicate key");
  expect_error(scene_of(R"({"name": "a", "name": "b", "points": [[0,0,0]]})"), "bodies[0].name", "duplicate key");
  expect_error("[1, 2]", "document", "expected an object");
  // A finite number too large for the JSON reader's double.
  // Beyond double range as a JSON number: still read exactly.
  {
    CGAL::Gmpz p10;
    mpz_ui_pow_ui(p10.mpz(), 10, 400);
    const Scene big = read_scene(scene_of(R"({"name": "a", "points": [[0,0,1e400]], "_s": "1e999 \" [1e999]"})"));
    BOOST_TEST(big.bodies[0].points[0][2] == Exact(p10));
    BOOST_TEST(read_scene(scene_of(R"({"name": "a", "points": [[0,0,-2.5E+400]]})")).bodies[0].points[0][2] < Exact(0));
    // A 400-digit integer without exponent, too.
    const std::string digits = "1" + std::string(400, '0');
    BOOST_TEST(read_scene(scene_of(R"({"name": "a", "points": [[0,0,)" + digits + "]]}")).bodies[0].points[0][2] ==
               Exact(p10));
    // Still a number: not accepted where a string is required.
    expect_error(scene_of(R"({"name": 1e400, "points": [[0,0,0]]})"), "bodies[0].name", "");
  }
  BOOST_TEST(read_scene(scene_of(R"({"name": "a", "points": [[0,0,"1e400"]]})")).bodies[0].points[0][2] > Exact(1));
}

BOOST_AUTO_TEST_CASE(deep_nesting_is_an_error_not_a_crash) {
  auto repeat = [](const std::string& s, int n) {
    std::string out;
    for (int i = 0; i < n; ++i) out += s;
    return out;
  };
  // 64 levels are open when the 65th would start.
  expect_error(repeat("[", 200000) + repeat("]", 200000), repeat("[0]", 64), "nesting");
  expect_error(kHead + R"("bodies": [{"name": "a", "points": [[0,0,0]], "_x": )" + repeat("[", 100) +
                   repeat("]", 100) + "}]}",
               "bodies[0]._x" + repeat("[0]", 61), "nesting");
}

BOOST_AUTO_TEST_CASE(top_level_errors) {
  const std::string body = R"({"name": "a", "points": [[0,0,0]]})";
  expect_error(R"({"bodies": [)" + body + "]}", "format", "missing");
  expect_error(R"({"format": "tmcert-scene/2", "bodies": [)" + body + "]}", "format", "unknown format version");
  expect_error(R"({"format": 1, "bodies": [)" + body + "]}", "format", "unknown format version");
  expect_error(scene_of(body, R"("bodys": 1)"), "bodys", "unknown field");
  expect_error(scene_of(body, R"("epsilon": -1)"), "epsilon", "positive");
  expect_error(scene_of(body, R"("epsilon": 0)"), "epsilon", "positive");
  expect_error(scene_of(body, R"("epsilon": "NaN")"), "epsilon", "not a number");
  expect_error(scene_of(body, R"("epsilon": "inf")"), "epsilon", "not a number");
  expect_error(scene_of(body, R"("epsilon": "")"), "epsilon", "not a number");
  expect_error(scene_of(body, R"("epsilon": "1/0")"), "epsilon", "not a number");
  expect_error(scene_of(body, R"("epsilon": true)"), "epsilon", "expected a number");
  expect_error(scene_of(body, R"("max_depth": 0)"), "max_depth", "between 1 and 200");
  expect_error(scene_of(body, R"("max_depth": 201)"), "max_depth", "between 1 and 200");
  expect_error(scene_of(body, R"("max_depth": 2.5)"), "max_depth", "integer");
  expect_error(kHead + R"("epsilon": 1})", "bodies", "missing");
  expect_error(scene_of(""), "bodies", "at least one body");
  expect_error(kHead + R"("bodies": {}})", "bodies", "expected an array");
}

BOOST_AUTO_TEST_CASE(body_errors) {
  expect_error(scene_of(R"({"points": [[0,0,0]]})"), "bodies[0].name", "missing");
  expect_error(scene_of(R"({"name": "", "points": [[0,0,0]]})"), "bodies[0].name", "non-empty");
  expect_error(scene_of(R"({"name": "a", "points": [[0,0,0]]}, {"name": "a", "points": [[0,0,0]]})"),
               "bodies[1].name", "duplicate body name");
  expect_error(scene_of(R"({"name": "a"})"), "bodies[0]", "no features");
  expect_error(scene_of(R"({"name": "a", "polygons": [], "points": []})"), "bodies[0]", "no features");
  expect_error(scene_of(R"({"name": "a", "points": [[0,0,0]], "colour": 1})"), "bodies[0].colour", "unknown field");
  expect_error(scene_of(R"({"name": "a", "mesh": "x.off"})"), "bodies[0].mesh", "x.off: cannot open file");
  expect_error(scene_of(R"({"name": "a", "points": [[0,0,0]], "solid": 1})"), "bodies[0].solid", "true or false");
  expect_error(scene_of(R"({"name": "a", "points": [[0,0]]})"), "bodies[0].points[0]", "3 coordinates");
  expect_error(scene_of(R"({"name": "a", "points": [[0,0,"x"]]})"), "bodies[0].points[0][2]", "not a number");
  expect_error(scene_of(R"({"name": "a", "points": [[0,0,null]]})"), "bodies[0].points[0][2]", "expected a number");
  expect_error(scene_of(R"({"name": "a", "points": [[0,0,0]], "segments": [[[1,2,3],[1,2,"3/1"]]]})"),
               "bodies[0].segments[0]", "equal");
  expect_error(scene_of(R"({"name": "a", "segments": [[[1,2,3]]]})"), "bodies[0].segments[0]", "2 points");
}

BOOST_AUTO_TEST_CASE(polygon_errors) {
  expect_error(scene_of(polygon_body("[[0,0,0],[1,0,0]]")), "bodies[0].polygons[0]", "at least 3 vertices");
  expect_error(scene_of(polygon_body("[[0,0,0],[1,0,0],[2,0,0],[3,0,0]]")), "bodies[0].polygons[0]", "collinear");
  expect_error(scene_of(polygon_body("[[0,0,0],[1,0,0],[1,1,0],[0,1,1]]")), "bodies[0].polygons[0]", "not planar");
  expect_error(scene_of(polygon_body("[[0,0,0],[1,0,0],[1,1,0],[1,0,0],[0,1,0]]")), "bodies[0].polygons[0]",
               "are equal");
  // Bow tie: edges 0-1 and 2-3 cross.
  expect_error(scene_of(polygon_body("[[0,0,0],[1,1,0],[1,0,0],[0,1,0]]")), "bodies[0].polygons[0]",
               "self-intersecting");
  // Pentagram: every turn has the same sign, but it winds twice.
  expect_error(scene_of(polygon_body("[[0,10,0],[6,-8,0],[-9,3,0],[9,3,0],[-6,-8,0]]")), "bodies[0].polygons[0]",
               "self-intersecting");
  // A vertex touching a non-adjacent edge.
  expect_error(scene_of(polygon_body("[[0,0,0],[4,0,0],[4,4,0],[2,0,0],[0,4,0]]")), "bodies[0].polygons[0]",
               "self-intersecting");
  // A spike: the edge 1-2 runs back along edge 0-1.
  expect_error(scene_of(polygon_body("[[0,0,0],[2,0,0],[1,0,0],[1,1,0]]")), "bodies[0].polygons[0]", "overlap");
  expect_error(scene_of(R"({"name": "a", "polygons": [[[0,0,0],[1,0,0],[0,1,0]], 5]})"), "bodies[0].polygons[1]",
               "expected an array");
}

BOOST_AUTO_TEST_CASE(mass_errors) {
  const std::string head = R"({"name": "a", "points": [[0,0,0]], "mass": )";
  const std::string tetra = R"([[0,0,0],[1,0,0],[0,1,0],[0,0,1]])";
  expect_error(scene_of(head + R"({"points": [[0,0,0],[1,0,0],[0,1,0],[1,1,0]], "weights": [1,1,1,1]}})"),
               "bodies[0].mass", "positive definite");
  expect_error(scene_of(head + R"({"points": )" + tetra + R"(, "weights": [1,0,1,1]}})"), "bodies[0].mass.weights[1]",
               "weight must be positive");
  expect_error(scene_of(head + R"({"points": )" + tetra + R"(, "weights": [1,1,1,"-1/2"]}})"),
               "bodies[0].mass.weights[3]", "weight must be positive");
  expect_error(scene_of(head + R"({"points": )" + tetra + R"(, "weights": [1,1,1]}})"), "bodies[0].mass.weights",
               "expected 4 weights");
  expect_error(scene_of(head + R"({"points": [], "weights": []}})"), "bodies[0].mass.points", "at least one");
  expect_error(scene_of(head + R"({"points": )" + tetra + "}}"), "bodies[0].mass.weights", "missing");
  expect_error(scene_of(head + R"({"points": )" + tetra + R"(, "weights": [1,1,1,1], "w": 1}})"),
               "bodies[0].mass.w", "unknown field");
}

BOOST_AUTO_TEST_CASE(motion_errors) {
  const std::string id = "[[1,0,0,0],[0,1,0,0],[0,0,1,0]]";
  auto with_motion = [](const std::string& motion) {
    return scene_of(R"({"name": "a", "points": [[0,0,0]]}, {"name": "b", "points": [[0,0,0]], "motion": )" + motion +
                    "}");
  };
  expect_error(with_motion(R"({"control_points": [)" + id + "]}"), "bodies[1].motion.type", "missing");
  expect_error(with_motion(R"({"type": "spline", "control_points": [)" + id + "]}"), "bodies[1].motion.type",
               "unknown motion type");
  expect_error(with_motion(R"({"type": "rational_bezier", "control_points": []})"),
               "bodies[1].motion.control_points", "at least one");
  expect_error(with_motion(R"({"type": "rational_bezier"})"), "bodies[1].motion.control_points", "missing");
  expect_error(with_motion(R"({"type": "rational_bezier", "control_points": [[[1,0,0,0],[0,1,0,0]]]})"),
               "bodies[1].motion.control_points[0]", "3 rows");
  expect_error(with_motion(R"({"type": "rational_bezier", "control_points": [)" + id +
                           R"(, [[1,0,0,0],[0,1,0,0],[0,0,1]]]})"),
               "bodies[1].motion.control_points[1][2]", "4 numbers");
  expect_error(with_motion(R"({"type": "rational_bezier", "control_points": [)" + id + R"(], "weights": [0]})"),
               "bodies[1].motion.weights[0]", "weight must be positive");
  expect_error(with_motion(R"({"type": "rational_bezier", "control_points": [)" + id + R"(], "weights": [1, 1]})"),
               "bodies[1].motion.weights", "expected 1 weights");
  expect_error(with_motion(R"({"type": "rational_bezier", "control_points": [)" + id + R"(], "interval": [1, 1]})"),
               "bodies[1].motion.interval", "less than");
  expect_error(with_motion(R"({"type": "rational_bezier", "control_points": [)" + id + R"(], "interval": [2, 1]})"),
               "bodies[1].motion.interval", "less than");
  expect_error(with_motion(R"({"type": "rational_bezier", "control_points": [)" + id + R"(], "interval": [0]})"),
               "bodies[1].motion.interval", "[t0, t1]");
  expect_error(with_motion(R"({"type": "rational_bezier", "control_points": [)" + id + R"(], "speed": 1})"),
               "bodies[1].motion.speed", "unknown field");
}

BOOST_AUTO_TEST_CASE(check_errors) {
  const std::string bodies = R"({"name": "a", "points": [[0,0,0]]}, {"name": "b", "points": [[1,0,0]]})";
  expect_error(scene_of(bodies, R"("checks": [["a", "c"]])"), "checks[0][1]", "unknown body");
  expect_error(scene_of(bodies, R"("checks": [["a", "a"]])"), "checks[0]", "itself");
  expect_error(scene_of(bodies, R"("checks": [["a", "b"], ["b", "a"]])"), "checks[1]", "duplicate check");
  expect_error(scene_of(bodies, R"("checks": [["a"]])"), "checks[0]", "exactly 2 bodies");
  expect_error(scene_of(bodies, R"("checks": [["a", 1]])"), "checks[0][1]", "expected a body name");
  expect_error(scene_of(bodies, R"("checks": {"a": "b"})"), "checks", "expected an array");
}

BOOST_AUTO_TEST_CASE(missing_file) {
  try {
    tmcert::parse_scene_file("/nonexistent/dir/scene.json");
    BOOST_FAIL("no error for a missing file");
  } catch (const InputError& e) {
    BOOST_TEST(std::string(e.what()) == "/nonexistent/dir/scene.json: cannot open file");
  }
}

#ifdef TMCERT_TEST_DATA
// Every file in tests/data/bad is rejected with a message naming the file
// and containing the substring listed in tests/data/bad/EXPECTED.
BOOST_AUTO_TEST_CASE(bad_scene_files) {
  const std::string dir = std::string(TMCERT_TEST_DATA) + "/bad/";
  std::ifstream expected(dir + "EXPECTED");
  BOOST_REQUIRE(expected.good());
  std::string line;
  int cases = 0;
  while (std::getline(expected, line)) {
    if (line.empty() || line[0] == '#') continue;
    const std::size_t tab = line.find('\t');
    BOOST_REQUIRE(tab != std::string::npos);
    const std::string file = dir + line.substr(0, tab), substring = line.substr(tab + 1);
    BOOST_TEST_CONTEXT(file) {
      std::string message;
      try {
        tmcert::parse_scene_file(file);
      } catch (const InputError& e) {
        message = e.what();
      }
      BOOST_TEST(message.rfind(file + ": ", 0) == 0, "message: " << message);
      BOOST_TEST(message.find(substring) != std::string::npos, "message: " << message);
    }
    ++cases;
  }
  BOOST_TEST(cases >= 30);
}
#endif

BOOST_AUTO_TEST_SUITE_END()
