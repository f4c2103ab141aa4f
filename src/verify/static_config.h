// Internal to src/verify: tests of one configuration of two bodies (an instant
// of a check): the filtered first common point of their parts, under interval
// or exact placements, and the exact closest pair within a bound
// (proofs/static-test.md, proofs/witness.md).  Used by the search (search.h)
// and by the fixed environment.
#pragma once

#include "kernels/distance.h"
#include "kernels/robust_crossing.h"
#include "kernels/static_intersection.h"
#include "src/verify/prepared.h"
#include "src/verify/verify.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

namespace tmcert::detail {

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


// The closest pair of points of two bodies' parts (placed by `ma`, `mb`
// when given; restricted to the part pairs in `only` when given), exactly,
// when their distance squared is at most `bound2`.
struct DistanceHit {
  int part_a, part_b;
  ClosestPoints points;
  // The simplices (indices into the parts' `simplices`) holding the points.
  int simplex_a = 0, simplex_b = 0;
};

std::optional<DistanceHit> closest_within(const std::vector<StaticPart>& a, const Mat34E* ma,
                                          const std::vector<StaticPart>& b, const Mat34E* mb,
                                          const Exact& bound2, const std::set<std::pair<int, int>>* only,
                                          CheckStats& stats);

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
std::optional<StaticHit> first_hit(const std::vector<StaticPart>& a, const std::vector<StaticPart>& b,
                                   const std::set<std::pair<int, int>>* only, CheckStats& stats);

}  // namespace tmcert::detail
