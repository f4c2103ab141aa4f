// Internal to src/verify: one check of a pair of bodies over a parameter range
// (DESIGN.md sections 4-6): its state and the declarations of its steps.  The
// steps are defined by topic: the tests at one instant and the witnesses
// (witness_search.h), pair pruning on a piece (pair_pruning.h), the ordered
// subdivision and its tasks (ordered_tasks.h), the start check and the
// partition (search.h, which includes them all and is what callers include).
#pragma once

#include "src/verify/kernel_policies.h"
#include "src/verify/exact_resolution.h"
#include "src/verify/static_config.h"
#include "src/verify/solid_contact.h"
#include "src/verify/true_shape.h"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace tmcert::detail {

// simplest_between: kernels/real_roots.h (shared with settle_rational).
using ::tmcert::simplest_between;

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
  Exact at(std::uint64_t k) const;  // k / 2^depth (ordered_tasks.cpp)
};

// Adds `part`, the result of the parameter range right after everything in
// `total`, to `total`: statistics, cleared pieces, undecided intervals
// (joined where they abut with the same reason), the first-contact bracket
// and the witness.  False once a witness ends the search.
bool merge_result(CheckResult& total, const CheckResult& part);

// What a check adds to the plain contact search (src/verify/general.cpp):
// a tube around the motion (tolerances), the clearance's offset, enclosed
// motions, and the distance witnesses of tolerance and clearance.
template <int B>
struct CheckExtras {
  double tube = 0;  // rational motions: every admissible pose is within this of the curve (product metric)
  double clear = 0;  // an upper bound of the clearance: the tests' offset (proofs/clearance.md)
  const EnclosedSource<B>* enclosed = nullptr;  // enclosed motions instead of `curve`
  // Witnesses at a distance (exact configurations only): the clearance
  // squared, and per side of the check (moving, other) the squared length
  // of a translation within that body's tolerance (r^2 / sum of its mass
  // weights: a translation by v has norm |v| sqrt(sum w)).
  Exact clearance2 = 0;
  std::array<Exact, 2> reach2{Exact(0), Exact(0)};
  bool distance_witness() const { return clearance2 > 0 || reach2[0] > 0 || reach2[1] > 0; }
  // The configuration at the start is already proven free: the part before
  // (a closed parameter range ending here) was cleared entirely, which
  // proves no contact (and, with a tube, no admissible contact) at its end.
  bool start_proven_free = false;
  // The caller has settled the containment of solids at the start (the
  // check's first part: Verifier::check_with, FixedEnvironment::check); a
  // start check of a later part (a join after a part not cleared entirely)
  // tests it too.
  bool start_solids_proven = true;
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
  CheckExtras<B> extras = {};
  // The curve in the power basis for exact resolution (exact_resolution.h),
  // computed once when first needed, shared with the forks.
  std::shared_ptr<PowerBasisCache> exact_power = std::make_shared<PowerBasisCache>();
  // The start of this range is neither proven free nor a contact (a join
  // after a part not cleared entirely, whose solids' containment the
  // enclosed poses leave open): the pieces cleared from it on are not
  // claimed until a later start is proven (secure_partition).
  bool start_unproven = false;
  // Set by true_witness when the polyhedra of a URDF primitive touch at a
  // candidate without a proven contact of the true shapes.
  bool enlarged_touch = false;

  // The same check writing into `part`.
  Check fork(CheckResult& part) const {
    return Check{moving, other, swapped, curve, root_interval, motion, eps2, rho2_sum, options, part, extras, exact_power};
  }

  Exact scene_t(const Exact& u) const { return motion.t0 + u * (motion.t1 - motion.t0); }
  Exact curve_u(const Exact& t) const { return (t - motion.t0) / (motion.t1 - motion.t0); }

  // ---- The configuration at one curve parameter, witnesses (witness_search.h).
  void set_witness(const Exact& u, const StaticHit& hit);
  std::optional<StaticHit> static_test(const Exact& u, const std::set<std::pair<int, int>>* only,
                                       bool* uncertain = nullptr);
  bool live_parts(const std::vector<PairRef>& alive, std::set<std::pair<int, int>>& parts) const;
  bool try_witness(const Exact& u, const std::vector<PairRef>& alive);
  bool true_witness(const Exact& u, const std::vector<PairRef>& alive);
  bool true_witness_later(const Exact& u0, const Exact& u1);
  std::array<ShapeSide, 2> sides_at(const Exact& u) const;
  bool has_solid() const { return moving.body->solid || other.body->solid; }
  Apartness interior_witness(const Exact& u);
  bool distance_witness(const Exact& u, const std::set<std::pair<int, int>>* only);
  Apartness containment_at(const Exact& u);
  Apartness free_at(const Exact& u);

  // ---- Undecided and cleared pieces.

  // A piece cleared entirely (options.record_cover), for certificates.
  void cleared(const Node& n) {
    piece_done(n);
    if (options.record_cover) result.cleared.push_back({n.index, n.depth});
  }

  // A piece is finished (cleared or recorded): its share of the check's
  // progress (src/verify/progress.h).
  void piece_done(const Node& n) {
    if (options.slot && n.depth < 64) options.slot->add(options.slot_span >> n.depth);
  }

  void record(const Node& n, StopReason reason) {
    piece_done(n);
    record_range(n.u0(), n.u1(), reason);
  }

  void record_range(const Exact& u0, const Exact& u1, StopReason reason) {
    const Exact t0 = scene_t(u0), t1 = scene_t(u1);
    if (!result.undecided.empty() && result.undecided.back().t1 == t0 && result.undecided.back().reason == reason)
      result.undecided.back().t1 = t1;
    else
      result.undecided.push_back({t0, t1, reason});
    if (!result.first_contact) result.first_contact = std::pair{t0, t1};
  }

  // ---- Pair pruning on a piece (pair_pruning.h).
  // The caches of one search's sphere tests.
  template <class Policy>
  struct Spheres {
    using FT = typename Policy::SphereFT;
    SphereCache<FT> moving_cells, other_cells;
    SlabSideCache other_slabs;  // the fixed body's side of the slab test (Interval only)
    std::array<SphereCache<FT>, 3> moving, other;  // by table: vertices, edges, faces
    SweptCache moving_swept_cells;                 // enclosed pieces of one moving body
    std::array<SweptCache, 3> moving_swept;        // by table, as `moving`
    SweptSlabCache other_swept_slabs;              // the fixed body's side of the swept slab test
    std::uint64_t piece = 0;
    std::vector<PairRef> scratch;  // prune's work stack
    Spheres(const PreparedBody& m, const PreparedBody& f) {
      moving_cells.reset(m.cells.tree.nodes.size());
      moving_swept_cells.reset(m.cells.tree.nodes.size());
      other_cells.reset(f.cells.tree.nodes.size());
      other_slabs.reset(f.cells.tree.nodes.size());
      other_swept_slabs.reset(f.cells.tree.nodes.size());
      int t = 0;
      for (const FeatureTable* x : {&m.vertices, &m.edges, &m.faces}) {
        moving_swept[t].reset(x->size());
        moving[t++].reset(x->size());
      }
      t = 0;
      for (const FeatureTable* x : {&f.vertices, &f.edges, &f.faces}) other[t++].reset(x->size());
    }
    // The same caches for another check (the next edge of a planner, the
    // next link): sized for its bodies, nothing zeroed.  `piece` goes on
    // counting, so every entry left from an earlier check carries a stamp
    // below every piece of this one and is computed again before use (the
    // same values as in fresh caches; proofs/search-and-pruning.md,
    // "Caches reused across checks").
    void rebind(const PreparedBody& m, const PreparedBody& f) {
      moving_cells.resize(m.cells.tree.nodes.size());
      moving_swept_cells.resize(m.cells.tree.nodes.size());
      other_cells.resize(f.cells.tree.nodes.size());
      other_slabs.resize(f.cells.tree.nodes.size());
      other_swept_slabs.resize(f.cells.tree.nodes.size());
      int t = 0;
      for (const FeatureTable* x : {&m.vertices, &m.edges, &m.faces}) {
        moving_swept[t].resize(x->size());
        moving[t++].resize(x->size());
      }
      t = 0;
      for (const FeatureTable* x : {&f.vertices, &f.edges, &f.faces}) other[t++].resize(x->size());
    }
  };

  // The table (0 vertices, 1 edges, 2 faces) of each body for a kind.
  static constexpr int moving_index(ContactKind k) { return static_cast<int>(k); }
  static constexpr int other_index(ContactKind k) { return 2 - static_cast<int>(k); }

  // Node pairs with at most this many feature pairs below are descended at
  // once; others when a node's world size exceeds kDescend times the
  // piece's fattening R (p_a + p_b) (a tuning choice: on the paper grid,
  // 2 tests far fewer feature pairs than 1 on pieces whose balls are still
  // too large to clear them).
  static constexpr std::uint64_t kExpandPairs = 64;

  static constexpr double kDescend = 2;
  // With the swept-sphere test (enclosed pieces of one moving body), whose
  // fattening is the tube rather than the ball, splitting nodes keeps
  // clearing pairs further down (a tuning choice: OMPL.app alpha-1.1,
  // 90 -> 36 million sphere tests; bench/README.md).
  static constexpr double kDescendSwept = 0.5;

  template <class Policy>
  bool hull_clears(const Policy& policy, const typename Policy::Piece& piece, const PairRef& p, CheckStats& stats);

  template <class Policy>
  bool clears(const Policy& policy, typename Policy::Ball& ball, const typename Policy::Piece& piece,
              const PairRef& p, CheckStats& stats);

  // At most this many feature pairs (and no node pair): the hull test runs
  // first, alone, and a piece it clears entirely needs no ball (the common
  // case of continuous-collision queries).  Longer lists get the cheap
  // sphere test first.
  static constexpr std::size_t kHullFirst = 16;

  template <class Policy, class GetBall>
  void prune(const Policy& policy, GetBall&& get_ball, const typename Policy::Piece& controls,
             std::vector<PairRef>& alive, bool expand_all, Spheres<Policy>& spheres, int depth);

  // A stop on a piece whose ball is not finite (an enclosure that
  // overflowed or divided by a weight enclosed with 0, e.g. weights 1 and
  // 1e400): every node pair becomes its feature pairs, untested (nothing
  // can be cleared on that ball), so that the exact decision of a rational
  // motion, which takes feature pairs only, can decide the piece.  Only up
  // to kUntestedPairs feature pairs in all; beyond, the node pairs stay
  // (and the piece stays undecided).
  static constexpr std::uint64_t kUntestedPairs = 4096;
  void expand_untested(std::vector<PairRef>& alive, std::uint8_t born) const;

  std::vector<PairRef> root_pairs() const;

  // The ball of a piece on the path to the current one (the hierarchy's
  // re-test at stops, below).  Shared read-only by the pieces under it.
  template <class Policy>
  struct Ancestor {
    typename Policy::Ball ball;
    typename Policy::Piece piece;  // for the hull test
    std::shared_ptr<const Ancestor> up;
    int depth;
  };

  template <class Policy>
  struct Item {
    Node node;
    typename Policy::Piece piece;
    std::shared_ptr<const Ancestor<Policy>> parent;  // hierarchy only
  };

  template <class Policy>
  void retest_above(const Policy& policy, const Item<Policy>& item, std::vector<PairRef>& alive);

  // ---- The ordered search (ordered_tasks.h).
  // What a node's tests decided.
  enum class Outcome { Cleared, Split, Stopped, Witness };

  // Exact resolution of a piece's feature pairs (src/verify/exact_resolution.h):
  // the outcome, or nothing when it could not decide.  Early, before the
  // stop, for the certified kernels when the few pairs left are cheaper to
  // decide than to subdivide (continuous-collision queries at the root).
  static constexpr std::size_t kExactEarlyWork = 16;  // alive pairs times the curve's degree
  // Exact resolution decides the nominal rational curve: not for enclosed
  // motions (no exact curve), and not with a tube (tolerance, clearance),
  // where "the nominal motion does not touch" would not clear the piece.
  bool exact_resolution_applies() const {
    // Not with a URDF primitive: its contacts are the polyhedron's, whose
    // roots say nothing about the true shape.
    return options.kernel != KernelKind::Fast && options.exact_resolution && !extras.enclosed && extras.tube == 0 &&
           !extras.distance_witness() && !enlarged_pair(*moving.body, *other.body);
  }
  // Higher degrees (the paper's degree-8 motions: contact polynomials of
  // degree 24 with large coefficients) are decided at the stop only, on
  // small pieces (a tuning choice: on the paper grid's collision scenes
  // somewhat faster than deciding early, e.g. n = 5 individual 0.23 -> 0.11 s).
  static constexpr std::size_t kExactEarlyDegree = 3;
  bool exact_early(const Node& node) const {
    if (!exact_resolution_applies()) return false;
    const std::size_t degree = curve.size() - 1;
    if (degree > kExactEarlyDegree || node.alive.size() * std::max<std::size_t>(degree, 1) > kExactEarlyWork)
      return false;
    return std::none_of(node.alive.begin(), node.alive.end(), [](const PairRef& p) { return p.nodes; });
  }
  std::optional<Outcome> decide_exactly(const Node& node) {
    switch (decide_piece<B>(*this, node)) {
      case ExactOutcome::Cleared: cleared(node); return Outcome::Cleared;
      case ExactOutcome::Witness: return Outcome::Witness;
      default: return std::nullopt;
    }
  }

  template <class Policy>
  Outcome visit(const Policy& policy, Item<Policy>& item, Item<Policy>& left, Item<Policy>& right,
                Spheres<Policy>& spheres);

  template <class Policy>
  bool dfs(const Policy& policy, Item<Policy> root, std::uint64_t budget, std::uint64_t stop_budget,
           Spheres<Policy>& spheres, std::atomic<std::uint64_t>* shared = nullptr, std::uint64_t shared_limit = 0);

  // Adds a task's result after everything before it in parameter order;
  // false once a witness ends the search.
  bool merge(const CheckResult& part) { return merge_result(result, part); }

  // The search: the top of the subdivision tree sequentially, then the
  // pieces at depth kTaskDepth (and shallower stops) as independent tasks
  // on up to options.threads threads, merged in parameter order.  The
  // result is the same for every thread count (the tasks and their node
  // budgets do not depend on it).
  static constexpr int kTaskDepth = 5;

  template <class Policy>
  void search(const Policy& policy);

  void run();


  // ---- The start check, the partition (search.h).
  void drop_cover(const Exact& s, const std::optional<Exact>& e);

  void secure_partition();

};

}  // namespace tmcert::detail
