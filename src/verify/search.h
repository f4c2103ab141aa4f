// Internal to src/verify: the search of one check: start check, pruned depth-first subdivision in
// parameter order, stop rules, witnesses (DESIGN.md sections 4-6,
// proofs/search-and-pruning.md, proofs/witness.md).
#pragma once

#include "src/verify/kernel_policies.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

namespace tmcert::detail {

// ------------------------------------------------------------------ static tests

struct StaticHit {
  int part_moving, part_other;
  Vec3E point;
};

inline std::optional<StaticHit> first_hit(const std::vector<StaticPart>& a, const std::vector<StaticPart>& b,
                                   const std::set<std::pair<int, int>>* only, CheckStats& stats) {
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) {
      if (only && !only->count({static_cast<int>(i), static_cast<int>(j)})) continue;
      for (const Simplex& s : a[i].simplices)
        for (const Simplex& t : b[j].simplices) {
          ++stats.static_tests;
          if (auto p = common_point(s, t)) return StaticHit{static_cast<int>(i), static_cast<int>(j), *p};
        }
    }
  return std::nullopt;
}

// ------------------------------------------------------------------ search

// The rational with the smallest denominator in the closed interval
// [lo, hi] (continued fractions, i.e. the Stern-Brocot descent).
inline Exact simplest_between(const Exact& lo, const Exact& hi) {
  if (lo <= 0 && hi >= 0) return Exact(0);
  if (hi < 0) return -simplest_between(-hi, -lo);
  CGAL::Gmpz fl;
  mpz_fdiv_q(fl.mpz(), lo.numerator().mpz(), lo.denominator().mpz());
  if (Exact(fl) == lo) return lo;
  if (Exact(fl + 1) <= hi) return Exact(fl + 1);
  // Both in (fl, fl + 1): recurse on the reciprocals of the fractional parts.
  return Exact(fl) + Exact(1) / simplest_between(Exact(1) / (hi - Exact(fl)), Exact(1) / (lo - Exact(fl)));
}

// The deepest subdivision level: a node's parameter interval is
// [index, index + 1] / 2^depth with a 64-bit index.
constexpr int kDepthCap = 62;

struct Node {
  std::uint64_t index;  // the piece is [index, index + 1] / 2^depth of the curve parameter
  int depth;
  std::vector<PairRef> alive;

  Exact u0() const { return at(index); }
  Exact u1() const { return at(index + 1); }
  Exact mid() const { return (u0() + u1()) / 2; }
  Exact at(std::uint64_t k) const {
    CGAL::Gmpz den;
    mpz_setbit(den.mpz(), static_cast<mp_bitcnt_t>(depth));
    return Exact(CGAL::Gmpz(static_cast<unsigned long>(k)), den);
  }
};

template <int B>
struct Check {
  const PreparedBody& moving;    // body 1
  const PreparedBody& other;     // body 2: fixed (B = 1) or moving (B = 2)
  bool swapped;                  // the check names body 2 first
  const HomogeneousCurve<Exact, B>& curve;
  HomogeneousCurve<Interval, B> root_interval;  // encloses `curve`
  const Motion& motion;          // body 1's: the parameter interval
  double eps2;                   // epsilon^2 for the stop test (a tolerance)
  double rho2_sum;               // max rho1^2 (+ max rho2^2): the fat size per unit R^2
  const VerifyOptions& options;
  CheckResult& result;

  Exact scene_t(const Exact& u) const { return motion.t0 + u * (motion.t1 - motion.t0); }
  Exact curve_u(const Exact& t) const { return (t - motion.t0) / (motion.t1 - motion.t0); }

  void set_witness(const Exact& u, const StaticHit& hit) {
    const std::string a = moving.body->name + " " + moving.parts[hit.part_moving].name;
    const std::string b = other.body->name + " " + other.parts[hit.part_other].name;
    Witness w{scene_t(u), swapped ? std::array{b, a} : std::array{a, b}, hit.point};
    result.witness = w;
    result.verdict = Verdict::Collision;
  }

  // The configuration at curve parameter u: interval maps first (cheap),
  // exact only for simplex pairs the interval filter cannot separate.
  std::optional<StaticHit> static_test(const Exact& u, const std::set<std::pair<int, int>>* only) {
    std::array<std::array<Interval, 12>, B> maps;
    {
      RoundingGuard guard;
      const Interval ui = to_interval(u), vi = Interval(1) - ui;
      HomogeneousCurve<Interval, B> work = root_interval;
      constexpr std::size_t W = kHomogeneousSize<B> - 1;
      for (std::size_t level = 1; level < work.size(); ++level)
        for (std::size_t k = 0; k + level < work.size(); ++k)
          for (std::size_t e = 0; e <= W; ++e) work[k][e] = vi * work[k][e] + ui * work[k + 1][e];
      for (int b = 0; b < B; ++b)
        for (int e = 0; e < 12; ++e) maps[b][e] = work[0][12 * b + e] / work[0][W];
    }
    auto placed = [](const Simplex& s, const std::array<Interval, 12>* m) {
      SimplexI out;
      out.count = s.count;
      for (int k = 0; k < s.count; ++k) {
        const std::array<Interval, 3> x = {to_interval(s.p[k][0]), to_interval(s.p[k][1]), to_interval(s.p[k][2])};
        if (!m) { out.p[k] = x; continue; }
        for (int i = 0; i < 3; ++i)
          out.p[k][i] = (*m)[4 * i] * x[0] + (*m)[4 * i + 1] * x[1] + (*m)[4 * i + 2] * x[2] + (*m)[4 * i + 3];
      }
      return out;
    };
    // Place every simplex of the parts involved once, with its interval box.
    struct Item {
      int part, index;
      SimplexI s;
      std::array<double, 3> lo, hi;
    };
    auto place_all = [&](const PreparedBody& body, const std::vector<char>& use, const std::array<Interval, 12>* m) {
      std::vector<Item> items;
      for (std::size_t i = 0; i < body.parts.size(); ++i) {
        if (!use[i]) continue;
        const auto& simplices = body.parts[i].simplices;
        for (std::size_t k = 0; k < simplices.size(); ++k) {
          Item it{static_cast<int>(i), static_cast<int>(k), placed(simplices[k], m), {}, {}};
          for (int c = 0; c < 3; ++c) {
            double lo = std::numeric_limits<double>::infinity(), hi = -lo;
            for (int v = 0; v < it.s.count; ++v) {
              const Interval& x = it.s.p[v][c];
              if (std::isnan(x.inf()) || std::isnan(x.sup())) { lo = -std::numeric_limits<double>::infinity(); hi = -lo; break; }
              lo = std::min(lo, x.inf());
              hi = std::max(hi, x.sup());
            }
            it.lo[c] = lo;
            it.hi[c] = hi;
          }
          items.push_back(std::move(it));
        }
      }
      return items;
    };
    std::vector<char> use_a(moving.parts.size(), only ? 0 : 1), use_b(other.parts.size(), only ? 0 : 1);
    if (only)
      for (const auto& [i, j] : *only) use_a[i] = use_b[j] = 1;
    struct Candidate { int pi, pj, si, sj; };
    std::vector<Candidate> candidates;
    {
      RoundingGuard guard;
      std::vector<Item> a_items = place_all(moving, use_a, &maps[0]);
      std::vector<Item> b_items = place_all(other, use_b, B == 2 ? &maps[B - 1] : nullptr);
      // Sweep along x: only pairs whose boxes overlap on every axis (boxes
      // hold the true simplices, so a strict gap proves disjointness) go on
      // to the separating-axis filter.
      auto by_lo = [](const Item& x, const Item& y) { return x.lo[0] < y.lo[0]; };
      std::sort(a_items.begin(), a_items.end(), by_lo);
      std::sort(b_items.begin(), b_items.end(), by_lo);
      auto overlap = [](const Item& x, const Item& y) {
        for (int c = 0; c < 3; ++c)
          if (x.hi[c] < y.lo[c] || y.hi[c] < x.lo[c]) return false;
        return true;
      };
      auto consider = [&](const Item& x, const Item& y) {  // x from the moving body
        if (only && !only->count({x.part, y.part})) return;
        if (!overlap(x, y) || certainly_disjoint(x.s, y.s)) return;
        candidates.push_back({x.part, y.part, x.index, y.index});
      };
      std::size_t first_b = 0;
      for (const Item& x : a_items) {
        // A leading b item that ends before x starts ends before every later
        // a item starts too (a items are sorted by their start): drop it.
        while (first_b < b_items.size() && b_items[first_b].hi[0] < x.lo[0]) ++first_b;
        for (std::size_t k = first_b; k < b_items.size() && !(x.hi[0] < b_items[k].lo[0]); ++k) consider(x, b_items[k]);
      }
    }
    // The order of the nested loops over parts and simplices, whatever the
    // sweep order: the first hit (and so the witness) does not depend on it.
    std::sort(candidates.begin(), candidates.end(), [](const Candidate& x, const Candidate& y) {
      return std::tie(x.pi, x.pj, x.si, x.sj) < std::tie(y.pi, y.pj, y.si, y.sj);
    });
    if (candidates.empty()) return std::nullopt;
    const Mat34E m1 = evaluate<B>(curve, u, 0);
    std::optional<Mat34E> m2;
    if constexpr (B == 2) m2 = evaluate<B>(curve, u, 1);
    auto exact_placed = [](Simplex s, const Mat34E* m) {
      if (m)
        for (int k = 0; k < s.count; ++k) {
          Vec3E r;
          for (int i = 0; i < 3; ++i)
            r[i] = (*m)[4 * i] * s.p[k][0] + (*m)[4 * i + 1] * s.p[k][1] + (*m)[4 * i + 2] * s.p[k][2] + (*m)[4 * i + 3];
          s.p[k] = r;
        }
      return s;
    };
    for (const Candidate& c : candidates) {
      ++result.stats.static_tests;
      const Simplex a = exact_placed(moving.parts[c.pi].simplices[c.si], &m1);
      const Simplex b = exact_placed(other.parts[c.pj].simplices[c.sj], m2 ? &*m2 : nullptr);
      if (auto p = common_point(a, b)) return StaticHit{c.pi, c.pj, *p};
    }
    return std::nullopt;
  }

  // Exact static test of the configuration at curve parameter u, restricted
  // to the parts that still have a live feature pair (all parts when a pair
  // of hierarchy nodes is still alive).
  bool try_witness(const Exact& u, const std::vector<PairRef>& alive) {
    std::set<std::pair<int, int>> parts;
    bool all = false;
    for (const PairRef& p : alive) {
      const FeatureTable& X = moving_table(moving, p.kind);
      const FeatureTable& Y = other_table(other, p.kind);
      if (!X.tree.leaf(p.i) || !Y.tree.leaf(p.j)) {
        all = true;
        break;
      }
      parts.insert({X.part[p.i], Y.part[p.j]});
    }
    if (auto hit = static_test(u, all ? nullptr : &parts)) {
      set_witness(u, *hit);
      return true;
    }
    return false;
  }

  void record(const Node& n, StopReason reason) {
    const Exact t0 = scene_t(n.u0()), t1 = scene_t(n.u1());
    if (!result.undecided.empty() && result.undecided.back().t1 == t0 && result.undecided.back().reason == reason)
      result.undecided.back().t1 = t1;
    else
      result.undecided.push_back({t0, t1, reason});
    if (!result.first_contact) result.first_contact = std::pair{t0, t1};
  }

  // The tests of one piece.  A feature pair gets the contact test; with the
  // hierarchy, every pair first gets the sphere test.  A pair of hierarchy
  // nodes that is not cleared is descended on this piece (its child pairs
  // tested in turn) when `expand_all` or when a node is larger in the world
  // than the piece's fattening R rho; otherwise it is carried as it is to
  // the sub-pieces, where the smaller balls make descending worthwhile.
  // Leaves `alive` with the pairs not cleared (proofs/hierarchy.md).
  template <class Policy>
  struct Spheres {
    using FT = typename Policy::SphereFT;
    std::array<SphereCache<FT>, 3> moving, other;  // by contact kind
    std::uint32_t piece = 0;
    Spheres(const PreparedBody& m, const PreparedBody& f) {
      for (ContactKind k : {ContactKind::VertexFace, ContactKind::EdgeEdge, ContactKind::FaceVertex}) {
        moving[static_cast<int>(k)].reset(moving_table(m, k).tree.nodes.size());
        other[static_cast<int>(k)].reset(other_table(f, k).tree.nodes.size());
      }
    }
  };

  template <class Policy>
  void prune(const Policy& policy, typename Policy::Ball& ball, std::vector<PairRef>& alive, bool expand_all,
             Spheres<Policy>& spheres) {
    if (!ball.valid()) return;  // nothing is cleared by an unbounded ball
    CheckStats& stats = result.stats;
    if (!options.hierarchy) {
      std::erase_if(alive, [&](const PairRef& p) { return policy.test(ball, p, stats) == CGAL::POSITIVE; });
      return;
    }
    using FT = typename Policy::SphereFT;
    RoundingFor<FT> rounding;  // the contact tests' exact fallbacks are rounding-independent
    const SphereFrame<FT> frame = policy.frame(ball);
    const std::uint32_t piece = ++spheres.piece;
    const double n1 = CGAL::to_double(frame.n1), n2 = CGAL::to_double(frame.n2), radius = CGAL::to_double(frame.R);
    std::vector<PairRef> work;
    work.swap(alive);
    alive.reserve(work.size());
    std::reverse(work.begin(), work.end());  // a stack that pops in list order
    while (!work.empty()) {
      const PairRef p = work.back();
      work.pop_back();
      const int k = static_cast<int>(p.kind);
      const BvTree& X = moving_table(moving, p.kind).tree;
      const BvTree& Y = other_table(other, p.kind).tree;
      ++stats.sphere_tests;
      if (world_spheres_apart(spheres.moving[k].get(piece, frame, true, X, p.i),
                              spheres.other[k].get(piece, frame, false, Y, p.j)))
        continue;
      const bool leaf_a = X.leaf(p.i), leaf_b = Y.leaf(p.j);
      if (leaf_a && leaf_b) {
        if (policy.test(ball, p, stats) != CGAL::POSITIVE) alive.push_back(p);
        continue;
      }
      const BvNode& a = X.nodes[p.i];
      const BvNode& b = Y.nodes[p.j];
      const double size_a = leaf_a ? -1 : n1 * a.r, size_b = leaf_b ? -1 : n2 * b.r;
      if (!expand_all && !(std::max(size_a, size_b) > radius * (a.p + b.p))) {
        alive.push_back(p);
        continue;
      }
      // Children pushed right first: the left one is tested first.
      if (size_a >= size_b) {
        work.push_back({p.kind, a.right, p.j});
        work.push_back({p.kind, a.left, p.j});
      } else {
        work.push_back({p.kind, p.i, b.right});
        work.push_back({p.kind, p.i, b.left});
      }
    }
  }

  std::vector<PairRef> root_pairs() const {
    if (!options.hierarchy) return all_pairs(moving, other);
    std::vector<PairRef> out;
    for (ContactKind k : {ContactKind::VertexFace, ContactKind::EdgeEdge, ContactKind::FaceVertex}) {
      const BvTree& X = moving_table(moving, k).tree;
      const BvTree& Y = other_table(other, k).tree;
      if (!X.empty() && !Y.empty()) out.push_back({k, X.root(), Y.root()});
    }
    return out;
  }

  template <class Policy>
  void search(const Policy& policy) {
    struct Item {
      Node node;
      typename Policy::Piece piece;
    };
    std::vector<Item> stack;
    stack.push_back({Node{0, 0, root_pairs()}, policy.root()});
    const int max_depth = std::min(options.max_depth, kDepthCap);
    CheckStats& stats = result.stats;
    Spheres<Policy> spheres(moving, other);
    while (!stack.empty()) {
      Item item = std::move(stack.back());
      stack.pop_back();
      Node& node = item.node;
      if (stats.nodes >= options.max_nodes) {  // resource limit: not cleared
        record(node, StopReason::Limit);
        continue;
      }
      ++stats.nodes;
      stats.max_depth = std::max(stats.max_depth, node.depth);
      typename Policy::Ball ball = policy.ball(item.piece);
      prune(policy, ball, node.alive, false, spheres);  // keep the pairs not cleared on this piece
      if (node.alive.empty()) continue;  // cleared on the whole piece
      std::optional<StopReason> stop;
      if (node.depth >= max_depth) stop = StopReason::Depth;
      else if (ball.valid() && ball.r2() * rho2_sum < eps2) stop = StopReason::Epsilon;
      if (stop) {
        // A stop is final: descend the hierarchy to feature pairs here.
        prune(policy, ball, node.alive, true, spheres);
        if (node.alive.empty()) continue;
        // Witness candidates: the midpoint, the end, and the scene time with
        // the smallest denominator in the piece (a contact at a "round"
        // rational time, such as 1/3 or 0.137, is found exactly there).
        const Exact mid = node.mid();
        const Exact end = node.u1();
        const Exact simple = curve_u(simplest_between(scene_t(node.u0()), scene_t(end)));
        for (const Exact* u : {&mid, &end, &simple}) {
          if (try_witness(*u, node.alive)) {
            const Exact lo = result.first_contact ? result.first_contact->first : scene_t(node.u0());
            result.first_contact = std::pair{lo, scene_t(*u)};
            return;
          }
        }
        record(node, *stop);
        continue;
      }
      Item left{Node{2 * node.index, node.depth + 1, node.alive}, {}};
      Item right{Node{2 * node.index + 1, node.depth + 1, std::move(node.alive)}, {}};
      policy.split(item.piece, left.piece, right.piece);
      stack.push_back(std::move(right));
      stack.push_back(std::move(left));  // parameter order: left first
    }
  }

  // The start check (DESIGN.md section 4: the contact tests are complete
  // only after a contact-free start), then the search.
  void run() {
    if (auto hit = static_test(Exact(0), nullptr)) {
      set_witness(Exact(0), *hit);
      result.first_contact = std::pair{motion.t0, motion.t0};
      return;
    }
    switch (options.kernel) {
      case KernelKind::Filtered: search(FilteredPolicy<B>{moving, other, curve}); break;
      case KernelKind::Exact: search(ExactPolicy<B>{moving, other, curve}); break;
      case KernelKind::Fast: search(FastPolicy<B>{moving, other, curve}); break;
    }
  }
};


}  // namespace tmcert::detail
