// Fuzz target: the scene reader (tests/fuzz/README.md).  The first byte of
// the input picks what the rest is: a scene document (JSON, numbers,
// motions), or a mesh file (OFF, OBJ, STL) read alone and as the mesh of a
// scene body.  Property: the reader returns a scene or throws InputError
// (bad input, exit 3); any other exception, a crash, a hang or a sanitizer
// report is a bug.  A scene read must satisfy the model's own invariants
// checked below.
#include "src/io/mesh.h"
#include "src/io/parse.h"
#include "tests/fuzz/fuzz.h"

#include <unistd.h>

#include <cstdio>
#include <new>
#include <string>

namespace {

std::string temp_file(const char* extension) {
  return "/tmp/tmcert-fuzz-" + std::to_string(::getpid()) + extension;
}

void write_file(const std::string& path, const std::uint8_t* data, std::size_t size) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) tmcert::fuzz::fail("cannot write " + path);
  if (size) std::fwrite(data, 1, size, f);
  std::fclose(f);
}

void check_scene(const tmcert::Scene& scene) {
  if (scene.bodies.empty()) tmcert::fuzz::fail("a scene without bodies was accepted");
  for (const tmcert::Body& b : scene.bodies) {
    if (b.name.empty()) tmcert::fuzz::fail("a body without a name was accepted");
    if (b.name.find('\0') != std::string::npos) tmcert::fuzz::fail("a body name with U+0000 was accepted");
  }
  for (const auto& [a, b] : scene.checks)
    if (a < 0 || b < 0 || a >= static_cast<int>(scene.bodies.size()) || b >= static_cast<int>(scene.bodies.size()) ||
        a == b)
      tmcert::fuzz::fail("a check with a bad body index was accepted");
}

template <class F>
void expect_input_error_or_success(F&& f, const char* what) {
  try {
    f();
  } catch (const tmcert::InputError&) {
    // bad input, reported: fine
  } catch (const std::bad_alloc&) {
    tmcert::fuzz::fail(std::string(what) + ": out of memory (a limit is missing)");
  } catch (const std::exception& e) {
    tmcert::fuzz::fail(std::string(what) + ": unexpected exception: " + e.what());
  } catch (...) {
    tmcert::fuzz::fail(std::string(what) + ": unexpected exception");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0 || size > (1u << 20)) return 0;
  const std::uint8_t mode = data[0] % 4;
  ++data;
  --size;
  if (mode == 0) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    expect_input_error_or_success([&] { check_scene(tmcert::parse_scene_text(text, "fuzz.json")); }, "scene");
    return 0;
  }
  const char* extension = mode == 1 ? ".off" : mode == 2 ? ".obj" : ".stl";
  const std::string mesh = temp_file(extension);
  write_file(mesh, data, size);
  expect_input_error_or_success(
      [&] {
        const tmcert::MeshData m = tmcert::read_mesh(mesh);
        for (const auto& face : m.faces) {
          if (face.size() < 3) tmcert::fuzz::fail("a mesh face with fewer than 3 vertices was accepted");
          for (std::size_t i : face)
            if (i >= m.vertices.size()) tmcert::fuzz::fail("a mesh face index out of range was accepted");
        }
      },
      "mesh");
  // The same mesh as a (solid) body of a scene: the polygon checks, the
  // triangulation of its faces and the solid's shell checks.
  const std::string scene =
      std::string(R"({"format":"tmcert-scene/1","bodies":[{"name":"m","mesh":")") + mesh +
      R"(","solid":true},{"name":"p","points":[[2,0,0]],"motion":{"type":"rational_bezier","control_points":)"
      R"([[[1,0,0,0],[0,1,0,0],[0,0,1,0]],[[1,0,0,1],[0,1,0,0],[0,0,1,0]]]}}]})";
  expect_input_error_or_success([&] { check_scene(tmcert::parse_scene_text(scene, "/tmp/fuzz.json")); }, "mesh scene");
  std::remove(mesh.c_str());
  return 0;
}
