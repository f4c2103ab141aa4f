// The scene reader's polygon checks (internal to src/io/): a polygon is
// planar, simple and has at least 3 non-collinear vertices, decided with
// exact arithmetic behind interval filters (the filtered-predicate pattern
// of DESIGN.md), and is split into convex pieces (CGAL's constrained
// Delaunay triangulation on a filtered exact kernel where it is not
// convex).  Mesh faces go through the same checks, with the rules for
// faces that are not exactly planar or have zero area
// (proofs/mesh-faces.md).
#pragma once

#include "src/model/model.h"

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace tmcert::reader {

constexpr std::size_t kMaxPolygonVertices = 100'000;

// Validates one input polygon and returns its cleaned vertices (vertices
// strictly between their neighbours removed) plus its convex pieces
// (tagged with `index`).  Throws InputError without a location.
std::pair<std::vector<Vec3E>, std::vector<ConvexPiece>> split_polygon(const std::vector<Vec3E>& vertices,
                                                                      int index);

// What add_mesh_face did beyond plain polygons, for the body's notes.
struct MeshFaceCounts {
  std::size_t fans = 0, fan_triangles = 0, fan_degenerate = 0, degenerate = 0;
  std::vector<std::size_t> fan_faces, degenerate_faces;  // the first few face numbers
};

// A face of a mesh file (docs/scene-format.md, "Data from real
// pipelines"; proofs/mesh-faces.md), added to `b` as polygons, segments or
// points:
//  * all vertices collinear (zero area; a triangle with a repeated
//    vertex too): the segment between its two extreme vertices, which is
//    exactly the face's point set (a point when all are equal);
//  * not exactly planar: the triangles (v0, v_k, v_k+1) of the fan from
//    its first vertex, each as a polygon (or, when of zero area, as its
//    segment); the fan's boundary is the face's boundary loop;
//  * otherwise the polygon checks of inline polygons (split_polygon).
// Throws InputError without a location.
void add_mesh_face(Body& b, const std::vector<Vec3E>& v, std::size_t face, MeshFaceCounts& counts);

// The notes on a mesh's fans and zero-area faces (none when there are
// none), each starting with `where`.
std::vector<std::string> mesh_face_notes(const std::string& where, const MeshFaceCounts& counts);

}  // namespace tmcert::reader
