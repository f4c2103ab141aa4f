// Internal to src/verify: the search of one check: start check, pruned depth-first subdivision in
// parameter order, stop rules, witnesses (DESIGN.md sections 4-6,
// proofs/search-and-pruning.md, proofs/witness.md).
#pragma once

#include "src/verify/kernel_policies.h"
#include "src/verify/exact_resolution.h"
#include "kernels/distance.h"
#include "kernels/robust_crossing.h"
#include "src/verify/solid_contact.h"
#include "src/verify/true_shape.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <memory>
#include <stdexcept>
#include <thread>
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
  std::optional<std::array<Interval, 3>> box;  // an enclosed configuration's crossing: `point` unused
};

// What a test of the configuration at one instant proves
// (proofs/partition.md): the bodies are apart there (surfaces disjoint,
// neither inside the other), they touch (the check's witness is set), or
// neither could be proven (an enclosed pose within rounding of contact).
enum class Apartness { Free, Contact, Unknown };

// Adds `part`, the result of the parameter range right after everything in
// `total`, to `total`: statistics, cleared pieces, undecided intervals
// (joined where they abut with the same reason), the first-contact bracket
// and the witness.  False once a witness ends the search.
inline bool merge_result(CheckResult& total, const CheckResult& part) {
  CheckStats& s = total.stats;
  const CheckStats& p = part.stats;
  s.nodes += p.nodes;
  s.stops += p.stops;
  s.max_depth = std::max(s.max_depth, p.max_depth);
  s.contact += p.contact;
  for (int k = 0; k < 3; ++k) s.by_kind[k] += p.by_kind[k];
  s.static_tests += p.static_tests;
  s.static_configurations += p.static_configurations;
  s.static_filter_pairs += p.static_filter_pairs;
  s.static_filter_exact += p.static_filter_exact;
  s.sphere_tests += p.sphere_tests;
  s.slab_clears += p.slab_clears;
  s.hull_clears += p.hull_clears;
  s.axis_clears += p.axis_clears;
  s.exact_pieces += p.exact_pieces;
  s.exact_unknown += p.exact_unknown;
  total.cleared.insert(total.cleared.end(), part.cleared.begin(), part.cleared.end());
  for (const UndecidedInterval& u : part.undecided) {
    if (!total.undecided.empty() && total.undecided.back().t1 == u.t0 && total.undecided.back().reason == u.reason) {
      total.undecided.back().t1 = u.t1;
    } else {
      total.undecided.push_back(u);
    }
  }
  if (part.witness) {
    total.witness = part.witness;
    total.verdict = Verdict::Collision;
    total.first_contact_exact = part.first_contact_exact && !total.first_contact;
    const Exact lo = total.first_contact ? total.first_contact->first : part.first_contact->first;
    total.first_contact = std::pair{lo, part.first_contact->second};
    return false;
  }
  if (!total.first_contact && part.first_contact) total.first_contact = part.first_contact;
  return true;
}

// The closest pair of points of two bodies' parts (placed by `ma`, `mb`
// when given; restricted to the part pairs in `only` when given), exactly,
// when their distance squared is at most `bound2`.
struct DistanceHit {
  int part_a, part_b;
  ClosestPoints points;
};

inline std::optional<DistanceHit> closest_within(const std::vector<StaticPart>& a, const Mat34E* ma,
                                                 const std::vector<StaticPart>& b, const Mat34E* mb,
                                                 const Exact& bound2, const std::set<std::pair<int, int>>* only,
                                                 CheckStats& stats) {
  double reach;
  {
    RoundingGuard guard;
    reach = CGAL::sqrt(to_interval(bound2)).sup();
  }
  struct Placed {
    int part;
    Simplex s;
    std::array<double, 3> lo, hi;
  };
  auto place = [&](const std::vector<StaticPart>& parts, const Mat34E* m, bool first) {
    std::vector<char> use(parts.size(), only ? 0 : 1);
    if (only)
      for (const auto& [i, j] : *only) use[first ? i : j] = 1;
    std::vector<Placed> out;
    for (std::size_t i = 0; i < parts.size(); ++i) {
      if (!use[i]) continue;
      for (Simplex s : parts[i].simplices) {
        if (m)
          for (int k = 0; k < s.count; ++k) {
            Vec3E r;
            for (int c = 0; c < 3; ++c)
              r[c] = (*m)[4 * c] * s.p[k][0] + (*m)[4 * c + 1] * s.p[k][1] + (*m)[4 * c + 2] * s.p[k][2] + (*m)[4 * c + 3];
            s.p[k] = r;
          }
        Placed p{static_cast<int>(i), s, {}, {}};
        for (int c = 0; c < 3; ++c) {
          p.lo[c] = std::numeric_limits<double>::infinity();
          p.hi[c] = -p.lo[c];
          for (int k = 0; k < s.count; ++k) {
            const Interval x = to_interval(s.p[k][c]);
            p.lo[c] = std::min(p.lo[c], x.inf());
            p.hi[c] = std::max(p.hi[c], x.sup());
          }
        }
        out.push_back(std::move(p));
      }
    }
    return out;
  };
  const std::vector<Placed> xs = place(a, ma, true), ys = place(b, mb, false);
  std::optional<DistanceHit> best;
  for (const Placed& x : xs)
    for (const Placed& y : ys) {
      if (only && !only->count({x.part, y.part})) continue;
      // Boxes (enclosing the exact simplices) farther apart along an axis
      // than the reach (rounded up) hold no pair within it.
      bool far = false;
      for (int c = 0; c < 3 && !far; ++c) far = x.lo[c] - y.hi[c] > reach || y.lo[c] - x.hi[c] > reach;
      if (far) continue;
      ++stats.static_tests;
      ClosestPoints cp = closest_points(x.s, y.s);
      if (cp.d2 <= bound2 && (!best || cp.d2 < best->points.d2)) best = DistanceHit{x.part, y.part, std::move(cp)};
    }
  return best;
}

// What a check adds to the plain contact search (src/verify/general.cpp):
// a tube around the motion (tolerances, clearance), enclosed motions, and
// the distance witnesses of tolerance and clearance.
template <int B>
struct CheckExtras {
  double tube = 0;  // rational motions: every admissible pose is within this of the curve (product metric)
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

// The first exact common point of a simplex of `a`'s parts and one of
// `b`'s, in the order of parts and simplices (so the witness does not
// depend on the filter); only pairs of parts in `only` when given.  The
// simplices are placed by the interval maps `map_a`, `map_b` (null: already
// in world coordinates) to boxes; a sweep along x and the separating-axis
// filter skip pairs proven disjoint (boxes and enclosures hold the true
// simplices), and the rest get the exact test on simplices placed by the
// exact maps that `exact_maps()` returns (a pair of optional Mat34E; called
// once, and only if some pair survives the filter).  Call without a
// rounding guard.
//
// `exact_maps()` may return nullopt instead: the configuration is known only
// by its interval enclosure (an enclosed motion), and a hit must then be a
// certain transversal crossing (kernels/robust_crossing.h); `uncertain`,
// when given, is set when a pair could be neither separated nor proven to
// meet.
template <class ExactMaps>
std::optional<StaticHit> filtered_first_hit(const std::vector<StaticPart>& a, const std::array<Interval, 12>* map_a,
                                            const std::vector<StaticPart>& b, const std::array<Interval, 12>* map_b,
                                            const std::set<std::pair<int, int>>* only, ExactMaps&& exact_maps,
                                            CheckStats& stats, bool* uncertain = nullptr) {
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
  auto place_all = [&](const std::vector<StaticPart>& parts, const std::vector<char>& use,
                       const std::array<Interval, 12>* m) {
    std::vector<Item> items;
    for (std::size_t i = 0; i < parts.size(); ++i) {
      if (!use[i]) continue;
      const auto& simplices = parts[i].simplices;
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
  std::vector<char> use_a(a.size(), only ? 0 : 1), use_b(b.size(), only ? 0 : 1);
  if (only)
    for (const auto& [i, j] : *only) use_a[i] = use_b[j] = 1;
  struct Candidate {
    int pi, pj, si, sj;
    SimplexI x, y;  // the placed enclosures, for certain crossings
  };
  std::vector<Candidate> candidates;
  {
    RoundingGuard guard;
    std::vector<Item> a_items = place_all(a, use_a, map_a);
    std::vector<Item> b_items = place_all(b, use_b, map_b);
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
    auto consider = [&](const Item& x, const Item& y) {  // x from a
      if (only && !only->count({x.part, y.part})) return;
      ++stats.static_filter_pairs;
      if (!overlap(x, y) || certainly_disjoint(x.s, y.s)) return;
      ++stats.static_filter_exact;
      candidates.push_back({x.part, y.part, x.index, y.index, x.s, y.s});
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
  const std::optional<std::pair<std::optional<Mat34E>, std::optional<Mat34E>>> exact = exact_maps();
  if (!exact) {
    RoundingGuard guard;
    for (const Candidate& c : candidates) {
      const std::optional<std::array<Interval, 3>> box = certain_crossing(c.x, c.y);
      if (!box) continue;
      StaticHit hit;
      hit.part_moving = c.pi;
      hit.part_other = c.pj;
      hit.box = box;
      return hit;
    }
    if (uncertain) *uncertain = true;
    return std::nullopt;
  }
  const std::pair<std::optional<Mat34E>, std::optional<Mat34E>>& maps = *exact;
  auto exact_placed = [](Simplex s, const std::optional<Mat34E>& m) {
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
    ++stats.static_tests;
    const Simplex x = exact_placed(a[c.pi].simplices[c.si], maps.first);
    const Simplex y = exact_placed(b[c.pj].simplices[c.sj], maps.second);
    if (auto p = common_point(x, y)) return StaticHit{c.pi, c.pj, *p};
  }
  return std::nullopt;
}

// Two bodies in world coordinates (both motionless): the same filtered test.
inline std::optional<StaticHit> first_hit(const std::vector<StaticPart>& a, const std::vector<StaticPart>& b,
                                          const std::set<std::pair<int, int>>* only, CheckStats& stats) {
  return filtered_first_hit(
      a, nullptr, b, nullptr, only,
      [] { return std::optional<std::pair<std::optional<Mat34E>, std::optional<Mat34E>>>(std::in_place); }, stats);
}

// ------------------------------------------------------------------ search

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

  void set_witness(const Exact& u, const StaticHit& hit) {
    const std::string a = moving.body->name + " " + moving.parts[hit.part_moving].name;
    const std::string b = other.body->name + " " + other.parts[hit.part_other].name;
    Witness w{scene_t(u), swapped ? std::array{b, a} : std::array{a, b}, hit.point};
    if (hit.box) {
      std::array<std::array<Exact, 2>, 3> box;
      for (int i = 0; i < 3; ++i) box[i] = {Exact((*hit.box)[i].inf()), Exact((*hit.box)[i].sup())};
      w.point_box = box;
    }
    result.witness = w;
    result.verdict = Verdict::Collision;
  }

  // The configuration at curve parameter u: interval maps first (cheap),
  // exact only for simplex pairs the interval filter cannot separate.
  // With enclosed motions the poses are known exactly only where the
  // motion is rational (keyframes with exact rotations); elsewhere a hit
  // must be a certain transversal crossing (kernels/robust_crossing.h), and
  // `uncertain` (when given) is set when a simplex pair could be neither
  // separated nor proven to meet.
  std::optional<StaticHit> static_test(const Exact& u, const std::set<std::pair<int, int>>* only,
                                       bool* uncertain = nullptr) {
    ++result.stats.static_configurations;
    std::array<std::array<Interval, 12>, B> maps;
    if (extras.enclosed) {
      maps = extras.enclosed->poses(u);
    } else {
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
    return filtered_first_hit(
        moving.parts, &maps[0], other.parts, B == 2 ? &maps[B - 1] : nullptr, only,
        [&]() -> std::optional<std::pair<std::optional<Mat34E>, std::optional<Mat34E>>> {
          std::pair<std::optional<Mat34E>, std::optional<Mat34E>> exact;
          if (extras.enclosed) {
            const auto poses = extras.enclosed->exact_poses(u);
            if (!poses) return std::nullopt;  // enclosed only: certain crossings
            exact.first = (*poses)[0];
            if constexpr (B == 2) exact.second = (*poses)[1];
            return exact;
          }
          exact.first = evaluate<B>(curve, u, 0);
          if constexpr (B == 2) exact.second = evaluate<B>(curve, u, 1);
          return exact;
        },
        result.stats, uncertain);
  }

  // The pairs of parts that still have a live feature pair, into `parts`;
  // true (parts left incomplete) when a pair of hierarchy nodes is still
  // alive, which may hold any pair of parts.
  bool live_parts(const std::vector<PairRef>& alive, std::set<std::pair<int, int>>& parts) const {
    for (const PairRef& p : alive) {
      if (p.nodes) return true;
      parts.insert({moving_table(moving, p.kind).part[p.i], other_table(other, p.kind).part[p.j]});
    }
    return false;
  }

  // Exact static test of the configuration at curve parameter u, restricted
  // to the parts that still have a live feature pair (all parts when a pair
  // of hierarchy nodes is still alive); then, with a tolerance or a
  // clearance, the distance witness.
  bool try_witness(const Exact& u, const std::vector<PairRef>& alive) {
    if (enlarged_pair(*moving.body, *other.body)) return true_witness(u, alive);
    std::set<std::pair<int, int>> parts;
    const bool all = live_parts(alive, parts);
    if (auto hit = static_test(u, all ? nullptr : &parts)) {
      set_witness(u, *hit);
      return true;
    }
    return interior_witness(u) == Apartness::Contact || distance_witness(u, all ? nullptr : &parts);
  }

  // A URDF cylinder or sphere (Body::primitive) in the check: a contact of
  // the polyhedra (a static hit, a component inside, a distance witness)
  // is one of the enlarged model only.  The witness is a point proven in
  // both true bodies at u (true_shape.h); when there is none but the
  // polyhedra touch at u, the piece's stop is `enlarged_model`
  // (proofs/robot-links.md section 6).
  bool true_witness(const Exact& u, const std::vector<PairRef>& alive) {
    const std::array<ShapeSide, 2> side = sides_at(u);
    if (const std::optional<TrueContact> c = true_contact(side[0], side[1], result.stats)) {
      result.witness = witness_of(scene_t(u), *c, swapped);
      result.verdict = Verdict::Collision;
      return true;
    }
    std::set<std::pair<int, int>> parts;
    const bool all = live_parts(alive, parts);
    bool uncertain = false;
    CheckResult probe;  // the enlarged model's witnesses, not reported
    Check sub = fork(probe);
    if (sub.static_test(u, all ? nullptr : &parts, &uncertain) || uncertain || sub.interior_witness(u) != Apartness::Free ||
        sub.distance_witness(u, all ? nullptr : &parts))
      enlarged_touch = true;
    result.stats.static_tests += probe.stats.static_tests;
    return false;
  }

  // The polyhedra of a URDF primitive touch on [u0, u1] without a contact
  // of the true shapes proven there: the contact tests see only the onset
  // of contact, and the true shapes meet (if they do) after the polyhedra
  // do, so the true contact is tried at later instants u1 + (u1 - u0) 2^k up
  // to the end.  Found at u: [u0, u] is undecided `enlarged_model` and the
  // witness is at u (proofs/robot-links.md section 6).
  bool true_witness_later(const Exact& u0, const Exact& u1) {
    Exact step = u1 - u0;
    if (!(step > 0)) step = Exact(1, 1024);
    for (int k = 0; k < 70 && u1 < 1; ++k, step *= 2) {
      const Exact u = std::min(Exact(1), u1 + step);
      const std::array<ShapeSide, 2> side = sides_at(u);
      if (const std::optional<TrueContact> c = true_contact(side[0], side[1], result.stats)) {
        const Exact t0 = scene_t(u0), tw = scene_t(u);
        if (!result.undecided.empty() && result.undecided.back().t1 == t0 &&
            result.undecided.back().reason == StopReason::EnlargedModel)
          result.undecided.back().t1 = tw;
        else
          result.undecided.push_back({t0, tw, StopReason::EnlargedModel});
        result.first_contact = std::pair{result.first_contact ? result.first_contact->first : t0, tw};
        result.witness = witness_of(tw, *c, swapped);
        result.verdict = Verdict::Collision;
        ++result.stats.stops;
        return true;
      }
      if (u == 1) break;
    }
    return false;
  }

  // The two bodies at curve parameter u (moving, other), for true_contact.
  std::array<ShapeSide, 2> sides_at(const Exact& u) const {
    std::array<PoseInterval, B> maps;
    std::array<std::optional<Mat34E>, B> exact;
    if (extras.enclosed) {
      maps = extras.enclosed->poses(u);
      for (int b = 0; b < B; ++b) exact[b] = extras.enclosed->models[b]->exact_pose(extras.enclosed->s_of(b, u));
    } else {
      for (int b = 0; b < B; ++b) {
        exact[b] = b == 0 ? evaluate<B>(curve, u, 0) : evaluate<B>(curve, u, B - 1);
        for (int e = 0; e < 12; ++e) maps[b][e] = to_interval((*exact[b])[e]);
      }
    }
    return {moving_side(moving, exact[0], maps[0]), B == 2 ? moving_side(other, exact[B - 1], maps[B - 1]) : fixed_side(other)};
  }

  // A solid's inside counts as contact: a vertex of one body inside a
  // solid body at u, exactly, is a collision there, so an interpenetration
  // lasting a moment is proven even when the surfaces meet only at
  // irrational times.  One vertex per connected component suffices when
  // the surfaces do not meet at u (proofs/containment.md §5); any vertex
  // found inside is a witness whatever the surfaces do.  Free: no solid, or
  // no component inside; Unknown: a solid and no exact pose at u.
  bool has_solid() const { return moving.body->solid || other.body->solid; }
  Apartness interior_witness(const Exact& u) {
    if (!has_solid()) return Apartness::Free;
    Mat34E pose[2];
    if (extras.enclosed) {  // exact poses only (a keyframe with an exact rotation)
      const auto poses = extras.enclosed->exact_poses(u);
      if (!poses) return Apartness::Unknown;
      pose[0] = (*poses)[0];
      pose[1] = B == 2 ? (*poses)[B - 1] : fixed_pose(*other.body);
    } else {
      pose[0] = evaluate<B>(curve, u, 0);
      pose[1] = B == 2 ? evaluate<B>(curve, u, B - 1) : fixed_pose(*other.body);
    }
    const Body* body[2] = {moving.body, other.body};
    for (int s = 0; s < 2; ++s) {
      if (!body[s]->solid) continue;
      const std::unique_ptr<ClosedSurface> surface = placed_surface(*body[s], pose[s]);
      if (!surface) continue;  // singular: the solid is its surface, tested above
      for (const auto& [part, point] : component_representatives(*body[1 - s], pose[1 - s])) {
        ++result.stats.static_tests;
        if (!surface->contains(point)) continue;
        std::array<std::string, 2> names;
        names[s] = body[s]->name + " interior";
        names[1 - s] = body[1 - s]->name + " " + part;
        result.witness = Witness{scene_t(u), swapped ? std::array{names[1], names[0]} : names, point};
        result.verdict = Verdict::Collision;
        return Apartness::Contact;
      }
    }
    return Apartness::Free;
  }


  // Tolerance and clearance (SCENE_FORMAT.md): at curve parameter u, where
  // the poses are exact, the exact closest points of the two bodies; they
  // prove a clearance violation when no farther apart than the clearance,
  // and a toleranced contact when a translation within one body's tolerance
  // brings them together (proofs/enclosures.md section 6).
  bool distance_witness(const Exact& u, const std::set<std::pair<int, int>>* only) {
    if (!extras.distance_witness()) return false;
    Mat34E m1;
    std::optional<Mat34E> m2;
    if (extras.enclosed) {
      const auto exact = extras.enclosed->exact_poses(u);
      if (!exact) return false;
      m1 = (*exact)[0];
      if constexpr (B == 2) m2 = (*exact)[1];
    } else {
      m1 = evaluate<B>(curve, u, 0);
      if constexpr (B == 2) m2 = evaluate<B>(curve, u, 1);
    }
    Exact bound2 = extras.clearance2;
    for (const Exact& r : extras.reach2) bound2 = std::max(bound2, r);
    const auto hit = closest_within(moving.parts, &m1, other.parts, m2 ? &*m2 : nullptr, bound2, only, result.stats);
    if (!hit) return false;
    const ClosestPoints* best = &hit->points;
    const int best_i = hit->part_a, best_j = hit->part_b;
    const std::string a = moving.body->name + " " + moving.parts[best_i].name;
    const std::string b = other.body->name + " " + other.parts[best_j].name;
    Witness w{scene_t(u), swapped ? std::array{b, a} : std::array{a, b}, best->a};
    if (best->d2 > 0) {
      if (extras.clearance2 > 0 && best->d2 <= extras.clearance2) {
        w.points = swapped ? std::array{best->b, best->a} : std::array{best->a, best->b};
        w.point = (*w.points)[0];
      } else if (best->d2 <= extras.reach2[0]) {  // translate the moving body onto the other
        w.displacement = Vec3E{best->b[0] - best->a[0], best->b[1] - best->a[1], best->b[2] - best->a[2]};
        w.displaced = swapped ? 1 : 0;
        w.point = best->b;
      } else {
        w.displacement = Vec3E{best->a[0] - best->b[0], best->a[1] - best->b[1], best->a[2] - best->b[2]};
        w.displaced = swapped ? 0 : 1;
        w.point = best->a;
      }
    }
    result.witness = w;
    result.verdict = Verdict::Collision;
    return true;
  }

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
  template <class Policy>
  struct Spheres {
    using FT = typename Policy::SphereFT;
    SphereCache<FT> moving_cells, other_cells;
    SlabSideCache other_slabs;  // the fixed body's side of the slab test (Interval only)
    std::array<SphereCache<FT>, 3> moving, other;  // by table: vertices, edges, faces
    std::uint64_t piece = 0;
    std::vector<PairRef> scratch;  // prune's work stack
    Spheres(const PreparedBody& m, const PreparedBody& f) {
      moving_cells.reset(m.cells.tree.nodes.size());
      other_cells.reset(f.cells.tree.nodes.size());
      other_slabs.reset(f.cells.tree.nodes.size());
      int t = 0;
      for (const FeatureTable* x : {&m.vertices, &m.edges, &m.faces}) moving[t++].reset(x->size());
      t = 0;
      for (const FeatureTable* x : {&f.vertices, &f.edges, &f.faces}) other[t++].reset(x->size());
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

  // 1 + twice log2(fattening / gap) of a slab test that failed by its
  // fattening, clamped to 1..255 (a search decision only).
  static std::uint8_t carry_shortfall(const SlabTest& slab) {
    const double ratio = slab.fat / slab.gap;
    if (!(ratio > 1)) return 1;
    return static_cast<std::uint8_t>(std::min(255.0, 1 + std::floor(2 * std::log2(ratio))));
  }
  static constexpr double kDescend = 2;

  // A feature pair is cleared on a piece when its hull test on the piece's
  // control points clears it (proofs/hull-test.md), or when the piece's ball
  // is valid and its contact test is POSITIVE (the sphere test only skips
  // contact tests that would be POSITIVE).  The same function of (pair,
  // piece) on every path: with and without the hierarchy, and in the re-test
  // above a stop, whatever order the tests run in.
  template <class Policy>
  bool hull_clears(const Policy& policy, const typename Policy::Piece& piece, const PairRef& p, CheckStats& stats) {
    if (!policy.hull(piece, p)) return false;
    ++stats.hull_clears;
    return true;
  }

  template <class Policy>
  bool clears(const Policy& policy, typename Policy::Ball& ball, const typename Policy::Piece& piece,
              const PairRef& p, CheckStats& stats) {
    return hull_clears(policy, piece, p, stats) || (ball.valid() && policy.test(ball, p, stats) == CGAL::POSITIVE);
  }

  // At most this many feature pairs (and no node pair): the hull test runs
  // first, alone, and a piece it clears entirely needs no ball (the common
  // case of continuous-collision queries).  Longer lists get the cheap
  // sphere test first.
  static constexpr std::size_t kHullFirst = 16;

  // `get_ball()` returns the piece's ball, computed on first use.
  template <class Policy, class GetBall>
  void prune(const Policy& policy, GetBall&& get_ball, const typename Policy::Piece& controls,
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
    // A feature pair: its sphere test, its hull test (unless it ran
    // first), then its contact test.
    auto feature = [&](const PairRef& p, bool hull_tested) {
      const int a = moving_index(p.kind), b = other_index(p.kind);
      ++stats.sphere_tests;
      if (world_spheres_apart(spheres.moving[a].get(piece, frame, true, moving_tables[a]->spheres, p.i),
                              spheres.other[b].get(piece, frame, false, other_tables[b]->spheres, p.j)))
        return;
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
      if (world_spheres_apart(spheres.moving_cells.get(piece, frame, true, X.tree.nodes, p.i),
                              spheres.other_cells.get(piece, frame, false, Y.tree.nodes, p.j)))
        continue;
      // Flat against fixed flat: their slabs (proofs/hierarchy.md §1b).
      SlabTest slab;
      if constexpr (std::is_same_v<FT, Interval>) {
        const BvNode& a = X.tree.nodes[p.i];
        const BvNode& b = Y.tree.nodes[p.j];
        if (a.slab && b.slab && !frame.body2_moving)
          slab = slab_test(frame, a, b, &spheres.other_slabs.get(piece, frame, Y.tree.nodes, p.j));
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
      if (!expand_all && !small && !(std::max(size_a, size_b) > kDescend * radius * (a.p + b.p))) {
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

  // A stop on a piece whose ball is not finite (an enclosure that
  // overflowed or divided by a weight enclosed with 0, e.g. weights 1 and
  // 1e400): every node pair becomes its feature pairs, untested (nothing
  // can be cleared on that ball), so that the exact decision of a rational
  // motion, which takes feature pairs only, can decide the piece.  Only up
  // to kUntestedPairs feature pairs in all; beyond, the node pairs stay
  // (and the piece stays undecided).
  static constexpr std::uint64_t kUntestedPairs = 4096;
  void expand_untested(std::vector<PairRef>& alive, std::uint8_t born) const {
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

  std::vector<PairRef> root_pairs() const {
    if (!options.hierarchy) return all_pairs(moving, other);
    const BvTree& X = moving.cells.tree;
    const BvTree& Y = other.cells.tree;
    if (X.empty() || Y.empty()) return {};
    return {node_pair(X.root(), Y.root())};
  }

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

  // With the hierarchy, a feature pair made at depth d was not tested on the
  // pieces above d, where carrying every pair (all pairs) would have tested
  // it.  At a stop, test it there too and drop it if any of those pieces
  // clears it: the pairs left are then exactly those all pairs leaves, so
  // the verdict, witness and undecided pieces are the same with or without
  // the hierarchy (proofs/hierarchy.md).
  template <class Policy>
  void retest_above(const Policy& policy, const Item<Policy>& item, std::vector<PairRef>& alive) {
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

  // Tests one node: prunes its pairs; on a stop, descends to feature pairs
  // and tries the witness candidates (setting the witness, or recording the
  // undecided piece); else splits it into `left` and `right`.
  template <class Policy>
  Outcome visit(const Policy& policy, Item<Policy>& item, Item<Policy>& left, Item<Policy>& right,
                Spheres<Policy>& spheres) {
    Node& node = item.node;
    CheckStats& stats = result.stats;
    ++stats.nodes;
    stats.max_depth = std::max(stats.max_depth, node.depth);
    std::optional<typename Policy::Ball> lazy;  // the piece's ball, computed when first needed
    auto get_ball = [&]() -> typename Policy::Ball& {
      if (!lazy) lazy.emplace(policy.ball(item.piece));
      return *lazy;
    };
    prune(policy, get_ball, item.piece, node.alive, false, spheres, node.depth);  // keep the pairs not cleared on this piece
    if (node.alive.empty()) {  // cleared on the whole piece
      cleared(node);
      return Outcome::Cleared;
    }
    if (exact_early(node)) {  // few feature pairs left: decide them exactly now
      if (const auto outcome = decide_exactly(node)) return *outcome;
    }
    typename Policy::Ball& ball = get_ball();
    std::optional<StopReason> stop;
    if (node.depth >= std::min(options.max_depth, kDepthCap)) stop = StopReason::Depth;
    else if (ball.valid() && ball.r2() * rho2_sum < eps2) stop = StopReason::Epsilon;
    if (stop) {
      // A stop is final: descend the hierarchy to feature pairs here.
      if (options.hierarchy) {
        prune(policy, get_ball, item.piece, node.alive, true, spheres, node.depth);
        retest_above(policy, item, node.alive);
      }
      if (node.alive.empty()) {
        cleared(node);
        return Outcome::Cleared;
      }
      if (exact_resolution_applies()) {  // rational motions, no tube
        if (const auto outcome = decide_exactly(node)) return *outcome;
      }
      // Witness candidates: the scene time with the smallest denominator in
      // the piece (a contact at a "round" rational time, such as 1/3 or
      // 0.137, is found exactly there), then the midpoint and the end.  An
      // isolated contact is found only at its own time, which is the
      // simplest one when anything is; a contact lasting over the piece is
      // found at any of them.  Exact static tests at deep dyadic times are
      // what a colliding check spends most on, so the likeliest goes first.
      const Exact mid = node.mid();
      const Exact end = node.u1();
      const Exact simple = curve_u(simplest_between(scene_t(node.u0()), scene_t(end)));
      enlarged_touch = false;
      for (const Exact* u : {&simple, &mid, &end}) {
        if (u != &simple && *u == simple) continue;  // tried already
        if (try_witness(*u, node.alive)) {
          // The piece before the witness was not cleared: undecided, for
          // the stop's reason (the witness ends the claims).
          if (node.u0() < *u) record_range(node.u0(), *u, *stop);
          const Exact lo = result.first_contact ? result.first_contact->first : scene_t(node.u0());
          result.first_contact = std::pair{lo, scene_t(*u)};
          return Outcome::Witness;
        }
      }
      if (enlarged_touch && true_witness_later(node.u0(), node.u1())) return Outcome::Witness;
      record(node, enlarged_touch ? StopReason::EnlargedModel : *stop);
      ++stats.stops;
      return Outcome::Stopped;
    }
    left = Item<Policy>{Node{2 * node.index, node.depth + 1, node.alive}, {}, nullptr};
    right = Item<Policy>{Node{2 * node.index + 1, node.depth + 1, std::move(node.alive)}, {}, nullptr};
    policy.split(item.piece, left.piece, right.piece);
    if (options.hierarchy) {
      // This piece is an ancestor retest_above needs only for feature pairs
      // made below it, which only a node pair alive here can make; without
      // one the sub-pieces keep the chain above (pairs made at this depth or
      // above are re-tested only on pieces above theirs).
      const bool nodes_alive =
          std::any_of(left.node.alive.begin(), left.node.alive.end(), [](const PairRef& p) { return p.nodes; });
      if (nodes_alive)  // the piece is no longer needed here: the ancestor keeps it
        left.parent = right.parent = std::make_shared<const Ancestor<Policy>>(
            Ancestor<Policy>{ball, std::move(item.piece), item.parent, node.depth});
      else
        left.parent = right.parent = item.parent;
    }
    return Outcome::Split;
  }

  // Depth-first search below `root` in parameter order, at most `budget`
  // nodes (then the rest is recorded as undecided "limit").  With `shared`,
  // every node is also counted there and the search gives up (returns
  // false, its result unusable) once that count passes `shared_limit`.
  template <class Policy>
  bool dfs(const Policy& policy, Item<Policy> root, std::uint64_t budget, std::uint64_t stop_budget,
           Spheres<Policy>& spheres, std::atomic<std::uint64_t>* shared = nullptr, std::uint64_t shared_limit = 0) {
    std::vector<Item<Policy>> stack;
    stack.push_back(std::move(root));
    const std::uint64_t limit = result.stats.nodes + budget;
    const std::uint64_t stop_limit = result.stats.stops + stop_budget;
    while (!stack.empty()) {
      Item<Policy> item = std::move(stack.back());
      stack.pop_back();
      if (result.stats.nodes >= limit || result.stats.stops >= stop_limit ||
          past_deadline(options)) {  // resource limit (nodes, stops, time): not cleared
        record(item.node, StopReason::Limit);
        continue;
      }
      if (shared && ++*shared > shared_limit) return false;
      Item<Policy> left, right;
      switch (visit(policy, item, left, right, spheres)) {
        case Outcome::Witness: return true;
        case Outcome::Split:
          stack.push_back(std::move(right));
          stack.push_back(std::move(left));  // parameter order: left first
          break;
        default: break;
      }
    }
    return true;
  }

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
  void search(const Policy& policy) {
    // The ordered entries: a task to search, or the finished result of a
    // shallower piece that stopped.
    struct Entry {
      std::optional<Item<Policy>> task;
      CheckResult part;
    };
    std::vector<Entry> entries;  // in parameter order
    Spheres<Policy> spheres(moving, other);
    {
      std::vector<Item<Policy>> stack;
      stack.push_back({Node{0, 0, root_pairs()}, policy.root(), nullptr});
      while (!stack.empty()) {
        Item<Policy> item = std::move(stack.back());
        stack.pop_back();
        if (item.node.depth >= kTaskDepth || result.stats.nodes >= options.max_nodes ||
            result.stats.stops >= options.max_stops || past_deadline(options)) {
          entries.push_back({std::move(item), {}});
          continue;
        }
        Item<Policy> left, right;
        if (entries.empty()) {
          // Nothing waits before this piece: its outcome goes straight into
          // the result (the common case of small checks: no copies).
          const Outcome outcome = visit(policy, item, left, right, spheres);
          if (outcome == Outcome::Witness) return;
          if (outcome == Outcome::Split) {
            stack.push_back(std::move(right));
            stack.push_back(std::move(left));
          }
          continue;
        }
        CheckResult part;
        Check sub = fork(part);
        const Outcome outcome = sub.visit(policy, item, left, right, spheres);
        if (outcome == Outcome::Split || outcome == Outcome::Cleared) {
          merge(part);  // statistics only
          if (outcome == Outcome::Split) {
            stack.push_back(std::move(right));
            stack.push_back(std::move(left));
          }
          continue;
        }
        entries.push_back({std::nullopt, std::move(part)});
        if (outcome == Outcome::Witness) break;  // nothing after it matters
      }
    }
    // The tasks run optimistically, in parallel, each with all the node
    // and stop budgets left; the merge then replays the sequential budgets:
    // a task that used more than what the tasks before it left (or gave up
    // because all tasks together passed the node budget) is searched again,
    // alone, with exactly that.  So the result is the sequential one for
    // every thread count.
    std::size_t task_count = 0;
    for (const Entry& e : entries) task_count += e.task ? 1 : 0;
    const std::uint64_t used = result.stats.nodes;
    const std::uint64_t remaining = options.max_nodes > used ? options.max_nodes - used : 0;
    const std::uint64_t stops_remaining =
        options.max_stops > result.stats.stops ? options.max_stops - result.stats.stops : 0;
    std::vector<std::optional<Item<Policy>>> originals(entries.size());
    std::vector<char> complete(entries.size(), 0);
    std::vector<std::exception_ptr> errors(entries.size());
    std::atomic<std::size_t> next{0};
    std::atomic<std::size_t> first_witness{entries.size()};
    std::atomic<std::uint64_t> spent{0};
    for (std::size_t i = 0; i < entries.size(); ++i)
      if (entries[i].task) originals[i] = *entries[i].task;
    auto worker = [&](Spheres<Policy>* own) {
      std::optional<Spheres<Policy>> local;
      for (std::size_t i = next++; i < entries.size(); i = next++) {
        Entry& e = entries[i];
        if (!e.task || i > first_witness.load()) continue;  // after a witness: not needed
        if (!own) own = &local.emplace(moving, other);
        try {
          Check sub = fork(e.part);
          complete[i] = sub.dfs(policy, std::move(*e.task), remaining, stops_remaining, *own, &spent, remaining) ? 1 : 0;
          if (complete[i] && e.part.witness) {
            std::size_t w = first_witness.load();
            while (i < w && !first_witness.compare_exchange_weak(w, i)) {}
          }
        } catch (...) {
          errors[i] = std::current_exception();
        }
      }
    };
    if (task_count > 0) {
      const int threads = std::max(1, std::min<int>(options.threads, static_cast<int>(task_count)));
      std::vector<std::thread> pool;
      for (int t = 1; t < threads; ++t) pool.emplace_back(worker, nullptr);
      worker(&spheres);
      for (std::thread& t : pool) t.join();
    }
    std::uint64_t cumulative = 0;
    for (std::size_t i = 0; i < entries.size(); ++i) {
      Entry& e = entries[i];
      if (originals[i]) {
        if (errors[i]) std::rethrow_exception(errors[i]);
        const std::uint64_t left = remaining > cumulative ? remaining - cumulative : 0;
        // The stops the pieces merged so far (tasks and shallower stops)
        // leave.  The task ran with stops_remaining >= stops_left: its run
        // is the one with stops_left unless it reached stops_left stops
        // with budget to spare (a run with stops_left would have ended
        // there).
        const std::uint64_t stops_left =
            options.max_stops > result.stats.stops ? options.max_stops - result.stats.stops : 0;
        const bool stops_differ = stops_left < stops_remaining && e.part.stats.stops >= stops_left;
        if (!complete[i] || e.part.stats.nodes > left || stops_differ) {
          e.part = CheckResult{};
          Check sub = fork(e.part);
          sub.dfs(policy, std::move(*originals[i]), left, stops_left, spheres);
        }
        cumulative += e.part.stats.nodes;
      }
      if (!merge(e.part)) return;
    }
  }

  // The start check (DESIGN.md section 4: the contact tests are complete
  // only after a contact-free start), then the search.
  void run() {
    bool uncertain = false;
    if (extras.start_proven_free) {
      // nothing to test at the start
    } else if (enlarged_pair(*moving.body, *other.body)) {
      // The polyhedra at the start: a contact there is proven on the true
      // shapes or leaves the whole part undecided (the contact tests are
      // complete only after a start free of contact of the polyhedra).
      bool touch = false;
      {
        CheckResult probe;
        Check sub = fork(probe);
        touch = sub.static_test(Exact(0), nullptr, &uncertain).has_value();
      }
      if (touch || uncertain) {
        if (true_witness(Exact(0), {})) {
          result.first_contact = std::pair{motion.t0, motion.t0};
          result.first_contact_exact = true;
          return;
        }
        if (true_witness_later(Exact(0), Exact(1, 1 << 20))) return;
        record(Node{0, 0, {}}, StopReason::EnlargedModel);
        ++result.stats.stops;
        return;
      }
    } else if (auto hit = static_test(Exact(0), nullptr, &uncertain)) {
      set_witness(Exact(0), *hit);
      result.first_contact = std::pair{motion.t0, motion.t0};
      result.first_contact_exact = true;
      return;
    }
    if (uncertain) {
      // An enclosed start configuration within rounding of contact: the
      // contact tests are complete only after a start proven free, so
      // nothing in this range can be cleared.
      record(Node{0, 0, {}}, StopReason::Epsilon);
      ++result.stats.stops;
      return;
    }
    if (!extras.start_proven_free && !extras.start_solids_proven) {
      // A join after a part that was not cleared entirely: a solid's
      // inside is contact there too (proofs/partition.md §3).
      const Apartness inside = containment_at(Exact(0));
      if (inside == Apartness::Contact) {
        result.first_contact = std::pair{motion.t0, motion.t0};
        result.first_contact_exact = true;
        return;
      }
      start_unproven = inside == Apartness::Unknown;
    }
    if (!extras.start_proven_free && enlarged_pair(*moving.body, *other.body) && extras.distance_witness()) {
      CheckResult probe;
      Check sub = fork(probe);
      if (sub.distance_witness(Exact(0), nullptr)) {  // within the clearance or tolerance on the polyhedra
        record(Node{0, 0, {}}, StopReason::EnlargedModel);
        ++result.stats.stops;
        return;
      }
    } else if (!extras.start_proven_free && distance_witness(Exact(0), nullptr)) {
      result.first_contact = std::pair{motion.t0, motion.t0};
      return;
    }
    if (extras.enclosed) {
      search(EnclosedPolicy<B>{FilteredPolicy<B>{moving, other, curve, 0}, *extras.enclosed});
    } else {
      switch (options.kernel) {
        case KernelKind::Filtered: search(FilteredPolicy<B>{moving, other, curve, extras.tube}); break;
        case KernelKind::Exact: search(ExactPolicy<B>{moving, other, curve, extras.tube}); break;
        case KernelKind::Fast: search(FastPolicy<B>{moving, other, curve, extras.tube}); break;
      }
    }
    secure_partition();
  }

  // ------------------------------------------------------------------ the partition

  // Whether one body of the pair (a solid) holds a component of the other
  // at curve parameter u, by the start machinery of solids
  // (start_containment: exact ray parity at exact poses, else the boxes
  // of the enclosed poses).  Contact sets the witness.
  Apartness containment_at(const Exact& u) {
    if (!has_solid()) return Apartness::Free;
    auto enclosed = [](const Mat34E& m) {
      std::array<Interval, 12> out;
      for (int e = 0; e < 12; ++e) out[e] = to_interval(m[e]);
      return out;
    };
    StartPose pose[2];
    if (extras.enclosed) {
      const auto boxes = extras.enclosed->poses(u);
      const auto exact = extras.enclosed->exact_poses(u);
      for (int b = 0; b < B; ++b) {
        pose[b].map = boxes[b];
        if (exact) pose[b].exact = (*exact)[b];
      }
    } else {
      for (int b = 0; b < B; ++b) {
        pose[b].exact = evaluate<B>(curve, u, b);
        pose[b].map = enclosed(*pose[b].exact);
      }
    }
    if constexpr (B == 1) {
      pose[1].exact = fixed_pose(*other.body);
      pose[1].map = enclosed(*pose[1].exact);
    }
    const Body* body[2] = {moving.body, other.body};
    bool unknown = false;
    for (int s = 0; s < 2; ++s) {
      if (!body[s]->solid) continue;
      const Mat34E identity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
      ++result.stats.static_tests;
      const Containment c = start_containment(*body[s], every_vertex(*body[s]), pose[s], *body[1 - s],
                                              component_representatives(*body[1 - s], identity), pose[1 - s],
                                              (s == 0) != swapped);
      if (c.kind == Containment::Kind::Hit) {
        result.witness = *c.witness;
        result.witness->t = scene_t(u);
        result.verdict = Verdict::Collision;
        return Apartness::Contact;
      }
      unknown = unknown || c.kind == Containment::Kind::Unknown;
    }
    return unknown ? Apartness::Unknown : Apartness::Free;
  }

  // The whole configuration at curve parameter u: every simplex pair's
  // static test, then the solids' insides, then (tolerance, clearance) the
  // distance witness.  Contact sets the witness.
  Apartness free_at(const Exact& u) {
    bool uncertain = false;
    if (auto hit = static_test(u, nullptr, &uncertain)) {
      set_witness(u, *hit);
      return Apartness::Contact;
    }
    const Apartness inside = uncertain ? Apartness::Unknown : containment_at(u);
    if (inside == Apartness::Contact) return inside;
    if (distance_witness(u, nullptr)) return Apartness::Contact;
    return inside;
  }

  // Drops the cleared pieces (certificates' cover) inside [s, e] (scene
  // parameters; without e: from s on).
  void drop_cover(const Exact& s, const std::optional<Exact>& e) {
    if (result.cleared.empty()) return;
    const Exact us = curve_u(s);
    const std::optional<Exact> ue = e ? std::optional<Exact>(curve_u(*e)) : std::nullopt;
    std::erase_if(result.cleared, [&](const CoverPiece& c) {
      const Node n{c.index, c.depth, {}};
      return n.u0() >= us && (!ue || n.u1() <= *ue);
    });
  }

  // The partition's claims after the search (SCENE_FORMAT.md, "Every
  // interval claim holds"; proofs/partition.md).  The contact tests clear a
  // piece of contact that begins in it; a run of cleared pieces is free of
  // contact when the bodies are apart at its start.  In parameter order:
  // the bodies are apart at the range's start (its start check), and stay
  // so over a cleared run that starts apart; after an undecided interval
  // nothing is known (a stop's witness candidates test only the parts that
  // own its live pairs, which need not hold a contact that began in the
  // stop: an edge is listed with one of the faces that share it).  So a run
  // that follows an undecided interval gets the test of the whole
  // configuration at its start: free, the run stands; contact, that
  // instant is the witness and nothing after it is claimed; neither, the
  // run is undecided "after_undecided", and the next run is tested in turn.
  void secure_partition() {
    std::vector<UndecidedInterval>& list = result.undecided;
    // The end of the claims: the witness's time, else the range's end.
    const Exact end = !result.witness ? motion.t1 : result.witness->root ? result.witness->root->hi : result.witness->t;
    bool apart = !start_unproven;
    Exact cursor = motion.t0;
    for (std::size_t k = 0; k <= list.size(); ++k) {
      const Exact run_end = k < list.size() ? list[k].t0 : end;
      if (cursor < run_end && !apart) {
        // At the range's start the test was just made (start_unproven).
        const Apartness at = cursor == motion.t0 ? Apartness::Unknown : free_at(curve_u(cursor));
        if (at == Apartness::Contact) {
          // The witness at `cursor`: nothing after it is claimed.
          list.resize(k);
          drop_cover(cursor, std::nullopt);
          const Exact lo = result.first_contact ? result.first_contact->first : cursor;
          result.first_contact = std::pair{std::min(lo, cursor), cursor};
          result.first_contact_exact = false;
          return;
        }
        if (at == Apartness::Free) {
          apart = true;
        } else {
          list.insert(list.begin() + static_cast<std::ptrdiff_t>(k),
                      UndecidedInterval{cursor, run_end, StopReason::AfterUndecided});
          drop_cover(cursor, run_end);
          if (!result.first_contact) result.first_contact = std::pair{cursor, run_end};
          else if (cursor < result.first_contact->first) result.first_contact->first = cursor;
          result.first_contact_exact = false;
          ++k;
        }
      }
      if (k >= list.size()) break;
      apart = false;  // after an undecided interval
      cursor = list[k].t1;
    }
  }

};


}  // namespace tmcert::detail
