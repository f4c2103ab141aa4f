// Clearance without the band (proofs/clearance.md): the contact test with
// the clearance's shift and the axis test with the clearance clear a pair
// only when every x, y of the pair keep |g(x) - y| > R rho(x) + d (so every
// map of the ball keeps them farther apart than d), checked exactly at
// sampled points; and they do clear pairs whose gap exceeds that bound.
#include "kernels/contact.h"
#include "kernels/filtered.h"
#include "kernels/separation.h"
#include "src/metric/metric.h"
#include "src/verify/kernel_policies.h"
#include "src/verify/prepared.h"
#include "tests/support/contact_pairs.h"
#include "tests/support/random_geometry.h"

#include <boost/test/unit_test.hpp>

#include <limits>

using namespace tmcert;
using namespace tmcert::testing;

namespace {

// |g(x) - y| > R rho(x) + d, decided exactly: with A = |g(x) - y|^2 - R^2 rho^2 - d^2,
// it holds iff A > 0 and A^2 > 4 d^2 R^2 rho^2.
bool farther_than_reach(const Exact& dist2, const Exact& r2, const Exact& rho2, const Exact& d) {
  const Exact a = dist2 - r2 * rho2 - d * d;
  return a > 0 && a * a > Exact(4) * d * d * r2 * rho2;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(clearance)

BOOST_AUTO_TEST_CASE(shift_is_an_upper_bound_and_infinite_on_overflow) {
  using detail::clearance_shift;
  BOOST_TEST(clearance_shift(0, 4, 9) == 0);
  // d^2 + 2 d R rho = 1/4 + 2 (1/2) 2 3 = 6.25, rounded up.
  BOOST_TEST(clearance_shift(0.5, 4, 9) >= 6.25);
  BOOST_TEST(clearance_shift(0.5, 4, 9) < 6.25 * (1 + 1e-12));
  BOOST_TEST(clearance_shift(0.5, 4, 9) <= clearance_shift(0.5, 4.5, 9));
  BOOST_TEST(std::isinf(clearance_shift(1e300, 1e300, 1e300)));
  BOOST_TEST(std::isinf(clearance_shift(0.5, std::numeric_limits<double>::infinity(), 1)));
}

// The shifted contact test (filtered and exact agree) and the axis test
// with a clearance, on random triangles, balls and clearances: whatever
// they clear keeps every sampled pair farther than R rho + d; both answers
// occur.
BOOST_AUTO_TEST_CASE(shifted_tests_clear_only_pairs_farther_than_the_clearance) {
  Rng r(2027);
  int cleared = 0, not_cleared = 0, axis = 0;
  for (int iter = 0; iter < 200; ++iter) {
    std::array<Vec3E, 3> tm{rand_point(r), rand_point(r), rand_point(r)};
    std::array<Vec3E, 3> tf{rand_point(r), rand_point(r), rand_point(r)};
    if (testing::collinear(tm[0], tm[1], tm[2]) || testing::collinear(tf[0], tf[1], tf[2])) continue;
    const TrianglePair pair(tm, tf);
    Placement<Exact> pe;
    for (auto& e : pe.g1) e = r.q(-4, 4, 4);
    pe.g1[0] += 1; pe.g1[5] += 1; pe.g1[10] += 1;
    pe.r2 = r.q(0, 8, 64);
    const Exact d = r.q(0, 6, 8) + Exact(1, 8);
    const double clear = to_interval(d).sup();
    Placement<Interval> pi;
    for (int e = 0; e < 12; ++e) pi.g1[e] = to_interval(pe.g1[e]);
    pi.r2 = to_interval(pe.r2);
    pi.clear = pe.clear = clear;
    const Exact clear_e(clear);  // the bound the tests use (>= d)

    const int n = 8;
    auto check_pair = [&](ContactKind kind, const FeatureGeometry<Exact>& X, const FeatureGeometry<Exact>& Y,
                          const FeatureGeometry<Interval>& Xi, const FeatureGeometry<Interval>& Yi, auto sample) {
      const double shift = detail::clearance_shift(clear, pi.r2.sup(), detail::pair_rho2<1>(Xi, Yi));
      BOOST_REQUIRE(std::isfinite(shift));
      pe.shift = Exact(shift);
      pi.shift = Interval(shift);
      const CGAL::Sign s = contact_sign<Exact>(kind, X, Y, pe);
      FilterCounters counters;
      const CGAL::Sign f = filtered([&] { return contact_sign<Interval>(kind, Xi, Yi, pi); },
                                    [&] { return contact_sign<Exact>(kind, X, Y, pe); }, counters);
      BOOST_CHECK(f == s);
      bool axis_clear;
      {
        RoundingGuard guard;
        axis_clear = apart_along_axis<Interval>(kind, Xi, Yi, pi);
      }
      bool all_far = true;
      for (int i = 0; i <= n && all_far; ++i)
        for (int j = 0; j <= n && all_far; ++j) {
          auto [x, y] = sample(Exact(i, n), Exact(j, n));
          const Vec3E gx = map_point(pe.g1, x);
          Exact d2 = 0;
          for (int k = 0; k < 3; ++k) d2 += (gx[k] - y[k]) * (gx[k] - y[k]);
          all_far = farther_than_reach(d2, pe.r2, pair.pm.exact_metric().rho2(x), clear_e);
        }
      if (s == CGAL::POSITIVE) {
        ++cleared;
        BOOST_CHECK_MESSAGE(all_far, "contact test cleared a pair within the clearance, iteration " << iter);
      } else {
        ++not_cleared;
      }
      if (axis_clear) {
        ++axis;
        BOOST_CHECK_MESSAGE(all_far, "axis test cleared a pair within the clearance, iteration " << iter);
      }
    };
    pair.for_each_sampled_pair(check_pair);
  }
  BOOST_TEST_MESSAGE("clearance: " << cleared << " cleared, " << not_cleared << " not, " << axis << " by the axis test");
  BOOST_TEST(cleared > 30);
  BOOST_TEST(not_cleared > 30);
  BOOST_TEST(axis > 10);
}

// The sphere test with a clearance: body 1's placed sphere grows by it, so
// two spheres at distance D with radii a, b are apart exactly when
// D > a + b + clear.
BOOST_AUTO_TEST_CASE(sphere_test_keeps_the_clearance) {
  RoundingGuard guard;
  WorldSphere<Interval> a{{Interval(0), Interval(0), Interval(0)}, Interval(1)};
  WorldSphere<Interval> b{{Interval(3), Interval(0), Interval(0)}, Interval(1)};
  BOOST_TEST(world_spheres_apart(a, b));       // gap 1
  SphereFrame<Interval> f;
  f.g1 = {Interval(1), Interval(0), Interval(0), Interval(0), Interval(0), Interval(1),
          Interval(0), Interval(0), Interval(0), Interval(0), Interval(1), Interval(0)};
  f.n1 = Interval(1);
  f.n2 = Interval(1);
  f.R = Interval(0);
  BvNode na, nb;
  na.c = {0, 0, 0};
  na.r = 1;
  nb.c = {3, 0, 0};
  nb.r = 1;
  f.clear = 0.75;
  BOOST_TEST(spheres_clear(f, na, nb));        // 3 > 1 + 1 + 0.75
  f.clear = 1;
  BOOST_TEST(!spheres_clear(f, na, nb));       // 3 = 1 + 1 + 1: within the clearance
}

// The hull test with a clearance (proofs/hull-test.md, claim HC): a point
// moving along the x axis from (-2, 0, 0) to (2, 0, 0) (rational Bezier
// pieces of degree 1 and 2, constant and varying weights) and a fixed point
// (0, D, 0), at distance exactly D at t = 1/2: the plane n = (0, -1, 0)
// clears the pair with a clearance below D and never with D or more (the
// pair comes within D), exactly and in interval arithmetic; the weights
// W_l enter the margin (with weight 2 and the margin's W_l taken as 1, a
// clearance of 3D/2 would pass); a normal of length 2 clears nothing with
// a clearance (its length is not bounded by kNormBound).  Before claim HC
// the policies' hull test cleared nothing with a clearance, and the
// face-to-face scene below took 17 s at default settings
// (tests/data/scenes/clearance-face-to-face-near-safe.json).
BOOST_AUTO_TEST_CASE(hull_test_keeps_the_clearance) {
  const Exact D(1, 4);
  FeatureGeometry<Exact> X, Y;
  X.dim = Y.dim = 0;
  X.origin = {0, 0, 0};
  Y.origin = {0, D, 0};
  FeatureGeometry<Interval> Xi, Yi;
  Xi.dim = Yi.dim = 0;
  Xi.origin = {Interval(0), Interval(0), Interval(0)};
  Yi.origin = {Interval(0), to_interval(D), Interval(0)};
  auto control = [](const Exact& x, const Exact& w) {
    std::array<Exact, 13> c{1, 0, 0, x, 0, 1, 0, 0, 0, 0, 1, 0, 1};
    for (Exact& e : c) e *= w;
    return c;
  };
  const HullPlane down{{0, -1, 0}, {0, -1, 0}};
  const double below = CGAL::to_double(D) * (1 - 1e-9), at = CGAL::to_double(D);
  int cases = 0;
  for (const auto& weights : std::vector<std::vector<Exact>>{{1, 1}, {2, 2}, {1, 3}, {1, Exact(1, 2), 3}, {2, 2, 2}}) {
    std::vector<std::array<Exact, 13>> piece;
    const std::size_t L = weights.size();
    for (std::size_t l = 0; l < L; ++l) piece.push_back(control(Exact(-2) + Exact(4 * static_cast<int>(l), static_cast<int>(L - 1)), weights[l]));
    std::vector<std::array<Interval, 13>> piece_i;
    for (const auto& c : piece) {
      std::array<Interval, 13> ci;
      for (int e = 0; e < 13; ++e) ci[e] = to_interval(c[e]);
      piece_i.push_back(ci);
    }
    auto apart = [&](const HullPlane& plane, double clear) {
      const bool exact = hull_apart<1>(piece, X, Y, plane, clear);
      RoundingGuard guard;
      const bool interval = hull_apart<1>(piece_i, Xi, Yi, plane, clear);
      BOOST_CHECK(!interval || exact);  // interval "apart" implies exact "apart"
      return exact;
    };
    BOOST_CHECK(apart(down, 0));
    BOOST_CHECK(apart(down, below));
    BOOST_CHECK(!apart(down, at));
    BOOST_CHECK(!apart(down, 1.5 * at));
    BOOST_CHECK(!apart(HullPlane{{0, -2, 0}, {0, -2, 0}}, 1.5 * at));
    BOOST_CHECK(!apart(down, -1));
    RoundingGuard guard;
    BOOST_CHECK(hull_apart<1>(piece_i, Xi, Yi, down, below));
    ++cases;
  }
  BOOST_TEST(cases == 5);
}

BOOST_AUTO_TEST_SUITE_END()
