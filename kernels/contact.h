// The three contact tests of the paper (vertex x face, edge x edge,
// face x vertex) as minimum-of-quadratic tests in world coordinates
// (DESIGN.md sections 2-4, proofs/contact-tests.md).
//
// For a ball B(g, R) of affine maps around the moving body's motion piece,
// every contact between feature X (body 1, moving) and Y (body 2) on that
// piece satisfies, for some x in X, y in Y,
//     Phi(x, y) = |g1(x) - g2(y)|^2 - R^2 (rho1(x)^2 + rho2(y)^2) <= 0,
// where the rho2 term is present only when body 2 moves too (joint ball).
// With x = oX + EX sX and y = oY + EY sY, Phi is a quadratic in the two
// parameters s = (sX, sY), and the pair is cleared exactly when the minimum
// of Phi over the parameter domain is positive.
#pragma once

#include "kernels/quadratic_min.h"

#include <array>
#include <cstdint>
#include <vector>

namespace tmcert {

template <class FT>
using Vec3 = std::array<FT, 3>;

// A point (dim 0), segment (dim 1) or convex polygon (dim 2) of one body in
// that body's frame (or in world coordinates for a fixed body).
template <class FT>
struct FeatureGeometry {
  int dim = 0;
  Vec3<FT> origin;
  std::array<Vec3<FT>, 2> axis;  // x(s) = origin + s1 axis[0] + s2 axis[1]
  // rho(x(s))^2 = [s; 1]^T Q [s; 1], Q symmetric 3x3 with index 2 the
  // constant slot; only the first `dim` parameter slots are used.
  std::array<FT, 9> rho2;
  // dim 2: the polygon's vertices in parameter coordinates, in order.
  std::vector<Pt2<FT>> domain;
  int orientation = 1;

  const FT& q(int i, int j) const { return rho2[3 * i + j]; }
};

// Ball of affine maps for one motion piece: center(s) and squared radius.
template <class FT>
struct Placement {
  std::array<FT, 12> g1;     // center for body 1, row-major [A | a]
  bool body2_moving = false;
  std::array<FT, 12> g2;     // center for body 2 when it moves
  FT r2;                     // squared radius of the (joint) ball
};

enum class ContactKind : std::uint8_t { VertexFace = 0, EdgeEdge = 1, FaceVertex = 2 };

namespace detail {

template <class FT>
Vec3<FT> apply_point(const std::array<FT, 12>& g, const Vec3<FT>& x) {
  Vec3<FT> r;
  for (int i = 0; i < 3; ++i) r[i] = g[4 * i] * x[0] + g[4 * i + 1] * x[1] + g[4 * i + 2] * x[2] + g[4 * i + 3];
  return r;
}

template <class FT>
Vec3<FT> apply_vector(const std::array<FT, 12>& g, const Vec3<FT>& v) {
  Vec3<FT> r;
  for (int i = 0; i < 3; ++i) r[i] = g[4 * i] * v[0] + g[4 * i + 1] * v[1] + g[4 * i + 2] * v[2];
  return r;
}

template <class FT>
FT dot(const Vec3<FT>& a, const Vec3<FT>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

}  // namespace detail

// The quadratic Phi(s) for features X (body 1) and Y (body 2), with X's
// parameters in slots [0, X.dim) and Y's in [X.dim, 2).  Requires
// X.dim + Y.dim == 2.
template <class FT>
Quadratic2<FT> contact_quadratic(const FeatureGeometry<FT>& X, const FeatureGeometry<FT>& Y,
                                 const Placement<FT>& p) {
  using detail::apply_point;
  using detail::apply_vector;
  using detail::dot;
  const int kx = X.dim, ky = Y.dim;
  // World difference g1(x(s)) - g2(y(s)) = a + L s.
  Vec3<FT> a = apply_point(p.g1, X.origin);
  const Vec3<FT> y0 = p.body2_moving ? apply_point(p.g2, Y.origin) : Y.origin;
  for (int i = 0; i < 3; ++i) a[i] -= y0[i];
  std::array<Vec3<FT>, 2> L;
  for (int j = 0; j < kx; ++j) L[j] = apply_vector(p.g1, X.axis[j]);
  for (int j = 0; j < ky; ++j) {
    Vec3<FT> v = p.body2_moving ? apply_vector(p.g2, Y.axis[j]) : Y.axis[j];
    for (int i = 0; i < 3; ++i) v[i] = -v[i];
    L[kx + j] = v;
  }
  FT h[2][2], b[2];
  for (int i = 0; i < 2; ++i) {
    b[i] = FT(2) * dot(a, L[i]);
    for (int j = 0; j < 2; ++j) h[i][j] = dot(L[i], L[j]);
  }
  FT c = dot(a, a);
  // Subtract R^2 rho^2 for each moving side.
  auto subtract_rho = [&](const FeatureGeometry<FT>& F, int first_slot) {
    for (int i = 0; i < F.dim; ++i) {
      b[first_slot + i] -= p.r2 * FT(2) * F.q(i, 2);
      for (int j = 0; j < F.dim; ++j) h[first_slot + i][first_slot + j] -= p.r2 * F.q(i, j);
    }
    c -= p.r2 * F.q(2, 2);
  };
  subtract_rho(X, 0);
  if (p.body2_moving) subtract_rho(Y, kx);
  return Quadratic2<FT>{h[0][0], h[0][1], h[1][1], b[0], b[1], c};
}

// Sign of min Phi over X x Y: POSITIVE means the pair is cleared on the
// piece; ZERO or NEGATIVE means it may touch.
template <class FT>
CGAL::Sign contact_sign(ContactKind kind, const FeatureGeometry<FT>& X, const FeatureGeometry<FT>& Y,
                        const Placement<FT>& p) {
  const Quadratic2<FT> q = contact_quadratic(X, Y, p);
  if (kind == ContactKind::EdgeEdge) {
    static const Pt2<FT> square[4] = {{FT(0), FT(0)}, {FT(1), FT(0)}, {FT(1), FT(1)}, {FT(0), FT(1)}};
    return min_sign(q, ConvexDomain<FT>{square, 4, 1});
  }
  const FeatureGeometry<FT>& face = kind == ContactKind::VertexFace ? Y : X;
  return min_sign(q, ConvexDomain<FT>{face.domain.data(), face.domain.size(), face.orientation});
}

}  // namespace tmcert
