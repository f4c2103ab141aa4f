// Internal to src/verify: a check's pruning of its live pairs on one piece
// (search_check.h): hull and contact tests of feature pairs, sphere and slab
// tests of hierarchy node pairs, descending or carrying node pairs, the
// re-test above a stop (proofs/search-and-pruning.md, proofs/hierarchy.md,
// proofs/hull-test.md).
#pragma once

#include "src/verify/search_check.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <type_traits>
#include <vector>

namespace tmcert::detail {

  // 1 + twice log2(fattening / gap) of a slab test that failed by its
  // fattening, clamped to 1..255 (a search decision only).
std::uint8_t carry_shortfall(const SlabTest& slab);

// A feature pair is cleared on a piece when its hull test on the piece's
// control points clears it (proofs/hull-test.md), or when the piece's ball
// is valid and its contact test is POSITIVE (the sphere test only skips
// contact tests that would be POSITIVE).  The same function of (pair,
// piece) on every path: with and without the hierarchy, and in the re-test
// above a stop, whatever order the tests run in.
template <int B>
template <class Policy>
bool Check<B>::hull_clears(const Policy& policy, const typename Policy::Piece& piece, const PairRef& p, CheckStats& stats) {
  if (!policy.hull(piece, p)) return false;
  ++stats.hull_clears;
  return true;
}

template <int B>
template <class Policy>
bool Check<B>::clears(const Policy& policy, typename Policy::Ball& ball, const typename Policy::Piece& piece,
                      const PairRef& p, CheckStats& stats) {
  return hull_clears(policy, piece, p, stats) || (ball.valid() && policy.test(ball, p, stats) == CGAL::POSITIVE);
}


// The tests of one piece.  A feature pair gets the sphere test on the
// two features' spheres, then the contact test.  A pair of hierarchy
// nodes (cells of the two bodies' trees) gets the sphere test; if it is
// not cleared, it is descended on this piece (its child pairs tested in
// turn) when `expand_all`, when few feature pairs are below, or when a
// node is larger in the world than kDescend times the piece's fattening; otherwise
// it is carried as it is to the sub-pieces, where the smaller balls make
// descending worthwhile.  A pair of two cells is replaced by its feature
// pairs (vertices owned by the first x face of the second, owned edges x
// owned edges, face of the first x vertices owned by the second), each
// tested as above.  Leaves `alive` with the pairs not cleared, in a
// deterministic order (proofs/hierarchy.md).
// `get_ball()` returns the piece's ball, computed on first use.
template <int B>
template <class Policy, class GetBall>
void Check<B>::prune(const Policy& policy, GetBall&& get_ball, const typename Policy::Piece& controls,
                     std::vector<PairRef>& alive, bool expand_all, Spheres<Policy>& spheres, int depth) {
  const auto born = static_cast<std::uint8_t>(std::min(depth, 255));
  CheckStats& stats = result.stats;
  const bool hull_first =
      alive.size() <= kHullFirst && std::none_of(alive.begin(), alive.end(), [](const PairRef& p) { return p.nodes; });
  if (hull_first) {
    std::erase_if(alive, [&](const PairRef& p) { return hull_clears(policy, controls, p, stats); });
    if (alive.empty()) return;
  }
  typename Policy::Ball& ball = get_ball();
  if (!ball.valid()) {  // an unbounded ball clears nothing; the hull test needs none
    if (expand_all && options.hierarchy) expand_untested(alive, born);
    if (!hull_first)
      std::erase_if(alive, [&](const PairRef& p) { return !p.nodes && hull_clears(policy, controls, p, stats); });
    return;
  }
  if (!options.hierarchy) {
    std::erase_if(alive, [&](const PairRef& p) {
      return policy.test(ball, p, stats, !hull_first) == CGAL::POSITIVE ||
             (!hull_first && hull_clears(policy, controls, p, stats));
    });
    return;
  }
  using FT = typename Policy::SphereFT;
  [[maybe_unused]] RoundingFor<FT> rounding;  // the contact tests' exact fallbacks are rounding-independent
  const SphereFrame<FT> frame = policy.frame(ball);
  const std::uint64_t piece = ++spheres.piece;
  const double n1 = CGAL::to_double(frame.n1), n2 = CGAL::to_double(frame.n2), radius = CGAL::to_double(frame.R);
  const CellTree& X = moving.cells;
  const CellTree& Y = other.cells;
  const FeatureTable* moving_tables[3] = {&moving.vertices, &moving.edges, &moving.faces};
  const FeatureTable* other_tables[3] = {&other.vertices, &other.edges, &other.faces};
  // An enclosed piece of one moving body: the swept-sphere test after a
  // failed sphere test (proofs/hierarchy.md §1c).
  SweptFrame swept;
  if constexpr (requires { policy.swept(controls); }) {
    if (!frame.body2_moving) swept = policy.swept(controls);
  }
  // A feature pair: its sphere test, its hull test (unless it ran
  // first), then its contact test.
  auto feature = [&](const PairRef& p, bool hull_tested) {
    const int a = moving_index(p.kind), b = other_index(p.kind);
    ++stats.sphere_tests;
    if (world_spheres_apart(spheres.moving[a].get(piece, p.i, [&] { return world_sphere(frame, true, moving_tables[a]->spheres[p.i]); }),
                            spheres.other[b].get(piece, p.j, [&] { return world_sphere(frame, false, other_tables[b]->spheres[p.j]); })))
      return;
    if (swept.valid &&
        swept_apart(spheres.moving_swept[a].get(piece, p.i, [&] { return swept_sphere(swept, moving_tables[a]->spheres[p.i]); }), other_tables[b]->spheres[p.j])) {
      ++stats.swept_clears;
      return;
    }
    // The contact test before the hull test here: on long lists (meshes)
    // it is the cheaper of the two and clears most pairs.
    if (policy.test(ball, p, stats, !hull_tested) == CGAL::POSITIVE) return;
    if (!hull_tested && hull_clears(policy, controls, p, stats)) return;
    alive.push_back(p);
  };
  std::vector<PairRef>& work = spheres.scratch;  // reused: no allocation per piece
  work.assign(alive.rbegin(), alive.rend());     // a stack that pops in list order
  alive.clear();
  while (!work.empty()) {
    const PairRef p = work.back();
    work.pop_back();
    if (!p.nodes) {
      feature(p, hull_first);
      continue;
    }
    ++stats.sphere_tests;
    if (world_spheres_apart(spheres.moving_cells.get(piece, p.i, [&] { return world_sphere(frame, true, X.tree.nodes[p.i]); }),
                            spheres.other_cells.get(piece, p.j, [&] { return world_sphere(frame, false, Y.tree.nodes[p.j]); })))
      continue;
    if (swept.valid && swept_apart(spheres.moving_swept_cells.get(piece, p.i, [&] { return swept_sphere(swept, X.tree.nodes[p.i]); }), Y.tree.nodes[p.j])) {
      ++stats.swept_clears;
      continue;
    }
    // Flat against fixed flat: their slabs (proofs/hierarchy.md §1b).
    SlabTest slab;
    if constexpr (std::is_same_v<FT, Interval>) {
      const BvNode& a = X.tree.nodes[p.i];
      const BvNode& b = Y.tree.nodes[p.j];
      if (a.slab && b.slab && !frame.body2_moving) {
        slab = slab_test(frame, a, b, &spheres.other_slabs.get(piece, p.j, [&] { return slab_side(frame, b); }));
        // On an enclosed piece: the slabs under the segment's end maps,
        // fattened by the tube (proofs/hierarchy.md §1d); only where the
        // ball's slabs are apart unfattened (otherwise the range under
        // the ball's centre, a pose of the segment up to rounding, meets
        // b's slab, and so would the swept range: a filter only).
        if (!slab.apart && slab.apart_unfattened && swept.valid) {
          const SweptSlabSide& side = spheres.other_swept_slabs.get(piece, p.j, [&] { return swept_slab_side(swept, b); });
          slab.apart = swept_slab_apart(swept, side.s0, side.s1, a, b);
        }
      }
    }
    if (slab.apart) {
      ++stats.slab_clears;
      continue;
    }
    const bool leaf_a = X.tree.leaf(p.i), leaf_b = Y.tree.leaf(p.j);
    // Two flat nodes whose slab test fails by the piece's fattening rather
    // than by the node's extent, and that would be apart without it:
    // splitting or expanding them cannot help on this piece, while a
    // smaller piece can clear the whole pair at once.  (Slabs that overlap
    // even unfattened - flat nodes side by side in one plane - are
    // descended: no piece clears them by their slabs.)  A pair carried
    // before is carried again only if the shortfall, fattening over gap,
    // has fallen by about half since (two steps of carry_shortfall, each
    // a factor of sqrt 2 up to rounding down): it does so while the gap
    // holds and the pieces halve (a body hovering over a plane), not near
    // a time where one slab passes through the other, where the gap
    // shrinks with the pieces and carrying would halve them towards that
    // time down to the stop at epsilon.
    if (!expand_all && slab.applicable && slab.apart_unfattened && !(slab.size > slab.fat)) {
      const std::uint8_t shortfall = carry_shortfall(slab);
      if (p.carried == 0 || shortfall + 1 < p.carried) {
        PairRef carried = p;
        carried.carried = shortfall;
        alive.push_back(carried);
        continue;
      }
    }
    if (leaf_a && leaf_b) {
      // Two cells: their feature pairs, in a fixed order.
      const std::int32_t face_a = X.face[p.i], face_b = Y.face[p.j];
      if (face_b >= 0)
        for (std::uint32_t k = X.vertex_begin[p.i]; k < X.vertex_begin[p.i + 1]; ++k)
          feature(feature_pair(ContactKind::VertexFace, X.vertices[k], static_cast<std::uint32_t>(face_b), born), false);
      for (std::uint32_t k = X.edge_begin[p.i]; k < X.edge_begin[p.i + 1]; ++k)
        for (std::uint32_t l = Y.edge_begin[p.j]; l < Y.edge_begin[p.j + 1]; ++l)
          feature(feature_pair(ContactKind::EdgeEdge, X.edges[k], Y.edges[l], born), false);
      if (face_a >= 0)
        for (std::uint32_t l = Y.vertex_begin[p.j]; l < Y.vertex_begin[p.j + 1]; ++l)
          feature(feature_pair(ContactKind::FaceVertex, static_cast<std::uint32_t>(face_a), Y.vertices[l], born), false);
      continue;
    }
    const BvNode& a = X.tree.nodes[p.i];
    const BvNode& b = Y.tree.nodes[p.j];
    // World sizes; a product that is not a number (inf * 0: an overflowed
    // frame norm times a zero radius) counts as the largest, so the pair
    // is descended rather than carried, and is never compared as NaN.
    auto world_size = [](bool leaf, double n, double r) {
      if (leaf) return -1.0;  // nothing to split
      const double s = n * r;
      return std::isnan(s) ? std::numeric_limits<double>::infinity() : s;
    };
    const double size_a = world_size(leaf_a, n1, a.r), size_b = world_size(leaf_b, n2, b.r);
    // Few feature pairs under the pair: test them now (cheaper than
    // carrying them down the pieces, and as tight as all pairs).
    const bool small = CellTree::pairs_below(X, p.i, Y, p.j) <= kExpandPairs;
    if (!expand_all && !small && !(std::max(size_a, size_b) > (swept.valid ? kDescendSwept : kDescend) * radius * (a.p + b.p))) {
      alive.push_back(p);
      continue;
    }
    // Split the larger node, never a leaf (not both are leaves here).
    // Children pushed right first: the left one is tested first.
    const bool split_a = leaf_b || (!leaf_a && size_a >= size_b);
    if (split_a) {
      const auto [left, right] = X.tree.children(p.i);
      work.push_back(node_pair(right, p.j));
      work.push_back(node_pair(left, p.j));
    } else {
      const auto [left, right] = Y.tree.children(p.j);
      work.push_back(node_pair(p.i, right));
      work.push_back(node_pair(p.i, left));
    }
  }
}

template <int B>
void Check<B>::expand_untested(std::vector<PairRef>& alive, std::uint8_t born) const {
  const CellTree& X = moving.cells;
  const CellTree& Y = other.cells;
  std::uint64_t total = 0;
  for (const PairRef& p : alive) total += p.nodes ? CellTree::pairs_below(X, p.i, Y, p.j) : 1;
  if (total > kUntestedPairs) return;
  std::vector<PairRef> work(alive.rbegin(), alive.rend());  // a stack that pops in list order
  alive.clear();
  while (!work.empty()) {
    const PairRef p = work.back();
    work.pop_back();
    if (!p.nodes) {
      alive.push_back(p);
      continue;
    }
    const bool leaf_a = X.tree.leaf(p.i), leaf_b = Y.tree.leaf(p.j);
    if (leaf_a && leaf_b) {  // the feature pairs of two cells, in prune's order
      const std::int32_t face_a = X.face[p.i], face_b = Y.face[p.j];
      if (face_b >= 0)
        for (std::uint32_t k = X.vertex_begin[p.i]; k < X.vertex_begin[p.i + 1]; ++k)
          alive.push_back(feature_pair(ContactKind::VertexFace, X.vertices[k], static_cast<std::uint32_t>(face_b), born));
      for (std::uint32_t k = X.edge_begin[p.i]; k < X.edge_begin[p.i + 1]; ++k)
        for (std::uint32_t l = Y.edge_begin[p.j]; l < Y.edge_begin[p.j + 1]; ++l)
          alive.push_back(feature_pair(ContactKind::EdgeEdge, X.edges[k], Y.edges[l], born));
      if (face_a >= 0)
        for (std::uint32_t l = Y.vertex_begin[p.j]; l < Y.vertex_begin[p.j + 1]; ++l)
          alive.push_back(feature_pair(ContactKind::FaceVertex, static_cast<std::uint32_t>(face_a), Y.vertices[l], born));
      continue;
    }
    if (!leaf_a) {
      const auto [left, right] = X.tree.children(p.i);
      work.push_back(node_pair(right, p.j));
      work.push_back(node_pair(left, p.j));
    } else {
      const auto [left, right] = Y.tree.children(p.j);
      work.push_back(node_pair(p.i, right));
      work.push_back(node_pair(p.i, left));
    }
  }
}

template <int B>
std::vector<PairRef> Check<B>::root_pairs() const {
  if (!options.hierarchy) return all_pairs(moving, other);
  const BvTree& X = moving.cells.tree;
  const BvTree& Y = other.cells.tree;
  if (X.empty() || Y.empty()) return {};
  return {node_pair(X.root(), Y.root())};
}

// With the hierarchy, a feature pair made at depth d was not tested on the
// pieces above d, where carrying every pair (all pairs) would have tested
// it.  At a stop, test it there too and drop it if any of those pieces
// clears it: the pairs left are then exactly those all pairs leaves, so
// the verdict, witness and undecided pieces are the same with or without
// the hierarchy (proofs/hierarchy.md).
template <int B>
template <class Policy>
void Check<B>::retest_above(const Policy& policy, const Item<Policy>& item, std::vector<PairRef>& alive) {
  std::erase_if(alive, [&](const PairRef& p) {
    if (p.nodes) return false;
    for (const Ancestor<Policy>* a = item.parent.get(); a; a = a->up.get()) {
      if (a->depth >= p.born) continue;
      typename Policy::Ball ball = a->ball;  // a copy: the test may fill its exact form
      if (clears(policy, ball, a->piece, p, result.stats)) return true;
    }
    return false;
  });
}

}  // namespace tmcert::detail
