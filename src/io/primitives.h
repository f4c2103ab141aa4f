// The URDF collision primitives as exact polyhedra, centred at the origin:
// a box exactly, a cylinder (axis z) and a sphere by circumscribed
// polyhedra with rational vertices that provably contain them
// (proofs/robot-links.md section 1, tests/io/test_robot.cpp).
//
// Both circumscribed solids come from one construction: tangent planes
// n . x = 1 (scaled by the radius) with rational UNIT normals
//     n_{k,i} = (c_k p_i, s_k),   p_i = (x_i, y_i),  x_i^2 + y_i^2 = 1,  c_k^2 + s_k^2 = 1,
// p_i from the rational points of the unit circle (12/13, 5/13),
// (697/985, 696/985) and their symmetric images: 16 azimuths, consecutive
// ones at most 22.7 degrees apart; (c_k, s_k) from the same points for the
// sphere's latitudes.  Each plane touches the unit ball, so the ball lies
// in the intersection of the half-spaces; the faces are that intersection.
#pragma once

#include "kernels/number_types.h"
#include "src/model/model.h"

#include <vector>

namespace tmcert {

using PolygonList = std::vector<std::vector<Vec3E>>;

// The box [-x/2, x/2] x [-y/2, y/2] x [-z/2, z/2] (sizes > 0): 6 faces.
PolygonList box_polyhedron(const Vec3E& size);

// A prism around the z axis containing the cylinder of this radius and
// length (> 0), with the same flat caps at z = +-length/2: 16 sides at
// level 0 (reaching at most 2% beyond the cylinder's radius), 64 at level 1
// (0.13%), 256 at level 2 (0.008%).
PolygonList cylinder_polyhedron(const Exact& radius, const Exact& length, int level = 0);

// A polyhedron containing the ball of this radius (> 0) about the origin:
// 114 faces at level 0 (reaching at most 4.1% beyond the ball's radius),
// 64 azimuths x 32 latitude bands at level 1 (0.25%), 256 x 128 at level 2
// (0.016%).
PolygonList sphere_polyhedron(const Exact& radius, int level = 0);

// The unit normals of the tangent planes (at distance `radius` from the
// origin) whose intersection the two circumscribed solids are, for tests:
// each face of the solid lies in one of these planes.
std::vector<Vec3E> cylinder_tangent_normals(int level = 0);
std::vector<Vec3E> sphere_tangent_normals(int level = 0);

// The finest level refine_primitive goes to: 2 for a cylinder (a prism of
// 256 sides), 1 for a sphere (its level 2 has some 33 000 faces, more than
// a search should carry for one primitive).
inline constexpr int kMaxCylinderLevel = 2;
inline constexpr int kMaxSphereLevel = 1;

// A body that is a URDF cylinder or sphere (Body::primitive) with its
// polyhedron at the next level (polygons and convex pieces; mass, solid
// and the rest kept); false, unchanged, at the finest level or for another
// body.
bool refine_primitive(Body& body);

}  // namespace tmcert
