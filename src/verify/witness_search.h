// Internal to src/verify: a check's tests of the configuration at one curve
// parameter (search_check.h): the filtered static test under the curve's or the
// enclosure's poses, the witnesses a stop tries (a common point, a vertex inside
// a solid, a closest pair within a clearance or tolerance, a point of the true
// shapes of URDF primitives), and the whole configuration's apartness used by
// the partition (proofs/witness.md, proofs/containment.md, proofs/partition.md).
#pragma once

#include "src/verify/search_check.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace tmcert::detail {

template <int B>
void Check<B>::set_witness(const Exact& u, const StaticHit& hit) {
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
template <int B>
std::optional<StaticHit> Check<B>::static_test(const Exact& u, const std::set<std::pair<int, int>>* only,
                                               bool* uncertain) {
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
template <int B>
bool Check<B>::live_parts(const std::vector<PairRef>& alive, std::set<std::pair<int, int>>& parts) const {
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
template <int B>
bool Check<B>::try_witness(const Exact& u, const std::vector<PairRef>& alive) {
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
template <int B>
bool Check<B>::true_witness(const Exact& u, const std::vector<PairRef>& alive) {
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
template <int B>
bool Check<B>::true_witness_later(const Exact& u0, const Exact& u1) {
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
template <int B>
std::array<ShapeSide, 2> Check<B>::sides_at(const Exact& u) const {
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
template <int B>
Apartness Check<B>::interior_witness(const Exact& u) {
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

// The rational poses at the centres of the pose boxes `maps` (only to aim a
// witness: nothing rests on them); none when a box is not finite.
template <int B>
std::optional<std::array<Mat34E, B>> box_centres(const std::array<PoseInterval, B>& maps) {
  std::array<Mat34E, B> near;
  for (int b = 0; b < B; ++b)
    for (int e = 0; e < 12; ++e) {
      const double lo = maps[b][e].inf(), hi = maps[b][e].sup();
      if (!std::isfinite(lo) || !std::isfinite(hi)) return std::nullopt;
      near[b][e] = Exact(lo) + (Exact(hi) - Exact(lo)) / 2;
    }
  return near;
}

// Tolerance at an enclosed pose (a transcendental motion at u, where the
// poses are known only as boxes): a translation v of one body within its
// tolerance (|v|^2 <= reach2, exact) after which an edge of one body
// crosses a triangle of the other for every pose in the boxes (the certain
// crossings of filtered_first_hit, kernels/robust_crossing.h).  v is
// aimed by the exact closest points at a rational pose near the boxes'
// centres, and made longer than their distance so that the displaced
// bodies interpenetrate by a depth that the boxes' width does not undo:
// the full reach first, then half way (a thin body must not be crossed
// through).  The witness is the crossing's point box and v
// (proofs/enclosures.md section 6).
template <int B>
bool displaced_crossing(Check<B>& c, const Exact& u, const std::set<std::pair<int, int>>* only) {
  const CheckExtras<B>& x = c.extras;
  const int k = x.reach2[1] > x.reach2[0] ? 1 : 0;  // the body translated: the longer reach
  if (!(x.reach2[k] > 0)) return false;
  std::array<PoseInterval, B> maps = x.enclosed->poses(u);
  const std::optional<std::array<Mat34E, B>> centres = box_centres<B>(maps);
  if (!centres) return false;
  const std::array<Mat34E, B>& near = *centres;
  const auto hit = closest_within(c.moving.parts, &near[0], c.other.parts, B == 2 ? &near[B - 1] : nullptr, x.reach2[k], only,
                                  c.result.stats);
  if (!hit || !(hit->points.d2 > 0)) return false;
  // The direction of the moving body's translation (relative to the other).
  const Vec3E& pa = hit->points.a;
  const Vec3E& pb = hit->points.b;
  const std::array<double, 3> dir = {CGAL::to_double(pb[0] - pa[0]), CGAL::to_double(pb[1] - pa[1]),
                                     CGAL::to_double(pb[2] - pa[2])};
  const double full = std::sqrt(CGAL::to_double(x.reach2[k] / hit->points.d2));
  if (!(full > 1)) return false;
  // Decimals with 1/1000 of the reach as their last digit (short witnesses).
  double scale = 1;
  CGAL::Gmpz scale_exact(1);
  for (const double reach = std::sqrt(CGAL::to_double(x.reach2[k])); scale * reach < 1000 && scale < 1e15; scale *= 10)
    scale_exact *= 10;
  for (double s : {full, (1 + full) / 2}) {
    for (int attempt = 0; attempt < 8; ++attempt, s *= 0.999) {
      Vec3E v;  // the moving body's relative translation, in decimals short of the reach
      for (int i = 0; i < 3; ++i) v[i] = Exact(CGAL::Gmpz(static_cast<long>(std::llround(dir[i] * s * scale))), scale_exact);
      if (v[0] * v[0] + v[1] * v[1] + v[2] * v[2] > x.reach2[k]) continue;  // rounded past the reach: shorter
      std::array<PoseInterval, B> shifted = maps;
      {
        RoundingGuard guard;
        for (int i = 0; i < 3; ++i) shifted[0][4 * i + 3] += to_interval(v[i]);
      }
      if constexpr (B == 2)
        if (k == 1) {  // translate the other body by -v instead (the same relative motion)
          shifted = maps;
          RoundingGuard guard;
          for (int i = 0; i < 3; ++i) shifted[1][4 * i + 3] -= to_interval(v[i]);
        }
      const std::optional<StaticHit> crossing = filtered_first_hit(
          c.moving.parts, &shifted[0], c.other.parts, B == 2 ? &shifted[B - 1] : nullptr, only,
          []() -> std::optional<std::pair<std::optional<Mat34E>, std::optional<Mat34E>>> { return std::nullopt; },
          c.result.stats);
      ++c.result.stats.static_configurations;
      if (!crossing || !crossing->box) break;  // try the shallower depth
      c.set_witness(u, *crossing);
      Witness& w = *c.result.witness;
      Vec3E applied = v;  // the translation of body k that the witness states
      if (k == 1) {
        for (int i = 0; i < 3; ++i) applied[i] = -v[i];
        if constexpr (B == 1)  // the fixed body moved by -v: every point by -v from the configuration tested
          for (int i = 0; i < 3; ++i) {
            (*w.point_box)[i][0] += applied[i];
            (*w.point_box)[i][1] += applied[i];
          }
      }
      w.displacement = applied;
      w.displaced = c.swapped ? 1 - k : k;
      return true;
    }
  }
  return false;
}

// Weights of a point x of simplex s (exactly on it), as short decimals
// (multiples of 10^-9, >= 0, sum exactly 1): a point of s near x.
inline std::array<Exact, 3> short_weights(const Simplex& s, const Vec3E& x) {
  std::array<double, 3> w = {1, 0, 0};
  auto dot = [](const Vec3E& a, const Vec3E& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
  auto sub = [](const Vec3E& a, const Vec3E& b) { return Vec3E{a[0] - b[0], a[1] - b[1], a[2] - b[2]}; };
  if (s.count == 2) {
    const Vec3E e = sub(s.p[1], s.p[0]);
    const Exact ee = dot(e, e);
    if (ee > 0) {
      const double l = CGAL::to_double(dot(sub(x, s.p[0]), e) / ee);
      w = {1 - l, l, 0};
    }
  } else if (s.count == 3) {  // the Gram system of the two edges from p0
    const Vec3E e1 = sub(s.p[1], s.p[0]), e2 = sub(s.p[2], s.p[0]), r = sub(x, s.p[0]);
    const Exact a = dot(e1, e1), b = dot(e1, e2), c = dot(e2, e2), det = a * c - b * b;
    if (det > 0) {
      const Exact r1 = dot(r, e1), r2 = dot(r, e2);
      const double l1 = CGAL::to_double((c * r1 - b * r2) / det), l2 = CGAL::to_double((a * r2 - b * r1) / det);
      w = {1 - l1 - l2, l1, l2};
    }
  }
  constexpr long kScale = 1000000000;
  std::array<long, 3> n{};
  long sum = 0;
  for (int k = 1; k < s.count; ++k) {
    n[k] = std::isfinite(w[k]) ? std::clamp(std::llround(w[k] * kScale), 0LL, static_cast<long long>(kScale)) : 0;
    sum += n[k];
  }
  if (sum > kScale)  // rounded past the simplex: scale back
    for (int k = 1; k < s.count; ++k) n[k] = n[k] * kScale / sum;
  n[0] = kScale;
  for (int k = 1; k < s.count; ++k) n[0] -= n[k];
  std::array<Exact, 3> out;
  for (int k = 0; k < 3; ++k) out[k] = k < s.count ? Exact(CGAL::Gmpz(n[k]), CGAL::Gmpz(kScale)) : Exact(0);
  return out;
}

// The exact inverse of an affine map [A | a] (nullopt when singular).
inline std::optional<Mat34E> inverse_affine(const Mat34E& m) {
  auto at = [&](int i, int j) -> const Exact& { return m[4 * i + j]; };
  const Exact det = at(0, 0) * (at(1, 1) * at(2, 2) - at(1, 2) * at(2, 1)) -
                    at(0, 1) * (at(1, 0) * at(2, 2) - at(1, 2) * at(2, 0)) +
                    at(0, 2) * (at(1, 0) * at(2, 1) - at(1, 1) * at(2, 0));
  if (det == 0) return std::nullopt;
  Mat34E inv;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {  // cofactor of (j, i) over det
      const int r0 = (j + 1) % 3, r1 = (j + 2) % 3, c0 = (i + 1) % 3, c1 = (i + 2) % 3;
      inv[4 * i + j] = (at(r0, c0) * at(r1, c1) - at(r0, c1) * at(r1, c0)) / det;
    }
  for (int i = 0; i < 3; ++i) inv[4 * i + 3] = -(inv[4 * i] * at(0, 3) + inv[4 * i + 1] * at(1, 3) + inv[4 * i + 2] * at(2, 3));
  return inv;
}

// A clearance and a tolerance together (proofs/clearance.md section 7):
// for closest points at squared distance d2 > c2 (the clearance squared),
// a fraction lambda in [0, 1] of their difference, a short decimal, such
// that translating one body by it leaves them within the clearance,
// (1 - lambda)^2 d2 <= c2, and stays within that body's translation
// reach, lambda^2 d2 <= r2; both decided exactly.  None when not found.
inline std::optional<Exact> clearance_step(const Exact& d2, const Exact& c2, const Exact& r2) {
  const double D = std::sqrt(CGAL::to_double(d2)), d = std::sqrt(CGAL::to_double(c2)),
               r = std::sqrt(CGAL::to_double(r2));
  if (!(D > 0) || !std::isfinite(D)) return std::nullopt;
  const double lo = std::max(0.0, 1 - d / D), hi = std::min(1.0, r / D);
  const double mid = (lo + hi) / 2;
  CGAL::Gmpz scale(1);
  for (int digits = 1; digits <= 15; ++digits) {
    scale *= 10;
    const Exact l(CGAL::Gmpz(static_cast<long>(std::llround(mid * std::pow(10.0, digits)))), scale);
    if (l < 0 || l > 1) continue;
    if ((1 - l) * (1 - l) * d2 <= c2 && l * l * d2 <= r2) return l;
  }
  return std::nullopt;
}

// Both bodies toleranced (proofs/witness.md, "Two displacements"): for
// closest points at squared distance d2 > 0, fractions l0, l1 >= 0 of
// their difference, short decimals with l0 + l1 <= 1, such that translating
// the first body by l0 of the way towards the other and the second by l1
// of the way back leaves them within the clearance c2 (squared; 0: they
// meet, l0 + l1 = 1), (1 - l0 - l1)^2 d2 <= c2, each within its own
// translation reach, l0^2 d2 <= r0 and l1^2 d2 <= r1; every inequality
// decided exactly (double only aims).  None when not found.
inline std::optional<std::array<Exact, 2>> shared_step(const Exact& d2, const Exact& c2, const Exact& r0, const Exact& r1) {
  const double D = std::sqrt(CGAL::to_double(d2)), d = std::sqrt(CGAL::to_double(c2)),
               s0 = std::sqrt(CGAL::to_double(r0)), s1 = std::sqrt(CGAL::to_double(r1));
  if (!(D > 0) || !std::isfinite(D) || !(s0 + s1 > 0)) return std::nullopt;
  // The total fraction: 1 without a clearance, else the middle of
  // [1 - d/D, (s0 + s1)/D] within [0, 1]; shared in proportion to the reaches.
  const double total = c2 > 0 ? (std::max(0.0, 1 - d / D) + std::min(1.0, (s0 + s1) / D)) / 2 : 1;
  const double first = total * s0 / (s0 + s1);
  CGAL::Gmpz scale(1);
  for (int digits = 1; digits <= 15; ++digits) {
    scale *= 10;
    const double p = std::pow(10.0, digits);
    const Exact T = c2 > 0 ? Exact(CGAL::Gmpz(static_cast<long>(std::llround(total * p))), scale) : Exact(1);
    const Exact l0(CGAL::Gmpz(static_cast<long>(std::llround(first * p))), scale);
    const Exact l1 = T - l0;
    if (l0 < 0 || l1 < 0 || T > 1) continue;
    if ((1 - T) * (1 - T) * d2 <= c2 && l0 * l0 * d2 <= r0 && l1 * l1 * d2 <= r1) return std::array{l0, l1};
  }
  return std::nullopt;
}

// Clearance at an enclosed pose (a transcendental motion at u, where the
// poses are known only as boxes): a point p of one body and a point q of
// the other, fixed in their bodies' frames (short decimal weights of two
// simplices, aimed by the exact closest pair at a rational pose near the
// boxes' centres), such that |M1 p - M2 q|^2 <= d^2 for every pose M1, M2
// of the boxes, decided by an interval upper bound (rounded up) compared
// exactly with d^2.  The true poses at u are in the boxes, so the bodies
// are within d at u.  The witness gives the two points' boxes and their
// exact body coordinates (proofs/clearance.md section 6).
//
// `displaced` (a clearance and a tolerance together, proofs/clearance.md
// section 8): the bodies may also be translated within their tolerances
// first.  The translations v0 (moving body) and v1 (other) are fractions
// of the closest pair's difference at the rational pose near the boxes'
// centres (clearance_step for one body, else shared_step for both), exact
// and within the reaches exactly; each point's box is translated by its
// body's v before the same interval bound, and the witness states them.
template <int B>
bool enclosed_clearance(Check<B>& c, const Exact& u, const std::set<std::pair<int, int>>* only, bool displaced = false) {
  const CheckExtras<B>& x = c.extras;
  if (!(x.clearance2 > 0)) return false;
  if (displaced && !(x.reach2[0] > 0 || x.reach2[1] > 0)) return false;
  const std::array<PoseInterval, B> maps = x.enclosed->poses(u);
  const std::optional<std::array<Mat34E, B>> centres = box_centres<B>(maps);
  if (!centres) return false;
  const std::array<Mat34E, B>& near = *centres;
  // Displaced: points up to d + r0 + r1 apart may serve, (d + r0 + r1)^2 <= 3 (d^2 + r0^2 + r1^2).
  const Exact bound2 = displaced ? 3 * (x.clearance2 + x.reach2[0] + x.reach2[1]) : x.clearance2;
  const auto hit = closest_within(c.moving.parts, &near[0], c.other.parts, B == 2 ? &near[B - 1] : nullptr, bound2,
                                  only, c.result.stats);
  if (!hit) return false;
  // The translations (zero unless displaced), exact, within the reaches.
  std::array<Vec3E, 2> shift{Vec3E{Exact(0), Exact(0), Exact(0)}, Vec3E{Exact(0), Exact(0), Exact(0)}};
  std::array<bool, 2> shifted{false, false};
  if (displaced) {
    if (!(hit->points.d2 > 0)) return false;
    std::array<Exact, 2> l{Exact(0), Exact(0)};
    const int k = x.reach2[1] > x.reach2[0] ? 1 : 0;  // the longer reach first, alone
    if (const std::optional<Exact> one = clearance_step(hit->points.d2, x.clearance2, x.reach2[k])) {
      l[k] = *one;
    } else if (x.reach2[0] > 0 && x.reach2[1] > 0) {
      const std::optional<std::array<Exact, 2>> two = shared_step(hit->points.d2, x.clearance2, x.reach2[0], x.reach2[1]);
      if (!two) return false;
      l = *two;
    } else {
      return false;
    }
    for (int i = 0; i < 3; ++i) {
      shift[0][i] = l[0] * (hit->points.b[i] - hit->points.a[i]);
      shift[1][i] = l[1] * (hit->points.a[i] - hit->points.b[i]);
    }
    shifted = {l[0] > 0, l[1] > 0};
    if (!shifted[0] && !shifted[1]) return false;
  }
  // The simplices in their own frames (the other body's in world
  // coordinates when it stands still), and the closest points there.
  const Simplex& sa = c.moving.parts[hit->part_a].simplices[hit->simplex_a];
  const Simplex& sb = c.other.parts[hit->part_b].simplices[hit->simplex_b];
  auto place = [](const Mat34E& m, const Vec3E& v) {
    Vec3E r;
    for (int i = 0; i < 3; ++i) r[i] = m[4 * i] * v[0] + m[4 * i + 1] * v[1] + m[4 * i + 2] * v[2] + m[4 * i + 3];
    return r;
  };
  auto local_point = [&](const Simplex& s, const Mat34E* m, const Vec3E& world) {
    Simplex placed = s;
    if (m)
      for (int k = 0; k < s.count; ++k) placed.p[k] = place(*m, s.p[k]);
    const std::array<Exact, 3> w = short_weights(placed, world);  // the same weights in the simplex's frame
    Vec3E p{Exact(0), Exact(0), Exact(0)};
    for (int k = 0; k < s.count; ++k)
      for (int i = 0; i < 3; ++i) p[i] += w[k] * s.p[k][i];
    return p;
  };
  const Vec3E p = local_point(sa, &near[0], hit->points.a);
  const Vec3E q = local_point(sb, B == 2 ? &near[B - 1] : nullptr, hit->points.b);
  std::array<std::array<Interval, 3>, 2> box;
  bool within = false;
  {
    RoundingGuard guard;
    auto place_interval = [](const PoseInterval& m, const Vec3E& v) {
      const std::array<Interval, 3> vi = {to_interval(v[0]), to_interval(v[1]), to_interval(v[2])};
      std::array<Interval, 3> r;
      for (int i = 0; i < 3; ++i) r[i] = m[4 * i] * vi[0] + m[4 * i + 1] * vi[1] + m[4 * i + 2] * vi[2] + m[4 * i + 3];
      return r;
    };
    box[0] = place_interval(maps[0], p);
    if constexpr (B == 2) box[1] = place_interval(maps[B - 1], q);
    else box[1] = {to_interval(q[0]), to_interval(q[1]), to_interval(q[2])};
    for (int s = 0; s < 2; ++s)  // translated within the tolerances (displaced)
      if (shifted[s])
        for (int i = 0; i < 3; ++i) box[s][i] += to_interval(shift[s][i]);
    Interval d2(0);
    for (int i = 0; i < 3; ++i) d2 += CGAL::square(box[0][i] - box[1][i]);
    within = std::isfinite(d2.sup()) && Exact(d2.sup()) <= x.clearance2;
  }
  ++c.result.stats.static_tests;
  if (!within) return false;
  // The points in their bodies' frames: the other body's, when it stands
  // still, from world coordinates through its fixed pose.
  Vec3E q_body = q;
  if constexpr (B == 1) {
    const std::optional<Mat34E> inv = inverse_affine(fixed_pose(*c.other.body));
    if (!inv) return false;
    q_body = place(*inv, q);
  }
  const std::string a = c.moving.body->name + " " + c.moving.parts[hit->part_a].name;
  const std::string b = c.other.body->name + " " + c.other.parts[hit->part_b].name;
  std::array<std::array<std::array<Exact, 2>, 3>, 2> boxes;
  for (int s = 0; s < 2; ++s)
    for (int i = 0; i < 3; ++i) boxes[s][i] = {Exact(box[s][i].inf()), Exact(box[s][i].sup())};
  Witness w;
  w.t = c.scene_t(u);
  w.features = c.swapped ? std::array<std::string, 2>{b, a} : std::array<std::string, 2>{a, b};
  w.points_box = c.swapped ? decltype(boxes){boxes[1], boxes[0]} : boxes;
  w.point_box = (*w.points_box)[0];
  w.local_points = c.swapped ? std::array<Vec3E, 2>{q_body, p} : std::array<Vec3E, 2>{p, q_body};
  if (shifted[0] || shifted[1]) {  // in the check's order: one displacement, or both
    const int first = c.swapped ? 1 : 0;  // the check's first body, as moving (0) or other (1)
    const int one = shifted[0] && shifted[1] ? first : (shifted[0] ? 0 : 1);
    w.displacement = shift[one];
    w.displaced = (one == 0) != c.swapped ? 0 : 1;
    if (shifted[0] && shifted[1]) w.displacement_other = shift[1 - one];
  }
  c.result.witness = w;
  c.result.verdict = Verdict::Collision;
  return true;
}

// Tolerance and clearance (SCENE_FORMAT.md): at curve parameter u, where
// the poses are exact, the exact closest points of the two bodies; they
// prove a clearance violation when no farther apart than the clearance,
// a toleranced contact when a translation within one body's tolerance
// brings them together (proofs/enclosures.md section 6), and, with both,
// a violation of the clearance after such a translation
// (proofs/clearance.md section 7).
template <int B>
bool Check<B>::distance_witness(const Exact& u, const std::set<std::pair<int, int>>* only) {
  if (!extras.distance_witness()) return false;
  Mat34E m1;
  std::optional<Mat34E> m2;
  if (extras.enclosed) {
    const auto exact = extras.enclosed->exact_poses(u);
    if (!exact)
      return enclosed_clearance(*this, u, only) || displaced_crossing(*this, u, only) ||
             enclosed_clearance(*this, u, only, true);
    m1 = (*exact)[0];
    if constexpr (B == 2) m2 = (*exact)[1];
  } else {
    m1 = evaluate<B>(curve, u, 0);
    if constexpr (B == 2) m2 = evaluate<B>(curve, u, 1);
  }
  Exact bound2 = extras.clearance2;
  for (const Exact& r : extras.reach2) bound2 = std::max(bound2, r);
  // Both a clearance and a tolerance: points up to d + r apart may serve,
  // and (d + r)^2 <= 2 (d^2 + r^2).
  const int k = extras.reach2[1] > extras.reach2[0] ? 1 : 0;  // the body translated: the longer reach
  const bool combined = extras.clearance2 > 0 && extras.reach2[k] > 0;
  if (combined) bound2 = 2 * (extras.clearance2 + extras.reach2[k]);
  // Both bodies toleranced: where a translation of one body alone does not
  // serve, points up to d + r0 + r1 apart may serve with both translated,
  // and (d + r0 + r1)^2 <= 3 (d^2 + r0^2 + r1^2) (a second search, only
  // where the first found nothing: the first's pair is the closest anyway).
  const bool both = extras.reach2[0] > 0 && extras.reach2[1] > 0;
  auto hit = closest_within(moving.parts, &m1, other.parts, m2 ? &*m2 : nullptr, bound2, only, result.stats);
  if (!hit && both)
    hit = closest_within(moving.parts, &m1, other.parts, m2 ? &*m2 : nullptr,
                         3 * (extras.clearance2 + extras.reach2[0] + extras.reach2[1]), only, result.stats);
  if (!hit) return false;
  const ClosestPoints* best = &hit->points;
  const int best_i = hit->part_a, best_j = hit->part_b;
  const std::string a = moving.body->name + " " + moving.parts[best_i].name;
  const std::string b = other.body->name + " " + other.parts[best_j].name;
  Witness w{scene_t(u), swapped ? std::array{b, a} : std::array{a, b}, best->a};
  // Both bodies translated, each by its share of the way (shared_step):
  // the moving body's point a by l0 (b - a), the other's b by l1 (a - b).
  auto both_translated = [&]() {
    if (!both) return false;
    const std::optional<std::array<Exact, 2>> l =
        shared_step(best->d2, extras.clearance2, extras.reach2[0], extras.reach2[1]);
    if (!l) return false;
    Vec3E v0, v1, a_moved, b_moved;
    for (int i = 0; i < 3; ++i) {
      v0[i] = (*l)[0] * (best->b[i] - best->a[i]);
      v1[i] = (*l)[1] * (best->a[i] - best->b[i]);
      a_moved[i] = best->a[i] + v0[i];
      b_moved[i] = best->b[i] + v1[i];
    }
    w.displacement = swapped ? v1 : v0;  // the first body of the check's
    w.displaced = 0;
    w.displacement_other = swapped ? v0 : v1;
    if (extras.clearance2 > 0) {
      w.points = swapped ? std::array{b_moved, a_moved} : std::array{a_moved, b_moved};
      w.point = (*w.points)[0];
    } else {
      w.point = a_moved;  // = b_moved: l0 + l1 = 1
    }
    return true;
  };
  if (best->d2 > 0) {
    if (extras.clearance2 > 0 && best->d2 <= extras.clearance2) {
      w.points = swapped ? std::array{best->b, best->a} : std::array{best->a, best->b};
      w.point = (*w.points)[0];
    } else if (combined) {  // translate body k by lambda of the way: within the clearance after it
      const std::optional<Exact> lambda = clearance_step(best->d2, extras.clearance2, extras.reach2[k]);
      if (!lambda) {
        if (!both_translated()) return false;
        result.witness = w;
        result.verdict = Verdict::Collision;
        return true;
      }
      const Vec3E& from = k == 0 ? best->a : best->b;  // the translated body's point
      const Vec3E& to = k == 0 ? best->b : best->a;
      Vec3E v, moved;
      for (int i = 0; i < 3; ++i) {
        v[i] = *lambda * (to[i] - from[i]);
        moved[i] = from[i] + v[i];
      }
      w.displacement = v;
      w.displaced = (k == 0) != swapped ? 0 : 1;
      const std::array<Vec3E, 2> pts = k == 0 ? std::array{moved, best->b} : std::array{best->a, moved};
      w.points = swapped ? std::array{pts[1], pts[0]} : pts;
      w.point = (*w.points)[0];
    } else if (best->d2 <= extras.reach2[0]) {  // translate the moving body onto the other
      w.displacement = Vec3E{best->b[0] - best->a[0], best->b[1] - best->a[1], best->b[2] - best->a[2]};
      w.displaced = swapped ? 1 : 0;
      w.point = best->b;
    } else if (best->d2 <= extras.reach2[1]) {
      w.displacement = Vec3E{best->a[0] - best->b[0], best->a[1] - best->b[1], best->a[2] - best->b[2]};
      w.displaced = swapped ? 0 : 1;
      w.point = best->a;
    } else if (!both_translated()) {
      return false;
    }
  }
  result.witness = w;
  result.verdict = Verdict::Collision;
  return true;
}

// Whether one body of the pair (a solid) holds a component of the other
// at curve parameter u, by the start machinery of solids
// (start_containment: exact ray parity at exact poses, else the boxes
// of the enclosed poses).  Contact sets the witness.
template <int B>
Apartness Check<B>::containment_at(const Exact& u) {
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
template <int B>
Apartness Check<B>::free_at(const Exact& u) {
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

}  // namespace tmcert::detail
