// A body's mass distribution, as the reader needs it (SCENE_FORMAT.md,
// DESIGN.md section 1): its moment matrix G = sum w_i m^_i m^_i^T
// (m^ = (m, 1)), exactly; whether G is positive definite, as every mass,
// given or default, must be for the body to have a metric; and the
// default mass distribution.  The metric built from G is src/metric/metric.h.
#pragma once

#include "src/model/model.h"

#include <array>
#include <vector>

namespace tmcert {

using Mat44E = std::array<Exact, 16>;  // row-major, symmetric here

// G, exactly (repeated points merged, their weights summed: the same G).
Mat44E moment_matrix(const MassDistribution& mass);

// The inverse of a symmetric 4x4 rational matrix, when it is positive
// definite (Gauss-Jordan without pivoting: a non-positive pivot proves it
// is not); false otherwise (`inv` then unspecified).
bool invert_positive_definite(const Mat44E& a, Mat44E& inv);

// Throws InputError (message starting with "moment matrix") when G is not
// positive definite, i.e. when the mass points lie in a plane.  An interval
// Sylvester test settles most distributions; the exact inverse decides the
// rest.
void require_positive_definite(const MassDistribution& mass);

// The default mass distribution of SCENE_FORMAT.md: the body's vertices with
// equal weights, plus, when they are coplanar, collinear or a single point,
// points offset off that flat set by a tenth of the body's size (the largest
// extent of its bounding box; `fallback_size` when that is zero).  The result
// always has a positive definite moment matrix.
MassDistribution default_mass(const std::vector<Vec3E>& vertices, const Exact& fallback_size);

// The `fallback_size` the default masses of a scene use: the largest extent
// of the bounding box of every body's vertices (polygons, segments and
// points, each in its body's own frame), or 1 when that is zero or there are
// none.
Exact default_mass_fallback_size(const std::vector<Body>& bodies);

}  // namespace tmcert
