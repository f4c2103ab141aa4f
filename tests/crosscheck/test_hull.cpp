// The swept-hull test of a feature pair on a motion piece
// (kernels/separation.h, the policies' `hull`, proofs/hull-test.md),
// checked in exact arithmetic.
//
// Random triangle bodies, one moving against a fixed one (B = 1) or both
// moving on their joint curve (B = 2), with rational Bezier motions of
// degree 1 to 3 (constant and varying weights, some "bouncing" so that the
// middle of a piece dips towards the other body while its ends stay away),
// and a contact built in at a known time t*.  Pieces at depths 0 to 11 on
// and around t*.  Whenever a kernel's hull test clears a feature pair on a
// piece:
//   - the claim's hypothesis holds exactly: for the plane the kernel
//     accepted, n(u) = (1 - u) n0 + u n1, every Bernstein coefficient of
//     n(u).(N1(u) x^ - N2(u) y^) is positive at every vertex pair (written
//     here pair by pair, without the linear-form shortcut of the code);
//   - its conclusion holds: the two features, placed exactly by the motions
//     (tests/support/exact_oracle.h, independent of src/motion), share no
//     point at t* (when t* is in the piece), at the piece's ends, at 9 more
//     rationals spread over it and at 4 random ones (exact static test).
// The certification alone is checked on other planes (perturbed
// candidates, random planes): interval "apart" implies the hypothesis,
// exact "apart" is the hypothesis.  Two wrong variants (the B = 1
// inequality without the weight W_l; only the first and the last control
// point) run on the same cases with the code's candidate planes: the oracle
// must catch both, so the sampling can fail.
//
// Seeds: TMCERT_SEED replaces the fixed seed; a failure names seed and case.
#include "kernels/separation.h"
#include "kernels/static_intersection.h"
#include "src/motion/bezier.h"
#include "src/verify/kernel_policies.h"
#include "src/verify/prepared.h"
#include "tests/support/exact_oracle.h"
#include "tests/support/random_geometry.h"

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <cstdlib>
#include <functional>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

using namespace tmcert;
using namespace tmcert::testing;

namespace {

unsigned hull_seed(unsigned fallback) {
  if (const char* s = std::getenv("TMCERT_SEED")) return static_cast<unsigned>(std::strtoul(s, nullptr, 10));
  return fallback;
}

Vec3E place(const Mat34E& m, const Vec3E& x) {
  Vec3E r;
  for (int i = 0; i < 3; ++i) r[i] = m[4 * i] * x[0] + m[4 * i + 1] * x[1] + m[4 * i + 2] * x[2] + m[4 * i + 3];
  return r;
}

// The exact vertices of a feature (its own exact geometry: origin, axes and
// parameter domain).
std::vector<Vec3E> vertices(const FeatureGeometry<Exact>& f) {
  if (f.dim == 0) return {f.origin};
  if (f.dim == 1) return {f.origin, {f.origin[0] + f.axis[0][0], f.origin[1] + f.axis[0][1], f.origin[2] + f.axis[0][2]}};
  std::vector<Vec3E> out;
  for (const auto& s : f.domain) {
    Vec3E x;
    for (int i = 0; i < 3; ++i) x[i] = f.origin[i] + s[0] * f.axis[0][i] + s[1] * f.axis[1][i];
    out.push_back(x);
  }
  return out;
}

Simplex simplex_of(const std::vector<Vec3E>& v) {
  Simplex s;
  s.count = static_cast<int>(v.size());
  for (int k = 0; k < s.count; ++k) s.p[k] = v[k];
  return s;
}

Mat34E identity() { return Mat34E{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0}; }

// A random rational Bezier motion over [0, 1]: linear parts near the
// identity, translations in [-2, 2]^3; `bounce` makes the translations
// alternate along one direction (the path goes back and forth).
Motion random_motion(Rng& r, int degree, bool rational, bool bounce) {
  Motion m;
  m.t0 = 0;
  m.t1 = 1;
  const Vec3E dir{r.q(-4, 4, 4), r.q(-4, 4, 4), r.q(1, 4, 4)};
  for (int k = 0; k <= degree; ++k) {
    Mat34E c = identity();
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) c[4 * i + j] += r.q(-2, 2, 8);
      c[4 * i + 3] = r.q(-8, 8, 4);
      if (bounce) c[4 * i + 3] = r.q(-1, 1, 8) + (k % 2 == 0 ? 3 : -3) * dir[i];
    }
    m.control_points.push_back(c);
    m.weights.push_back(rational ? r.q(1, 12, 4) : Exact(1));
  }
  return m;
}

void translate(Motion& m, const Vec3E& d) {
  for (Mat34E& c : m.control_points)
    for (int i = 0; i < 3; ++i) c[4 * i + 3] += d[i];
}

// A random point of a triangle: a vertex, a point of an edge or an inner point.
Vec3E random_point(Rng& r, const std::array<Vec3E, 3>& t) {
  const int kind = r.i(0, 2);
  if (kind == 0) return t[r.i(0, 2)];
  Exact a = r.q(1, 7, 8), b = kind == 1 ? Exact(0) : r.q(0, 7, 8) * (1 - a);
  Exact c = 1 - a - b;
  const int rot = r.i(0, 2);
  const Vec3E& p = t[rot];
  const Vec3E& q = t[(rot + 1) % 3];
  const Vec3E& s = t[(rot + 2) % 3];
  return {a * p[0] + c * q[0] + b * s[0], a * p[1] + c * q[1] + b * s[1], a * p[2] + c * q[2] + b * s[2]};
}

std::array<Vec3E, 3> random_triangle(Rng& r) {
  for (;;) {
    std::array<Vec3E, 3> t;
    for (auto& p : t) p = {r.q(-8, 8, 4), r.q(-8, 8, 4), r.q(-8, 8, 4)};
    if (!collinear(t)) return t;
  }
}

template <int B>
HomogeneousCurve<Exact, B> curve_of(const Motion& m1, const std::optional<Motion>& m2) {
  if constexpr (B == 1) return homogeneous_curve(m1);
  else return joint_curve(m1, *m2);
}

// The piece [k, k + 1] / 2^depth of a curve, by repeated halving (exact, and
// interval / double the way the search computes them).
template <class NT, std::size_t N>
std::vector<std::array<NT, N>> piece_of(std::vector<std::array<NT, N>> c, int depth, std::uint64_t k) {
  for (int level = depth - 1; level >= 0; --level) {
    std::vector<std::array<NT, N>> l, r;
    split_half(c, l, r);
    c = ((k >> level) & 1) ? r : l;
  }
  return c;
}

// The claim's hypothesis, exactly: every control point separates the two
// vertex sets along the plane: for the plane n(u) = (1 - u) n0 + u n1 and
// L control points, every Bernstein coefficient (times L) of
// n(u).(N1(u) x^ - N2(u) y^), (L - k) n0.d_k + k n1.d_(k-1) with
// d_l = N1_l x^ - N2_l y^ (B = 1: N1_l x^ - W_l y), is positive for every
// vertex pair (x, y) and k = 0 .. L.
template <int B>
bool inequalities(const HomogeneousCurve<Exact, B>& piece, const std::vector<Vec3E>& xs, const std::vector<Vec3E>& ys,
                  const HullPlane& plane) {
  const Vec3E n0{Exact(plane.n0[0]), Exact(plane.n0[1]), Exact(plane.n0[2])};
  const Vec3E n1{Exact(plane.n1[0]), Exact(plane.n1[1]), Exact(plane.n1[2])};
  const std::size_t L = piece.size();
  auto d = [&](std::size_t l, const Vec3E& x, const Vec3E& y) {
    const auto& P = piece[l];
    Mat34E m1, m2;
    for (int e = 0; e < 12; ++e) m1[e] = P[e];
    if constexpr (B == 2)
      for (int e = 0; e < 12; ++e) m2[e] = P[12 + e];
    const Vec3E other = B == 2 ? place(m2, y) : Vec3E{P[12] * y[0], P[12] * y[1], P[12] * y[2]};
    return sub(place(m1, x), other);
  };
  for (std::size_t k = 0; k <= L; ++k)
    for (const Vec3E& x : xs)
      for (const Vec3E& y : ys) {
        Exact c = 0;
        if (k < L) c += Exact(static_cast<long>(L - k)) * dot(n0, d(k, x, y));
        if (k > 0) c += Exact(static_cast<long>(k)) * dot(n1, d(k - 1, x, y));
        if (!(c > 0)) return false;
      }
  return true;
}

// The first of the code's candidate planes that `apart` accepts.
template <int B, class NT, class Apart>
std::optional<HullPlane> accepted(const std::vector<std::array<NT, 12 * B + 1>>& piece, const FeatureGeometry<double>& X,
                                  const FeatureGeometry<double>& Y, Apart&& apart) {
  for (const HullPlane& plane : hull_candidates<B>(piece, X, Y))
    if (apart(plane)) return plane;
  return std::nullopt;
}

struct Counts {
  int pairs = 0, filtered = 0, exact = 0, fast = 0, filtered_without_exact = 0;
  int near = 0;  // filtered clears on pieces next to the one holding t*
  int directions = 0, directions_apart = 0;
  int weightless_wrong = 0, ends_wrong = 0, weightless_clears = 0, ends_clears = 0;
};

template <int B>
void run_case(Rng& r, int case_index, unsigned seed, Counts& counts) {
  const int degree1 = r.i(1, 3), degree2 = r.i(1, 3);
  const bool rational = r.i(0, 1) == 1, bounce = r.i(0, 3) == 0;
  std::array<Vec3E, 3> t1 = random_triangle(r), t2 = random_triangle(r);
  // Away from the origin (where a missing weight shows), in either body's
  // frame.
  const Vec3E offset{r.q(-40, 40, 4), r.q(-40, 40, 4), r.q(-40, 40, 4)};
  for (Vec3E& v : r.i(0, 1) ? t1 : t2)
    for (int c = 0; c < 3; ++c) v[c] += offset[c];
  Body b1 = triangle_body("one", t1), b2 = triangle_body("two", t2);
  Motion m1 = random_motion(r, degree1, rational, bounce);
  std::optional<Motion> m2;
  if constexpr (B == 2) m2 = random_motion(r, degree2, rational, !bounce && r.i(0, 2) == 0);
  // The contact at t*: x0 of triangle 1 meets y0 of triangle 2.
  const Exact tstar = r.i(0, 4) == 0 ? r.q(1, 15, 16) : r.q(1, 20, 21);
  const Vec3E x0 = random_point(r, t1), y0 = random_point(r, t2);
  if constexpr (B == 1) {
    translate(m1, sub(y0, place(eval_motion(m1, tstar), x0)));
  } else {
    translate(*m2, sub(place(eval_motion(m1, tstar), x0), place(eval_motion(*m2, tstar), y0)));
  }
  b1.motion = m1;
  if constexpr (B == 2) b2.motion = m2;
  const PreparedBody p1(b1), p2(b2);
  const HomogeneousCurve<Exact, B> curve = curve_of<B>(m1, m2);
  const HomogeneousCurve<Interval, B> curve_i = enclose(curve);
  const HomogeneousCurve<double, B> curve_d = approximate(curve);
  const detail::FilteredPolicy<B> filtered{p1, p2, curve};
  const detail::ExactPolicy<B> exact{p1, p2, curve};
  const detail::FastPolicy<B> fast{p1, p2, curve};
  auto placed = [&](const Mat34E& m, const std::vector<Vec3E>& v) {
    std::vector<Vec3E> out;
    for (const Vec3E& x : v) out.push_back(place(m, x));
    return out;
  };
  for (int trial = 0; trial < 6; ++trial) {
    const int depth = r.i(0, 11);
    CGAL::Gmpz two_to_depth;
    mpz_setbit(two_to_depth.mpz(), static_cast<mp_bitcnt_t>(depth));
    const Exact scale(two_to_depth);
    CGAL::Gmpz fl;
    const Exact pos = tstar * scale;
    mpz_fdiv_q(fl.mpz(), pos.numerator().mpz(), pos.denominator().mpz());
    const long home = mpz_get_si(fl.mpz());
    const long max_index = (1L << depth) - 1;
    long k = home + r.i(-2, 2);
    if (trial == 0) k = home;
    if (k < 0 || k > max_index) k = home;
    const Exact u0 = Exact(k) / scale, u1 = Exact(k + 1) / scale;
    const bool holds_tstar = u0 <= tstar && tstar <= u1;
    const auto piece_e = piece_of(curve, depth, static_cast<std::uint64_t>(k));
    HomogeneousCurve<Interval, B> piece_i;
    {
      RoundingGuard guard;
      piece_i = piece_of(curve_i, depth, static_cast<std::uint64_t>(k));
    }
    const auto piece_d = piece_of(curve_d, depth, static_cast<std::uint64_t>(k));
    // The oracle's parameters: t* (when in the piece), 11 spread over the
    // piece, 4 random; the two bodies' poses there, exactly.
    std::vector<Exact> samples;
    if (holds_tstar) samples.push_back(tstar);
    for (int s = 0; s <= 10; ++s) samples.push_back(u0 + (u1 - u0) * Exact(s, 10));
    for (int s = 0; s < 4; ++s) samples.push_back(u0 + (u1 - u0) * r.q(0, 997, 997));
    std::vector<std::pair<Mat34E, Mat34E>> poses;
    for (const Exact& u : samples) poses.push_back({eval_motion(m1, u), B == 2 ? eval_motion(*m2, u) : identity()});
    for (ContactKind kind : {ContactKind::VertexFace, ContactKind::EdgeEdge, ContactKind::FaceVertex}) {
      const FeatureTable& X = detail::moving_table(p1, kind);
      const FeatureTable& Y = detail::other_table(p2, kind);
      for (std::uint32_t i = 0; i < X.size(); ++i)
        for (std::uint32_t j = 0; j < Y.size(); ++j) {
          ++counts.pairs;
          const detail::PairRef pair = detail::feature_pair(kind, i, j);
          const bool by_filtered = filtered.hull(piece_i, pair);
          const bool by_exact = exact.hull(piece_e, pair);
          const bool by_fast = fast.hull(piece_d, pair);
          const std::vector<Vec3E> xs = vertices(detail::moving_exact(p1, kind)[i]);
          const std::vector<Vec3E> ys = vertices(detail::other_exact(p2, kind)[j]);
          // The planes the kernels accepted (the candidates are
          // deterministic), for the hypothesis.
          const auto& Xi = X.interval[i];
          const auto& Yi = Y.interval[j];
          const auto& Xe = detail::moving_exact(p1, kind)[i];
          const auto& Ye = detail::other_exact(p2, kind)[j];
          const auto plane_i = accepted<B>(piece_i, X.approx[i], Y.approx[j], [&](const HullPlane& pl) {
            RoundingGuard guard;
            return hull_apart<B>(piece_i, Xi, Yi, pl);
          });
          const auto plane_e = accepted<B>(piece_e, X.approx[i], Y.approx[j],
                                           [&](const HullPlane& pl) { return hull_apart<B>(piece_e, Xe, Ye, pl); });
          BOOST_REQUIRE(plane_i.has_value() == by_filtered);
          BOOST_REQUIRE(plane_e.has_value() == by_exact);
          // The wrong variants: the code's candidates and the inequalities
          // on wrong data (weights 1 for B = 1; the first and last control
          // points only).
          bool weightless = false, ends = false;
          if constexpr (B == 1) {
            HomogeneousCurve<Exact, B> unweighted = piece_e;
            for (auto& P : unweighted) P[12] = 1;
            weightless = accepted<B>(unweighted, X.approx[i], Y.approx[j], [&](const HullPlane& pl) {
                           return inequalities<B>(unweighted, xs, ys, pl);
                         }).has_value();
          }
          {
            const HomogeneousCurve<Exact, B> end_points{piece_e.front(), piece_e.back()};
            ends = accepted<B>(end_points, X.approx[i], Y.approx[j], [&](const HullPlane& pl) {
                     return inequalities<B>(end_points, xs, ys, pl);
                   }).has_value();
          }
          // The certification alone, on other planes (the candidates,
          // perturbed, and random fixed and moving ones): interval "apart"
          // implies the inequalities exactly, and exact "apart" is exactly
          // them.
          {
            std::vector<HullPlane> planes;
            auto perturbed = [&](std::array<double, 3> n, double size) {
              const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
              for (double& c : n) c += size * len * r.noise();
              return n;
            };
            for (const HullPlane& c : hull_candidates<B>(piece_i, X.approx[i], Y.approx[j]))
              for (double size : {1e-2, 1e-6}) {
                const auto n0 = perturbed(c.n0, size);
                planes.push_back({n0, c.n0 == c.n1 ? n0 : perturbed(c.n1, size)});
              }
            const std::array<double, 3> random0{r.noise(), r.noise(), r.noise()};
            planes.push_back({random0, random0});
            planes.push_back({random0, {r.noise(), r.noise(), r.noise()}});
            for (const HullPlane& d : planes) {
              bool apart_i;
              {
                RoundingGuard guard;
                apart_i = hull_apart<B>(piece_i, Xi, Yi, d);
              }
              const bool apart_e = hull_apart<B>(piece_e, Xe, Ye, d);
              const bool truth = inequalities<B>(piece_e, xs, ys, d);
              ++counts.directions;
              counts.directions_apart += truth;
              BOOST_REQUIRE_MESSAGE(!apart_i || truth, "interval certification without the inequalities, seed " << seed << " case " << case_index);
              BOOST_REQUIRE_MESSAGE(apart_e == truth, "exact certification differs from the inequalities, seed " << seed << " case " << case_index);
            }
          }
          counts.filtered += by_filtered;
          counts.exact += by_exact;
          counts.fast += by_fast;
          counts.weightless_clears += weightless;
          counts.ends_clears += ends;
          if (by_filtered && !holds_tstar && (k + 1 == home || k == home + 1)) ++counts.near;
          if (!by_filtered && !by_exact && !weightless && !ends) continue;
          std::ostringstream where;
          where << "seed " << seed << " (TMCERT_SEED), case " << case_index << " B=" << B << " trial " << trial
                << " piece [" << u0 << ", " << u1 << "] kind " << static_cast<int>(kind) << " pair " << i << "," << j;
          // The hypothesis, exactly, for the certified kernels' clears.
          if (by_filtered) BOOST_REQUIRE_MESSAGE(inequalities<B>(piece_e, xs, ys, *plane_i), "filtered: hypothesis fails, " << where.str());
          if (by_exact) BOOST_REQUIRE_MESSAGE(inequalities<B>(piece_e, xs, ys, *plane_e), "exact: hypothesis fails, " << where.str());
          if (by_filtered && !by_exact) ++counts.filtered_without_exact;
          // The conclusion: no common point at sampled exact parameters.
          bool touches = false;
          for (const auto& [pose1, pose2] : poses) {
            if (common_point(simplex_of(placed(pose1, xs)), simplex_of(placed(pose2, ys)))) {
              touches = true;
              break;
            }
          }
          BOOST_REQUIRE_MESSAGE(!(touches && by_filtered), "filtered hull test cleared a touching pair, " << where.str());
          BOOST_REQUIRE_MESSAGE(!(touches && by_exact), "exact hull test cleared a touching pair, " << where.str());
          counts.weightless_wrong += touches && weightless;
          counts.ends_wrong += touches && ends;
        }
    }
  }
}

}  // namespace

BOOST_AUTO_TEST_SUITE(hull)

BOOST_AUTO_TEST_CASE(hull_test_never_clears_a_touching_pair) {
  const unsigned seed = hull_seed(20261123);
  Rng r(seed);
  Counts counts;
  for (int c = 0; c < 80; ++c) {
    if (c % 2 == 0) run_case<1>(r, c, seed, counts);
    else run_case<2>(r, c, seed, counts);
  }
  BOOST_TEST_MESSAGE("hull: " << counts.pairs << " pair-pieces, cleared filtered " << counts.filtered << " exact "
                              << counts.exact << " (filtered but not exact " << counts.filtered_without_exact
                              << ") fast " << counts.fast << ", next to the contact " << counts.near
                              << "; wrong variants: without W_l " << counts.weightless_wrong << " of "
                              << counts.weightless_clears << ", ends only " << counts.ends_wrong << " of "
                              << counts.ends_clears << "; other directions " << counts.directions << ", apart "
                              << counts.directions_apart);
  // Not vacuous: many clears, some right next to the contact.
  BOOST_TEST(counts.filtered > counts.pairs / 10);
  BOOST_TEST(counts.near > 20);
  BOOST_TEST(counts.directions_apart > counts.directions / 10);
  BOOST_TEST(counts.directions_apart < counts.directions * 9 / 10);
  // The oracle catches both wrong variants.
  BOOST_TEST(counts.weightless_wrong > 0);
  BOOST_TEST(counts.ends_wrong > 0);
}

BOOST_AUTO_TEST_SUITE_END()
