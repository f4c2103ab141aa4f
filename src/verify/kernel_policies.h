// Internal to src/verify: the piece representation, ball and contact test of each kernel
// (filtered, exact, fast) for one (B = 1) or two (B = 2) moving bodies.
#pragma once

#include "kernels/filtered.h"
#include "kernels/separation.h"
#include "src/verify/pairs.h"
#include "src/verify/verify.h"

#include <CGAL/number_utils.h>

#include <optional>

namespace tmcert::detail {

// ------------------------------------------------------------------ kernels
// Each policy supplies the piece representation, its ball and the contact
// test in one number type; the search below is shared.  B = 1: body 1 moves,
// body 2 is fixed (world coordinates, no rho term); B = 2: both move along
// their joint curve, with the product metric.

template <int B, class FT>
Placement<FT> make_placement(const std::array<FT, 12 * B>& center, const FT& r2) {
  Placement<FT> p;
  for (int e = 0; e < 12; ++e) p.g1[e] = center[e];
  if constexpr (B == 2) {
    p.body2_moving = true;
    for (int e = 0; e < 12; ++e) p.g2[e] = center[12 + e];
  }
  p.r2 = r2;
  return p;
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
    BallD<B> ball;
    Placement<Interval> interval;
    std::optional<Placement<Exact>> exact;  // built on the first exact fallback
    VertexImages moving_images, other_images;  // for the axis test
    bool valid() const { return ball.valid; }
    double r2() const { return ball.r2; }
  };
  const PreparedBody& m;
  const PreparedBody& f;
  const HomogeneousCurve<Exact, B>& curve;

  Piece root() const { return enclose(curve); }
  void split(const Piece& p, Piece& l, Piece& r) const {
    RoundingGuard guard;  // interval de Casteljau encloses the exact halves
    split_half(p, l, r);
  }
  Ball ball(const Piece& p) const {
    Ball b{bounding_ball<B>(p, metrics_of<B>(m, f)), {}, std::nullopt};
    if (b.ball.valid) {
      std::array<Interval, 12 * B> c;
      for (int e = 0; e < 12 * B; ++e) c[e] = Interval(b.ball.center[e]);
      b.interval = make_placement<B>(c, Interval(b.ball.r2));
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
      if (apart_along_axis<Interval>(p.kind, xs, nx, ys, ny, rho, b.interval.r2)) {
        ++stats.axis_clears;
        return CGAL::POSITIVE;
      }
    }
    return filtered(
        [&] { return contact_sign<Interval>(p.kind, X.interval[p.i], Y.interval[p.j], b.interval); },
        [&] {
          if (!b.exact) {
            std::array<Exact, 12 * B> c;
            for (int e = 0; e < 12 * B; ++e) c[e] = Exact(b.ball.center[e]);
            b.exact = make_placement<B>(c, Exact(b.ball.r2));
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
    const FeatureTable& X = moving_table(m, p.kind);
    const FeatureTable& Y = other_table(f, p.kind);
    return hull_search<B>(piece, X.approx[p.i], Y.approx[p.j], [&](const HullPlane& plane) {
      RoundingGuard guard;
      return hull_apart<B>(piece, X.interval[p.i], Y.interval[p.j], plane);
    });
  }
};

template <int B>
struct ExactPolicy {
  using Piece = HomogeneousCurve<Exact, B>;
  struct Ball {
    Placement<Exact> placement;
    bool valid() const { return true; }
    double r2() const { return CGAL::to_double(placement.r2); }
  };
  const PreparedBody& m;
  const PreparedBody& f;
  const HomogeneousCurve<Exact, B>& curve;

  Piece root() const { return curve; }
  void split(const Piece& p, Piece& l, Piece& r) const { split_half(p, l, r); }
  Ball ball(const Piece& p) const {
    BallE<B> b = bounding_ball<B>(p, metrics_of<B>(m, f));
    return Ball{make_placement<B>(b.center, b.r2)};
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
    return sphere_frame(p);
  }
  CGAL::Sign test(Ball& b, const PairRef& p, CheckStats& stats, bool axis = false) const {
    FilterCounters& c = stats.by_kind[static_cast<int>(p.kind)];
    ++c.calls;
    ++c.exact_fallbacks;  // every call is exact
    return contact_sign<Exact>(p.kind, moving_exact(m, p.kind)[p.i], other_exact(f, p.kind)[p.j],
                               b.placement);
  }
  // The hull test, decided exactly (proofs/hull-test.md).
  bool hull(const Piece& piece, const PairRef& p) const {
    return hull_search<B>(piece, moving_table(m, p.kind).approx[p.i], other_table(f, p.kind).approx[p.j],
                          [&](const HullPlane& plane) {
                            return hull_apart<B>(piece, moving_exact(m, p.kind)[p.i], other_exact(f, p.kind)[p.j], plane);
                          });
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

  Piece root() const { return approximate(curve); }
  void split(const Piece& p, Piece& l, Piece& r) const { split_half(p, l, r); }
  Ball ball(const Piece& p) const {
    Ball b{bounding_ball<B>(p, metrics_of<B>(m, f)), {}};
    b.placement = make_placement<B>(b.ball.center, b.ball.r2);
    return b;
  }
  using SphereFT = double;
  SphereFrame<double> frame(const Ball& b) const { return sphere_frame(b.placement); }
  CGAL::Sign test(Ball& b, const PairRef& p, CheckStats& stats, bool axis = false) const {
    // No axis test here: in double the contact test itself is about as
    // cheap (gripper: 0.19 -> 0.21 s with it).
    ++stats.by_kind[static_cast<int>(p.kind)].calls;
    return contact_sign<double>(p.kind, moving_table(m, p.kind).approx[p.i], other_table(f, p.kind).approx[p.j],
                                b.placement);
  }
  // The hull test in double (not certified, like everything here).
  bool hull(const Piece& piece, const PairRef& p) const {
    const FeatureGeometry<double>& X = moving_table(m, p.kind).approx[p.i];
    const FeatureGeometry<double>& Y = other_table(f, p.kind).approx[p.j];
    return hull_search<B>(piece, X, Y, [&](const HullPlane& plane) { return hull_apart<B>(piece, X, Y, plane); });
  }
};


}  // namespace tmcert::detail
