// Contact tests: the orbit formula of the metric, and contact_sign against a
// direct evaluation of Phi(x, y) = |g(x) - y|^2 - R^2 rho(x)^2 at sampled
// points (an independent computation through Metric::rho2).
#include "kernels/contact.h"
#include "kernels/filtered.h"
#include "src/metric/metric.h"
#include "src/verify/prepared.h"
#include "tests/support/contact_pairs.h"
#include "tests/support/random_geometry.h"

#include <boost/test/unit_test.hpp>

using namespace tmcert;
using namespace tmcert::testing;

BOOST_AUTO_TEST_SUITE(contact)

// |delta(x)|^2 <= ||delta||^2 rho(x)^2 for every affine delta, with equality
// for delta = u (G^-1 x^)^T: rho is exactly the orbit radius per unit R.
BOOST_AUTO_TEST_CASE(orbit_radius_is_rho_and_tight) {
  Rng r(11);
  for (int iter = 0; iter < 200; ++iter) {
    MassDistribution mass;
    for (int k = 0; k < 5; ++k) {
      mass.points.push_back(rand_point(r));
      mass.weights.push_back(r.q(1, 9, 3));
    }
    Metric metric;
    try {
      metric = Metric::from_mass(mass);
    } catch (const InputError&) {
      continue;  // coplanar draw
    }
    const Vec3E x = rand_point(r);
    const Exact xh[4] = {x[0], x[1], x[2], 1};
    const Exact rho2 = metric.rho2(x);
    // Random delta: bound holds.
    Mat34E d;
    for (auto& e : d) e = r.q(-5, 5, 3);
    Exact dx2 = 0;
    for (int row = 0; row < 3; ++row) {
      Exact s = 0;
      for (int c = 0; c < 4; ++c) s += d[4 * row + c] * xh[c];
      dx2 += s * s;
    }
    BOOST_CHECK(dx2 <= metric.norm2(d) * rho2);
    // The maximiser: equality.
    Exact gx[4];
    for (int rr = 0; rr < 4; ++rr) {
      gx[rr] = 0;
      for (int c = 0; c < 4; ++c) gx[rr] += metric.inverse()[4 * rr + c] * xh[c];
    }
    Mat34E m;
    const Exact u[3] = {1, 2, -2};  // |u|^2 = 9
    for (int row = 0; row < 3; ++row)
      for (int c = 0; c < 4; ++c) m[4 * row + c] = u[row] * gx[c];
    Exact mx2 = 0;
    for (int row = 0; row < 3; ++row) {
      Exact s = 0;
      for (int c = 0; c < 4; ++c) s += m[4 * row + c] * xh[c];
      mx2 += s * s;
    }
    BOOST_CHECK(mx2 == metric.norm2(m) * rho2);
    BOOST_CHECK(metric.norm2(m) == 9 * rho2);
  }
}

// contact_sign(POSITIVE) must imply Phi > 0 at every sampled (x, y); and a
// sampled Phi <= 0 must make it non-positive.  Also: filtered == exact.
BOOST_AUTO_TEST_CASE(contact_sign_matches_sampled_phi) {
  Rng r(2026);
  int cleared = 0, not_cleared = 0;
  for (int iter = 0; iter < 150; ++iter) {
    std::array<Vec3E, 3> tm{rand_point(r), rand_point(r), rand_point(r)};
    std::array<Vec3E, 3> tf{rand_point(r), rand_point(r), rand_point(r)};
    if (testing::collinear(tm[0], tm[1], tm[2]) || testing::collinear(tf[0], tf[1], tf[2])) continue;
    const TrianglePair pair(tm, tf);
    Placement<Exact> pe;
    for (auto& e : pe.g1) e = r.q(-4, 4, 4);
    pe.g1[0] += 1; pe.g1[5] += 1; pe.g1[10] += 1;
    pe.r2 = r.q(0, 48, 64);
    Placement<Interval> pi;
    for (int e = 0; e < 12; ++e) pi.g1[e] = to_interval(pe.g1[e]);
    pi.r2 = to_interval(pe.r2);

    auto phi = [&](const Vec3E& x, const Vec3E& y) {
      const Vec3E gx = map_point(pe.g1, x);
      Exact d2 = 0;
      for (int i = 0; i < 3; ++i) d2 += (gx[i] - y[i]) * (gx[i] - y[i]);
      return d2 - pe.r2 * pair.pm.exact_metric().rho2(x);
    };
    const int n = 8;
    auto check_pair = [&](ContactKind kind, const FeatureGeometry<Exact>& X, const FeatureGeometry<Exact>& Y,
                          const FeatureGeometry<Interval>& Xi, const FeatureGeometry<Interval>& Yi, auto sample) {
      const CGAL::Sign s = contact_sign<Exact>(kind, X, Y, pe);
      bool sampled_touch = false;
      for (int i = 0; i <= n && !sampled_touch; ++i)
        for (int j = 0; j <= n && !sampled_touch; ++j) {
          auto [x, y] = sample(Exact(i, n), Exact(j, n));
          if (!(phi(x, y) > 0)) sampled_touch = true;
        }
      if (s == CGAL::POSITIVE) {
        ++cleared;
        BOOST_CHECK_MESSAGE(!sampled_touch, "false clearance, iteration " << iter << " kind " << int(kind));
      } else {
        ++not_cleared;
      }
      FilterCounters counters;
      const CGAL::Sign f = filtered([&] { return contact_sign<Interval>(kind, Xi, Yi, pi); },
                                    [&] { return contact_sign<Exact>(kind, X, Y, pe); }, counters);
      BOOST_CHECK(f == s);
    };
    pair.for_each_sampled_pair(check_pair);
  }
  BOOST_TEST(cleared > 30);
  BOOST_TEST(not_cleared > 30);
}

// The axis test (a shortcut in front of the interval contact test) only
// ever clears pairs the exact contact test clears: one body moving (no rho
// term for body 2) and both moving (joint placement, both rho terms), on
// random features and balls, with radii spread around the clearances so
// that both answers occur.
BOOST_AUTO_TEST_CASE(axis_test_clears_only_what_the_exact_test_clears) {
  Rng r(77);
  int axis = 0, exact_cleared = 0, total = 0;
  for (int iter = 0; iter < 400; ++iter) {
    std::array<Vec3E, 3> tm{rand_point(r), rand_point(r), rand_point(r)};
    std::array<Vec3E, 3> tf{rand_point(r), rand_point(r), rand_point(r)};
    if (testing::collinear(tm[0], tm[1], tm[2]) || testing::collinear(tf[0], tf[1], tf[2])) continue;
    const bool both = iter % 2 == 1;
    const Body bm = TrianglePair::moving(triangle_body("m", tm));
    const Body bf = both ? TrianglePair::moving(triangle_body("f", tf)) : triangle_body("f", tf);
    const PreparedBody pm(bm), pf(bf);
    Placement<Exact> pe;
    auto random_map = [&](std::array<Exact, 12>& g) {
      for (auto& e : g) e = r.q(-4, 4, 8);
      g[0] += 1; g[5] += 1; g[10] += 1;
    };
    random_map(pe.g1);
    pe.body2_moving = both;
    if (both) random_map(pe.g2);
    pe.r2 = r.q(0, 64, 64);
    Placement<Interval> pi;
    for (int e = 0; e < 12; ++e) pi.g1[e] = to_interval(pe.g1[e]);
    pi.body2_moving = both;
    if (both)
      for (int e = 0; e < 12; ++e) pi.g2[e] = to_interval(pe.g2[e]);
    pi.r2 = to_interval(pe.r2);
    auto check = [&](ContactKind kind, const FeatureGeometry<Exact>& X, const FeatureGeometry<Exact>& Y,
                     const FeatureGeometry<Interval>& Xi, const FeatureGeometry<Interval>& Yi) {
      ++total;
      const bool cleared = contact_sign<Exact>(kind, X, Y, pe) == CGAL::POSITIVE;
      exact_cleared += cleared;
      RoundingGuard guard;
      if (apart_along_axis<Interval>(kind, Xi, Yi, pi)) {
        ++axis;
        BOOST_CHECK_MESSAGE(cleared, "axis test cleared a pair the exact test does not, iteration " << iter
                                                                                              << " kind " << int(kind));
      }
    };
    check(ContactKind::VertexFace, pm.exact().vertices[1], pf.exact().faces[0], pm.vertices.interval[1], pf.faces.interval[0]);
    check(ContactKind::FaceVertex, pm.exact().faces[0], pf.exact().vertices[2], pm.faces.interval[0], pf.vertices.interval[2]);
    for (int i = 0; i < 3; ++i)
      check(ContactKind::EdgeEdge, pm.exact().edges[i], pf.exact().edges[(i + iter) % 3], pm.edges.interval[i],
            pf.edges.interval[(i + iter) % 3]);
  }
  BOOST_TEST_MESSAGE("axis test: " << axis << " of " << exact_cleared << " exact clears, " << total << " pairs");
  BOOST_TEST(axis > total / 10);                  // it does clear
  BOOST_TEST(exact_cleared - axis > total / 20);  // and leaves some clears to the full test
  BOOST_TEST(total - exact_cleared > total / 10); // not everything is apart
}

BOOST_AUTO_TEST_SUITE_END()
