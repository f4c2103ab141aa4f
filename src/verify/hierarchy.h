// Bounding-volume hierarchies over a body's contact features, and the
// certified test that clears a pair of bounding spheres on a motion piece
// (proofs/hierarchy.md).
//
// A sphere S(c, r) of a body (its frame for a moving body, world coordinates
// for a fixed one) under a ball B(g, R) of affine maps: every point x of S is
// placed at g(x) + delta(x) with |delta(x)| <= R rho(x) (DESIGN.md section 2),
// and |g(x) - g(c)| <= |A| r for the linear part A of g.  With p >= max rho
// over S, a contact between x in S_a (body 1) and y in S_b (body 2) needs
//     |g1(c_a) - g2(c_b)| <= |A1| r_a + |A2| r_b + R sqrt(p_a^2 + p_b^2)
// (for a fixed body 2: g2 the identity, |A2| = 1, p_b = 0).  So a strict
// reverse inequality, certified in interval arithmetic, clears every feature
// pair under the two spheres on the whole piece.
#pragma once

#include "kernels/contact.h"
#include "kernels/number_types.h"

#include <CGAL/number_utils.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace tmcert {

// A node of a hierarchy: a sphere certainly holding its features, and an
// upper bound of rho over the sphere (0 for a fixed body).  Leaves are the
// features themselves, in table order: node i < leaves is feature i.
struct BvNode {
  std::array<double, 3> c{};   // center (a double, used exactly)
  double r = 0;                // radius, rounded upward
  double p = 0;                // >= max rho over the sphere, rounded upward
  std::uint32_t left = 0, right = 0;  // children of an internal node
  std::uint32_t leaves = 1;           // features under the node
};

struct BvTree {
  std::vector<BvNode> nodes;   // [0, leaves): features; internal nodes after; root last
  std::uint32_t leaves = 0;
  bool leaf(std::uint32_t i) const { return i < leaves; }
  bool empty() const { return nodes.empty(); }
  std::uint32_t root() const { return static_cast<std::uint32_t>(nodes.size() - 1); }
};

// Builds the hierarchy of features given by the enclosures of their vertices
// (a feature is the convex hull of its vertices).  `gi` encloses G^-1 of a
// moving body, null for a fixed body.  Median splits along the longest axis
// of the feature centers: depth about log2(features).
BvTree build_tree(const std::vector<std::vector<Vec3<Interval>>>& features, const std::array<Interval, 16>* gi);

// The ball of a motion piece as the sphere test needs it: the centers, the
// Frobenius norms of their linear parts (upper bounds of the operator norms)
// and the radius.
template <class FT>
struct SphereFrame {
  std::array<FT, 12> g1, g2;
  bool body2_moving = false;
  FT n1, n2, R;
};

namespace detail {
inline Interval sqrt_of(const Interval& x) { return CGAL::sqrt(x); }
inline double sqrt_of(double x) { return std::sqrt(x); }
inline bool certainly_greater(const Interval& a, const Interval& b) { return a.inf() > b.sup(); }
inline bool certainly_greater(double a, double b) { return a > b; }

template <class FT>
FT frobenius_linear(const std::array<FT, 12>& g) {
  FT s(0);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) s += g[4 * i + j] * g[4 * i + j];
  return sqrt_of(s);
}
}  // namespace detail

// FT = Interval: call under RoundingGuard.
template <class FT>
SphereFrame<FT> sphere_frame(const Placement<FT>& p) {
  SphereFrame<FT> f;
  f.g1 = p.g1;
  f.body2_moving = p.body2_moving;
  if (p.body2_moving) f.g2 = p.g2;
  f.n1 = detail::frobenius_linear(p.g1);
  f.n2 = p.body2_moving ? detail::frobenius_linear(p.g2) : FT(1);
  f.R = detail::sqrt_of(p.r2);
  return f;
}

// A node's sphere placed in the world by the piece's ball: every point the
// node's features can occupy on the piece lies within `f` of `c`
// (|A| r + R p for a moving body, r for a fixed one).
template <class FT>
struct WorldSphere {
  Vec3<FT> c;
  FT f;
};

// body1: the node is body 1's, else body 2's.  FT = Interval: call under
// RoundingGuard.
template <class FT>
WorldSphere<FT> world_sphere(const SphereFrame<FT>& fr, bool body1, const BvNode& n) {
  const Vec3<FT> c{FT(n.c[0]), FT(n.c[1]), FT(n.c[2])};
  if (body1) return {detail::apply_point(fr.g1, c), fr.n1 * FT(n.r) + fr.R * FT(n.p)};
  if (fr.body2_moving) return {detail::apply_point(fr.g2, c), fr.n2 * FT(n.r) + fr.R * FT(n.p)};
  return {c, FT(n.r)};
}

// True when the two placed spheres certainly do not meet.  FT = Interval:
// call under RoundingGuard; a NaN or an overlap of the bounds gives false.
template <class FT>
bool world_spheres_apart(const WorldSphere<FT>& a, const WorldSphere<FT>& b) {
  FT d2(0);
  for (int i = 0; i < 3; ++i) d2 += CGAL::square(a.c[i] - b.c[i]);
  const FT t = a.f + b.f;
  return detail::certainly_greater(d2, t * t);
}

// True when no feature under `a` (body 1) can touch one under `b` (body 2)
// on the piece: the two world spheres are apart.  (The joint ball's
// R sqrt(p_a^2 + p_b^2) is bounded by R p_a + R p_b, which lets each
// placed sphere be computed once per piece.)  FT = Interval: call under
// RoundingGuard; certified.  FT = double: the fast path.
template <class FT>
bool spheres_clear(const SphereFrame<FT>& f, const BvNode& a, const BvNode& b) {
  return world_spheres_apart(world_sphere(f, true, a), world_sphere(f, false, b));
}

// The placed spheres of the nodes of one tree, computed once per piece
// (`stamp` says for which piece an entry is current).
template <class FT>
struct SphereCache {
  std::vector<std::uint32_t> stamp;
  std::vector<WorldSphere<FT>> sphere;
  void reset(std::size_t nodes) {
    stamp.assign(nodes, 0);
    sphere.resize(nodes);
  }
  const WorldSphere<FT>& get(std::uint32_t piece, const SphereFrame<FT>& fr, bool body1, const BvTree& tree,
                             std::uint32_t i) {
    if (stamp[i] != piece) {
      stamp[i] = piece;
      sphere[i] = world_sphere(fr, body1, tree.nodes[i]);
    }
    return sphere[i];
  }
};

// Holds upward rounding for interval arithmetic, nothing for double.
template <class FT>
struct RoundingFor {};
template <>
struct RoundingFor<Interval> {
  RoundingGuard guard;
};

// The world size of a node under the piece's ball (for descent decisions
// only; no guarantee depends on it).
template <class FT>
double world_radius(const FT& norm, const BvNode& n) {
  return CGAL::to_double(norm) * n.r;
}

}  // namespace tmcert
