// Motions: exact evaluation, subdivision (exact and enclosed), certified
// bounding balls, and the joint curve of two motions.
#include "src/motion/bezier.h"
#include "tests/support/random_geometry.h"

#include <boost/test/unit_test.hpp>

using namespace tmcert;
using namespace tmcert::testing;

namespace {

Motion random_motion(Rng& r, int degree, bool rational) {
  Motion m;
  for (int k = 0; k <= degree; ++k) {
    Mat34E a;
    for (auto& e : a) e = r.q(-9, 9, 3);
    m.control_points.push_back(a);
    m.weights.push_back(rational ? r.q(1, 9, 2) : Exact(1));
  }
  return m;
}

// c(u) straight from the definition: sum B_k w_k P_k / sum B_k w_k.
Mat34E by_definition(const Motion& m, const Exact& u) {
  const int n = m.degree();
  Mat34E num;
  for (auto& e : num) e = 0;
  Exact den = 0;
  for (int k = 0; k <= n; ++k) {
    Exact b = 1;
    for (int i = 1; i <= k; ++i) b = b * Exact(n - k + i) / Exact(i);
    for (int i = 0; i < k; ++i) b *= u;
    for (int i = 0; i < n - k; ++i) b *= Exact(1) - u;
    for (int e = 0; e < 12; ++e) num[e] += b * m.weights[k] * m.control_points[k][e];
    den += b * m.weights[k];
  }
  for (auto& e : num) e /= den;
  return num;
}

Exact metric_norm2(const Metric& metric, const Mat34E& a, const std::array<double, 12>& g) {
  Mat34E d;
  for (int e = 0; e < 12; ++e) d[e] = a[e] - Exact(g[e]);
  return metric.norm2(d);
}

Metric some_metric() {
  MassDistribution mass;
  mass.points = {Vec3E{0, 0, 0}, Vec3E{1, 0, 0}, Vec3E{0, 1, 0}, Vec3E{0, 0, Exact(1, 5)}};
  mass.weights = {1, 1, 1, 1};
  return Metric::from_mass(mass);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(motion)

BOOST_AUTO_TEST_CASE(evaluation_matches_definition) {
  Rng r(1);
  for (int iter = 0; iter < 30; ++iter) {
    const Motion m = random_motion(r, 1 + iter % 5, iter % 2 == 0);
    const auto c = homogeneous_curve(m);
    for (const Exact u : {Exact(0), Exact(1), Exact(1, 3), Exact(5, 7)})
      BOOST_CHECK(evaluate<1>(c, u) == by_definition(m, u));
  }
}

BOOST_AUTO_TEST_CASE(exact_halves_reparametrise_the_curve) {
  Rng r(2);
  for (int iter = 0; iter < 20; ++iter) {
    const Motion m = random_motion(r, 1 + iter % 6, true);
    const auto c = homogeneous_curve(m);
    HomogeneousCurve<Exact, 1> left, right;
    split_half(c, left, right);
    for (const Exact u : {Exact(0), Exact(1, 3), Exact(1)}) {
      BOOST_CHECK(evaluate<1>(left, u) == evaluate<1>(c, u / 2));
      BOOST_CHECK(evaluate<1>(right, u) == evaluate<1>(c, (u + 1) / 2));
    }
  }
}

BOOST_AUTO_TEST_CASE(interval_halves_enclose_the_exact_halves) {
  Rng r(3);
  for (int iter = 0; iter < 20; ++iter) {
    const auto c = homogeneous_curve(random_motion(r, 2 + iter % 6, true));
    HomogeneousCurve<Exact, 1> el = c, er;
    HomogeneousCurve<Interval, 1> il = enclose(c), ir;
    for (int level = 0; level < 12; ++level) {  // descend alternately left and right
      HomogeneousCurve<Exact, 1> a, b;
      HomogeneousCurve<Interval, 1> ia, ib;
      split_half(el, a, b);
      {
        RoundingGuard guard;
        split_half(il, ia, ib);
      }
      el = level % 2 ? a : b;
      il = level % 2 ? ia : ib;
      for (std::size_t k = 0; k < el.size(); ++k)
        for (int e = 0; e < 13; ++e) {
          const Interval x = to_interval(el[k][e]);
          BOOST_CHECK(il[k][e].inf() <= x.inf() && x.sup() <= il[k][e].sup());
        }
    }
  }
}

// The certified ball contains the curve: ||c(u) - g||^2 <= R^2, exactly, at
// many parameters of many pieces.
BOOST_AUTO_TEST_CASE(ball_contains_the_piece) {
  Rng r(4);
  const Metric metric = some_metric();
  const MetricData data = metric_data_of(metric);
  int checked = 0;
  for (int iter = 0; iter < 20; ++iter) {
    const Motion m = random_motion(r, 1 + iter % 5, true);
    const auto c = homogeneous_curve(m);
    HomogeneousCurve<Exact, 1> piece = c, a, b;
    for (int level = 0; level < 4; ++level) {
      const BallD<1> ball = bounding_ball<1>(enclose(piece), {&data});
      BOOST_REQUIRE(ball.valid);
      const BallE<1> exact_ball = bounding_ball<1>(piece, {&data});
      for (int s = 0; s <= 8; ++s) {
        const Mat34E p = evaluate<1>(piece, Exact(s, 8));
        BOOST_CHECK(metric_norm2(metric, p, ball.center) <= Exact(ball.r2));
        Mat34E d;
        for (int e = 0; e < 12; ++e) d[e] = p[e] - exact_ball.center[e];
        BOOST_CHECK(metric.norm2(d) <= exact_ball.r2);
        ++checked;
      }
      split_half(piece, a, b);
      piece = level % 2 ? a : b;
    }
  }
  BOOST_TEST(checked > 500);
}

BOOST_AUTO_TEST_CASE(joint_curve_carries_both_motions) {
  Rng r(5);
  for (int iter = 0; iter < 24; ++iter) {
    const bool rational = iter % 3 != 0;
    const Motion m1 = random_motion(r, 1 + iter % 4, rational);
    const Motion m2 = random_motion(r, iter % 3, rational && iter % 2 == 0);
    const auto joint = joint_curve(m1, m2);
    for (const auto& h : joint) BOOST_CHECK(h[24] > 0);
    for (const Exact u : {Exact(0), Exact(1, 4), Exact(2, 3), Exact(1)}) {
      BOOST_CHECK(evaluate<2>(joint, u, 0) == by_definition(m1, u));
      BOOST_CHECK(evaluate<2>(joint, u, 1) == by_definition(m2, u));
    }
  }
  // Equal degrees with weights all 1 (two linear per-vertex motions, say):
  // the joint curve copies the control points as they are.
  for (int iter = 0; iter < 12; ++iter) {
    const int degree = iter % 4;
    const Motion m1 = random_motion(r, degree, false), m2 = random_motion(r, degree, false);
    const auto joint = joint_curve(m1, m2);
    BOOST_CHECK_EQUAL(joint.size(), static_cast<std::size_t>(degree + 1));
    for (const Exact u : {Exact(0), Exact(1, 4), Exact(2, 3), Exact(1)}) {
      BOOST_CHECK(evaluate<2>(joint, u, 0) == by_definition(m1, u));
      BOOST_CHECK(evaluate<2>(joint, u, 1) == by_definition(m2, u));
    }
  }
}

// The parser's cheap check agrees with the exact one: it throws exactly when
// from_mass does, on random distributions, on coplanar ones (not positive
// definite) and on nearly coplanar ones (positive definite, with minors far
// below what the interval test resolves at this scale).
BOOST_AUTO_TEST_CASE(positive_definite_check_agrees_with_the_exact_metric) {
  Rng r(7);
  auto throws = [](auto&& f) {
    try {
      f();
    } catch (const InputError&) {
      return true;
    }
    return false;
  };
  int singular = 0;
  for (int iter = 0; iter < 300; ++iter) {
    MassDistribution mass;
    const int n = 1 + iter % 6;
    const int kind = iter % 3;  // 0 random, 1 coplanar (z = x + y), 2 coplanar but one point lifted by 2^-60
    for (int k = 0; k < n; ++k) {
      Vec3E p{r.q(-20, 20, 4), r.q(-20, 20, 4), r.q(-20, 20, 4)};
      if (kind != 0) p[2] = Exact(1000000) + p[0] + p[1];
      if (kind == 2 && k == n - 1) p[2] += Exact(1, 1 << 30) * Exact(1, 1 << 30);
      mass.points.push_back(p);
      mass.weights.push_back(r.q(1, 9, 2));
    }
    const bool exact = throws([&] { Metric::from_mass(mass); });
    BOOST_CHECK_EQUAL(throws([&] { Metric::require_positive_definite(mass); }), exact);
    singular += exact;
  }
  BOOST_CHECK_GT(singular, 100);  // both answers were exercised
  BOOST_CHECK_LT(singular, 300);
}

BOOST_AUTO_TEST_SUITE_END()
