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

#include <vector>

namespace tmcert {

using PolygonList = std::vector<std::vector<Vec3E>>;

// The box [-x/2, x/2] x [-y/2, y/2] x [-z/2, z/2] (sizes > 0): 6 faces.
PolygonList box_polyhedron(const Vec3E& size);

// A prism with 16 sides around the z axis containing the cylinder of this
// radius and length (> 0), with the same flat caps at z = +-length/2.
PolygonList cylinder_polyhedron(const Exact& radius, const Exact& length);

// A polyhedron containing the ball of this radius (> 0) about the origin.
PolygonList sphere_polyhedron(const Exact& radius);

// The unit normals of the tangent planes (at distance `radius` from the
// origin) whose intersection the two circumscribed solids are, for tests:
// each face of the solid lies in one of these planes.
std::vector<Vec3E> cylinder_tangent_normals();
std::vector<Vec3E> sphere_tangent_normals();

}  // namespace tmcert
