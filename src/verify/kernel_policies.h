// Internal to src/verify: the piece representation, ball and contact test of each kernel
// (filtered, exact, fast) for one (B = 1) or two (B = 2) moving bodies.
#pragma once

#include "kernels/filtered.h"
#include "kernels/separation.h"
#include "src/verify/pairs.h"
#include "src/verify/swept_spheres.h"
#include "src/verify/verify.h"
#include "src/motion/enclosure.h"

#include <CGAL/number_utils.h>

#include <optional>

namespace tmcert::detail {

// ------------------------------------------------------------------ kernels
// Each policy supplies the piece representation, its ball and the contact
// test in one number type; the search below is shared.  B = 1: body 1 moves,
// body 2 is fixed (world coordinates, no rho term); B = 2: both move along
// their joint curve, with the product metric.

// Sets p's centre(s) and radius, in place (its clearance fields stay).
// In place, not returned and assigned: with a returned Placement<Interval>
// assigned to a ball's member and then given its clearance, GCC 12 -O3
// left body2_moving and g2 as stack garbage in the copy (release builds
// crashed on two-moving-body checks; -O1 with sanitizers did not).
template <int B, class FT>
void set_placement(Placement<FT>& p, const std::array<FT, 12 * B>& center, const FT& r2) {
  for (int e = 0; e < 12; ++e) p.g1[e] = center[e];
  p.body2_moving = B == 2;
  if constexpr (B == 2) {
    for (int e = 0; e < 12; ++e) p.g2[e] = center[12 + e];
  }
  p.r2 = r2;
}


// A ball of squared radius r2 widened by `tube` (a tolerance, or the
// remainder of an enclosed motion): (sqrt(r2) + tube)^2, rounded upward.
// Infinity when not finite.
inline double widen_r2(double r2, double tube) {
  if (tube == 0) return r2;
  RoundingGuard guard;
  const Interval r = CGAL::sqrt(Interval(r2)) + Interval(tube);
  const double out = CGAL::square(r).sup();
  return std::isfinite(out) ? out : std::numeric_limits<double>::infinity();
}

// A clearance d (proofs/clearance.md): an upper bound of
// d^2 + 2 d R sqrt(rho2), R = sqrt(r2) the (widened) ball's radius and rho2
// an upper bound of rho^2 over the feature pair; the contact test lowers
// Phi by it.  `clear` is an upper bound of d.  Infinity when not finite (the
// caller then clears nothing).
inline double clearance_shift(double clear, double r2, double rho2) {
  if (clear == 0) return 0;
  RoundingGuard guard;
  const Interval d(clear);
  const Interval out = CGAL::square(d) + Interval(2) * d * CGAL::sqrt(Interval(r2)) * CGAL::sqrt(Interval(rho2));
  return std::isfinite(out.sup()) ? out.sup() : std::numeric_limits<double>::infinity();
}

// An upper bound of max rho^2 over the pair of p (both sides when body 2
// moves), from the features' bounds.
template <int B>
double pair_rho2(const FeatureGeometry<Interval>& x, const FeatureGeometry<Interval>& y) {
  RoundingGuard guard;
  Interval rho = detail::max_rho2(x);
  if constexpr (B == 2) rho += detail::max_rho2(y);
  return rho.sup();
}

template <int B>
Metrics<B> metrics_of(const PreparedBody& m, const PreparedBody& f) {
  if constexpr (B == 1) return {&m.metric_data};
  else return {&m.metric_data, &f.metric_data};
}

// The axis test's vertex images of one moving body's features under one
// ball's centre, per feature table, computed on first use: a piece tests
// each feature against many others.  (A fixed body's are kept with its
// features: FeatureTable::fixed_images.)
class VertexImages {
 public:
  // The images of feature i of table t (of `size` features); the pointer
  // stays valid until the next call.
  std::pair<const Vec3<Interval>*, std::size_t> get(int t, std::size_t i, std::size_t size,
                                                    const FeatureGeometry<Interval>& F,
                                                    const std::array<Interval, 12>* g) {
    std::vector<std::int32_t>& first = first_[t];
    if (first.empty()) {
      first.assign(size, -1);
      count_[t].assign(size, 0);
    }
    if (first[i] < 0) {
      std::array<Vec3<Interval>, detail::kAxisMaxVertices> tmp;
      const std::size_t n = detail::vertex_images(F, g, tmp.data());
      first[i] = static_cast<std::int32_t>(points_.size());
      count_[t][i] = static_cast<std::uint8_t>(n);
      points_.insert(points_.end(), tmp.begin(), tmp.begin() + n);
    }
    return {points_.data() + first[i], count_[t][i]};
  }

 private:
  std::array<std::vector<std::int32_t>, 3> first_;  // per table: where a feature's images start, or -1
  std::array<std::vector<std::uint8_t>, 3> count_;  // per table: how many
  std::vector<Vec3<Interval>> points_;
};

template <int B>
struct FilteredPolicy {
  using Piece = HomogeneousCurve<Interval, B>;
  struct Ball {
    BallD<B> ball;            // the control points' ball: its r2 decides the stops
    double placed_r2 = 0;     // widened by the tube: what the tests use
    Placement<Interval> interval;
    std::optional<Placement<Exact>> exact;  // built on the first exact fallback
    VertexImages moving_images, other_images;  // for the axis test
    bool valid() const { return ball.valid; }
    double r2() const { return ball.r2; }
  };
  const PreparedBody& m;
  const PreparedBody& f;
  const HomogeneousCurve<Exact, B>& curve;
  double tube = 0;  // every pose of the check lies within this of its piece's curve (tolerance)
  double clear = 0;  // an upper bound of the check's clearance (proofs/clearance.md)

  Piece root() const { return enclose(curve); }
  void split(const Piece& p, Piece& l, Piece& r) const {
    RoundingGuard guard;  // interval de Casteljau encloses the exact halves
    split_half(p, l, r);
  }
  Ball ball(const Piece& p) const { return ball_of(p, tube); }
  // The ball of control points `p` widened by `widen`.
  Ball ball_of(const Piece& p, double widen) const {
    Ball b{bounding_ball<B>(p, metrics_of<B>(m, f)), 0, {}, std::nullopt};
    if (b.ball.valid) {
      b.placed_r2 = widen_r2(b.ball.r2, widen);
      if (!std::isfinite(b.placed_r2)) {
        b.ball.valid = false;
        return b;
      }
      std::array<Interval, 12 * B> c;
      for (int e = 0; e < 12 * B; ++e) c[e] = Interval(b.ball.center[e]);
      set_placement<B>(b.interval, c, Interval(b.placed_r2));
      b.interval.clear = clear;
    }
    return b;
  }
  // Call under RoundingGuard.
  using SphereFT = Interval;
  SphereFrame<Interval> frame(const Ball& b) const { return sphere_frame(b.interval); }
  CGAL::Sign test(Ball& b, const PairRef& p, CheckStats& stats, bool axis = false) const {
    const FeatureTable& X = moving_table(m, p.kind);
    const FeatureTable& Y = other_table(f, p.kind);
    // The axis test first, when asked (`axis`: the pair has not failed the
    // hull test, which clears most of what it would): it settles most mesh
    // pairs for a quarter of the cost, and it only ever answers POSITIVE
    // where the contact test would (proofs/contact-tests.md section 3), so
    // the answer is the same with or without it.
    if (axis) {
      RoundingGuard guard;
      const FeatureGeometry<Interval>& x = X.interval[p.i];
      const FeatureGeometry<Interval>& y = Y.interval[p.j];
      const int tx = static_cast<int>(p.kind), ty = 2 - static_cast<int>(p.kind);  // tables: vertices, edges, faces
      const auto [xs, nx] = b.moving_images.get(tx, p.i, X.interval.size(), x, &b.interval.g1);
      const auto [ys, ny] = b.interval.body2_moving ? b.other_images.get(ty, p.j, Y.interval.size(), y, &b.interval.g2)
                                                    : Y.fixed_images(p.j);
      Interval rho = detail::max_rho2(x);
      if (b.interval.body2_moving) rho += detail::max_rho2(y);
      if (apart_along_axis<Interval>(p.kind, xs, nx, ys, ny, rho, b.interval.r2, clear)) {
        ++stats.axis_clears;
        return CGAL::POSITIVE;
      }
    }
    if (clear > 0) {
      // The contact test with the clearance's shift for this pair.
      const double shift = clearance_shift(clear, b.placed_r2, pair_rho2<B>(X.interval[p.i], Y.interval[p.j]));
      if (!std::isfinite(shift)) return CGAL::ZERO;  // no bound: not cleared
      b.interval.shift = Interval(shift);
      if (b.exact) b.exact->shift = Exact(shift);
    }
    return filtered(
        [&] { return contact_sign<Interval>(p.kind, X.interval[p.i], Y.interval[p.j], b.interval); },
        [&] {
          if (!b.exact) {
            std::array<Exact, 12 * B> c;
            for (int e = 0; e < 12 * B; ++e) c[e] = Exact(b.ball.center[e]);
            b.exact.emplace();
            set_placement<B>(*b.exact, c, Exact(b.placed_r2));
            b.exact->shift = Exact(b.interval.shift.sup());
          }
          return contact_sign<Exact>(p.kind, moving_exact(m, p.kind)[p.i], other_exact(f, p.kind)[p.j], *b.exact);
        },
        stats.by_kind[static_cast<int>(p.kind)]);
  }
  // The hull test of a feature pair on the piece (proofs/hull-test.md):
  // candidate planes from the approximate features and piece, certified
  // over the intervals enclosing the control points and features.  An
  // uncertain comparison only means "not cleared": no exact fallback.
  bool hull(const Piece& piece, const PairRef& p) const {
    if (tube > 0) return false;  // the hull test knows no tube: it clears nothing then
    const FeatureTable& X = moving_table(m, p.kind);
    const FeatureTable& Y = other_table(f, p.kind);
    return hull_search<B>(piece, X.approx[p.i], Y.approx[p.j], [&](const HullPlane& plane) {
      RoundingGuard guard;
      return hull_apart<B>(piece, X.interval[p.i], Y.interval[p.j], plane, clear);  // a clearance widens it (claim HC)
    }, clear);
  }
};

template <int B>
struct ExactPolicy {
  using Piece = HomogeneousCurve<Exact, B>;
  struct Ball {
    Placement<Exact> placement;
    double hull_r2 = 0;  // the control points' ball, for the stops
    bool valid() const { return true; }
    double r2() const { return hull_r2; }
  };
  const PreparedBody& m;
  const PreparedBody& f;
  const HomogeneousCurve<Exact, B>& curve;
  double tube = 0;
  double clear = 0;  // an upper bound of the check's clearance (proofs/clearance.md)

  Piece root() const { return curve; }
  void split(const Piece& p, Piece& l, Piece& r) const { split_half(p, l, r); }
  Ball ball(const Piece& p) const {
    BallE<B> b = bounding_ball<B>(p, metrics_of<B>(m, f));
    const double r2 = CGAL::to_double(b.r2);
    if (tube > 0) {
      // (sqrt(r2) + tube)^2 from an upper bound of r2: a larger ball, still exact.
      const double widened = widen_r2(to_interval(b.r2).sup(), tube);
      b.r2 = std::isfinite(widened) ? Exact(widened) : b.r2 + Exact(1e300);
    }
    Ball out{{}, r2};
    set_placement<B>(out.placement, b.center, b.r2);
    out.placement.clear = clear;
    return out;
  }
  // The sphere test over intervals enclosing the exact ball: certified, and
  // it only ever skips contact tests that would clear too.
  // Call under RoundingGuard.
  using SphereFT = Interval;
  SphereFrame<Interval> frame(const Ball& b) const {
    Placement<Interval> p;
    for (int e = 0; e < 12; ++e) p.g1[e] = to_interval(b.placement.g1[e]);
    p.body2_moving = b.placement.body2_moving;
    if (p.body2_moving)
      for (int e = 0; e < 12; ++e) p.g2[e] = to_interval(b.placement.g2[e]);
    p.r2 = to_interval(b.placement.r2);
    p.clear = b.placement.clear;
    return sphere_frame(p);
  }
  CGAL::Sign test(Ball& b, const PairRef& p, CheckStats& stats, bool axis = false) const {
    FilterCounters& c = stats.by_kind[static_cast<int>(p.kind)];
    ++c.calls;
    ++c.exact_fallbacks;  // every call is exact
    if (clear > 0) {
      const FeatureTable& X = moving_table(m, p.kind);
      const FeatureTable& Y = other_table(f, p.kind);
      const double shift = clearance_shift(clear, to_interval(b.placement.r2).sup(),
                                           pair_rho2<B>(X.interval[p.i], Y.interval[p.j]));
      if (!std::isfinite(shift)) return CGAL::ZERO;  // no bound: not cleared
      b.placement.shift = Exact(shift);
    }
    return contact_sign<Exact>(p.kind, moving_exact(m, p.kind)[p.i], other_exact(f, p.kind)[p.j],
                               b.placement);
  }
  // The hull test, decided exactly (proofs/hull-test.md).
  bool hull(const Piece& piece, const PairRef& p) const {
    if (tube > 0) return false;
    return hull_search<B>(piece, moving_table(m, p.kind).approx[p.i], other_table(f, p.kind).approx[p.j],
                          [&](const HullPlane& plane) {
                            return hull_apart<B>(piece, moving_exact(m, p.kind)[p.i], other_exact(f, p.kind)[p.j], plane,
                                                 clear);
                          }, clear);
  }
};

template <int B>
struct FastPolicy {
  using Piece = HomogeneousCurve<double, B>;
  struct Ball {
    BallD<B> ball;
    Placement<double> placement;
    bool valid() const { return ball.valid; }
    double r2() const { return ball.r2; }
  };
  const PreparedBody& m;
  const PreparedBody& f;
  const HomogeneousCurve<Exact, B>& curve;
  double tube = 0;
  double clear = 0;  // the check's clearance (not certified here)

  Piece root() const { return approximate(curve); }
  void split(const Piece& p, Piece& l, Piece& r) const { split_half(p, l, r); }
  Ball ball(const Piece& p) const {
    Ball b{bounding_ball<B>(p, metrics_of<B>(m, f)), {}};
    const double r = std::sqrt(b.ball.r2) + tube;
    set_placement<B>(b.placement, b.ball.center, tube > 0 ? r * r : b.ball.r2);
    b.placement.clear = clear;
    return b;
  }
  using SphereFT = double;
  SphereFrame<double> frame(const Ball& b) const { return sphere_frame(b.placement); }
  CGAL::Sign test(Ball& b, const PairRef& p, CheckStats& stats, bool axis = false) const {
    // No axis test here: in double the contact test itself is about as
    // cheap (gripper: 0.19 -> 0.21 s with it).
    ++stats.by_kind[static_cast<int>(p.kind)].calls;
    if (clear > 0) {
      const FeatureGeometry<double>& X = moving_table(m, p.kind).approx[p.i];
      const FeatureGeometry<double>& Y = other_table(f, p.kind).approx[p.j];
      double rho2 = CGAL::to_double(detail::max_rho2(X));
      if constexpr (B == 2) rho2 += CGAL::to_double(detail::max_rho2(Y));
      b.placement.shift = clear * clear + 2 * clear * std::sqrt(b.placement.r2) * std::sqrt(rho2);
    }
    return contact_sign<double>(p.kind, moving_table(m, p.kind).approx[p.i], other_table(f, p.kind).approx[p.j],
                                b.placement);
  }
  // The hull test in double (not certified, like everything here).
  bool hull(const Piece& piece, const PairRef& p) const {
    if (tube > 0) return false;
    const FeatureGeometry<double>& X = moving_table(m, p.kind).approx[p.i];
    const FeatureGeometry<double>& Y = other_table(f, p.kind).approx[p.j];
    return hull_search<B>(piece, X, Y, [&](const HullPlane& plane) { return hull_apart<B>(piece, X, Y, plane, clear); }, clear);
  }
};


// ------------------------------------------------------------------ enclosed motions
// The motions of a check's bodies over one parameter interval, as segment
// models (keyframe interpolations that are not rational, or rational ones
// checked together with them): each body's segment parameter is
// s = s0 + u (s1 - s0) for the check's curve parameter u in [0, 1].
template <int B>
struct EnclosedSource {
  std::array<const SegmentModel*, B> models{};
  std::array<Exact, B> s0, s1;
  std::array<const MetricData*, B> metrics{};
  std::array<double, B> tube{};  // per body: tolerance, in its metric

  Exact s_of(int b, const Exact& u) const { return s0[b] + u * (s1[b] - s0[b]); }
  // The poses at u, enclosed.
  std::array<PoseInterval, B> poses(const Exact& u) const {
    std::array<PoseInterval, B> out;
    for (int b = 0; b < B; ++b) out[b] = enclose_pose(*models[b], s_of(b, u));
    return out;
  }
  // The poses at u exactly, when every one is known exactly there.
  std::optional<std::array<Mat34E, B>> exact_poses(const Exact& u) const {
    std::array<Mat34E, B> out;
    for (int b = 0; b < B; ++b) {
      const auto m = models[b]->exact_pose(s_of(b, u));
      if (!m) return std::nullopt;
      out[b] = *m;
    }
    return out;
  }
};

// The search's policy for enclosed motions: a piece is the degree-1 Taylor
// enclosure of every body's motion on it (src/motion/enclosure.h), whose
// ball is widened by the remainder tube (and the bodies' tolerances); the
// tests are the filtered kernel's.  Sub-pieces are enclosed anew from the
// motion, not subdivided.  No hull test (it knows no tube).
template <int B>
struct EnclosedPolicy {
  struct Piece {
    Exact u0, u1;
    HomogeneousCurve<Interval, B> controls;
    double tube = 0;
    double remainder = 0;  // the Taylor remainders' part of the tube (no tolerance)
  };
  // The filtered kernel's ball, whose stop radius also holds the Taylor
  // remainder: a piece whose motion is known only to within more than
  // epsilon (an enclosure blown up near a near-singular pose) is
  // subdivided further (or stops at the depth limit), never reported as
  // the bodies coming within epsilon.  Tolerances are not part of it.
  struct Ball : FilteredPolicy<B>::Ball {
    double remainder = 0;
    double r2() const { return widen_r2(this->ball.r2, remainder); }
  };
  using SphereFT = Interval;
  FilteredPolicy<B> base;
  const EnclosedSource<B>& source;

  Piece enclose_on(const Exact& u0, const Exact& u1) const {
    Piece p{u0, u1, HomogeneousCurve<Interval, B>(2), 0, 0};
    Interval tube2(0), remainder2(0);
    bool valid = true;
    for (int b = 0; b < B; ++b) {
      const PieceEnclosure e =
          enclose_piece(*source.models[b], source.s_of(b, u0), source.s_of(b, u1), source.metrics[b]->g_interval);
      valid = valid && e.valid;
      for (int k = 0; k < 2; ++k) {
        for (int i = 0; i < 12; ++i) p.controls[k][12 * b + i] = e.controls[k][i];
        p.controls[k][12 * B] = Interval(1);
      }
      RoundingGuard guard;
      tube2 += CGAL::square(Interval(e.tube) + Interval(source.tube[b]));
      remainder2 += CGAL::square(Interval(e.tube));
    }
    {
      // The product metric: |(d1, d2)| = sqrt(|d1|^2 + |d2|^2).
      RoundingGuard guard;
      p.tube = valid ? CGAL::sqrt(tube2).sup() : std::numeric_limits<double>::infinity();
      p.remainder = valid ? CGAL::sqrt(remainder2).sup() : std::numeric_limits<double>::infinity();
    }
    if (!std::isfinite(p.tube)) p.tube = std::numeric_limits<double>::infinity();
    return p;
  }
  Piece root() const { return enclose_on(Exact(0), Exact(1)); }
  void split(const Piece& p, Piece& l, Piece& r) const {
    const Exact mid = (p.u0 + p.u1) / 2;
    l = enclose_on(p.u0, mid);
    r = enclose_on(mid, p.u1);
  }
  Ball ball(const Piece& p) const {
    if (!std::isfinite(p.tube)) {
      Ball b{};
      b.ball.valid = false;
      return b;
    }
    return Ball{base.ball_of(p.controls, p.tube), p.remainder};
  }
  SphereFrame<Interval> frame(const Ball& b) const { return base.frame(b); }
  // The piece's segment and tube for the swept-sphere test (one moving
  // body; proofs/hierarchy.md §1c).  Call under RoundingGuard.
  SweptFrame swept(const Piece& p) const {
    if constexpr (B != 1) return {};
    std::array<Interval, 12> g0, g1;
    for (int i = 0; i < 12; ++i) g0[i] = p.controls[0][i], g1[i] = p.controls[1][i];
    return swept_frame(g0, g1, p.tube, base.clear);  // the clearance too (proofs/hierarchy.md §1c)
  }
  CGAL::Sign test(Ball& b, const PairRef& p, CheckStats& stats, bool axis = false) const {
    return base.test(b, p, stats, axis);
  }
  bool hull(const Piece&, const PairRef&) const { return false; }
};

}  // namespace tmcert::detail
