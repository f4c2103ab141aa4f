// The object-oriented metric of a body (paper Section 2, DESIGN.md section 1).
//
// A mass distribution (points m_i, weights w_i > 0) gives the 4x4 moment
// matrix G = sum w_i m^_i m^_i^T with m^ = (m, 1).  For an affine map with
// 3x4 matrix M, ||M||^2 = trace(M G M^T).  The distortion rate is
// rho(x)^2 = x^T G^-1 x^ (x^ = (x, 1)): the largest ||delta(x)|| over affine
// delta with ||delta|| <= 1.  Everything is an exact rational.
#pragma once

#include "src/model/model.h"

#include <array>

namespace tmcert {

using Mat44E = std::array<Exact, 16>;  // row-major, symmetric here

class Metric {
 public:
  // Throws InputError (message starting with "moment matrix") when G is not
  // positive definite, i.e. when the mass points lie in a plane.
  static Metric from_mass(const MassDistribution& mass);

  // Throws as from_mass does when G is not positive definite; cheaper: an
  // interval Sylvester test settles most distributions without building the
  // exact inverse (from_mass decides the rest).
  static void require_positive_definite(const MassDistribution& mass);

  const Mat44E& moment() const { return g_; }
  const Mat44E& inverse() const { return g_inv_; }

  // rho(x)^2 = x^T G^-1 x^, exact.
  Exact rho2(const Vec3E& x) const;

  // ||M||^2 = trace(M G M^T) for a 3x4 matrix, exact.
  Exact norm2(const Mat34E& m) const;

 private:
  Mat44E g_, g_inv_;
};

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
