// The swept-sphere test of enclosed pieces (src/verify/swept_spheres.h,
// proofs/hierarchy.md §1c): it never clears a node pair one of whose points
// can reach the other's sphere on the segment of maps widened by the tube,
// and it clears a thin sweep beside a sphere while keeping a touching one.
#include "src/verify/swept_spheres.h"

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <random>

using namespace tmcert;

namespace {

using Map = std::array<double, 12>;

std::array<Interval, 12> boxes(const Map& g) {
  std::array<Interval, 12> out;
  for (int i = 0; i < 12; ++i) out[i] = Interval(g[i]);
  return out;
}

// A rotation (rounded to doubles: a near rotation) and a translation.
Map random_map(std::mt19937_64& rng, double spread) {
  std::normal_distribution<double> n(0, 1);
  double q[4];
  double s = 0;
  for (double& x : q) x = n(rng), s += x * x;
  s = std::sqrt(s);
  for (double& x : q) x /= s;
  const double a = q[0], b = q[1], c = q[2], d = q[3];
  std::uniform_real_distribution<double> u(-spread, spread);
  return {a * a + b * b - c * c - d * d, 2 * (b * c - a * d), 2 * (b * d + a * c), u(rng),
          2 * (b * c + a * d), a * a - b * b + c * c - d * d, 2 * (c * d - a * b), u(rng),
          2 * (b * d - a * c), 2 * (c * d + a * b), a * a - b * b - c * c + d * d, u(rng)};
}

bool swept(const Map& g0, const Map& g1, double tube, const BvNode& a, const BvNode& b) {
  RoundingGuard guard;
  const SweptFrame f = swept_frame(boxes(g0), boxes(g1), tube);
  return swept_apart(swept_sphere(f, a), b);
}

BvNode node(double x, double y, double z, double r, double p = 0) {
  BvNode n;
  n.c = {x, y, z};
  n.r = r;
  n.p = p;
  return n;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(verify_swept_spheres)

// Random maps P0, P1 (a near rotation each, within a few units), a node
// sphere of body 1, a tube and a fixed sphere placed near the capsule's
// boundary.  Whenever the test clears, the points of body 1's sphere
// placed by L(l) = (1 - l) P0 + l P1 at sampled l (with l near the nearest
// point), moved by up to tube p towards the fixed centre, stay outside the
// fixed sphere (checked in rationals).  Dropping the tube term tube p from
// the capsule's radius makes it fail.
BOOST_AUTO_TEST_CASE(swept_test_never_clears_a_reachable_contact) {
  std::mt19937_64 rng(20261128);
  std::uniform_real_distribution<double> unit(0, 1);
  int cleared = 0, checked = 0, failures = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const Map g0 = random_map(rng, 5);
    Map g1 = g0;
    if (trial % 3) g1 = random_map(rng, 5);  // else: a pure translation
    else for (int i : {3, 7, 11}) g1[i] += 4 * (unit(rng) - 0.5);
    const BvNode a = node(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5, unit(rng), 1 + unit(rng));
    const double tube = trial % 4 == 0 ? 0 : 0.3 * unit(rng);
    // The fixed centre: off a random point of the segment (of the centre's
    // images), at about the capsule's radius plus r_b.
    const double l0 = 1.4 * unit(rng) - 0.2;
    double at[3], dir[3], norm = 0;
    std::normal_distribution<double> n(0, 1);
    for (int i = 0; i < 3; ++i) {
      const double p0 = g0[4 * i] * a.c[0] + g0[4 * i + 1] * a.c[1] + g0[4 * i + 2] * a.c[2] + g0[4 * i + 3];
      const double p1 = g1[4 * i] * a.c[0] + g1[4 * i + 1] * a.c[1] + g1[4 * i + 2] * a.c[2] + g1[4 * i + 3];
      at[i] = p0 + l0 * (p1 - p0);
      dir[i] = n(rng);
      norm += dir[i] * dir[i];
    }
    norm = std::sqrt(norm);
    const double rb = unit(rng);
    const double dist = (a.r + tube * a.p + rb) * (0.9 + 0.3 * unit(rng));
    const BvNode b = node(at[0] + dist * dir[0] / norm, at[1] + dist * dir[1] / norm, at[2] + dist * dir[2] / norm, rb);
    if (!swept(g0, g1, tube, a, b)) continue;
    ++cleared;
    // Reachable points: x = c + r u (|u| <= 1), at l, moved by e with
    // |e| <= tube p, all towards b's centre (the worst case), in rationals.
    for (int k = 0; k <= 32; ++k) {
      const Exact l = Exact(k, 32);
      Exact m[12];
      for (int i = 0; i < 12; ++i) m[i] = Exact(g0[i]) + l * (Exact(g1[i]) - Exact(g0[i]));
      Exact y[3];
      for (int i = 0; i < 3; ++i) y[i] = m[4 * i] * Exact(a.c[0]) + m[4 * i + 1] * Exact(a.c[1]) + m[4 * i + 2] * Exact(a.c[2]) + m[4 * i + 3];
      // u: the direction (in body 1's frame) whose image points at b's centre, approximately.
      double v[3], w[3], vn = 0;
      for (int i = 0; i < 3; ++i) w[i] = b.c[i] - CGAL::to_double(y[i]);
      for (int j = 0; j < 3; ++j) v[j] = CGAL::to_double(m[j]) * w[0] + CGAL::to_double(m[4 + j]) * w[1] + CGAL::to_double(m[8 + j]) * w[2];
      for (double x : v) vn += x * x;
      vn = std::sqrt(vn) * (1 + 1e-9);
      if (!(vn > 0)) continue;
      Exact x[3], ux2 = 0;
      for (int j = 0; j < 3; ++j) ux2 += Exact(v[j] / vn) * Exact(v[j] / vn);
      if (ux2 > 1) continue;
      for (int j = 0; j < 3; ++j) x[j] = Exact(a.c[j]) + Exact(a.r) * Exact(v[j] / vn);
      Exact pos[3], e2 = 0, en2 = 0;
      for (int i = 0; i < 3; ++i) pos[i] = m[4 * i] * x[0] + m[4 * i + 1] * x[1] + m[4 * i + 2] * x[2] + m[4 * i + 3];
      // e = tube p (b.c - pos)/|b.c - pos|, rounded down in length.
      double dv[3], dn = 0;
      for (int i = 0; i < 3; ++i) dv[i] = b.c[i] - CGAL::to_double(pos[i]), dn += dv[i] * dv[i];
      dn = std::sqrt(dn) * (1 + 1e-9);
      Exact e[3];
      for (int i = 0; i < 3; ++i) e[i] = dn > 0 ? Exact(tube * a.p * (dv[i] / dn)) * Exact(1 - 1e-9) : Exact(0);
      for (int i = 0; i < 3; ++i) en2 += e[i] * e[i];
      if (en2 > Exact(tube * a.p) * Exact(tube * a.p)) continue;
      for (int i = 0; i < 3; ++i) e2 += CGAL::square(pos[i] + e[i] - Exact(b.c[i]));
      ++checked;
      if (!(e2 > Exact(b.r) * Exact(b.r))) ++failures;
    }
  }
  BOOST_TEST_MESSAGE("swept test: " << cleared << " cleared, " << checked << " reachable points checked");
  BOOST_TEST(cleared > 300);
  BOOST_TEST(failures == 0);
}

// A long translation along x: a unit sphere beside its middle is cleared
// (the ball around the middle pose, of radius half the sweep, would hold
// it), one beyond the end is cleared by the end's distance, and spheres
// touching the capsule, or a tube reaching them, are kept.
BOOST_AUTO_TEST_CASE(swept_test_clears_a_thin_sweep_and_keeps_a_touching_one) {
  const Map g0 = {1, 0, 0, -10, 0, 1, 0, 0, 0, 0, 1, 0};
  const Map g1 = {1, 0, 0, 10, 0, 1, 0, 0, 0, 0, 1, 0};
  const BvNode a = node(0, 0, 0, 1, 2);
  BOOST_TEST(swept(g0, g1, 0, a, node(3, 2.5, 0, 1)));     // beside: 2.5 > 1 + 1
  BOOST_TEST(!swept(g0, g1, 0, a, node(3, 1.9, 0, 1)));    // touching the capsule
  BOOST_TEST(!swept(g0, g1, 0.25, a, node(3, 2.5, 0, 1)));  // the tube (0.25 * p = 0.5) reaches it
  BOOST_TEST(swept(g0, g1, 0.2, a, node(3, 2.5, 0, 1)));    // 0.4 does not
  BOOST_TEST(swept(g0, g1, 0, a, node(12.5, 0, 0, 0.4)));   // beyond the end: 2.5 > 1.4
  BOOST_TEST(!swept(g0, g1, 0, a, node(12.5, 0, 0, 1.6)));  // touching the end
  BOOST_TEST(swept(g0, g1, 0, a, node(-12.5, 1, 0, 0.4)));  // before the start
  // No motion (P0 = P1): the line test cannot decide; the ends decide.
  BOOST_TEST(swept(g0, g0, 0, a, node(-10, 3, 0, 1)));
  BOOST_TEST(!swept(g0, g0, 0, a, node(-10, 1.5, 0, 1)));
  // Not finite: no claim.
  BOOST_TEST(!swept(g0, g1, std::numeric_limits<double>::infinity(), a, node(3, 2.5, 0, 1)));
}

BOOST_AUTO_TEST_SUITE_END()
