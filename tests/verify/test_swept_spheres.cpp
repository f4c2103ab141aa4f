// The swept-sphere test of enclosed pieces (src/verify/swept_spheres.h,
// proofs/hierarchy.md §1c): it never clears a node pair one of whose points
// can reach the other's sphere on the segment of maps widened by the tube,
// and it clears a thin sweep beside a sphere while keeping a touching one.
#include "src/verify/swept_spheres.h"

#include <boost/test/unit_test.hpp>

#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

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

// A flat node: normal n, slab [lo, hi].
BvNode flat(BvNode b, std::array<double, 3> n, double lo, double hi) {
  b.slab = true;
  b.slab_n = n;
  b.slab_lo = lo;
  b.slab_hi = hi;
  return b;
}

bool swept_slab(const Map& g0, const Map& g1, double tube, const BvNode& a, const BvNode& b) {
  RoundingGuard guard;
  const SweptFrame f = swept_frame(boxes(g0), boxes(g1), tube);
  const SweptSlabSide side = swept_slab_side(f, b);
  return swept_slab_apart(f, side.s0, side.s1, a, b);
}

Exact dot_exact(const std::array<double, 3>& n, const Exact* x) {
  return Exact(n[0]) * x[0] + Exact(n[1]) * x[1] + Exact(n[2]) * x[2];
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

// Random maps P0, P1 (near rotations or a translation), a thin flat node a
// of body 1 (normal n_a, slab within 1e-3 of its centre), a tube, and a
// fixed slab of b placed just beyond the range of n_b.L(l)(x), at a gap
// between -0.1 and 1.2 times the tube's reach tube p |n_b|.  Whenever the
// swept slab test clears, points x of a (checked in a's sphere and slab in
// rationals: the extremes of n_b.L(l)(x) over the sphere at sampled l, and
// random ones), placed by L(l) and moved by tube p along n_b towards b's
// slab, stay outside it (in rationals).  Dropping the tube term from the
// test makes it fail.
BOOST_AUTO_TEST_CASE(swept_slab_test_never_clears_a_reachable_contact) {
  std::mt19937_64 rng(20261129);
  std::uniform_real_distribution<double> unit(0, 1);
  std::normal_distribution<double> gauss(0, 1);
  auto random_dir = [&] {
    std::array<double, 3> d;
    double s = 0;
    for (double& x : d) x = gauss(rng), s += x * x;
    s = std::sqrt(s);
    for (double& x : d) x /= s;
    return d;
  };
  int cleared = 0, checked = 0, failures = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const Map g0 = random_map(rng, 5);
    Map g1 = g0;
    if (trial % 3) {
      g1 = random_map(rng, 5);
      // Mostly near g0 (a short piece): blend towards it.
      const double w = trial % 2 ? 0.1 * unit(rng) : 1.0;
      for (int i = 0; i < 12; ++i) g1[i] = g0[i] + w * (g1[i] - g0[i]);
    } else {
      for (int i : {3, 7, 11}) g1[i] += 4 * (unit(rng) - 0.5);
    }
    const std::array<double, 3> na = random_dir(), nb = random_dir();
    BvNode a = node(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5, 0.2 + unit(rng), 1 + unit(rng));
    const double sa = na[0] * a.c[0] + na[1] * a.c[1] + na[2] * a.c[2];
    a = flat(a, na, sa - 1e-3, sa + 1e-3);
    const double tube = trial % 4 == 0 ? 0 : 0.3 * unit(rng);
    // Points of a: per sampled l, the two extremes of n_b.L(l)(x) over a's
    // sphere within its plane, and a few random ones.
    std::vector<std::array<Exact, 3>> points;
    auto add_point = [&](const std::array<double, 3>& v) {
      std::array<Exact, 3> x;
      Exact d2 = 0;
      for (int j = 0; j < 3; ++j) x[j] = Exact(a.c[j]) + Exact(v[j]), d2 += Exact(v[j]) * Exact(v[j]);
      const Exact s = dot_exact(na, x.data());
      if (d2 <= Exact(a.r) * Exact(a.r) && s >= Exact(a.slab_lo) && s <= Exact(a.slab_hi)) points.push_back(x);
    };
    for (int k = 0; k <= 8; ++k) {
      const double l = k / 8.0;
      double m[3];
      for (int j = 0; j < 3; ++j) {
        m[j] = 0;
        for (int i = 0; i < 3; ++i) m[j] += ((1 - l) * g0[4 * i + j] + l * g1[4 * i + j]) * nb[i];
      }
      const double mn = m[0] * na[0] + m[1] * na[1] + m[2] * na[2];
      double q[3], qn = 0;
      for (int j = 0; j < 3; ++j) q[j] = m[j] - mn * na[j], qn += q[j] * q[j];
      qn = std::sqrt(qn);
      if (!(qn > 0)) continue;
      for (double sign : {1.0, -1.0}) {
        std::array<double, 3> v;
        for (int j = 0; j < 3; ++j) v[j] = sign * 0.999 * a.r * q[j] / qn;
        add_point(v);
      }
    }
    for (int k = 0; k < 4; ++k) {
      std::array<double, 3> v = random_dir();
      const double vn = v[0] * na[0] + v[1] * na[1] + v[2] * na[2];
      const double len = a.r * unit(rng);
      for (int j = 0; j < 3; ++j) v[j] = len * (v[j] - vn * na[j]);
      add_point(v);
    }
    if (points.empty()) continue;
    // The range of n_b.L(l)(x) over those points at the ends (it is linear in l).
    double top = -1e300, bottom = 1e300;
    for (const Map* g : {static_cast<const Map*>(&g0), static_cast<const Map*>(&g1)})
      for (const auto& x : points) {
        double v = 0;
        for (int i = 0; i < 3; ++i)
          v += nb[i] * ((*g)[4 * i] * CGAL::to_double(x[0]) + (*g)[4 * i + 1] * CGAL::to_double(x[1]) +
                        (*g)[4 * i + 2] * CGAL::to_double(x[2]) + (*g)[4 * i + 3]);
        top = std::max(top, v), bottom = std::min(bottom, v);
      }
    const double reach = tube * a.p, gap = reach * (1.3 * unit(rng) - 0.1) + 1e-6 * (unit(rng) - 0.5);
    const double thick = 0.5 * unit(rng);
    const bool above = trial % 2 == 0;
    const BvNode b = above ? flat(node(0, 0, 0, 1), nb, top + gap, top + gap + thick)
                           : flat(node(0, 0, 0, 1), nb, bottom - gap - thick, bottom - gap);
    if (!swept_slab(g0, g1, tube, a, b)) continue;
    ++cleared;
    // e = tube p along n_b towards b's slab, rounded down in length.
    const double sign = above ? 1 : -1;
    Exact e[3], en2 = 0;
    for (int i = 0; i < 3; ++i) e[i] = Exact(sign * reach * nb[i]) * Exact(1 - 1e-9), en2 += e[i] * e[i];
    if (en2 > Exact(reach) * Exact(reach)) continue;
    for (int k = 0; k <= 16; ++k) {
      const Exact l = Exact(k, 16);
      Exact m[12];
      for (int i = 0; i < 12; ++i) m[i] = Exact(g0[i]) + l * (Exact(g1[i]) - Exact(g0[i]));
      for (const auto& x : points) {
        Exact pos[3];
        for (int i = 0; i < 3; ++i) pos[i] = m[4 * i] * x[0] + m[4 * i + 1] * x[1] + m[4 * i + 2] * x[2] + m[4 * i + 3] + e[i];
        const Exact v = dot_exact(nb, pos);
        ++checked;
        if (v >= Exact(b.slab_lo) && v <= Exact(b.slab_hi)) ++failures;
      }
    }
  }
  BOOST_TEST_MESSAGE("swept slab test: " << cleared << " cleared, " << checked << " reachable points checked");
  BOOST_TEST(cleared > 250);
  BOOST_TEST(failures == 0);
}

// A flat node (unit sphere, normal z, within 1e-3 of z = 0) translated
// along x by 20 over a fixed plane z in [-1, -0.5]: cleared by the swept
// slabs (the ball around the middle pose, of radius about half the sweep
// times p, would reach the plane); kept when the tube reaches it, when the
// piece ends in the plane's slab, and with a tilted end map whose range
// reaches z = -0.6.
BOOST_AUTO_TEST_CASE(swept_slab_test_clears_a_gliding_plate_and_keeps_a_reaching_one) {
  const Map g0 = {1, 0, 0, -10, 0, 1, 0, 0, 0, 0, 1, 0};
  const Map g1 = {1, 0, 0, 10, 0, 1, 0, 0, 0, 0, 1, 0};
  const BvNode a = flat(node(0, 0, 0, 1, 2), {0, 0, 1}, -1e-3, 1e-3);
  const BvNode plane = flat(node(0, 0, -5, 5), {0, 0, 1}, -1, -0.5);
  BOOST_TEST(swept_slab(g0, g1, 0, a, plane));
  BOOST_TEST(swept_slab(g0, g1, 0.2, a, plane));    // reach 0.4 < 0.499
  BOOST_TEST(!swept_slab(g0, g1, 0.25, a, plane));  // reach 0.5: touches
  Map low = g1;
  low[11] = -0.6;  // the end pose sits in the plane's slab
  BOOST_TEST(!swept_slab(g0, low, 0, a, plane));
  Map tilted = g1;  // a rotation about y at the end (cos 0.8, sin 0.6)
  tilted[0] = 0.8, tilted[2] = 0.6, tilted[8] = -0.6, tilted[10] = 0.8;
  BOOST_TEST(!swept_slab(g0, tilted, 0, a, plane));
  // Not flat, or not finite: no claim.
  BvNode round = a;
  round.slab = false;
  BOOST_TEST(!swept_slab(g0, g1, 0, round, plane));
  BOOST_TEST(!swept_slab(g0, g1, std::numeric_limits<double>::infinity(), a, plane));
}

BOOST_AUTO_TEST_SUITE_END()
