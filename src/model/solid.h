// Solids (SCENE_FORMAT.md "Solids", proofs/containment.md §4): a solid
// body's polygons form one or more closed shells, and its inside is the
// union of the shells' insides.
#pragma once

#include "src/model/model.h"

#include <string>
#include <vector>

namespace tmcert {

// The shell of each polygon of `b`: polygons linked by a shared edge (the
// same two endpoints, exactly) are in one shell.  Shells are numbered
// 0, 1, ... in the order of their first polygon.
std::vector<int> polygon_shells(const Body& b);

// Why `b` cannot be a solid: it has segments or points, or an edge belongs
// to other than exactly two polygons (so a shell is not closed).  Empty
// when it can.  Cheap (one pass over the edges).
std::string solid_problem(const Body& b);

// Why the shells of `b` (a body for which solid_problem is empty) are not
// each free of self-intersection: two polygons of one shell that meet
// outside their shared edges and vertices (a repeated polygon among them).
// Empty when every shell is embedded.  Exact; an interval filter and a box
// sweep keep it near linear for meshes.
std::string shell_intersection_problem(const Body& b);

}  // namespace tmcert
