// The scene reader's polygon checks (src/io/polygon.cpp): convex polygons
// stay one piece, others are triangulated exactly, vertices strictly
// between their neighbours go, and each kind of bad polygon has its
// message; mesh faces that are not exactly planar or have zero area.
#include "src/io/polygon.h"

#include "src/io/parse.h"

#include <boost/test/unit_test.hpp>

#include <string>
#include <vector>

using tmcert::Exact;
using tmcert::InputError;
using tmcert::Vec3E;
namespace reader = tmcert::reader;

namespace {

Vec3E v(long x, long y, long z = 0) { return {Exact(x), Exact(y), Exact(z)}; }

std::string error_of(const std::vector<Vec3E>& polygon) {
  try {
    reader::split_polygon(polygon, 0);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// Twice the area of a planar piece in the z = 0 plane.
Exact twice_area(const std::vector<Vec3E>& p) {
  Exact a = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3E &s = p[i], &t = p[(i + 1) % p.size()];
    a += s[0] * t[1] - s[1] * t[0];
  }
  return a;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(polygon)

BOOST_AUTO_TEST_CASE(convex_polygon_is_one_piece_without_its_collinear_vertex) {
  const auto [clean, pieces] = reader::split_polygon({v(0, 0), v(1, 0), v(2, 0), v(2, 2), v(0, 2)}, 7);
  BOOST_TEST(clean.size() == 4u);  // (1, 0) lies between its neighbours
  BOOST_REQUIRE(pieces.size() == 1u);
  BOOST_TEST(pieces[0].polygon == 7);
  BOOST_TEST(pieces[0].vertices.size() == 4u);
}

BOOST_AUTO_TEST_CASE(non_convex_polygon_is_triangulated_exactly) {
  // An L of area 3, clockwise.
  const std::vector<Vec3E> l = {v(0, 0), v(0, 2), v(1, 2), v(1, 1), v(2, 1), v(2, 0)};
  const auto [clean, pieces] = reader::split_polygon(l, 0);
  BOOST_TEST(clean.size() == 6u);
  BOOST_REQUIRE(pieces.size() == 4u);
  Exact total = 0;
  for (const tmcert::ConvexPiece& piece : pieces) {
    BOOST_TEST(piece.vertices.size() == 3u);
    BOOST_TEST(twice_area(piece.vertices) < 0);  // the polygon's orientation
    total += twice_area(piece.vertices);
  }
  BOOST_TEST(total == Exact(-6));
}

BOOST_AUTO_TEST_CASE(bad_polygons_say_why) {
  BOOST_TEST(error_of({v(0, 0), v(1, 0), v(2, 0)}) == "polygon vertices are collinear");
  BOOST_TEST(error_of({v(0, 0), v(1, 0), v(1, 1), v(0, 0)}) ==
             "vertex 0 and vertex 3 are equal (a polygon must be simple)");
  BOOST_TEST(error_of({v(0, 0), v(1, 0), v(1, 1), v(0, 1, 1)}) ==
             "polygon is not planar: vertex 3 is off the plane of vertices 0, 1 and 2");
  BOOST_TEST(error_of({v(0, 0), v(2, 2), v(2, 0), v(0, 2)}) ==
             "polygon is self-intersecting: edge 0-1 and edge 2-3 meet");
  BOOST_TEST(error_of({v(0, 0), v(2, 0), v(1, 0), v(1, 1)}) ==
             "adjacent edges overlap at vertex 1 (a polygon must be simple)");
  BOOST_TEST(tmcert::split_scene_polygon({v(0, 0), v(1, 0), v(0, 1)}, 3).second.at(0).polygon == 3);
}

BOOST_AUTO_TEST_CASE(mesh_faces_fan_or_degenerate) {
  tmcert::Body b;
  reader::MeshFaceCounts counts;
  reader::add_mesh_face(b, {v(0, 0), v(1, 0), v(1, 1), v(0, 1)}, 0, counts);  // planar: one polygon
  BOOST_TEST(b.polygons.size() == 1u);
  reader::add_mesh_face(b, {v(0, 0), v(1, 0), v(1, 1), v(0, 1, 1)}, 1, counts);  // not planar: a fan of 2
  BOOST_TEST(b.polygons.size() == 3u);
  BOOST_TEST(counts.fans == 1u);
  BOOST_TEST(counts.fan_triangles == 2u);
  reader::add_mesh_face(b, {v(0, 0), v(2, 0), v(1, 0)}, 2, counts);  // zero area: its segment
  BOOST_REQUIRE(b.segments.size() == 1u);
  BOOST_TEST((b.segments[0][0] == v(0, 0)));
  BOOST_TEST((b.segments[0][1] == v(2, 0)));
  reader::add_mesh_face(b, {v(5, 5), v(5, 5), v(5, 5)}, 3, counts);  // one point
  BOOST_TEST(b.points.size() == 1u);
  const std::vector<std::string> notes = reader::mesh_face_notes("s.json: bodies[0].mesh: m.obj: ", counts);
  BOOST_REQUIRE(notes.size() == 2u);
  BOOST_TEST(notes[0] == "s.json: bodies[0].mesh: m.obj: 1 face is not exactly planar (face 1): each is split "
                         "into the triangles of a fan from its first vertex, 2 triangles in all; the body is these "
                         "triangles");
  BOOST_TEST(notes[1] == "s.json: bodies[0].mesh: m.obj: 2 faces have zero area (faces 2, 3): each is read as the "
                         "segment (or point) it covers");
  BOOST_TEST(reader::mesh_face_notes("x", reader::MeshFaceCounts{}).empty());
}

BOOST_AUTO_TEST_SUITE_END()
