// Clearance without the band (proofs/clearance.md): the contact test with
// the clearance's shift and the axis test with the clearance clear a pair
// only when every x, y of the pair keep |g(x) - y| > R rho(x) + d (so every
// map of the ball keeps them farther apart than d), checked exactly at
// sampled points; and they do clear pairs whose gap exceeds that bound.
#include "kernels/contact.h"
#include "kernels/filtered.h"
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

BOOST_AUTO_TEST_SUITE_END()
