// Bounding-volume hierarchies over a body's contact features, and the
// certified test that clears a pair of bounding spheres on a motion piece
// (proofs/hierarchy.md).
//
// One hierarchy per body, over "cells": each convex piece with the edges and
// vertices it owns (every vertex and edge feature is owned by exactly one
// cell), segments and points as cells of their own.  Every feature also has
// its own sphere, for a last sphere test per feature pair.
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

#include <CGAL/FPU.h>
#include <CGAL/number_utils.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <new>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace tmcert {

// A node of a hierarchy: a sphere certainly holding its features, and an
// upper bound of rho over the sphere (0 for a fixed body).  Leaves are the
// items the tree is built over (cells), in their order: node i < leaves is
// item i.  Also the sphere of one feature.
struct BvNode {
  std::array<double, 3> c{};   // center (a double, used exactly)
  double r = 0;                // radius, rounded upward
  double p = 0;                // >= max rho over the sphere, rounded upward
  std::uint32_t left = 0, right = 0;  // children of an internal node
  std::uint32_t leaves = 1;           // items under the node
  // A slab {x : lo <= n.x <= hi} holding the node's items (n a unit-ish
  // double vector, lo and hi rounded outward), when the node is flat: its
  // items have (nearly) parallel normals; or, for an internal node whose
  // items are not, along the thinnest of a few of its leaves' normals when
  // that is thinner than the node's sphere (`slab_thick`).  Used by
  // slab_test.
  bool slab = false;
  bool slab_thick = false;
  std::array<double, 3> slab_n{};
  double slab_lo = 0, slab_hi = 0;
};

struct BvTree {
  std::vector<BvNode> nodes;   // [0, leaves): items; internal nodes after; root last
  std::uint32_t leaves = 0;
  bool leaf(std::uint32_t i) const { return i < leaves; }
  // The two children of internal node i.  A leaf has none (its `left` and
  // `right` are unused zeros, which would name node 0): asking for them is
  // an internal error, never a silent step back to node 0.
  std::array<std::uint32_t, 2> children(std::uint32_t i) const {
    if (leaf(i) || i >= nodes.size()) throw std::logic_error("BvTree::children: node " + std::to_string(i) + " is a leaf");
    return {nodes[i].left, nodes[i].right};
  }
  bool empty() const { return nodes.empty(); }
  std::uint32_t root() const { return static_cast<std::uint32_t>(nodes.size() - 1); }
};

// Builds the hierarchy of items given by the enclosures of their points
// (an item - a cell, or a feature - lies in the convex hull of its points).
// `gi` encloses G^-1 of a moving body, null for a fixed body.  Median splits
// along the longest axis of the item centers: depth about log2(items).
BvTree build_tree(const std::vector<std::vector<Vec3<Interval>>>& items, const std::array<Interval, 16>* gi);

// The leaf spheres alone (as the leaves of build_tree): one per item.
std::vector<BvNode> item_spheres(const std::vector<std::vector<Vec3<Interval>>>& items,
                                 const std::array<Interval, 16>* gi);

// A body's one hierarchy: its leaves are the cells.  Cell k holds face
// `face[k]` (an index into the body's face table, or -1: a segment, a point,
// a piece degenerate under a singular pose) and owns the edges
// edges[edge_begin[k], edge_begin[k + 1]) and the vertices
// vertices[vertex_begin[k], vertex_begin[k + 1]) of the body's tables.
// Every face, edge and vertex feature belongs to exactly one cell.
struct CellTree {
  BvTree tree;
  std::vector<std::int32_t> face;
  std::vector<std::uint32_t> edge_begin{0}, edges;
  std::vector<std::uint32_t> vertex_begin{0}, vertices;
  // Per node: the vertices, edges and faces of the cells below it.
  std::vector<std::array<std::uint32_t, 3>> below;
  std::size_t cells() const { return face.size(); }
  // Feature pairs (vertex x face, edge x edge, face x vertex) under a node
  // pair of two bodies' trees.
  static std::uint64_t pairs_below(const CellTree& a, std::uint32_t i, const CellTree& b, std::uint32_t j) {
    const auto& x = a.below[i];
    const auto& y = b.below[j];
    return std::uint64_t(x[0]) * y[2] + std::uint64_t(x[1]) * y[1] + std::uint64_t(x[2]) * y[0];
  }
};

// Fills `tree` and `below` of a CellTree whose cells are set, from the
// enclosures of the points of each cell's features.
void build_cell_tree(CellTree& cells, const std::vector<std::vector<Vec3<Interval>>>& cell_points,
                     const std::array<Interval, 16>* gi);

// The ball of a motion piece as the sphere test needs it: the centers, upper
// bounds of the operator norms of their linear parts and the radius.
template <class FT>
struct SphereFrame {
  std::array<FT, 12> g1, g2;
  bool body2_moving = false;
  FT n1, n2, R;
  // An upper bound of the check's clearance d (0: none): body 1's placed
  // spheres grow by it, and the slab test's range by d |n_b|
  // (proofs/clearance.md): apart then means farther apart than d.
  double clear = 0;
};

namespace detail {
inline Interval sqrt_of(const Interval& x) { return CGAL::sqrt(x); }
inline double sqrt_of(double x) { return std::sqrt(x); }
inline bool certainly_greater(const Interval& a, const Interval& b) { return a.inf() > b.sup(); }
inline bool certainly_greater(double a, double b) { return a > b; }

inline double upper(const Interval& x) { return x.sup(); }
inline double upper(double x) { return x; }

// An upper bound of the operator norm |A|_2 of the linear part A of g:
// sqrt(lambda_max(A^T A)), with lambda_max bounded by the smaller of the
// trace (= |A|_F^2) and the largest Gershgorin row bound of A^T A (the
// eigenvalues of a symmetric matrix lie in the union of its Gershgorin
// intervals).  For a near rotation: about 1 instead of |A|_F = sqrt 3.
// FT = Interval: call under RoundingGuard; the upper end bounds |A|_2 for
// every matrix in the intervals.  With a NaN: the Frobenius norm (a NaN).
template <class FT>
FT operator_norm_bound(const std::array<FT, 12>& g) {
  FT m[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j) {
      FT s(0);
      for (int k = 0; k < 3; ++k) s += g[4 * k + i] * g[4 * k + j];
      m[i][j] = s;
      m[j][i] = s;
    }
  const FT trace = m[0][0] + m[1][1] + m[2][2];
  double gershgorin = 0;
  for (int i = 0; i < 3; ++i) {
    FT row = m[i][i];
    for (int j = 0; j < 3; ++j)
      if (j != i) row += CGAL::abs(m[i][j]);
    const double u = upper(row);
    if (!(u >= 0)) return sqrt_of(trace);  // NaN: as the Frobenius norm would be
    gershgorin = std::max(gershgorin, u);
  }
  const double t = upper(trace);
  if (!(t >= 0) || t <= gershgorin) return sqrt_of(trace);
  return sqrt_of(FT(gershgorin));
}
}  // namespace detail

// FT = Interval: call under RoundingGuard.
template <class FT>
SphereFrame<FT> sphere_frame(const Placement<FT>& p) {
  SphereFrame<FT> f;
  f.g1 = p.g1;
  f.body2_moving = p.body2_moving;
  if (p.body2_moving) f.g2 = p.g2;
  f.n1 = detail::operator_norm_bound(p.g1);
  f.n2 = p.body2_moving ? detail::operator_norm_bound(p.g2) : FT(1);
  f.R = detail::sqrt_of(p.r2);
  f.clear = p.clear;
  return f;
}

// A node's sphere placed in the world by the piece's ball: every point the
// node's features can occupy on the piece lies within `f` of `c`
// (|A| r + R p for a moving body, r for a fixed one), and with a clearance d
// body 1's spheres hold every point within d of those (|A| r + R p + d).
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
  if (body1) {
    if (fr.clear > 0) return {detail::apply_point(fr.g1, c), fr.n1 * FT(n.r) + fr.R * FT(n.p) + FT(fr.clear)};
    return {detail::apply_point(fr.g1, c), fr.n1 * FT(n.r) + fr.R * FT(n.p)};
  }
  if (fr.body2_moving) return {detail::apply_point(fr.g2, c), fr.n2 * FT(n.r) + fr.R * FT(n.p)};
  return {c, FT(n.r)};
}

// True when the two placed spheres certainly do not meet.  FT = Interval:
// call under RoundingGuard; a NaN or an overlap of the bounds gives false.
template <class FT>
bool world_spheres_apart(const WorldSphere<FT>& a, const WorldSphere<FT>& b) {
  if constexpr (std::is_same_v<FT, Interval>) {
    // The bounds interval arithmetic gives, without its sign cases.  Under
    // the upward rounding, per axis the difference lies in [lo, hi] with
    // lo = -(b.sup - a.inf) and hi = a.sup - b.inf; m, the lower bound of
    // its absolute value, gives -m^2 <= (-m) m rounded up; so minus the sum
    // of those is a lower bound of the squared distance.  (-m passes
    // through IA_opacify, as in CGAL's Interval_nt, so that the compiler
    // cannot fold the negations; so do the compared values.)
    CGAL_assertion(CGAL::FPU_get_cw() == CGAL_FE_UPWARD);
    double neg = 0;
    for (int i = 0; i < 3; ++i) {
      const double lo = -(b.c[i].sup() - a.c[i].inf()), hi = a.c[i].sup() - b.c[i].inf();
      if (!(lo <= hi)) return false;  // NaN
      const double m = lo > 0 ? lo : hi < 0 ? -hi : 0;
      neg += CGAL::IA_opacify(-m) * m;
    }
    const double t = a.f.sup() + b.f.sup();  // an upper bound of the radii's sum
    // Opacified: computed here, under the caller's upward rounding.
    const double d2_lo = -CGAL::IA_opacify(neg), t2_up = CGAL::IA_opacify(t * t);
    if (!(t >= 0) || !std::isfinite(d2_lo)) return false;  // NaN or unbounded: no claim
    return d2_lo > t2_up;
  } else {
    FT d2(0);
    for (int i = 0; i < 3; ++i) d2 += CGAL::square(a.c[i] - b.c[i]);
    const FT t = a.f + b.f;
    return detail::certainly_greater(d2, t * t);
  }
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

// The slab test of a moving flat node `a` (body frame) against a fixed flat
// node `b` (world) on a piece (proofs/hierarchy.md §1b).  For x in a's items,
// n_b.(g(x) + delta(x)) = m.x + n_b.t + n_b.delta(x) with m = A^T n_b, and
// m.x = alpha (n_a.x) + (m - alpha n_a).x for any alpha, where n_a.x lies in
// a's slab, x in a's sphere and |delta(x)| <= R p_a.  `apart`: the range of
// that projection certainly misses b's slab, so no feature pair under the
// two nodes can touch on the piece.  `size` (the part of the range that
// shrinks when a is split) and `fat` (R p_a |n_b|) guide the descent only.
struct SlabTest {
  bool applicable = false, apart = false;
  // Apart without the piece's fattening: what a smaller piece could reach
  // (for the descent decision only).
  bool apart_unfattened = false;
  // The slabs' gap without the fattening (> 0 when apart_unfattened), the
  // node's spread and the fattening (descent decisions only).
  double gap = 0, size = 0, fat = 0;
};

// The part of the slab test that depends on the fixed node b and the piece
// only: m = A^T n_b, n_b.t and an upper bound of |n_b|.  Call under
// RoundingGuard.
struct SlabSide {
  Interval m[3];
  Interval shift;
  double nb_up = 0;
};
// Of the map g (its 12 entries, row-major [A | t]).
inline SlabSide slab_side(const std::array<Interval, 12>& g, const BvNode& b) {
  SlabSide s;
  for (int j = 0; j < 3; ++j)
    s.m[j] = g[j] * Interval(b.slab_n[0]) + g[4 + j] * Interval(b.slab_n[1]) + g[8 + j] * Interval(b.slab_n[2]);
  Interval nb2(0), shift(0);
  for (int i = 0; i < 3; ++i) {
    nb2 += CGAL::square(Interval(b.slab_n[i]));
    shift += Interval(b.slab_n[i]) * g[4 * i + 3];
  }
  s.shift = shift;
  s.nb_up = std::sqrt(nb2.sup());  // upward rounding: an upper bound of |n_b|
  return s;
}
inline SlabSide slab_side(const SphereFrame<Interval>& f, const BvNode& b) { return slab_side(f.g1, b); }

// The unfattened range of n_b.g(x) over the points x of a flat node a under
// the map g of `sb`: within [-(base_negdown + size_up), base_up + size_up]
// (three upper bounds; proofs/hierarchy.md §1b).  Not valid with a NaN or
// an infinite bound.  Call under RoundingGuard.
struct SlabBase {
  bool valid = false;
  double base_up = 0, base_negdown = 0, size_up = 0;
  double alpha = 0;  // the coefficient of n_a.x (descent decisions only)
};
inline SlabBase slab_base(const SlabSide& sb, const BvNode& a) {
  SlabBase out;
  CGAL_assertion(CGAL::FPU_get_cw() == CGAL_FE_UPWARD);
  const Interval* m = sb.m;
  double alpha = 0;
  for (int j = 0; j < 3; ++j) alpha += CGAL::to_double(m[j]) * a.slab_n[j];
  if (!std::isfinite(alpha)) return out;
  // The bounds interval arithmetic gives, without its sign cases.  Under
  // the upward rounding a sum or product rounds up, and a lower bound is
  // minus an upper bound of the negated quantity (negated operands pass
  // through IA_opacify, as in CGAL's Interval_nt, so that the compiler
  // cannot fold the negations).  Per axis: perp = m - alpha n_a in
  // [perp_lo, perp_hi]; then perp.c (c: a's centre) and |perp|^2.
  auto neg = [](double x) { return CGAL::IA_opacify(-x); };
  double c_up = 0, c_negdown = 0, perp2_up = 0;  // perp.c <= c_up, -(perp.c) <= c_negdown
  for (int j = 0; j < 3; ++j) {
    const double n = a.slab_n[j], c = a.c[j];
    const double p_up = alpha * n, p_negdown = neg(alpha) * n;  // alpha n <= p_up, -(alpha n) <= p_negdown
    const double perp_hi = m[j].sup() + p_negdown;               // m - alpha n <= perp_hi
    const double perp_lo = -(p_up - m[j].inf());                 // m - alpha n >= perp_lo
    if (!(perp_lo <= perp_hi)) return out;                      // NaN
    c_up += c * (c >= 0 ? perp_hi : perp_lo);
    c_negdown += neg(c) * (c >= 0 ? perp_lo : perp_hi);
    perp2_up += std::max(perp_lo * perp_lo, perp_hi * perp_hi);
  }
  const Interval& shift = sb.shift;
  // Upper bounds only: under the guard the rounding is upward, so sqrt,
  // products and sums of non-negative upper bounds round up (cheaper than
  // interval square roots, which switch the rounding mode).
  out.size_up = std::sqrt(perp2_up) * a.r;
  // alpha (n_a.x) over a's slab [slab_lo, slab_hi], plus perp.c and the shift.
  const double s_hi = alpha >= 0 ? a.slab_hi : a.slab_lo, s_lo = alpha >= 0 ? a.slab_lo : a.slab_hi;
  out.base_up = alpha * s_hi + c_up + shift.sup();
  out.base_negdown = neg(alpha) * s_lo + c_negdown + neg(shift.inf());
  out.alpha = alpha;
  out.valid = true;
  return out;
}

// Call under RoundingGuard.  `side`: slab_side(f, b), when the caller keeps
// it per piece (it is computed here otherwise).
inline SlabTest slab_test(const SphereFrame<Interval>& f, const BvNode& a, const BvNode& b,
                          const SlabSide* side = nullptr) {
  SlabTest out;
  if (!a.slab || !b.slab || f.body2_moving) return out;
  CGAL_assertion(CGAL::FPU_get_cw() == CGAL_FE_UPWARD);
  const SlabSide own = side ? SlabSide{} : slab_side(f, b);
  const SlabSide& sb = side ? *side : own;
  const SlabBase base = slab_base(sb, a);
  if (!base.valid) return out;
  const double size_up = base.size_up, base_up = base.base_up, base_negdown = base.base_negdown;
  const double fat_up = sb.nb_up * f.R.sup() * a.p;
  // A clearance d: every point within d of a's features projects within
  // d |n_b| of theirs (proofs/clearance.md); no piece shrinks it.
  const double clear_up = f.clear > 0 ? sb.nb_up * f.clear : 0.0;
  const double spread = size_up + fat_up + clear_up;
  if (!(spread >= 0) || !std::isfinite(spread)) return out;  // NaN or unbounded: no claim
  // Opacified: computed here, under the caller's upward rounding.
  const double hi_up = CGAL::IA_opacify(base_up + spread), lo_negdown = CGAL::IA_opacify(base_negdown + spread);
  if (!std::isfinite(hi_up) || !std::isfinite(lo_negdown) || !(-lo_negdown <= hi_up)) return out;  // NaN or unbounded: no claim
  // The range of n_b.(g(x) + delta(x)): [-(base_negdown + spread), base_up + spread].
  out.applicable = true;
  out.apart = hi_up < b.slab_lo || -lo_negdown > b.slab_hi;
  const double reach = size_up + clear_up;  // descent decisions only, from here
  const double w0_hi = base_up + reach, w0_lo = -(base_negdown + reach);
  out.apart_unfattened = w0_hi < b.slab_lo || w0_lo > b.slab_hi;
  out.gap = std::max(b.slab_lo - w0_hi, w0_lo - b.slab_hi);
  // What splitting the nodes can shrink: a's spread across its normal and
  // the widths of thick slabs (a flat node's is about 0 and left out).
  double thickness = 0;
  if (a.slab_thick) thickness += std::fabs(base.alpha) * (a.slab_hi - a.slab_lo);
  if (b.slab_thick) thickness += b.slab_hi - b.slab_lo;
  out.size = size_up + thickness;
  out.fat = fat_up;
  return out;
}
inline SlabTest slab_test(const SphereFrame<double>&, const BvNode&, const BvNode&, const void* = nullptr) { return {}; }

// A value per node of one tree (or per feature of one table), computed at
// most once per piece: `stamp[i]` says for which piece entry i is current
// (pieces are numbered from 1 by a 64-bit counter that never wraps around
// to a stale entry; 0: none yet).  `make()` computes entry i for the
// current piece.  The entries are raw storage until first written (a
// search makes one cache per table: initializing every entry would cost
// more than the entries a short check uses); an entry is read only after
// it was written for the current piece.
template <class T>
class StampedCache {
  static_assert(std::is_trivially_destructible_v<T>);
  struct Slot {
    alignas(T) unsigned char bytes[sizeof(T)];
  };

 public:
  void reset(std::size_t nodes) {
    stamp_.assign(nodes, 0);
    slot_.reset(new Slot[nodes]);  // not initialized
    capacity_ = nodes;
  }
  // Sized for another check's bodies (Spheres::rebind), nothing zeroed that
  // the stamps already guard: entries kept in place keep their stamps, which
  // lie below every piece of the next check (the piece counter goes on);
  // new or reallocated slots get stamp 0, below every piece (pieces count
  // from 1).
  void resize(std::size_t nodes) {
    if (nodes > capacity_) {
      reset(nodes);
      return;
    }
    stamp_.resize(nodes, 0);
  }
  template <class Make>
  const T& get(std::uint64_t piece, std::uint32_t i, Make&& make) {
    if (stamp_[i] != piece) {
      stamp_[i] = piece;
      return *::new (static_cast<void*>(slot_[i].bytes)) T(make());  // over a trivially destructible old entry
    }
    return *std::launder(reinterpret_cast<const T*>(slot_[i].bytes));
  }

 private:
  std::vector<std::uint64_t> stamp_;
  std::unique_ptr<Slot[]> slot_;
  std::size_t capacity_ = 0;
};

// slab_side per node of the fixed body's tree (a fixed node meets many
// moving ones on a piece).
using SlabSideCache = StampedCache<SlabSide>;

// The placed spheres of the nodes of one tree (or of one feature table).
template <class FT>
using SphereCache = StampedCache<WorldSphere<FT>>;

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
