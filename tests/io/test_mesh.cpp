// Mesh bodies (src/io/mesh.cpp, the "mesh" and "solid" fields in
// src/io/parse.cpp): every format read exactly, OBJ index forms, binary
// and ASCII STL, relative paths, closedness of solids, and one check per
// class of error (each an InputError naming the file and the line, face or
// field).
#include "src/io/mesh.h"
#include "src/io/parse.h"
#include "src/model/solid.h"
#include "src/verify/verify.h"

#include <boost/test/unit_test.hpp>

#include <unistd.h>

#include <array>
#include <atomic>
#include <bit>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

using tmcert::Exact;
using tmcert::InputError;
using tmcert::MeshData;
using tmcert::Scene;
using tmcert::Vec3E;

namespace fs = std::filesystem;

namespace {

#ifdef TMCERT_TEST_DATA
const std::string kData = TMCERT_TEST_DATA;
#else
const std::string kData = "tests/data";
#endif
const std::string kMeshes = kData + "/meshes/";

Exact q(const char* text) {
  Exact value;
  BOOST_REQUIRE(tmcert::parse_exact(text, value));
  return value;
}

Vec3E v(const char* x, const char* y, const char* z) { return {q(x), q(y), q(z)}; }

// A fresh directory under the system's temporary directory, removed at the end.
struct TempDir {
  fs::path path;
  TempDir() {
    static std::atomic<int> counter{0};
    path = fs::temp_directory_path() /
           ("tmcert-mesh-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    fs::create_directories(path);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
  std::string write(const std::string& name, const std::string& bytes) const {
    const fs::path file = path / name;
    fs::create_directories(file.parent_path());
    std::ofstream out(file, std::ios::binary);
    out << bytes;
    return file.string();
  }
};

// The message of the InputError that reading `file` throws, or "".
std::string mesh_error(const std::string& file) {
  try {
    tmcert::read_mesh(file);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// Reading `content` as `name` fails with a one-line message that starts
// with the file name and contains `expected`.
void expect_mesh_error(const TempDir& dir, const std::string& name, const std::string& content,
                       const std::string& expected) {
  const std::string file = dir.write(name, content);
  const std::string message = mesh_error(file);
  BOOST_TEST_CONTEXT(name << ": " << expected) {
    BOOST_TEST(!message.empty());
    BOOST_TEST(message.find('\n') == std::string::npos, "message: " << message);
    BOOST_TEST(message.rfind(file + ": ", 0) == 0, "message: " << message);
    BOOST_TEST(message.find(expected) != std::string::npos, "message: " << message);
  }
}

// ---------------------------------------------------------------- binary STL

void put32(std::string& out, std::uint32_t x) {
  for (int i = 0; i < 4; ++i) out += static_cast<char>((x >> (8 * i)) & 0xff);
}
void put_float(std::string& out, float f) { put32(out, std::bit_cast<std::uint32_t>(f)); }

using Triangle = std::array<std::array<float, 3>, 3>;

// A binary STL; the 80-byte header starts with `header` (often "solid ...").
std::string binary_stl(const std::vector<Triangle>& triangles, const std::string& header = "solid binary") {
  std::string out = header;
  out.resize(80, ' ');
  put32(out, static_cast<std::uint32_t>(triangles.size()));
  for (const Triangle& t : triangles) {
    for (int k = 0; k < 3; ++k) put_float(out, 0.0f);  // normal
    for (const auto& p : t)
      for (float c : p) put_float(out, c);
    out += '\0';
    out += '\0';
  }
  return out;
}

// ---------------------------------------------------------------- scenes

const std::string kMover =
    R"({"name": "p", "points": [[5, 5, 5]], "motion": {"type": "rational_bezier", "control_points": )"
    R"([[[1,0,0,0],[0,1,0,0],[0,0,1,0]], [[1,0,0,1],[0,1,0,0],[0,0,1,0]]]}})";

// A scene with one body made of `fields` and a moving point.
std::string scene_with(const std::string& fields) {
  return R"({"format": "tmcert-scene/1", "bodies": [{"name": "m", )" + fields + "}, " + kMover + "]}";
}

std::string scene_error(const std::string& text, const std::string& source = "t.json") {
  try {
    tmcert::parse_scene_text(text, source);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

void expect_scene_error(const std::string& text, const std::string& path, const std::string& expected) {
  const std::string message = scene_error(text);
  BOOST_TEST_CONTEXT(expected) {
    BOOST_TEST(message.find('\n') == std::string::npos, "message: " << message);
    BOOST_TEST(message.rfind("t.json: " + path + ": ", 0) == 0, "message: " << message);
    BOOST_TEST(message.find(expected) != std::string::npos, "message: " << message);
  }
}

// JSON for the six faces of the axis box [0, s]^3, outward.
std::string cube_polygons(const std::string& s = "1") {
  const std::string o = "0";
  auto p = [&](const std::string& x, const std::string& y, const std::string& z) {
    return "[" + x + "," + y + "," + z + "]";
  };
  auto quad = [&](const std::string& a, const std::string& b, const std::string& c, const std::string& d) {
    return "[" + a + "," + b + "," + c + "," + d + "]";
  };
  const std::string v0 = p(o, o, o), v1 = p(s, o, o), v2 = p(s, s, o), v3 = p(o, s, o);
  const std::string v4 = p(o, o, s), v5 = p(s, o, s), v6 = p(s, s, s), v7 = p(o, s, s);
  return "[" + quad(v0, v3, v2, v1) + "," + quad(v4, v5, v6, v7) + "," + quad(v0, v1, v5, v4) + "," +
         quad(v1, v2, v6, v5) + "," + quad(v2, v3, v7, v6) + "," + quad(v3, v0, v4, v7) + "]";
}

const std::vector<std::vector<std::size_t>> kCubeFaces = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                                          {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};

}  // namespace

BOOST_AUTO_TEST_SUITE(mesh)

// ---------------------------------------------------------------- formats

BOOST_AUTO_TEST_CASE(off_is_read_exactly) {
  const MeshData m = tmcert::read_mesh(kMeshes + "cube.off");
  BOOST_TEST_REQUIRE(m.vertices.size() == 8u);
  BOOST_TEST(m.vertices[1][0] == Exact(1, 10));  // 0.1 is 1/10, not the nearest double
  BOOST_TEST(m.vertices[6] == v("1/10", "1/10", "1/10"));
  BOOST_TEST(m.vertices[7] == v("0", "1/10", "1/10"));  // after a blank line
  BOOST_TEST(m.faces == kCubeFaces);
}

BOOST_AUTO_TEST_CASE(off_header_variants) {
  // CNOFF with the counts on the header line, signs, "1.", "1E0", and
  // normals and colours after the coordinates and indices (ignored).
  const MeshData c = tmcert::read_mesh(kMeshes + "cube_color.off");
  BOOST_TEST_REQUIRE(c.vertices.size() == 8u);
  BOOST_TEST(c.vertices[0] == v("-1", "-1", "-1"));
  BOOST_TEST(c.vertices[1] == v("1", "-1", "-1"));
  BOOST_TEST(c.vertices[2] == v("1", "1", "-1"));
  BOOST_TEST(c.vertices[5] == v("1", "-1", "1"));
  BOOST_TEST(c.faces == kCubeFaces);
  // 4OFF: homogeneous coordinates divided exactly.
  const MeshData h = tmcert::read_mesh(kMeshes + "cube_homogeneous.off");
  BOOST_TEST_REQUIRE(h.vertices.size() == 8u);
  BOOST_TEST(h.vertices[1] == v("1/3", "0", "0"));
  BOOST_TEST(h.vertices[6] == v("1/3", "1/3", "1/3"));
  BOOST_TEST(h.faces == kCubeFaces);
}

BOOST_AUTO_TEST_CASE(obj_index_forms) {
  // CRLF lines, a continuation line, w = 1, the x y z r g b extension, and
  // faces with i, i/j, i//k, i/j/k and negative indices.
  const MeshData m = tmcert::read_mesh(kMeshes + "cube.obj");
  BOOST_TEST_REQUIRE(m.vertices.size() == 8u);
  BOOST_TEST(m.vertices[0] == v("-1/2", "-1/2", "-1/2"));
  BOOST_TEST(m.vertices[5] == v("1/2", "-1/2", "1/2"));
  BOOST_TEST(m.vertices[6] == v("1/2", "1/2", "1/2"));
  BOOST_TEST(m.vertices[7] == v("-1/2", "1/2", "1/2"));
  BOOST_TEST(m.faces == kCubeFaces);
}

BOOST_AUTO_TEST_CASE(obj_forward_references_and_extension_case) {
  TempDir dir;
  const MeshData m = tmcert::read_mesh(dir.write("Tri.OBJ", "f 1 2 3\nv 0 0 0\nv 1e-3 0 0\nv 0 +2 0\n"));
  BOOST_TEST_REQUIRE(m.vertices.size() == 3u);
  BOOST_TEST(m.vertices[1] == v("1/1000", "0", "0"));
  BOOST_TEST(m.vertices[2] == v("0", "2", "0"));
  BOOST_TEST(m.faces == (std::vector<std::vector<std::size_t>>{{0, 1, 2}}));
}

BOOST_AUTO_TEST_CASE(ascii_stl_merges_vertices) {
  const MeshData m = tmcert::read_mesh(kMeshes + "tetra.stl");
  BOOST_TEST_REQUIRE(m.vertices.size() == 4u);  // 12 corners, 4 distinct points
  BOOST_TEST_REQUIRE(m.faces.size() == 4u);
  BOOST_TEST(m.vertices[0] == v("0", "0", "0"));
  BOOST_TEST(m.vertices[1] == v("0", "1", "0"));
  BOOST_TEST(m.vertices[2] == v("1", "0", "0"));
  BOOST_TEST(m.vertices[3] == v("0", "0", "1/4"));
  BOOST_TEST(m.faces[0] == (std::vector<std::size_t>{0, 1, 2}));
  BOOST_TEST(m.faces[3] == (std::vector<std::size_t>{2, 1, 3}));
}

BOOST_AUTO_TEST_CASE(binary_stl_is_exact_even_when_it_starts_with_solid) {
  TempDir dir;
  const float tenth = 0.1f;
  const std::string bytes = binary_stl({{{{0.0f, 0.0f, 0.0f}, {tenth, 0.0f, 0.0f}, {0.0f, tenth, 0.0f}}},
                                        {{{-0.0f, tenth, 0.0f}, {tenth, 0.0f, 0.0f}, {tenth, tenth, 0.0f}}}},
                                       "solid but binary");
  const MeshData m = tmcert::read_mesh(dir.write("two.stl", bytes));
  BOOST_TEST_REQUIRE(m.vertices.size() == 4u);  // -0 merges with 0
  // The float nearest 0.1 is exactly 13421773 / 2^27, not 1/10.
  BOOST_TEST(m.vertices[1][0] == Exact(13421773, 134217728));
  BOOST_TEST(m.vertices[1][0] != Exact(1, 10));
  BOOST_TEST(m.faces[0] == (std::vector<std::size_t>{0, 1, 2}));
  BOOST_TEST(m.faces[1] == (std::vector<std::size_t>{2, 1, 3}));
  // And a header that does not say "solid".
  const MeshData n = tmcert::read_mesh(dir.write("plain.STL", binary_stl({{{{1, 2, 3}, {4, 5, 6}, {7, 8, 10}}}}, "x")));
  BOOST_TEST_REQUIRE(n.vertices.size() == 3u);
  BOOST_TEST(n.vertices[2] == v("7", "8", "10"));
}

// ---------------------------------------------------------------- mesh errors

BOOST_AUTO_TEST_CASE(file_errors) {
  TempDir dir;
  const std::string missing = (dir.path / "missing.off").string();
  BOOST_TEST(mesh_error(missing) == missing + ": cannot open file");
  fs::create_directories(dir.path / "folder.obj");
  BOOST_TEST(mesh_error((dir.path / "folder.obj").string()).find("is a directory") != std::string::npos);
  expect_mesh_error(dir, "cube.ply", "ply\n", "unknown mesh file extension \".ply\"");
  expect_mesh_error(dir, "cube", "OFF\n", "unknown mesh file extension (none)");
}

BOOST_AUTO_TEST_CASE(off_errors) {
  TempDir dir;
  const std::string tri = "0 0 0\n1 0 0\n0 1 0\n";
  expect_mesh_error(dir, "a.off", "", "empty file");
  expect_mesh_error(dir, "b.off", "OF\n3 1 0\n", "line 1: malformed OFF header");
  expect_mesh_error(dir, "c.off", "OFF\n3\n", "line 2: malformed counts");
  expect_mesh_error(dir, "d.off", "OFF\n3 x 0\n", "line 2: face count is not a non-negative integer");
  expect_mesh_error(dir, "e.off", "OFF\n3 1 0\n0 0 nan\n1 0 0\n0 1 0\n3 0 1 2\n", "line 3: vertex 0: not a number");
  expect_mesh_error(dir, "f.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 inf 0\n3 0 1 2\n", "line 5: vertex 2: not a number");
  expect_mesh_error(dir, "g.off", "OFF\n3 1 0\n0 0 0\n1/2 0 0\n0 1 0\n3 0 1 2\n", "line 4: vertex 1: not a number");
  expect_mesh_error(dir, "h.off", "OFF\n3 1 0\n0 0\n", "line 3: vertex 0 needs 3 coordinates");
  expect_mesh_error(dir, "i.off", "OFF\n3 1 0\n" + tri + "3 0 1 3\n", "line 6: face 0: vertex index 3 out of range");
  expect_mesh_error(dir, "j.off", "OFF\n3 1 0\n" + tri + "2 0 1\n", "line 6: face 0 has 2 vertices");
  expect_mesh_error(dir, "k.off", "OFF\n3 1 0\n" + tri + "4 0 1 2\n", "line 6: face 0 announces 4 vertices");
  expect_mesh_error(dir, "l.off", "OFF\n3 2 0\n" + tri + "3 0 1 2\n", "line 7: unexpected end of file: expected face 1 of 2");
  expect_mesh_error(dir, "m.off", "OFF\n3 1 0\n" + tri + "3 0 1 2\n0 0 0\n", "line 7: unexpected content after the last face");
  expect_mesh_error(dir, "n.off", "OFF\n10000001 0 0\n", "line 2: too many vertices");
  expect_mesh_error(dir, "o.off", "OFF\n3 10000001 0\n", "line 2: too many faces");
  expect_mesh_error(dir, "p.off", "OFF\n3 1 0\n" + tri + "3 0 1 -2\n", "line 6: face 0: vertex index is not");
  expect_mesh_error(dir, "q.off", "nOFF\n3\n", "line 1: nOFF");
  expect_mesh_error(dir, "r.off", "OFF BINARY\n", "line 1: binary OFF is not supported");
  expect_mesh_error(dir, "s.off", "4OFF\n3 1 0\n0 0 0 0\n", "line 3: vertex 0: homogeneous coordinate w is 0");
  expect_mesh_error(dir, "t.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n", "line 5: unexpected end of file: expected vertex 2 of 3");
}

BOOST_AUTO_TEST_CASE(obj_errors) {
  TempDir dir;
  const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  expect_mesh_error(dir, "a.obj", tri + "f 1 2 0\n", "line 4: malformed face vertex \"0\"");
  expect_mesh_error(dir, "b.obj", tri + "f 1 2 4\n", "line 4: vertex index 4 out of range");
  expect_mesh_error(dir, "c.obj", tri + "f -1 -2 -4\n", "line 4: relative vertex index -4 out of range");
  expect_mesh_error(dir, "d.obj", tri + "f 1 2\n", "line 4: a face needs at least 3 vertices");
  expect_mesh_error(dir, "e.obj", "v 1 2\n", "line 1: a vertex needs x y z");
  expect_mesh_error(dir, "f.obj", "v 1 2 3 2\n", "line 1: vertex weight w = \"2\" is not supported");
  expect_mesh_error(dir, "g.obj", tri + "l 1 2\n", "line 4: line elements are not supported");
  expect_mesh_error(dir, "h.obj", tri + "p 1\n", "line 4: point elements are not supported");
  expect_mesh_error(dir, "i.obj", tri + "frobnicate 1\n", "line 4: unknown OBJ statement \"frobnicate\"");
  expect_mesh_error(dir, "j.obj", "v 1 2 NaN\n", "line 1: vertex: not a number: \"NaN\"");
  expect_mesh_error(dir, "k.obj", tri + "f 1/1/1/1 2 3\n", "line 4: malformed face vertex \"1/1/1/1\"");
  expect_mesh_error(dir, "l.obj", tri + "f 1/ 2 3\n", "line 4: malformed face vertex \"1/\"");
  expect_mesh_error(dir, "m.obj", tri + "f 1/x 2 3\n", "line 4: malformed face vertex");
  expect_mesh_error(dir, "n.obj", tri + "curv 0 1 1 2\n", "line 4: free-form curves and surfaces are not supported");
  // The error names the first line of a continued line.
  expect_mesh_error(dir, "o.obj", tri + "f 1 2 \\\n 9\n", "line 4: vertex index 9 out of range");
}

BOOST_AUTO_TEST_CASE(stl_errors) {
  TempDir dir;
  const std::string facet = "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n";
  expect_mesh_error(dir, "a.stl", "solid x\n" + facet, "line 9: unexpected end of file (expected \"facet\" or \"endsolid\")");
  expect_mesh_error(dir, "b.stl", "solid x\nfacet normal 0 0 1\nouter lop\n", "line 3: expected \"loop\", got \"lop\"");
  expect_mesh_error(dir, "c.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0\nvertex 1 0 0\n",
                    "line 4: a vertex needs 3 coordinates");
  expect_mesh_error(dir, "d.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 inf\n",
                    "line 4: vertex: not a number: \"inf\"");
  expect_mesh_error(dir, "e.stl", "solid x\n" + facet + "endsolid x\njunk\n", "line 10: unexpected content after \"endsolid\"");
  expect_mesh_error(dir, "f.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nvertex 1 1 0\n",
                    "line 7: expected \"endloop\", got \"vertex\"");

  // Binary: size mismatch (truncated), short files, NaN and infinity.
  std::string good = binary_stl({{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}}, {{{1, 0, 0}, {1, 1, 0}, {0, 1, 0}}}});
  expect_mesh_error(dir, "g.stl", good.substr(0, good.size() - 7),
                    "truncated or malformed binary STL: the header announces 2 triangles (184 bytes), the file has 177 bytes");
  expect_mesh_error(dir, "h.stl", std::string("\x01\x02\x03", 3), "truncated binary STL: 3 bytes");
  expect_mesh_error(dir, "i.stl", binary_stl({}, "no header word").substr(0, 50), "truncated binary STL: 50 bytes");
  // Cut inside a header that says "solid": read as ASCII STL, which ends too early.
  expect_mesh_error(dir, "i2.stl", good.substr(0, 50), "line 2: unexpected end of file");
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  expect_mesh_error(dir, "j.stl", binary_stl({{{{0, 0, 0}, {1, nan, 0}, {0, 1, 0}}}}),
                    "triangle 0: vertex 1 has a NaN coordinate");
  expect_mesh_error(dir, "k.stl", binary_stl({{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}}, {{{0, 0, 0}, {1, 0, 0}, {0, 1, -inf}}}}),
                    "triangle 1: vertex 2 has a infinite coordinate");
}

// ---------------------------------------------------------------- scenes

BOOST_AUTO_TEST_CASE(mesh_paths_are_relative_to_the_scene_file) {
  const Scene scene = tmcert::parse_scene_file(kMeshes + "scenes/solid-cube.json");
  const tmcert::Body& cube = scene.bodies[0];
  BOOST_TEST(cube.solid);
  BOOST_TEST_REQUIRE(cube.polygons.size() == 6u);
  BOOST_TEST(cube.polygons[0][0] == v("-1/2", "-1/2", "-1/2"));
  BOOST_TEST(cube.pieces.size() == 6u);
  // The default mass uses the mesh vertices.
  BOOST_TEST(cube.mass_is_default);
  BOOST_TEST(cube.mass.points.size() >= 8u);
}

BOOST_AUTO_TEST_CASE(mesh_polygons_follow_explicit_polygons) {
  const Scene scene = tmcert::parse_scene_file(kMeshes + "scenes/mixed.json");
  const tmcert::Body& table = scene.bodies[0];
  BOOST_TEST(!table.solid);
  BOOST_TEST_REQUIRE(table.polygons.size() == 5u);
  BOOST_TEST(table.polygons[0][1] == v("1", "0", "0"));  // the explicit square
  BOOST_TEST(table.polygons[4][2] == v("0", "0", "1/4"));  // the tetrahedron's last face
  BOOST_TEST_REQUIRE(table.pieces.size() == 5u);
  BOOST_TEST(table.pieces.back().polygon == 4);
}

BOOST_AUTO_TEST_CASE(text_scenes_resolve_against_the_current_directory) {
  // Absolute paths work from anywhere.
  const std::string absolute = fs::absolute(kMeshes + "cube.off").string();
  const Scene a = tmcert::parse_scene_text(scene_with(R"("mesh": ")" + absolute + "\""), "<memory>");
  BOOST_TEST(a.bodies[0].polygons.size() == 6u);
  // A relative path with a source that is not a file: the current directory.
  const fs::path saved = fs::current_path();
  fs::current_path(kMeshes);
  std::string message;
  try {
    const Scene b = tmcert::parse_scene_text(scene_with(R"("mesh": "tetra.stl")"), "<memory>");
    BOOST_TEST(b.bodies[0].polygons.size() == 4u);
    tmcert::parse_scene_text(scene_with(R"("mesh": "scenes/../cube.obj")"), "<memory>");
  } catch (const std::exception& e) {
    message = e.what();
  }
  fs::current_path(saved);
  BOOST_TEST(message == "");
}

BOOST_AUTO_TEST_CASE(scene_in_a_temporary_directory) {
  TempDir dir;
  dir.write("sub/part.stl", binary_stl({{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}}}));
  const std::string scene = dir.write("scene.json", scene_with(R"("mesh": "sub/part.stl")"));
  const Scene s = tmcert::parse_scene_file(scene);
  BOOST_TEST_REQUIRE(s.bodies[0].polygons.size() == 1u);
  BOOST_TEST(s.bodies[0].polygons[0][1] == v("1", "0", "0"));
  // The scene file's directory, not the current one.
  const std::string message = scene_error(scene_with(R"("mesh": "sub/part.stl")"), "t.json");
  BOOST_TEST(message.find("sub/part.stl: cannot open file") != std::string::npos, "message: " << message);
}

BOOST_AUTO_TEST_CASE(mesh_field_errors) {
  TempDir dir;
  expect_scene_error(scene_with(R"("mesh": 3)"), "bodies[0].mesh", "expected a mesh file name");
  expect_scene_error(scene_with(R"("mesh": "")"), "bodies[0].mesh", "an empty string");
  const std::string missing = (dir.path / "nowhere.obj").string();
  expect_scene_error(scene_with(R"("mesh": ")" + missing + "\""), "bodies[0].mesh", missing + ": cannot open file");
  // Reader errors keep the file and line.
  const std::string bad = dir.write("bad.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n");
  expect_scene_error(scene_with(R"("mesh": ")" + bad + "\""), "bodies[0].mesh",
                     bad + ": line 6: face 0: vertex index 7 out of range");
  // Faces that stay errors: a planar face that is not simple, a repeated
  // vertex in a face of positive area (zero-area and non-planar faces are
  // read: data_from_real_pipelines below).
  const std::string crossed = dir.write("crossed.off", "OFF\n4 1 0\n0 0 0\n1 1 0\n1 0 0\n0 1 0\n4 0 1 2 3\n");
  expect_scene_error(scene_with(R"("mesh": ")" + crossed + "\""), "bodies[0].mesh",
                     crossed + ": face 0: polygon is self-intersecting");
  const std::string repeated = dir.write("repeated.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 2 3 4\n");
  expect_scene_error(scene_with(R"("mesh": ")" + repeated + "\""), "bodies[0].mesh",
                     repeated + ": face 0: vertex 1 and vertex 2 are equal");
  const std::string empty = dir.write("empty.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n");
  expect_scene_error(scene_with(R"("mesh": ")" + empty + "\""), "bodies[0].mesh", empty + ": mesh has no faces");
}

// docs/scene-format.md, "Data from real pipelines": a mesh face that is not
// exactly planar becomes the triangles of the fan from its first vertex; a
// zero-area face becomes the segment (or point) it covers; the scene notes
// both.  Inline polygons stay strict.
BOOST_AUTO_TEST_CASE(data_from_real_pipelines) {
  TempDir dir;
  // A quad whose last vertex is 1e-7 off the plane of the others.
  const std::string quad = dir.write("quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 1e-7\nf 1 2 3 4\n");
  const Scene s = tmcert::parse_scene_text(scene_with(R"("mesh": ")" + quad + "\""), "t.json");
  const tmcert::Body& m = s.bodies[0];
  BOOST_REQUIRE_EQUAL(m.polygons.size(), 2u);
  // The fan from vertex 0: (v0, v1, v2) and (v0, v2, v3), exactly.
  BOOST_TEST((m.polygons[0] == std::vector<Vec3E>{v("0", "0", "0"), v("1", "0", "0"), v("1", "1", "0")}));
  BOOST_TEST((m.polygons[1] == std::vector<Vec3E>{v("0", "0", "0"), v("1", "1", "0"), v("0", "1", "1e-7")}));
  BOOST_REQUIRE_EQUAL(s.notes.size(), 1u);
  BOOST_TEST(s.notes[0] == "t.json: bodies[0].mesh: " + quad +
                               ": 1 face is not exactly planar (face 0): each is split into the triangles of a fan "
                               "from its first vertex, 2 triangles in all; the body is these triangles");
  BOOST_TEST(s.warnings.empty());

  // Zero-area faces: three collinear vertices (a segment between the
  // extreme ones, whatever their order), a repeated vertex after STL
  // merging, a face of one point; ordinary faces keep their polygons.
  const std::string slivers = dir.write(
      "slivers.stl", binary_stl({{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}},
                                 {{{2, 0, 0}, {0, 0, 0}, {1, 0, 0}}},
                                 {{{0, 0, 0}, {0, 1, 0}, {0, 1, 0}}},
                                 {{{3, 3, 3}, {3, 3, 3}, {3, 3, 3}}}}));
  const Scene z = tmcert::parse_scene_text(scene_with(R"("mesh": ")" + slivers + "\""), "t.json");
  const tmcert::Body& b = z.bodies[0];
  BOOST_TEST(b.polygons.size() == 1u);
  BOOST_REQUIRE_EQUAL(b.segments.size(), 2u);
  BOOST_TEST((b.segments[0] == std::array<Vec3E, 2>{v("2", "0", "0"), v("0", "0", "0")}));
  BOOST_TEST((b.segments[1] == std::array<Vec3E, 2>{v("0", "0", "0"), v("0", "1", "0")}));
  BOOST_TEST((b.points == std::vector<Vec3E>{v("3", "3", "3")}));
  BOOST_REQUIRE_EQUAL(z.notes.size(), 1u);
  BOOST_TEST(z.notes[0] == "t.json: bodies[0].mesh: " + slivers +
                               ": 3 faces have zero area (faces 1, 2, 3): each is read as the segment (or point) it covers");

  // A fan triangle of zero area (the non-planar face passes twice through a
  // line) is its segment; the note counts it.
  const std::string folded = dir.write("folded.off", "OFF\n5 1 0\n0 0 0\n1 0 0\n2 0 0\n1 1 1\n0 1 0\n5 0 1 2 3 4\n");
  const Scene f = tmcert::parse_scene_text(scene_with(R"("mesh": ")" + folded + "\""), "t.json");
  BOOST_TEST(f.bodies[0].polygons.size() == 2u);
  BOOST_TEST(f.bodies[0].segments.size() == 1u);
  BOOST_REQUIRE_EQUAL(f.notes.size(), 1u);
  BOOST_TEST(f.notes[0].find("3 triangles in all (1 of zero area, read as segments)") != std::string::npos, f.notes[0]);

  // Inline polygons stay strict.
  expect_scene_error(scene_with(R"("polygons": [[[0,0,0],[1,0,0],[1,1,0],[0,1,"1e-7"]]])"), "bodies[0].polygons[0]",
                     "polygon is not planar");
  expect_scene_error(scene_with(R"("polygons": [[[0,0,0],[1,0,0],[2,0,0]]])"), "bodies[0].polygons[0]",
                     "polygon vertices are collinear");
  // A clean mesh has no notes.
  const std::string clean = dir.write("clean.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n");
  BOOST_TEST(tmcert::parse_scene_text(scene_with(R"("mesh": ")" + clean + "\""), "t.json").notes.empty());
}

// A fan of a non-planar face and a zero-area face are features like any
// other: a point crossing the fan's second triangle, and a segment crossing
// the sliver, are collisions; one passing beside them is safe.
BOOST_AUTO_TEST_CASE(real_pipeline_faces_are_verified) {
  TempDir dir;
  const std::string quad = dir.write("quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 1e-7\nf 1 2 3 4\n");
  auto verdict = [&](const std::string& mover) {
    const std::string text = R"({"format": "tmcert-scene/1", "bodies": [{"name": "m", "mesh": ")" + quad + R"("}, )" +
                             mover + "]}";
    return tmcert::verify_scene(tmcert::parse_scene_text(text, "t.json"), tmcert::VerifyOptions{}).verdict;
  };
  const std::string down = R"({"name": "p", "points": [[0.25, 0.75, 1]], "motion": {"type": "rational_bezier", )"
                           R"("control_points": [[[1,0,0,0],[0,1,0,0],[0,0,1,0]], [[1,0,0,0],[0,1,0,0],[0,0,1,-2]]]}})";
  BOOST_TEST(verdict(down) == tmcert::Verdict::Collision);
  const std::string beside = R"({"name": "p", "points": [[1.5, 0.75, 1]], "motion": {"type": "rational_bezier", )"
                             R"("control_points": [[[1,0,0,0],[0,1,0,0],[0,0,1,0]], [[1,0,0,0],[0,1,0,0],[0,0,1,-2]]]}})";
  BOOST_TEST(verdict(beside) == tmcert::Verdict::Safe);

  const std::string sliver = dir.write("sliver.off", "OFF\n3 1 0\n0 0 0\n2 0 0\n1 0 0\n3 0 1 2\n");
  const std::string text = R"({"format": "tmcert-scene/1", "bodies": [{"name": "m", "mesh": ")" + sliver +
                           R"("}, {"name": "s", "segments": [[[1.5, -1, 1], [1.5, 1, 1]]], "motion": {"type": )"
                           R"("rational_bezier", "control_points": [[[1,0,0,0],[0,1,0,0],[0,0,1,0]], )"
                           R"([[1,0,0,0],[0,1,0,0],[0,0,1,-2]]]}}]})";
  const tmcert::SceneResult r = tmcert::verify_scene(tmcert::parse_scene_text(text, "t.json"), tmcert::VerifyOptions{});
  BOOST_TEST(r.verdict == tmcert::Verdict::Collision);
  BOOST_REQUIRE(r.checks[0].witness);
  BOOST_TEST(r.checks[0].witness->t == Exact(1, 2));
}

BOOST_AUTO_TEST_CASE(solid_needs_a_closed_surface) {
  // Explicit polygons forming a cube: accepted.
  const Scene cube = tmcert::parse_scene_text(scene_with(R"("solid": true, "polygons": )" + cube_polygons("\"1/3\"")), "t.json");
  BOOST_TEST(cube.bodies[0].solid);
  // Half of the faces from a mesh, half explicit: still one closed surface.
  const Scene ok = tmcert::parse_scene_text(
      scene_with(R"("solid": true, "mesh": ")" + kMeshes + "tetra.stl\""), "t.json");
  BOOST_TEST(ok.bodies[0].solid);
  BOOST_TEST(!tmcert::parse_scene_text(scene_with(R"("solid": false, "mesh": ")" + kMeshes + "open_box.off\""), "t.json")
                  .bodies[0]
                  .solid);

  expect_scene_error(scene_with(R"("solid": true, "mesh": ")" + kMeshes + "open_box.off\""), "bodies[0].solid",
                     "not a closed surface: the edge (1, 0, 1)-(0, 0, 1) (of polygon 1) belongs to 1 polygon (every "
                     "edge of a solid must belong to exactly 2)");
  // A fin on an edge of the cube: that edge belongs to 3 polygons.
  std::string fin = cube_polygons();
  fin.back() = ',';
  fin += "[[0,0,0],[1,0,0],[1,-1,0]]]";
  expect_scene_error(scene_with(R"("solid": true, "polygons": )" + fin), "bodies[0].solid",
                     "the edge (0, 0, 0)-(1, 0, 0) (of polygon 0) belongs to 3 polygons");
  expect_scene_error(scene_with(R"("solid": true, "polygons": )" + cube_polygons() + R"(, "points": [[0,0,0]])"),
                     "bodies[0].solid", "a solid body cannot have segments or points");
  expect_scene_error(scene_with(R"("solid": true, "polygons": )" + cube_polygons() + R"(, "segments": [[[0,0,0],[1,1,1]]])"),
                     "bodies[0].solid", "a solid body cannot have segments or points");
  // The front face split in two: geometrically closed, but the bottom
  // edge (0,0,0)-(1,0,0) meets a T-junction at (1/2,0,0) and is not
  // matched edge for edge, so it is refused (conservatively).
  const std::string split_front =
      R"([[[0,0,0],[0,1,0],[1,1,0],[1,0,0]], [[0,0,1],[1,0,1],[1,1,1],[0,1,1]],)"
      R"( [[0,0,0],["1/2",0,0],["1/2",0,1],[0,0,1]], [["1/2",0,0],[1,0,0],[1,0,1],["1/2",0,1]],)"
      R"( [[1,0,0],[1,1,0],[1,1,1],[1,0,1]], [[1,1,0],[0,1,0],[0,1,1],[1,1,1]], [[0,1,0],[0,0,0],[0,0,1],[0,1,1]]])";
  expect_scene_error(scene_with(R"("solid": true, "polygons": )" + split_front), "bodies[0].solid",
                     "the edge (0, 0, 0)-(1, 0, 0) (of polygon 0) belongs to 1 polygon");
  // Without the T-junction (the bottom and top split as well) it is closed.
  std::string matched = split_front;
  const std::string bottom = R"([[0,0,0],[0,1,0],[1,1,0],[1,0,0]])", top = R"([[0,0,1],[1,0,1],[1,1,1],[0,1,1]])";
  matched.replace(matched.find(bottom), bottom.size(),
                  R"([[0,0,0],[0,1,0],["1/2",1,0],["1/2",0,0]], [["1/2",0,0],["1/2",1,0],[1,1,0],[1,0,0]])");
  matched.replace(matched.find(top), top.size(),
                  R"([[0,0,1],["1/2",0,1],["1/2",1,1],[0,1,1]], [["1/2",0,1],[1,0,1],[1,1,1],["1/2",1,1]])");
  matched.replace(matched.find(R"([[1,1,0],[0,1,0],[0,1,1],[1,1,1]])"), 33,
                  R"([[1,1,0],["1/2",1,0],["1/2",1,1],[1,1,1]], [["1/2",1,0],[0,1,0],[0,1,1],["1/2",1,1]])");
  BOOST_TEST(tmcert::parse_scene_text(scene_with(R"("solid": true, "polygons": )" + matched), "t.json").bodies[0].solid);
}

BOOST_AUTO_TEST_CASE(shells_must_not_intersect_themselves) {
  // SCENE_FORMAT.md "Solids": one or more closed shells, none intersecting
  // itself; shells may overlap one another.
  auto cube_at = [](int o, int s) {
    std::string text = cube_polygons(std::to_string(s));
    // Shift every coordinate by o: cube_polygons writes "0" and the size.
    std::string out;
    for (std::size_t i = 0; i < text.size(); ++i) {
      const bool number_start = (text[i] == '0' || std::isdigit(static_cast<unsigned char>(text[i]))) &&
                                (i == 0 || text[i - 1] == '[' || text[i - 1] == ',');
      if (!number_start) {
        out += text[i];
        continue;
      }
      std::size_t j = i;
      while (j < text.size() && std::isdigit(static_cast<unsigned char>(text[j]))) ++j;
      out += std::to_string(std::stoi(text.substr(i, j - i)) + o);
      i = j - 1;
    }
    return out.substr(1, out.size() - 2);  // without the outer brackets
  };
  auto solid = [&](const std::string& polygons) {
    return tmcert::parse_scene_text(scene_with(R"("solid": true, "polygons": [)" + polygons + "]"), "t.json");
  };
  // Overlapping, nested and corner-touching cubes: separate shells, accepted.
  for (const std::string& two : {cube_at(0, 2) + "," + cube_at(1, 2), cube_at(0, 3) + "," + cube_at(1, 1),
                                 cube_at(0, 1) + "," + cube_at(1, 1)}) {
    const Scene scene = solid(two);
    const std::vector<int> shells = tmcert::polygon_shells(scene.bodies[0]);
    BOOST_TEST(shells == (std::vector<int>{0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 1}), boost::test_tools::per_element());
  }
  // One triangle listed twice: every edge has two uses, but it is no shell.
  expect_scene_error(scene_with(R"("solid": true, "polygons": [[[0,0,0],[1,0,0],[0,1,0]], [[0,1,0],[0,0,0],[1,0,0]]])"),
                     "bodies[0].solid", "shell 0 intersects itself: polygon 1 repeats polygon 0");
  // A bipyramid over (0,0,0), (4,0,0), (0,4,0) with apexes (1,1,2) and
  // (-5,1,1): the lower faces cut through the upper ones.
  const std::string a = "[0,0,0]", b = "[4,0,0]", c = "[0,4,0]", p = "[1,1,2]";
  auto bipyramid = [&](const std::string& q) {
    return "[" + p + "," + a + "," + b + "],[" + p + "," + b + "," + c + "],[" + p + "," + c + "," + a + "],[" + q +
           "," + b + "," + a + "],[" + q + "," + c + "," + b + "],[" + q + "," + a + "," + c + "]";
  };
  BOOST_TEST(solid(bipyramid("[1,1,-2]")).bodies[0].solid);
  expect_scene_error(scene_with(R"("solid": true, "polygons": [)" + bipyramid("[-5,1,1]") + "]"), "bodies[0].solid",
                     "shell 0 intersects itself: polygons");
  // A tetrahedron whose apex is pushed into its base's plane, inside the
  // base: every edge still has two faces, but the side faces lie on the
  // base (coplanar, on the same side of each shared edge).
  const std::string t0 = "[0,0,0]", t1 = "[2,0,0]", t2 = "[0,2,0]", t3 = R"(["1/2","1/2",0])";
  expect_scene_error(scene_with(R"("solid": true, "polygons": [[)" + t0 + "," + t2 + "," + t1 + "],[" + t0 + "," + t1 +
                                "," + t3 + "],[" + t1 + "," + t2 + "," + t3 + "],[" + t2 + "," + t0 + "," + t3 + "]]"),
                     "bodies[0].solid", "shell 0 intersects itself: polygons 0 and 1");
}

BOOST_AUTO_TEST_CASE(mesh_bodies_are_verified_as_surfaces) {
  // The cube [0, 1/10]^3 from cube.off, fixed; a point crossing it, and one
  // passing above it.
  auto run = [](const std::string& z) {
    const std::string text = R"({"format": "tmcert-scene/1", "bodies": [{"name": "cube", "mesh": ")" + kMeshes +
                             R"(cube.off"}, {"name": "p", "points": [[-1, "1/20", )" + z +
                             R"(]], "motion": {"type": "rational_bezier", "control_points": )"
                             R"([[[1,0,0,0],[0,1,0,0],[0,0,1,0]], [[1,0,0,2],[0,1,0,0],[0,0,1,0]]]}}]})";
    const Scene scene = tmcert::parse_scene_text(text, "t.json");
    tmcert::VerifyOptions options;
    options.epsilon = tmcert::default_epsilon(scene);
    return tmcert::verify_scene(scene, options).verdict;
  };
  BOOST_TEST(run("\"1/20\"") == tmcert::Verdict::Collision);
  BOOST_TEST(run("1") == tmcert::Verdict::Safe);
}

BOOST_AUTO_TEST_SUITE_END()
