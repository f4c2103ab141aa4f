// Planner motions (issue 12; proofs/enclosures.md "Checked by"): validated
// transcendental functions against MPFR, jets against analytic derivatives,
// the keyframe models (slerp, screw, nlerp, rpy) against an independent
// high-precision reference (tests/support/mp_reference.h), exact nlerp,
// Taylor enclosures of pieces against dense sampling, certain transversal
// crossings, exact closest points against a brute-force oracle, and the
// validation of rotation matrices.
#include "kernels/distance.h"
#include "kernels/jet.h"
#include "kernels/robust_crossing.h"
#include "kernels/validated.h"
#include "src/metric/metric.h"
#include "src/model/chain.h"
#include "src/motion/chain.h"
#include "src/motion/enclosure.h"
#include "src/motion/segment.h"
#include "tests/support/exact_oracle.h"
#include "tests/support/mp_reference.h"
#include "tests/support/random_geometry.h"

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <cstring>
#include <limits>
#include <optional>

using namespace tmcert;
using namespace tmcert::testing;

namespace {

// Rigorous MPFR bounds [L, U] of f(x) for an exact double x: f computed
// rounded down and up at 256 bits (MPFR's functions are correctly rounded).
template <class F>
std::pair<Mp, Mp> mp_bounds(double x, F f) {
  Mp in(x), lo, hi;
  f(lo.get(), in.get(), MPFR_RNDD);
  f(hi.get(), in.get(), MPFR_RNDU);
  return {lo, hi};
}

// [lo, hi] holds [L, U] and is at most `ulps` units in the last place wider
// than the correctly rounded outward enclosure of [L, U].
template <class F>
void check_point_function(const char* name, double x, const Interval& got, F f, int ulps = 2) {
  const auto [L, U] = mp_bounds(x, f);
  BOOST_TEST_CONTEXT(name << "(" << x << ") = [" << got.inf() << ", " << got.sup() << "]") {
    BOOST_TEST(mpfr_cmp_d(L.get(), got.inf()) >= 0);
    BOOST_TEST(mpfr_cmp_d(U.get(), got.sup()) <= 0);
    double lo = mpfr_get_d(L.get(), MPFR_RNDD), hi = mpfr_get_d(U.get(), MPFR_RNDU);
    for (int i = 0; i < ulps; ++i) {
      lo = std::nextafter(lo, -INFINITY);
      hi = std::nextafter(hi, INFINITY);
    }
    BOOST_TEST(got.inf() >= lo);  // narrow: within `ulps` of the best enclosure
    BOOST_TEST(got.sup() <= hi);
  }
}

Pose pose_q(const Vec3E& t, const std::array<Exact, 4>& q) {
  Pose p;
  p.translation = t;
  p.rotation.kind = Rotation::Kind::Quaternion;
  p.rotation.quaternion = q;
  return p;
}
Pose pose_rpy(const Vec3E& t, const std::array<Exact, 3>& e) {
  Pose p;
  p.translation = t;
  p.rotation.kind = Rotation::Kind::Rpy;
  p.rotation.rpy = e;
  return p;
}
Pose pose_m(const Vec3E& t, const std::array<Exact, 9>& m) {
  Pose p;
  p.translation = t;
  p.rotation.kind = Rotation::Kind::Matrix;
  p.rotation.matrix = m;
  return p;
}

MotionSegment keyframe_segment(const Pose& a, const Pose& b, Interpolation how) {
  MotionSegment seg;
  seg.t0 = 0;
  seg.t1 = 1;
  seg.from = a;
  seg.to = b;
  seg.interpolation = how;
  return seg;
}

// Every entry of the enclosure holds the reference, and the enclosure is
// narrow (so that containment means something).
void check_pose_encloses(const PoseInterval& got, const MpPose& want, double max_width, const std::string& what) {
  for (int e = 0; e < 12; ++e)
    BOOST_TEST_CONTEXT(what << " entry " << e << " [" << got[e].inf() << ", " << got[e].sup() << "] vs "
                            << want[e].to_double()) {
      BOOST_TEST(mp_inside(want[e], got[e]));
      BOOST_TEST(got[e].sup() - got[e].inf() <= max_width);
    }
}

Mat34E exact_pose_of(const Pose& p) {
  const auto m = exact_pose(p);
  BOOST_REQUIRE(m);
  return *m;
}

// The rotation form R(q) (not normalised), exact: the textbook matrix of
// q/|q| times |q|^2.
std::array<Exact, 9> rq(const std::array<Exact, 4>& q) {
  const Exact &w = q[0], &x = q[1], &y = q[2], &z = q[3];
  const Exact n = w * w + x * x + y * y + z * z;
  return {n - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w),
          2 * (x * y + z * w), n - 2 * (x * x + z * z), 2 * (y * z - x * w),
          2 * (x * z - y * w), 2 * (y * z + x * w), n - 2 * (x * x + y * y)};
}

std::array<Interval, 16> moment_interval(const MassDistribution& mass) {
  const Metric metric = Metric::from_mass(mass);
  std::array<Interval, 16> g;
  for (int i = 0; i < 16; ++i) g[i] = to_interval(metric.moment()[i]);
  return g;
}

MassDistribution tetra_mass() {
  MassDistribution mass;
  mass.points = {Vec3E{0, 0, 0}, Vec3E{2, 0, 0}, Vec3E{0, 1, 0}, Vec3E{0, 0, Exact(1, 2)}};
  mass.weights = {1, 2, 1, Exact(1, 2)};
  return mass;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(planner_motions)

// ------------------------------------------------------------------ validated functions

BOOST_AUTO_TEST_CASE(validated_sin_cos_enclose_mpfr_and_are_narrow) {
  Rng r(12);
  std::vector<double> xs = {0.0, 1e-300, -1e-300, 5e-324, 1.0, -1.0, 0.5, 3.141592653589793, 1.5707963267948966,
                            6.283185307179586, 1e5, -123456.789, 710.0, 1e-8};
  for (int k = 0; k < 300; ++k) xs.push_back(r.noise() * std::ldexp(1.0, r.i(-20, 12)));
  for (const double x : xs) {
    check_point_function("sin", x, validated::sin(Interval(x)), mpfr_sin);
    check_point_function("cos", x, validated::cos(Interval(x)), mpfr_cos);
  }
}

// sin and cos remember their last results per thread (kernels/validated.cpp
// Memo): intervals sharing one end, or hashing alike, must each get their
// own enclosure, and a second pass in another order the same bits.
BOOST_AUTO_TEST_CASE(validated_sin_cos_remembered_results_belong_to_their_argument) {
  Rng r(21);
  std::vector<Interval> xs;
  for (int k = 0; k < 200; ++k) {
    const double a = r.noise() * 4, w = std::ldexp(1.0, r.i(-30, 1));
    xs.push_back(Interval(a, a + w));
    xs.push_back(Interval(a, a + 2 * w));   // the same lower end
    xs.push_back(Interval(a - w, a + w));   // the same upper end as the first
    xs.push_back(Interval(a));
  }
  // Many intervals sharing one end (more than the table has entries, so
  // that some share a slot): sin and cos are monotone over [1/4, 5/4], so
  // a remembered narrower interval's enclosure would miss the other end.
  for (int k = 1; k <= 1000; ++k) {
    xs.push_back(Interval(0.25, 0.25 + k / 1024.0));
    xs.push_back(Interval(1.25 - k / 1024.0, 1.25));
  }
  std::vector<std::pair<Interval, Interval>> first;
  for (const Interval& x : xs) {
    const Interval s = validated::sin(x), c = validated::cos(x);
    for (const double e : {x.inf(), x.sup()}) {
      const auto [sl, sh] = mp_bounds(e, mpfr_sin);
      const auto [cl, ch] = mp_bounds(e, mpfr_cos);
      BOOST_TEST(mpfr_cmp_d(sl.get(), s.inf()) >= 0);
      BOOST_TEST(mpfr_cmp_d(sh.get(), s.sup()) <= 0);
      BOOST_TEST(mpfr_cmp_d(cl.get(), c.inf()) >= 0);
      BOOST_TEST(mpfr_cmp_d(ch.get(), c.sup()) <= 0);
    }
    first.push_back({s, c});
  }
  for (std::size_t k = xs.size(); k-- > 0;) {
    const Interval s = validated::sin(xs[k]), c = validated::cos(xs[k]);
    BOOST_TEST(s.inf() == first[k].first.inf());
    BOOST_TEST(s.sup() == first[k].first.sup());
    BOOST_TEST(c.inf() == first[k].second.inf());
    BOOST_TEST(c.sup() == first[k].second.sup());
  }
}

BOOST_AUTO_TEST_CASE(validated_functions_enclose_every_point_of_an_interval) {
  Rng r(13);
  for (int k = 0; k < 200; ++k) {
    const double a = r.noise() * 8, w = std::ldexp(std::fabs(r.noise()), r.i(-30, 1));
    const Interval x(a, a + w);
    const Interval s = validated::sin(x), c = validated::cos(x);
    const Interval y(a * 0.5 - 0.25, a * 0.5 - 0.25 + w);
    const Interval at = validated::atan2(y, Interval(1.5, 1.5 + w));
    for (int i = 0; i <= 16; ++i) {
      const double p = i == 16 ? x.sup() : x.inf() + w * i / 16;  // a double of [a, a + w]
      if (p > x.sup()) continue;
      const auto [sl, su] = mp_bounds(p, mpfr_sin);
      const auto [cl, cu] = mp_bounds(p, mpfr_cos);
      BOOST_TEST(mpfr_cmp_d(sl.get(), s.inf()) >= 0);
      BOOST_TEST(mpfr_cmp_d(su.get(), s.sup()) <= 0);
      BOOST_TEST(mpfr_cmp_d(cl.get(), c.inf()) >= 0);
      BOOST_TEST(mpfr_cmp_d(cu.get(), c.sup()) <= 0);
      const double yp = y.inf() + (y.sup() - y.inf()) * i / 16, xp = 1.5 + w * (16 - i) / 16;
      if (yp > y.sup() || xp > 1.5 + w) continue;
      const Mp ref = atan2(Mp(yp), Mp(xp));
      BOOST_TEST(mp_inside(ref, at));
    }
    // Narrow: the width of sin over [a, a + w] is at most w (|sin'| <= 1),
    // plus rounding and Arb's ball radii (stored with 30-bit magnitudes,
    // and Arb's error terms for a wide ball: Arb lowers its working
    // precision to the accuracy of the input, observed up to 1.3 % of w).
    BOOST_TEST(s.sup() - s.inf() <= w * 1.05 + 1e-15);
    BOOST_TEST(c.sup() - c.inf() <= w * 1.05 + 1e-15);
  }
}

BOOST_AUTO_TEST_CASE(validated_atan2_pi_and_sqrt) {
  Rng r(14);
  for (int k = 0; k < 300; ++k) {
    const double y = r.noise() * std::ldexp(1.0, r.i(-10, 10)), x = r.noise() * std::ldexp(1.0, r.i(-10, 10));
    const Interval got = validated::atan2(Interval(y), Interval(x));
    Mp lo, hi, my(y), mx(x);
    mpfr_atan2(lo.get(), my.get(), mx.get(), MPFR_RNDD);
    mpfr_atan2(hi.get(), my.get(), mx.get(), MPFR_RNDU);
    BOOST_TEST_CONTEXT("atan2(" << y << ", " << x << ")") {
      BOOST_TEST(mpfr_cmp_d(lo.get(), got.inf()) >= 0);
      BOOST_TEST(mpfr_cmp_d(hi.get(), got.sup()) <= 0);
      BOOST_TEST(got.sup() - got.inf() <= 4 * std::numeric_limits<double>::epsilon() * std::max(1.0, std::fabs(got.sup())));
    }
  }
  // Points on the axes, where atan2 is exact or pi.
  BOOST_TEST(validated::atan2(Interval(0), Interval(1)).inf() <= 0);
  BOOST_TEST(validated::atan2(Interval(0), Interval(1)).sup() >= 0);
  const Interval p = validated::pi();
  BOOST_TEST(mp_inside(mp_pi(), p));
  BOOST_TEST(p.sup() - p.inf() <= 1e-15);
  BOOST_TEST(mp_inside(mp_pi(), validated::atan2(Interval(0), Interval(-1))));
  BOOST_TEST(mp_inside(mp_pi() / Mp(2), validated::atan2(Interval(1), Interval(0))));
  // sqrt of rationals: rigorous MPFR bounds from the rational rounded down/up.
  for (int k = 0; k < 300; ++k) {
    const Exact q = k < 5 ? Exact(k * k) : Exact(r.i(0, 1000000), r.i(1, 99999));
    const Interval got = validated::sqrt(q);
    Mp ql, qh, lo, hi;
    mpfr_set_q(ql.get(), q.mpq(), MPFR_RNDD);
    mpfr_set_q(qh.get(), q.mpq(), MPFR_RNDU);
    mpfr_sqrt(lo.get(), ql.get(), MPFR_RNDD);
    mpfr_sqrt(hi.get(), qh.get(), MPFR_RNDU);
    BOOST_TEST_CONTEXT("sqrt(" << to_string(q) << ")") {
      BOOST_TEST(mpfr_cmp_d(lo.get(), got.inf()) >= 0);
      BOOST_TEST(mpfr_cmp_d(hi.get(), got.sup()) <= 0);
      BOOST_TEST(got.sup() - got.inf() <= 4 * std::numeric_limits<double>::epsilon() * std::max(1.0, got.sup()));
    }
  }
  BOOST_TEST(validated::sqrt(Exact(4)).inf() == 2.0);  // exact squares: the point
  BOOST_TEST(validated::sqrt(Exact(4)).sup() == 2.0);
}

BOOST_AUTO_TEST_CASE(validated_non_finite_input_is_a_harmless_enclosure) {
  const double inf = std::numeric_limits<double>::infinity();
  const Interval s = validated::sin(Interval(-inf, inf));
  BOOST_TEST(s.inf() <= -1.0);
  BOOST_TEST(s.sup() >= 1.0);
  const Interval a = validated::atan2(Interval(-1, 1), Interval(-1, 1));  // both contain 0
  BOOST_TEST(a.inf() <= -3.14159);
  BOOST_TEST(a.sup() >= 3.14159);
}

// ------------------------------------------------------------------ jets

namespace {

// f(s) = sin(s^2) cos(3 s) / (1 + s^2) and its derivatives, analytically,
// in MPFR: g = sin(s^2), h = cos(3s) / u with u = 1 + s^2.
std::array<Mp, 3> f_analytic(const Mp& s) {
  const Mp one(1), two(2), three(3), four(4), nine(9);
  const Mp s2 = s * s;
  const Mp g = sin(s2), g1 = two * s * cos(s2), g2 = two * cos(s2) - four * s2 * sin(s2);
  const Mp c = cos(three * s), c1 = -three * sin(three * s), c2 = -nine * cos(three * s);
  const Mp u = one + s2, u1 = two * s, u2 = two;
  const Mp h = c / u, h1 = (c1 * u - c * u1) / (u * u);
  const Mp h2 = (c2 * u - c * u2) / (u * u) - two * u1 * (c1 * u - c * u1) / (u * u * u);
  return {g * h, g1 * h + g * h1, g2 * h + two * g1 * h1 + g * h2};
}

Jet f_jet(const Jet& s) { return sin(s * s) * cos(Interval(3) * s) / (Jet(Interval(1)) + s * s); }

}  // namespace

BOOST_AUTO_TEST_CASE(jets_of_composed_functions_match_analytic_derivatives) {
  Rng r(15);
  for (int k = 0; k < 200; ++k) {
    const double s = r.noise() * 3;
    Jet j;
    {
      RoundingGuard guard;
      j = f_jet(Jet::variable(Interval(s)));
    }
    const std::array<Mp, 3> want = f_analytic(Mp(s));
    BOOST_TEST_CONTEXT("s = " << s) {
      BOOST_TEST(mp_inside(want[0], j.v));
      BOOST_TEST(mp_inside(want[1], j.d));
      BOOST_TEST(mp_inside(want[2], j.dd));
      BOOST_TEST(j.v.sup() - j.v.inf() <= 1e-13);
      BOOST_TEST(j.d.sup() - j.d.inf() <= 1e-12);
      BOOST_TEST(j.dd.sup() - j.dd.inf() <= 1e-11);
    }
  }
  // A product rule that dropped the factor 2 of (fg)'' = f''g + 2f'g' + fg''
  // would fail here: (s^2)'' = 2 at any s, (s^3)'' = 6 s.
  RoundingGuard guard;
  const Jet s = Jet::variable(Interval(0.5));
  const Jet cube = s * s * s;
  BOOST_TEST(cube.dd.inf() <= 3.0);
  BOOST_TEST(cube.dd.sup() >= 3.0);
  BOOST_TEST(cube.dd.sup() - cube.dd.inf() <= 1e-15);
  const Jet q = Jet(Interval(1)) / s;  // 1/s: -1/s^2, 2/s^3
  BOOST_TEST(q.d.inf() <= -4.0);
  BOOST_TEST(q.d.sup() >= -4.0);
  BOOST_TEST(q.dd.inf() <= 16.0);
  BOOST_TEST(q.dd.sup() >= 16.0);
}

BOOST_AUTO_TEST_CASE(interval_jets_contain_point_evaluations) {
  Rng r(16);
  for (int k = 0; k < 60; ++k) {
    const double a = r.noise() * 2, w = std::ldexp(1.0, r.i(-10, -1));
    Jet over;
    {
      RoundingGuard guard;
      over = f_jet(Jet::variable(Interval(a, a + w)));
    }
    for (int i = 0; i <= 32; ++i) {
      const std::array<Mp, 3> want = f_analytic(Mp(a) + Mp(w) * Mp(i) / Mp(32));
      BOOST_TEST(mp_inside(want[0], over.v));
      BOOST_TEST(mp_inside(want[1], over.d));
      BOOST_TEST(mp_inside(want[2], over.dd));
    }
  }
}

// ------------------------------------------------------------------ pose models

namespace {

struct Case {
  std::string name;
  Pose a, b;
  Interpolation how;
};

std::vector<Case> model_cases() {
  const Vec3E o{0, 0, 0};
  std::vector<Case> c;
  for (const Interpolation how : {Interpolation::Slerp, Interpolation::Screw, Interpolation::Nlerp}) {
    const std::string n = how == Interpolation::Slerp ? "slerp" : how == Interpolation::Screw ? "screw" : "nlerp";
    c.push_back({n + " quaternions", pose_q({1, 2, 3}, {1, 0, 0, 0}), pose_q({3, -1, Exact(1, 2)}, {2, 1, -1, 3}), how});
    c.push_back({n + " negative dot", pose_q(o, {1, 2, 0, 1}), pose_q({1, 0, 0}, {-3, -1, 2, -2}), how});
    c.push_back({n + " small angle", pose_q({0, 0, 0}, {1000, 1, 0, 0}), pose_q({Exact(1, 10), 0, 0}, {1000, 0, 1, 2}), how});
    c.push_back({n + " rpy", pose_rpy({0, 1, 0}, {Exact(1, 3), Exact(-1, 2), Exact(2, 1)}),
                 pose_rpy({2, 0, -1}, {Exact(1, 5), Exact(1, 4), Exact(3, 1)}), how});
    c.push_back({n + " matrix to quaternion", pose_m({1, 1, 1}, {Exact(3, 5), Exact(-4, 5), 0, Exact(4, 5), Exact(3, 5), 0, 0, 0, 1}),
                 pose_q({-1, 2, 0}, {1, 1, 1, 1}), how});
    c.push_back({n + " large offset", pose_q({10, -5, 2}, {3, 0, 1, 0}), pose_q({-20, 30, 7}, {1, 2, 0, -1}), how});
  }
  return c;
}

}  // namespace

BOOST_AUTO_TEST_CASE(models_enclose_keyframes_and_the_reference_motion) {
  for (const Case& c : model_cases()) {
    BOOST_TEST_CONTEXT(c.name) {
      const auto model = make_segment_model(keyframe_segment(c.a, c.b, c.how));
      // The keyframes: the exact poses (rpy: the reference) at s = 0 and 1.
      for (int end = 0; end < 2; ++end) {
        const Pose& p = end == 0 ? c.a : c.b;
        const PoseInterval got = enclose_pose(*model, Exact(end));
        if (const auto m = exact_pose(p)) {
          for (int e = 0; e < 12; ++e) {
            BOOST_TEST(CGAL::to_interval((*m)[e]).first >= got[e].inf());
            BOOST_TEST(CGAL::to_interval((*m)[e]).second <= got[e].sup());
          }
        }
        check_pose_encloses(got, make_pose(rotation_matrix(p.rotation), mp_vec(p.translation)), 1e-9,
                            end == 0 ? "s = 0" : "s = 1");
      }
      // Inside: the independent reference (slerp by acos, screw by the SE(3) log/exp, nlerp as written).
      for (int i = 1; i < 16; ++i) {
        const Exact s(i, 16);
        check_pose_encloses(enclose_pose(*model, s), reference_pose(c.a, c.b, c.how, Mp(s)), 1e-8,
                            "s = " + to_string(s));
      }
    }
  }
}

// SegmentModel::pose_values is the value part of pose(Jet(s)) bit for bit:
// the link chain's own value-only evaluation (LinkChain::pose_values) on a
// chain with rpy and quaternion constants, an identity constant, revolute
// joints (one axis not of unit length) and a prismatic one; the keyframe
// models through the default.  Slices' boxes and sampled poses rely on it
// (proofs/enclosures.md section 2).
BOOST_AUTO_TEST_CASE(pose_values_are_the_jet_values_bit_for_bit) {
  auto rpy_pose = [](const char* x, const char* y, const char* z, std::array<const char*, 3> rpy) {
    Pose p;
    auto e = [](const char* text) { return Exact(std::string(text)); };
    p.translation = {e(x), e(y), e(z)};
    p.rotation.kind = Rotation::Kind::Rpy;
    p.rotation.rpy = {e(rpy[0]), e(rpy[1]), e(rpy[2])};
    return p;
  };
  Pose quat;
  quat.translation = {Exact(0), Exact(1, 10), Exact(3, 10)};
  quat.rotation.kind = Rotation::Kind::Quaternion;
  quat.rotation.quaternion = {Exact(3), Exact(1), Exact(0), Exact(-2)};
  const std::vector<std::vector<Pose>> constants = {{rpy_pose("0", "0", "4/5", {"0", "0", "2/5"})},
                                                    {rpy_pose("1/5", "0", "1/2", {"1/10", "-3/10", "0"}), quat},
                                                    {},
                                                    {rpy_pose("3/5", "0", "0", {"0", "0", "0"})},
                                                    {rpy_pose("0", "1/20", "1/5", {"7/10", "0", "-1/5"})}};
  std::vector<ChainJoint> joints(4);
  joints[0].axis = {Exact(0), Exact(0), Exact(1)};
  joints[1].axis = {Exact(0), Exact(2), Exact(1)};  // length sqrt 5
  joints[2].axis = {Exact(1), Exact(0), Exact(0)};
  joints[3].kind = ChainJoint::Kind::Prismatic;
  joints[3].axis = {Exact(1), Exact(0), Exact(0)};
  auto link = std::make_shared<LinkMotion>();
  link->chain = std::make_shared<const ChainDescription>(constants, joints);
  link->from = {Exact(-1, 2), Exact(1, 4), Exact(2), Exact(0)};
  link->to = {Exact(6, 5), Exact(-3, 4), Exact(-1, 3), Exact(3, 10)};
  MotionSegment seg;
  seg.t0 = 0;
  seg.t1 = 1;
  seg.link = link;
  MotionSegment slerp;
  slerp.t0 = 0;
  slerp.t1 = 1;
  slerp.from = pose_q({Exact(0), Exact(0), Exact(0)}, {Exact(1), Exact(0), Exact(0), Exact(0)});
  slerp.to = pose_q({Exact(1), Exact(2), Exact(-1)}, {Exact(2), Exact(1), Exact(-1), Exact(3)});
  slerp.interpolation = Interpolation::Slerp;
  int compared = 0;
  for (const MotionSegment* sg : {&seg, &slerp}) {
    const std::unique_ptr<SegmentModel> model = make_segment_model(*sg);
    for (int k = 0; k < 16; ++k)
      for (const Interval& s : {Interval(k / 16.0, (k + 1) / 16.0), Interval(k / 16.0), to_interval(Exact(k, 17))}) {
        RoundingGuard guard;
        const PoseJet j = model->pose(Jet(s));
        const PoseInterval v = model->pose_values(s);
        for (int e = 0; e < 12; ++e) {
          BOOST_TEST(std::memcmp(&j[e].v, &v[e], sizeof(Interval)) == 0, "entry " << e << " at s = " << s);
          ++compared;
        }
      }
  }
  BOOST_TEST(compared == 2 * 16 * 3 * 12);
}

BOOST_AUTO_TEST_CASE(slerp_rotation_stays_orthonormal) {
  const Pose a = pose_q({0, 0, 0}, {1, 2, 3, 4}), b = pose_rpy({1, 1, 1}, {Exact(1), Exact(2), Exact(-1, 2)});
  const auto model = make_segment_model(keyframe_segment(a, b, Interpolation::Slerp));
  for (int i = 0; i <= 20; ++i) {
    const PoseInterval p = enclose_pose(*model, Exact(i, 20));
    RoundingGuard guard;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) {
        const Interval d = p[4 * r] * p[4 * c] + p[4 * r + 1] * p[4 * c + 1] + p[4 * r + 2] * p[4 * c + 2];
        const double want = r == c ? 1.0 : 0.0;
        BOOST_TEST(d.inf() <= want);
        BOOST_TEST(d.sup() >= want);
        BOOST_TEST(d.sup() - d.inf() <= 1e-12);
      }
    const Interval det = p[0] * (p[5] * p[10] - p[6] * p[9]) - p[1] * (p[4] * p[10] - p[6] * p[8]) +
                         p[2] * (p[4] * p[9] - p[5] * p[8]);
    BOOST_TEST(det.inf() <= 1.0);
    BOOST_TEST(det.sup() >= 1.0);
  }
}

BOOST_AUTO_TEST_CASE(screw_about_the_origin_equals_slerp) {
  // Rotation only, and rotation with a translation along the rotation axis
  // (axis (1,2,2)/3 of the quaternion (1, 1, 2, 2)): the constant screw is
  // the slerp with linear translation.
  for (const Vec3E t : {Vec3E{0, 0, 0}, Vec3E{Exact(1, 3), Exact(2, 3), Exact(2, 3)}}) {
    const Pose a = pose_q({0, 0, 0}, {1, 0, 0, 0}), b = pose_q(t, {1, 1, 2, 2});
    const auto screw = make_segment_model(keyframe_segment(a, b, Interpolation::Screw));
    const auto slerp = make_segment_model(keyframe_segment(a, b, Interpolation::Slerp));
    for (int i = 0; i <= 10; ++i) {
      const PoseInterval x = enclose_pose(*screw, Exact(i, 10)), y = enclose_pose(*slerp, Exact(i, 10));
      for (int e = 0; e < 12; ++e) {
        BOOST_TEST(x[e].inf() <= y[e].sup());  // overlap ...
        BOOST_TEST(y[e].inf() <= x[e].sup());
        BOOST_TEST(x[e].sup() - x[e].inf() <= 1e-12);  // ... of narrow enclosures
        BOOST_TEST(y[e].sup() - y[e].inf() <= 1e-12);
      }
    }
  }
}

BOOST_AUTO_TEST_CASE(screw_with_offset_axis_matches_the_se3_formula_and_differs_from_slerp) {
  // T1 = (Rz(90), (2, 0, 0)) from the identity: the rotation about the
  // vertical axis through (1, 1); the origin follows c - Rz(s pi/2) c.
  const Pose a = pose_q({0, 0, 0}, {1, 0, 0, 0}), b = pose_q({2, 0, 0}, {1, 0, 0, 1});
  const auto screw = make_segment_model(keyframe_segment(a, b, Interpolation::Screw));
  const PoseInterval mid = enclose_pose(*screw, Exact(1, 2));
  const Mp r2 = sqrt(Mp(2));
  BOOST_TEST(mp_inside(Mp(1), mid[3]));
  BOOST_TEST(mp_inside(Mp(1) - r2, mid[7]));  // y = 1 - sqrt 2, slerp's is 0
  BOOST_TEST(mp_inside(Mp(0), mid[11]));
  // A general screw with pitch, rotated first pose: the SE(3) log/exp reference.
  const Pose c = pose_q({1, -2, 3}, {2, 1, 0, -1}), d = pose_q({4, 1, -1}, {1, 3, -1, 2});
  const auto general = make_segment_model(keyframe_segment(c, d, Interpolation::Screw));
  for (int i = 0; i <= 32; ++i) {
    const Exact s(i, 32);
    check_pose_encloses(enclose_pose(*general, s), screw_pose(c, d, Mp(s)), 1e-8, "screw s = " + to_string(s));
  }
}

BOOST_AUTO_TEST_CASE(nlerp_of_exact_quaternions_is_the_exact_formula) {
  struct Q {
    std::array<Exact, 4> q0, q1;
  };
  const std::vector<Q> cases = {
      {{1, 0, 0, 0}, {1, 0, 0, 1}},
      {{1, 0, 0, 0}, {10, 0, 0, 10}},                       // unequal norms
      {{2, 1, -1, 3}, {-1, -2, 1, 0}},                       // negative dot: q1 negated
      {{Exact(1, 3), 2, Exact(-5, 7), 1}, {3, Exact(1, 2), 1, -2}},
  };
  Rng r(17);
  for (const Q& c : cases) {
    const Pose a = pose_q({1, 2, 3}, c.q0), b = pose_q({-1, Exact(1, 2), 4}, c.q1);
    const Exact t0(-1, 2), t1(3, 2);
    const auto m = rational_keyframe_segment(a, b, Interpolation::Nlerp, t0, t1);
    BOOST_REQUIRE(m);
    BOOST_TEST(m->t0 == t0);
    BOOST_TEST(m->t1 == t1);
    for (const Exact& w : m->weights) BOOST_TEST(w > 0);
    std::array<Exact, 4> q1 = c.q1;
    Exact dot = 0;
    for (int i = 0; i < 4; ++i) dot += c.q0[i] * q1[i];
    if (dot < 0)
      for (Exact& x : q1) x = -x;
    for (int k = 0; k <= 12; ++k) {
      const Exact s = k <= 8 ? Exact(k, 8) : r.q(1, 999, 1000);
      std::array<Exact, 4> q;
      for (int i = 0; i < 4; ++i) q[i] = (1 - s) * c.q0[i] + s * q1[i];
      const Exact n2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
      const std::array<Exact, 9> R = rq(q);
      const Mat34E got = eval_motion(*m, t0 + s * (t1 - t0));
      for (int row = 0; row < 3; ++row) {
        for (int col = 0; col < 3; ++col) BOOST_TEST(got[4 * row + col] == R[3 * row + col] / n2);
        BOOST_TEST(got[4 * row + 3] == (1 - s) * a.translation[row] + s * b.translation[row]);
      }
    }
  }
  // Equal rotations (proportional quaternions, either sign): a translation for every interpolation.
  for (const Interpolation how : {Interpolation::Slerp, Interpolation::Screw, Interpolation::Nlerp}) {
    const auto m = rational_keyframe_segment(pose_q({0, 0, 0}, {1, 2, 3, 4}), pose_q({1, 1, 1}, {-2, -4, -6, -8}), how, 0, 1);
    BOOST_REQUIRE(m);
    const Mat34E mid = eval_motion(*m, Exact(1, 3));
    const std::array<Exact, 9> R = rq({1, 2, 3, 4});
    for (int row = 0; row < 3; ++row) {
      for (int col = 0; col < 3; ++col) BOOST_TEST(mid[4 * row + col] == R[3 * row + col] / 30);
      BOOST_TEST(mid[4 * row + 3] == Exact(1, 3));
    }
  }
  // Slerp and screw between different rotations are not rational.
  BOOST_TEST(!rational_keyframe_segment(pose_q({0, 0, 0}, {1, 0, 0, 0}), pose_q({0, 0, 0}, {1, 0, 0, 1}), Interpolation::Slerp, 0, 1));
  BOOST_TEST(!rational_keyframe_segment(pose_q({0, 0, 0}, {1, 0, 0, 0}), pose_q({0, 0, 0}, {1, 0, 0, 1}), Interpolation::Screw, 0, 1));
}

BOOST_AUTO_TEST_CASE(rpy_poses_follow_urdf_convention) {
  Rng r(18);
  for (int k = 0; k < 50; ++k) {
    const std::array<Exact, 3> e = {r.q(-700, 700, 100), r.q(-150, 150, 100), r.q(-700, 700, 100)};
    PoseInterval got;
    {
      RoundingGuard guard;
      got = interval_pose(pose_rpy({1, 2, 3}, e));
    }
    check_pose_encloses(got, make_pose(rpy_matrix(Mp(e[0]), Mp(e[1]), Mp(e[2])), mp_vec({1, 2, 3})), 1e-12,
                        "rpy " + to_string(e[0]) + " " + to_string(e[1]) + " " + to_string(e[2]));
  }
  // rpy [0, 0, 0] is the identity exactly.
  const auto id = exact_pose(pose_rpy({0, 0, 0}, {0, 0, 0}));
  BOOST_REQUIRE(id);
  for (int rr = 0; rr < 3; ++rr)
    for (int c = 0; c < 3; ++c) BOOST_TEST((*id)[4 * rr + c] == Exact(rr == c ? 1 : 0));
  BOOST_TEST(!exact_pose(pose_rpy({0, 0, 0}, {0, 0, Exact(1, 2)})));
}

// ------------------------------------------------------------------ Taylor enclosures of pieces

namespace {

// max over dense samples s of [s0, s1] of |M(s) - P(lambda)|_mu - (tube + w),
// with P(lambda) = M(m) + M'(m)(s - m) the segment point enclosed by the
// controls (lambda = (s - m)/h), its enclosure's width bounded by w.  The
// reference M(s) and the norm are MPFR.  Returns the largest distance found.
double check_piece(const Case& c, const Exact& s0, const Exact& s1, const MassDistribution& mass, double& tube_out) {
  const auto model = make_segment_model(keyframe_segment(c.a, c.b, c.how));
  const std::array<Interval, 16> g = moment_interval(mass);
  const PieceEnclosure piece = enclose_piece(*model, s0, s1, g);
  BOOST_REQUIRE(piece.valid);
  tube_out = piece.tube;
  const Metric metric = Metric::from_mass(mass);
  const Exact mid = (s0 + s1) / 2, half = (s1 - s0) / 2;
  double worst = 0;
  for (int i = 0; i <= 64; ++i) {
    const Exact s = s0 + (s1 - s0) * Exact(i, 64);
    const Exact lambda = (s - mid) / half;  // in [-1, 1]
    const MpPose want = reference_pose(c.a, c.b, c.how, Mp(s));
    // P = (1 - lambda)/2 P0 + (1 + lambda)/2 P1 at the controls' midpoints;
    // the enclosure's half-widths give the extra term w.
    std::array<Mp, 12> diff;
    std::array<double, 12> rad;
    for (int e = 0; e < 12; ++e) {
      const Interval &p0 = piece.controls[0][e], &p1 = piece.controls[1][e];
      const Mp a0 = (Mp(p0.inf()) + Mp(p0.sup())) / Mp(2), a1 = (Mp(p1.inf()) + Mp(p1.sup())) / Mp(2);
      const Mp l(lambda);
      diff[e] = want[e] - ((Mp(1) - l) / Mp(2) * a0 + (Mp(1) + l) / Mp(2) * a1);
      rad[e] = (p0.sup() - p0.inf()) + (p1.sup() - p1.inf());
    }
    // |X|_mu^2 = trace(X G X^T), in MPFR from the exact G.
    Mp n2(0);
    double w2 = 0;
    for (int r = 0; r < 3; ++r)
      for (int i2 = 0; i2 < 4; ++i2)
        for (int j = 0; j < 4; ++j) {
          n2 = n2 + diff[4 * r + i2] * Mp(metric.moment()[4 * i2 + j]) * diff[4 * r + j];
          w2 += rad[4 * r + i2] * std::fabs(CGAL::to_double(metric.moment()[4 * i2 + j])) * rad[4 * r + j];
        }
    const double dist = sqrt(n2).to_double();
    worst = std::max(worst, dist);
    BOOST_TEST_CONTEXT(c.name << " piece [" << to_string(s0) << ", " << to_string(s1) << "] at s = " << to_string(s)) {
      BOOST_TEST(dist <= piece.tube + 2 * std::sqrt(w2) + 1e-300);
    }
  }
  return worst;
}

}  // namespace

BOOST_AUTO_TEST_CASE(piece_enclosures_hold_dense_samples_and_shrink_quadratically) {
  const MassDistribution mass = tetra_mass();
  for (const Case& c : model_cases()) {
    double tube_whole = 0, tube_half = 0, tube_quarter = 0;
    const double worst = check_piece(c, Exact(1, 4), Exact(3, 4), mass, tube_whole);
    check_piece(c, Exact(1, 4), Exact(1, 2), mass, tube_half);
    const double worst_quarter = check_piece(c, Exact(1, 4), Exact(3, 8), mass, tube_quarter);
    BOOST_TEST_MESSAGE(c.name << ": tube [1/4,3/4] " << tube_whole << " (samples up to " << worst << "), [1/4,3/8] "
                              << tube_quarter << " (samples up to " << worst_quarter << ")");
    check_piece(c, Exact(0), Exact(1), mass, tube_whole);  // the whole segment, ends included
    double tube_mid = 0;
    check_piece(c, Exact(1, 4), Exact(3, 4), mass, tube_mid);
    BOOST_TEST_CONTEXT(c.name << ": tubes " << tube_mid << " " << tube_half << " " << tube_quarter << ", worst sample " << worst) {
      // Halving the piece divides the bound by about 4 (h^2; sup |M''| over a sub-piece is no larger).
      BOOST_TEST(tube_half <= 0.26 * tube_mid + 1e-14);
      BOOST_TEST(tube_quarter <= 0.26 * tube_half + 1e-14);
      // Not vacuous: on the small piece the samples come within a sizeable
      // fraction of the bound (on [1/4, 3/4] nlerp's interval quotient
      // overestimates sup |M''| up to 120 times; slerp and screw 2-3 times).
      BOOST_TEST(worst_quarter >= tube_quarter / 10);
    }
  }
}

BOOST_AUTO_TEST_CASE(metric_norm_upper_bounds_the_exact_norm_tightly) {
  Rng r(21);
  const MassDistribution mass = tetra_mass();
  const Metric metric = Metric::from_mass(mass);
  const std::array<Interval, 16> g = moment_interval(mass);
  for (int k = 0; k < 200; ++k) {
    Mat34E x;
    for (Exact& e : x) e = r.q(-50, 50, 7);
    PoseInterval xi;
    for (int e = 0; e < 12; ++e) xi[e] = to_interval(x[e]);
    double up;
    {
      RoundingGuard guard;
      up = metric_norm_upper(xi, g);
    }
    const Mp exact = sqrt(Mp(metric.norm2(x)));
    BOOST_TEST(mpfr_cmp_d(exact.get(), up) <= 0);               // an upper bound ...
    BOOST_TEST(up <= exact.to_double() * (1 + 1e-12) + 1e-300);  // ... and a tight one
  }
  // Intervals: the bound covers every matrix inside.
  PoseInterval wide;
  for (int e = 0; e < 12; ++e) wide[e] = Interval(-0.5, 1.0);
  double up;
  {
    RoundingGuard guard;
    up = metric_norm_upper(wide, g);
  }
  Mat34E corner;
  for (int e = 0; e < 12; ++e) corner[e] = e % 2 ? Exact(1) : Exact(-1, 2);
  BOOST_TEST(mpfr_cmp_d(sqrt(Mp(metric.norm2(corner))).get(), up) <= 0);
  for (int e = 0; e < 12; ++e) corner[e] = 1;
  BOOST_TEST(mpfr_cmp_d(sqrt(Mp(metric.norm2(corner))).get(), up) <= 0);
}

// ------------------------------------------------------------------ certain crossings

namespace {

using V3 = std::array<Interval, 3>;

V3 v3(double x, double y, double z, double r = 0) { return {Interval(x - r, x + r), Interval(y - r, y + r), Interval(z - r, z + r)}; }

SimplexI tri(const V3& a, const V3& b, const V3& c) {
  SimplexI s;
  s.count = 3;
  s.p = {a, b, c};
  return s;
}
SimplexI seg(const V3& a, const V3& b) {
  SimplexI s;
  s.count = 2;
  s.p = {a, b, b};
  return s;
}

bool box_holds(const std::array<Interval, 3>& box, double x, double y, double z) {
  return box[0].inf() <= x && x <= box[0].sup() && box[1].inf() <= y && y <= box[1].sup() && box[2].inf() <= z &&
         z <= box[2].sup();
}

}  // namespace

BOOST_AUTO_TEST_CASE(certain_crossing_hand_made_cases) {
  RoundingGuard guard;
  const SimplexI t = tri(v3(0, 0, 0), v3(2, 0, 0), v3(0, 2, 0));
  // Transversal crossing through the interior, either order.
  for (const double r : {0.0, 1e-6, 1e-3}) {
    const SimplexI e = seg(v3(0.5, 0.5, -1, r), v3(0.5, 0.25, 1, r));
    const auto x = certain_crossing(e, t);
    BOOST_REQUIRE(x);
    BOOST_TEST(box_holds(*x, 0.5, 0.375, 0.0));
    BOOST_TEST((*x)[0].sup() - (*x)[0].inf() <= 10 * r + 1e-12);
    const auto y = certain_crossing(t, e);
    BOOST_REQUIRE(y);
    BOOST_TEST(box_holds(*y, 0.5, 0.375, 0.0));
  }
  // Enclosures wide enough to admit a miss: no certainty.
  BOOST_TEST(!certain_crossing(seg(v3(0.5, 0.5, -1, 0.6), v3(0.5, 0.5, 1, 0.6)), t));
  // Misses, grazing and degenerate cases: nothing.
  BOOST_TEST(!certain_crossing(seg(v3(3, 3, -1), v3(3, 3, 1)), t));         // outside
  BOOST_TEST(!certain_crossing(seg(v3(1, 0, -1), v3(1, 0, 1)), t));         // through an edge
  BOOST_TEST(!certain_crossing(seg(v3(0, 0, -1), v3(0, 0, 1)), t));         // through a vertex
  BOOST_TEST(!certain_crossing(seg(v3(0.5, 0.5, 0), v3(0.5, 0.5, 1)), t));  // ends on the plane
  BOOST_TEST(!certain_crossing(seg(v3(0.5, 0.5, 1), v3(0.5, 0.5, 2)), t));  // same side
  BOOST_TEST(!certain_crossing(seg(v3(-1, 0.5, 0), v3(3, 0.5, 0)), t));     // in the plane
  BOOST_TEST(!certain_crossing(seg(v3(0.5, 0.5, -1), v3(0.5, 0.5, 1)), tri(v3(0, 0, 0), v3(1, 1, 0), v3(2, 2, 0))));  // flat triangle
  BOOST_TEST(!certain_crossing(seg(v3(0.5, 0.5, -1), v3(0.5, 0.5, 1)), seg(v3(0, 0, 0), v3(1, 1, 0))));  // two segments
  // A triangle whose edge pierces another triangle.
  const SimplexI u = tri(v3(0.5, 0.5, -1), v3(0.5, 0.5, 1), v3(5, 5, 1));
  const auto x = certain_crossing(u, t);
  BOOST_REQUIRE(x);
  BOOST_TEST(box_holds(*x, 0.5, 0.5, 0.0));
  // Two triangles touching along a shared edge only: nothing.
  BOOST_TEST(!certain_crossing(tri(v3(0, 0, 0), v3(2, 0, 0), v3(0, 0, 2)), t));
}

// ------------------------------------------------------------------ closest points

namespace {

Simplex simplex(std::vector<Vec3E> p) {
  Simplex s;
  s.count = static_cast<int>(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) s.p[i] = p[i];
  return s;
}

Vec3E vadd(const Vec3E& a, const Vec3E& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Vec3E vmul(const Exact& s, const Vec3E& a) { return {s * a[0], s * a[1], s * a[2]}; }

bool in_simplex(const Vec3E& x, const Simplex& s) {
  if (s.count == 1) return x == s.p[0];
  if (s.count == 2) return on_segment(x, s.p[0], s.p[1]);
  return in_triangle(x, s.p[0], s.p[1], s.p[2]);
}

// Solves the n x n system A x = b exactly (Gauss-Jordan); nullopt when singular.
std::optional<std::vector<Exact>> solve(std::vector<std::vector<Exact>> A, std::vector<Exact> b) {
  const std::size_t n = b.size();
  for (std::size_t c = 0; c < n; ++c) {
    std::size_t p = c;
    while (p < n && A[p][c] == 0) ++p;
    if (p == n) return std::nullopt;
    std::swap(A[p], A[c]);
    std::swap(b[p], b[c]);
    for (std::size_t r = 0; r < n; ++r) {
      if (r == c || A[r][c] == 0) continue;
      const Exact f = A[r][c] / A[c][c];
      for (std::size_t k = c; k < n; ++k) A[r][k] -= f * A[c][k];
      b[r] -= f * b[c];
    }
  }
  for (std::size_t r = 0; r < n; ++r) b[r] /= A[r][r];
  return b;
}

// The brute-force oracle: the minimum of |p - q|^2 over every pair of faces
// (vertices, edges, the triangle) whose affine hulls' unconstrained
// minimiser is inside both faces (KKT: the minimiser lies in the relative
// interior of some pair of faces; singular pairs are covered by their
// boundaries).
Exact oracle_d2(const Simplex& A, const Simplex& B) {
  auto faces = [](const Simplex& s) {
    std::vector<std::vector<Vec3E>> f;
    for (int i = 0; i < s.count; ++i) f.push_back({s.p[i]});
    if (s.count >= 2)
      for (int i = 0; i < s.count; ++i)
        for (int j = i + 1; j < s.count; ++j) f.push_back({s.p[i], s.p[j]});
    if (s.count == 3) f.push_back({s.p[0], s.p[1], s.p[2]});
    return f;
  };
  std::optional<Exact> best;
  for (const auto& fa : faces(A))
    for (const auto& fb : faces(B)) {
      // p = fa0 + sum u_i (fa_i - fa0), q = fb0 + sum v_j (fb_j - fb0); columns of M = [Ea, -Eb].
      std::vector<Vec3E> cols;
      for (std::size_t i = 1; i < fa.size(); ++i) cols.push_back(sub(fa[i], fa[0]));
      for (std::size_t j = 1; j < fb.size(); ++j) cols.push_back(vmul(Exact(-1), testing::sub(fb[j], fb[0])));
      const Vec3E rhs = sub(fb[0], fa[0]);
      std::vector<Exact> x;
      if (!cols.empty()) {
        std::vector<std::vector<Exact>> M(cols.size(), std::vector<Exact>(cols.size()));
        std::vector<Exact> b(cols.size());
        for (std::size_t i = 0; i < cols.size(); ++i) {
          for (std::size_t j = 0; j < cols.size(); ++j) M[i][j] = dot(cols[i], cols[j]);
          b[i] = dot(cols[i], rhs);
        }
        const auto sol = solve(M, b);
        if (!sol) continue;
        x = *sol;
      }
      Exact su = 0, sv = 0;
      bool inside = true;
      for (std::size_t i = 0; i < x.size(); ++i) {
        if (x[i] < 0) inside = false;
        (i + 1 < fa.size() ? su : sv) += x[i];
      }
      if (!inside || su > 1 || sv > 1) continue;
      Vec3E p = fa[0], q = fb[0];
      for (std::size_t i = 1; i < fa.size(); ++i) p = vadd(p, vmul(x[i - 1], testing::sub(fa[i], fa[0])));
      for (std::size_t j = 1; j < fb.size(); ++j) q = vadd(q, vmul(x[fa.size() - 1 + j - 1], testing::sub(fb[j], fb[0])));
      const Vec3E d = sub(p, q);
      const Exact d2 = dot(d, d);
      if (!best || d2 < *best) best = d2;
    }
  return *best;
}

void check_closest(const Simplex& a, const Simplex& b, const std::string& what) {
  const ClosestPoints c = closest_points(a, b);
  BOOST_TEST_CONTEXT(what) {
    BOOST_TEST(c.d2 == oracle_d2(a, b));
    BOOST_TEST(in_simplex(c.a, a));
    BOOST_TEST(in_simplex(c.b, b));
    const Vec3E d = sub(c.a, c.b);
    BOOST_TEST(dot(d, d) == c.d2);
  }
}

}  // namespace

BOOST_AUTO_TEST_CASE(closest_points_match_a_brute_force_oracle) {
  Rng r(19);
  auto point = [&] { return Vec3E{r.q(-8, 8, 4), r.q(-8, 8, 4), r.q(-8, 8, 4)}; };
  auto random_simplex = [&](int count) {
    for (;;) {
      std::vector<Vec3E> p;
      for (int i = 0; i < count; ++i) p.push_back(point());
      if (count == 2 && p[0] == p[1]) continue;
      if (count == 3 && testing::collinear(p[0], p[1], p[2])) continue;
      return simplex(p);
    }
  };
  int zero = 0;
  for (int k = 0; k < 600; ++k) {
    const Simplex a = random_simplex(1 + k % 3), b = random_simplex(1 + (k / 3) % 3);
    check_closest(a, b, "random pair " + std::to_string(k));
    if (closest_points(a, b).d2 == 0) ++zero;
  }
  BOOST_TEST_MESSAGE(zero << " of 600 random pairs intersect");
  // Parallel segments (overlapping and not), collinear segments, a segment
  // parallel to a triangle, intersecting pairs (d2 = 0), coplanar triangles.
  const Vec3E o{0, 0, 0};
  check_closest(simplex({o, {4, 0, 0}}), simplex({{1, 1, 0}, {3, 1, 0}}), "parallel, overlapping");
  check_closest(simplex({o, {4, 0, 0}}), simplex({{5, 1, 1}, {7, 1, 1}}), "parallel, apart");
  check_closest(simplex({o, {4, 0, 0}}), simplex({{6, 0, 0}, {5, 0, 0}}), "collinear, apart");
  check_closest(simplex({o, {4, 0, 0}}), simplex({{2, 0, 0}, {6, 0, 0}}), "collinear, overlapping");
  check_closest(simplex({{0, 0, 1}, {1, 1, 1}}), simplex({o, {4, 0, 0}, {0, 4, 0}}), "parallel to a triangle above it");
  check_closest(simplex({{1, 1, -1}, {1, 1, 1}}), simplex({o, {4, 0, 0}, {0, 4, 0}}), "segment through a triangle");
  check_closest(simplex({{-1, 1, 0}, {1, -1, 0}}), simplex({{-1, -1, 0}, {1, 1, 0}}), "crossing segments");
  check_closest(simplex({{1, 1, 0}, {5, 1, 0}, {1, 5, 0}}), simplex({o, {4, 0, 0}, {0, 4, 0}}), "coplanar overlapping triangles");
  check_closest(simplex({{1, 1, 1}, {3, 1, 1}, {1, 3, 1}}), simplex({o, {4, 0, 0}, {0, 4, 0}}), "parallel triangles");
  check_closest(simplex({{1, 1, 0}}), simplex({o, {4, 0, 0}, {0, 4, 0}}), "point in a triangle");
  BOOST_TEST(closest_points(simplex({{1, 1, -1}, {1, 1, 1}}), simplex({o, {4, 0, 0}, {0, 4, 0}})).d2 == 0);
  BOOST_TEST(closest_points(simplex({o, {4, 0, 0}}), simplex({{5, 1, 1}, {7, 1, 1}})).d2 == 3);
}

// ------------------------------------------------------------------ rotations

BOOST_AUTO_TEST_CASE(rotation_matrices_are_validated_exactly) {
  BOOST_TEST(rotation_matrix_problem({Exact(3, 5), Exact(-4, 5), 0, Exact(4, 5), Exact(3, 5), 0, 0, 0, 1}).empty());
  BOOST_TEST(rotation_matrix_problem({1, 0, 0, 0, 1, 0, 0, 0, 1}).empty());
  const std::string skew = rotation_matrix_problem({1, 0, 0, 0, 1, Exact(1, 10), 0, 0, 1});
  BOOST_TEST(skew.find("orthonormal") != std::string::npos, skew);
  const std::string scaled = rotation_matrix_problem({2, 0, 0, 0, 2, 0, 0, 0, 2});
  BOOST_TEST(scaled.find("orthonormal") != std::string::npos, scaled);
  const std::string reflection = rotation_matrix_problem({1, 0, 0, 0, 1, 0, 0, 0, -1});
  BOOST_TEST(reflection.find("determinant") != std::string::npos, reflection);
  const std::string swap = rotation_matrix_problem({0, 1, 0, 1, 0, 0, 0, 0, 1});
  BOOST_TEST(swap.find("determinant") != std::string::npos, swap);
  // Within rounding of orthonormal is not orthonormal.
  BOOST_TEST(!rotation_matrix_problem({0.6, -0.8, 0, 0.8, 0.6, 0, 0, 0, 1}).empty());

  // R(q)/|q|^2 of random rational quaternions (half turns included) are
  // rotations, and the quaternion read back from the matrix is proportional to q.
  Rng r(20);
  std::vector<std::array<Exact, 4>> qs = {{0, 1, 2, 3}, {0, 0, 0, 1}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 3, -1, 2}};
  for (int k = 0; k < 100; ++k) qs.push_back({r.q(-5, 5, 2), r.q(-5, 5, 2), r.q(-5, 5, 2), r.q(-5, 5, 2)});
  for (const auto& q : qs) {
    const Exact n2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
    if (n2 == 0) continue;
    std::array<Exact, 9> m = rq(q);
    for (Exact& x : m) x /= n2;
    BOOST_TEST(rotation_matrix_problem(m).empty());
    Rotation rot;
    rot.kind = Rotation::Kind::Matrix;
    rot.matrix = m;
    const auto back = exact_quaternion(rot);
    BOOST_REQUIRE(back);
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) BOOST_TEST((*back)[i] * q[j] == (*back)[j] * q[i]);
    // And the pose of the matrix is the pose of the quaternion.
    BOOST_TEST(exact_pose_of(pose_m({1, 2, 3}, m)) == exact_pose_of(pose_q({1, 2, 3}, q)));
  }
}

BOOST_AUTO_TEST_CASE(half_turns_cannot_be_interpolated_by_slerp_or_screw) {
  const Pose a = pose_q({0, 0, 0}, {1, 0, 0, 0}), b = pose_q({1, 0, 0}, {0, 0, 0, 1});
  BOOST_CHECK_THROW(require_interpolable(a, b, Interpolation::Slerp), InputError);
  BOOST_CHECK_THROW(require_interpolable(a, b, Interpolation::Screw), InputError);
  BOOST_CHECK_NO_THROW(require_interpolable(a, b, Interpolation::Nlerp));  // nlerp's dot is 0: q(s) stays nonzero
  // A matrix half turn against a quaternion.
  const Pose m = pose_m({0, 0, 0}, {1, 0, 0, 0, -1, 0, 0, 0, -1});
  BOOST_CHECK_THROW(require_interpolable(a, m, Interpolation::Slerp), InputError);
  // rpy: pi written to 40 digits is within rounding of a half turn; 3 radians is provably less.
  const Pose near = pose_rpy({0, 0, 0}, {0, 0, Exact(0)});
  Exact pi40;
  BOOST_REQUIRE(parse_exact("3.141592653589793238462643383279502884197", pi40));
  BOOST_CHECK_THROW(require_interpolable(near, pose_rpy({0, 0, 0}, {0, 0, pi40}), Interpolation::Slerp), InputError);
  BOOST_CHECK_THROW(require_interpolable(pose_rpy({0, 0, 0}, {0, 0, Exact(1, 10)}), pose_rpy({0, 0, 0}, {0, 0, pi40 + Exact(1, 10)}),
                                         Interpolation::Screw),
                    InputError);
  BOOST_CHECK_NO_THROW(require_interpolable(near, pose_rpy({0, 0, 0}, {0, 0, Exact(3)}), Interpolation::Slerp));
  BOOST_CHECK_NO_THROW(require_interpolable(a, pose_q({0, 0, 0}, {1, 0, 0, 1000}), Interpolation::Slerp));  // 179.9 degrees
}

// Nlerp with an rpy end whose dot product with the other quaternion is
// negative but within rounding of 0: the contract negates the second
// quaternion then, and which arc that is cannot be proven, so the keyframes
// are refused (accepted, the model enclosed the longer arc: a false safe and
// a false collision, tests/data/bad/nlerp-rpy-arc-undecidable-*.json).
BOOST_AUTO_TEST_CASE(nlerp_rpy_arc_must_be_proven) {
  Exact y;
  BOOST_REQUIRE(parse_exact("3.141592653589793238462643383279502884197169399375105820974945", y));  // > pi
  const Pose a = pose_q({0, 0, 0}, {1, 0, 0, 0}), b = pose_rpy({0, 0, 0}, {0, 0, y});
  BOOST_CHECK_THROW(require_interpolable(a, b, Interpolation::Nlerp), InputError);
  // A yaw clearly below pi is accepted, and the model keeps the shorter arc
  // (counter-clockwise: at s = 1/2 the x axis turns towards +y).
  const Pose c = pose_rpy({0, 0, 0}, {0, 0, Exact(3)});
  BOOST_CHECK_NO_THROW(require_interpolable(a, c, Interpolation::Nlerp));
  const auto model = make_segment_model(keyframe_segment(a, c, Interpolation::Nlerp));
  const PoseInterval mid = enclose_pose(*model, Exact(1, 2));
  BOOST_TEST(mid[4].inf() > 0);
}

BOOST_AUTO_TEST_SUITE_END()
