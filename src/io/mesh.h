// Reading polygon meshes (OFF, OBJ, STL, COLLADA) exactly, for "mesh" bodies
// (SCENE_FORMAT.md).  Text coordinates are read as the exact decimals they
// spell; binary STL floats are converted exactly (every finite float is a
// rational).  Nothing is rounded.
#pragma once

#include "kernels/number_types.h"

#include <cstddef>
#include <string>
#include <vector>

namespace tmcert {

// A polygon soup: vertex coordinates and faces as indices into `vertices`,
// in file order.  Faces are not validated geometrically here (the scene
// parser runs each face through the polygon checks); each has >= 3 indices,
// all in range.  Vertices no face uses are kept but carry no geometry.
struct MeshData {
  std::vector<Vec3E> vertices;
  std::vector<std::vector<std::size_t>> faces;
  // Read from single-precision floats (COLLADA: the result says so), and
  // the format's name for that note.
  bool from_floats = false;
  std::string format;
};

// Limits that turn absurd files into errors instead of exhausted memory.
inline constexpr std::size_t kMaxMeshVertices = 10'000'000;
inline constexpr std::size_t kMaxMeshFaces = 10'000'000;
inline constexpr std::size_t kMaxMeshFaceVertices = 100'000;       // per face
inline constexpr std::size_t kMaxMeshFaceIndices = 100'000'000;    // all faces
inline constexpr unsigned long long kMaxMeshFileBytes = 1ull << 30;

// Reads `file` by its extension (case-insensitive):
//  .off  OFF with header [ST][C][N][4]OFF (extra per-vertex and per-face
//        data such as colours, normals, texture coordinates are ignored;
//        4OFF divides by w exactly); nOFF and binary OFF are refused.
//  .obj  Wavefront OBJ: `v x y z` (a fourth value w must be exactly 1; six
//        values are read as x y z r g b), `f`/`fo` with i, i/j, i//k, i/j/k
//        and negative (relative) indices; vt/vn/vp and grouping, smoothing
//        and material statements are ignored; line (`l`), point (`p`) and
//        free-form elements are refused rather than dropped.
//  .stl  ASCII or binary (binary iff the size is 84 + 50 * count, or the
//        file holds a NUL byte); vertices are merged by exact equality.
//  .dae  COLLADA through assimp: polygons as assimp triangulates them,
//        every mesh instance placed by its node transforms multiplied
//        exactly from assimp's floats (the <unit> scale included, the up
//        axis as written), vertices merged by exact equality; lines and
//        points are refused.  Coordinates are the exact values of those
//        floats under those products (MeshData::from_floats).
// Throws InputError "<file>: line N: what" (or "<file>: triangle N: what",
// "<file>: what") on unreadable, malformed or out-of-limits input.
MeshData read_mesh(const std::string& file);

}  // namespace tmcert
