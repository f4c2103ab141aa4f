// The three contact tests of the paper (vertex x face, edge x edge,
// face x vertex) as minimum-of-quadratic tests in world coordinates
// (DESIGN.md sections 2-4, proofs/contact-tests.md).
//
// For a ball B(g, R) of affine maps around the moving body's motion piece,
// every contact between feature X (body 1, moving) and Y (body 2) on that
// piece satisfies, for some x in X, y in Y,
//     Phi(x, y) = |g1(x) - g2(y)|^2 - R^2 (rho1(x)^2 + rho2(y)^2) <= 0,
// where the rho2 term is present only when body 2 moves too (joint ball).
// With a clearance d the pair is cleared only when the bodies stay farther
// apart than d: Phi is lowered by a constant `shift` >= d^2 + 2 d R rhobar,
// rhobar >= rho over the pair (proofs/clearance.md): Phi - shift > 0 gives
// |g1(x) - g2(y)| > R rho(x, y) + d, so every map in the ball keeps x and y
// farther apart than d.
// With x = oX + EX sX and y = oY + EY sY, Phi is a quadratic in the two
// parameters s = (sX, sY), and the pair is cleared exactly when the minimum
// of Phi over the parameter domain is positive.
#pragma once

#include "kernels/quadratic_min.h"
#include "kernels/vec3.h"

#include <CGAL/Interval_nt.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>
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
  // An upper bound of rho^2 over the whole feature (detail::max_rho2), kept
  // when the feature is prepared; negative when not computed.
  double rho2_max = -1;

  const FT& q(int i, int j) const { return rho2[3 * i + j]; }
};

// Ball of affine maps for one motion piece: center(s) and squared radius.
template <class FT>
struct Placement {
  std::array<FT, 12> g1;     // center for body 1, row-major [A | a]
  bool body2_moving = false;
  std::array<FT, 12> g2;     // center for body 2 when it moves
  FT r2;                     // squared radius of the (joint) ball
  // A clearance d (proofs/clearance.md): `shift` (an upper bound of
  // d^2 + 2 d R rhobar, subtracted from Phi's constant term) for the contact
  // test, `clear` (an upper bound of d) for the sphere, slab and axis tests.
  FT shift = FT(0);
  double clear = 0;
};

enum class ContactKind : std::uint8_t { VertexFace = 0, EdgeEdge = 1, FaceVertex = 2 };

namespace detail {

// The verifier's vocabulary (kernels/vec3.h) under the names this header's
// callers use: g applied to a point, and its linear part to a vector.
template <class FT>
Vec3<FT> apply_point(const std::array<FT, 12>& g, const Vec3<FT>& x) {
  return vec3::apply(g, x);
}

template <class FT>
Vec3<FT> apply_vector(const std::array<FT, 12>& g, const Vec3<FT>& v) {
  return vec3::apply_linear(g, v);
}

// max of rho^2 over a feature, as an upper bound: rho^2 = [s; 1]^T Q [s; 1]
// is a convex quadratic of the parameters (Q positive semidefinite), so its
// maximum over the segment or polygon is at a vertex. Over intervals the
// result is the interval [0, the largest upper end]: a bound, not an
// enclosure of the maximum.
template <class FT>
FT max_rho2(const FeatureGeometry<FT>& F) {
  if (F.rho2_max >= 0) {
    if constexpr (std::is_same_v<FT, CGAL::Interval_nt<false>>) return FT(0, F.rho2_max); else return FT(F.rho2_max);
  }
  auto at = [&](const FT& s1, const FT& s2) {
    return F.q(0, 0) * s1 * s1 + FT(2) * F.q(0, 1) * s1 * s2 + F.q(1, 1) * s2 * s2 + FT(2) * F.q(0, 2) * s1 +
           FT(2) * F.q(1, 2) * s2 + F.q(2, 2);
  };
  auto upper = [](const FT& x) {
    if constexpr (std::is_same_v<FT, CGAL::Interval_nt<false>>) return x.sup(); else return CGAL::to_double(x);
  };
  double best = 0;  // rho^2 >= 0
  bool finite = true;
  auto take = [&](double v) {
    if (std::isfinite(v)) best = std::max(best, v);
    else finite = false;  // NaN or infinite: no bound
  };
  if (F.dim == 0) {
    take(upper(F.q(2, 2)));
  } else if (F.dim == 1) {
    take(upper(at(FT(0), FT(0))));
    take(upper(at(FT(1), FT(0))));
  } else {
    for (const Pt2<FT>& t : F.domain) take(upper(at(t[0], t[1])));
  }
  if (!finite) best = std::numeric_limits<double>::infinity();
  if constexpr (std::is_same_v<FT, CGAL::Interval_nt<false>>) return FT(0, best); else return FT(best);
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
  using vec3::dot;
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
  c -= p.shift;
  return Quadratic2<FT>{h[0][0], h[0][1], h[1][1], b[0], b[1], c};
}

// A cheap test that clears a pair without the quadratic's minimum
// (proofs/contact-tests.md section 3). For a direction n, every image
// g1(x) of a point of X projects onto n between the smallest and largest
// projection of the images of X's vertices (an affine map keeps convex
// combinations), and so for Y; rho^2 is a convex quadratic of the feature's
// parameters, so it is largest at a vertex. If the two projection ranges
// are apart by a gap with
//     gap^2 > R^2 |n|^2 (max_X rho1^2 + max_Y rho2^2)
// (the rho2 term only when body 2 moves), then |g1(x) - g2(y)| >= gap / |n|
// gives Phi(x, y) > 0 for every x in X and y in Y.  n is any direction,
// chosen in double from the approximate images (a face's normal or the
// cross product of two edges, then the line between the centroids); only
// the bounds and the comparison must be rigorous: over intervals (call
// under RoundingGuard) every projection contributes its interval's lower
// or upper end.  The filtered kernel runs it before its contact test; the
// fast kernel does not (in double the contact test is about as cheap), and
// it answers false for exact placements (the reference keeps the plain
// contact test).  In double it computes the same test, uncertified.
namespace detail {

// The axis test handles features of at most this many vertices.
constexpr std::size_t kAxisMaxVertices = 16;

// Writes the images under g (null: the identity) of F's vertices (its
// origin, a segment's other end, a polygon's vertices from its parameter
// domain) to out; returns their count, or 0 when F has more than
// kAxisMaxVertices.
template <class FT>
std::size_t vertex_images(const FeatureGeometry<FT>& F, const std::array<FT, 12>* g, Vec3<FT>* out) {
  std::size_t count = 0;
  auto emit = [&](const Vec3<FT>& x) { out[count++] = g ? apply_point(*g, x) : x; };
  if (F.dim == 0) {
    emit(F.origin);
  } else if (F.dim == 1) {
    emit(F.origin);
    emit(Vec3<FT>{F.origin[0] + F.axis[0][0], F.origin[1] + F.axis[0][1], F.origin[2] + F.axis[0][2]});
  } else {
    if (F.domain.size() > kAxisMaxVertices) return 0;
    for (const Pt2<FT>& t : F.domain) {
      Vec3<FT> x;
      for (int i = 0; i < 3; ++i) x[i] = F.origin[i] + t[0] * F.axis[0][i] + t[1] * F.axis[1][i];
      emit(x);
    }
  }
  return count;
}

}  // namespace detail

// The test on vertex images already placed: xs (nx of them) of X under g1,
// ys of Y under g2 (or as they are), with rho an upper bound of
// max_X rho1^2 (+ max_Y rho2^2 when body 2 moves) and r2 the ball's R^2.
// With a clearance (`clear` >= d > 0) the gap must exceed
// |n| (R sqrt(rho) + clear) instead (proofs/clearance.md): then
// |g1(x) - g2(y)| > R rho(x, y) + d.
template <class FT>
bool apart_along_axis(ContactKind kind, const Vec3<FT>* xs, std::size_t nx, const Vec3<FT>* ys, std::size_t ny,
                      const FT& rho, const FT& r2, double clear = 0) {
  constexpr bool interval = std::is_same_v<FT, CGAL::Interval_nt<false>>;
  if constexpr (!interval && !std::is_same_v<FT, double>) {
    return false;
  } else {
    if (nx == 0 || ny == 0) return false;
    if constexpr (interval) CGAL_assertion(CGAL::FPU_get_cw() == CGAL_FE_UPWARD);
    if ((kind == ContactKind::EdgeEdge && (nx < 2 || ny < 2)) ||
        (kind == ContactKind::VertexFace && ny < 3) || (kind == ContactKind::FaceVertex && nx < 3))
      return false;
    auto lo = [](const FT& x) { if constexpr (interval) return x.inf(); else return x; };
    auto hi = [](const FT& x) { if constexpr (interval) return x.sup(); else return x; };
    auto mid = [](const FT& x) { return CGAL::to_double(x); };
    // The directions, in double.
    auto d = [&](const Vec3<FT>& a, const Vec3<FT>& b) {
      return std::array<double, 3>{mid(a[0]) - mid(b[0]), mid(a[1]) - mid(b[1]), mid(a[2]) - mid(b[2])};
    };
    using vec3::cross;
    // Two directions: the normal of the face, or of both edges (where the
    // features face each other across a plane), then the line between the
    // centroids (features side by side in one plane, where the first
    // projects both onto one value).
    std::array<std::array<double, 3>, 2> axes;
    if (kind == ContactKind::EdgeEdge) {
      axes[0] = cross(d(xs[1], xs[0]), d(ys[1], ys[0]));
    } else {
      const Vec3<FT>* face = kind == ContactKind::VertexFace ? ys : xs;
      axes[0] = cross(d(face[1], face[0]), d(face[2], face[0]));
    }
    for (int which = 0; which < 2; ++which) {
      if (which == 1) {  // the centroids' line, only when the first axis fails
        const double wy = 1 / static_cast<double>(ny), wx = 1 / static_cast<double>(nx);
        axes[1] = {0, 0, 0};
        for (std::size_t k = 0; k < ny; ++k)
          for (int i = 0; i < 3; ++i) axes[1][i] += mid(ys[k][i]) * wy;
        for (std::size_t k = 0; k < nx; ++k)
          for (int i = 0; i < 3; ++i) axes[1][i] -= mid(xs[k][i]) * wx;
      }
      const std::array<double, 3>& n = axes[which];
      if (!std::isfinite(n[0]) || !std::isfinite(n[1]) || !std::isfinite(n[2])) continue;
      if (n[0] == 0 && n[1] == 0 && n[2] == 0) continue;
      // Projection ranges, from the lower and upper ends of the projections.
      // For intervals, the ends of n.x over the box of x directly: the
      // largest value picks each coordinate's upper end where n_i >= 0 and
      // its lower end where n_i < 0, the smallest the other ends; under the
      // upward rounding the sum of the products rounds up, and the smallest
      // is -(sum of (-n_i) times its ends), rounded up and negated: the same
      // enclosure as interval arithmetic, without its sign cases per product
      // (-n passes through IA_opacify, as in CGAL's Interval_nt, so that the
      // compiler cannot fold the negations; so do the resulting ends, so that
      // they are computed before the caller's guard restores the rounding).
      std::array<double, 3> neg_n{};
      if constexpr (interval)
        for (int i = 0; i < 3; ++i) neg_n[i] = CGAL::IA_opacify(-n[i]);
      auto range = [&](const Vec3<FT>* pts, std::size_t count, double& low, double& high) {
        low = std::numeric_limits<double>::infinity();
        high = -low;
        for (std::size_t k = 0; k < count; ++k) {
          double vlo, vhi;
          if constexpr (interval) {
            double up = 0, down = 0;  // an upper bound of the largest, of minus the smallest
            for (int i = 0; i < 3; ++i) {
              const double a = pts[k][i].inf(), b = pts[k][i].sup();
              up += n[i] * (n[i] >= 0 ? b : a);
              down += neg_n[i] * (n[i] >= 0 ? a : b);
            }
            vlo = -down;
            vhi = up;
          } else {
            vlo = vhi = n[0] * pts[k][0] + n[1] * pts[k][1] + n[2] * pts[k][2];
          }
          if (!(vlo <= vhi)) return false;  // NaN
          low = std::min(low, vlo);
          high = std::max(high, vhi);
        }
        if constexpr (interval) {
          low = CGAL::IA_opacify(low);
          high = CGAL::IA_opacify(high);
        }
        return std::isfinite(low) && std::isfinite(high);  // unbounded: no claim
      };
      double xlo, xhi, ylo, yhi;
      if (!range(xs, nx, xlo, xhi) || !range(ys, ny, ylo, yhi)) continue;
      const double gap = std::max(ylo - xhi, xlo - yhi);  // rounded: only a candidate, checked below
      if (!(gap > 0)) continue;
      // gap^2 > R^2 |n|^2 (rho terms), with the gap's own rounding enclosed.
      if constexpr (interval) {
        // Directly, under the upward rounding: a lower bound of the gap is
        // minus the difference the other way round, rounded up; of its
        // square, minus (-g) g rounded up; the bound's factors are
        // non-negative upper bounds, so their products round up.
        // (Opacified as above.)
        const double g_lo = ylo - xhi >= xlo - yhi ? -CGAL::IA_opacify(xhi - ylo) : -CGAL::IA_opacify(yhi - xlo);
        const double g2_lo = -CGAL::IA_opacify(CGAL::IA_opacify(-g_lo) * g_lo);
        if (clear > 0) {
          // |n| (R sqrt(rho) + clear), each factor an upper bound rounded
          // up (IEEE sqrt rounds by the current, upward, mode).
          const double reach_up = CGAL::IA_opacify(std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) *
                                                   (std::sqrt(hi(r2)) * std::sqrt(hi(rho)) + clear));
          if (g_lo > 0 && std::isfinite(reach_up) && g_lo > reach_up) return true;
          continue;
        }
        const double bound_up = CGAL::IA_opacify(hi(r2) * (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) * hi(rho));
        if (g_lo > 0 && g2_lo > bound_up) return true;
      } else {
        const FT g = ylo - xhi >= xlo - yhi ? FT(ylo) - FT(xhi) : FT(xlo) - FT(yhi);
        if (clear > 0) {
          const double reach = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) *
                               (std::sqrt(hi(r2)) * std::sqrt(hi(rho)) + clear);
          if (lo(g) > reach) return true;
          continue;
        }
        const FT bound = r2 * (FT(n[0]) * FT(n[0]) + FT(n[1]) * FT(n[1]) + FT(n[2]) * FT(n[2])) * rho;
        if (lo(g) > 0 && lo(g * g) > hi(bound)) return true;
      }
    }
    return false;
  }
}

// The same from the features and the ball: places their vertices first.
template <class FT>
bool apart_along_axis(ContactKind kind, const FeatureGeometry<FT>& X, const FeatureGeometry<FT>& Y,
                      const Placement<FT>& p) {
  std::array<Vec3<FT>, detail::kAxisMaxVertices> xs, ys;
  const std::size_t nx = detail::vertex_images(X, &p.g1, xs.data());
  const std::size_t ny = detail::vertex_images(Y, p.body2_moving ? &p.g2 : nullptr, ys.data());
  FT rho = detail::max_rho2(X);
  if (p.body2_moving) rho = rho + detail::max_rho2(Y);
  return apart_along_axis<FT>(kind, xs.data(), nx, ys.data(), ny, rho, p.r2, p.clear);
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
