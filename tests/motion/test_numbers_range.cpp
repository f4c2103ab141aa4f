// Numbers at the edges (issue 21, findings 5-8): exact inputs beyond the
// double range (weights and quaternions of 1e400 or 1e-400, normalised
// exactly), screw motions between rotations equal up to rounding (bounded
// enclosures, regular at angle 0), the default epsilon of nlerp keyframes
// (from their poses, not their control points), and approximations (the
// nearest double, or a 17-digit decimal beyond the double range, also for
// algebraic numbers).  proofs/input-exactness.md, proofs/enclosures.md,
// docs/scene-format.md "Approximations".
#include "kernels/decimal.h"
#include "kernels/jet.h"
#include "kernels/real_roots.h"
#include "kernels/validated.h"
#include "src/report/report.h"
#include "src/motion/enclosure.h"
#include "src/motion/segment.h"
#include "src/io/parse.h"
#include "src/verify/verify.h"
#include "tests/support/mp_reference.h"

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <limits>
#include <string>

using namespace tmcert;
using namespace tmcert::testing;

namespace {

Exact q(const std::string& text) {
  Exact x;
  BOOST_REQUIRE(parse_exact(text, x));
  return x;
}

Pose pose_q(const Vec3E& t, const std::array<Exact, 4>& quat) {
  Pose p;
  p.translation = t;
  p.rotation.kind = Rotation::Kind::Quaternion;
  p.rotation.quaternion = quat;
  return p;
}

Pose pose_rpy(const Vec3E& t, const std::array<Exact, 3>& e) {
  Pose p;
  p.translation = t;
  p.rotation.kind = Rotation::Kind::Rpy;
  p.rotation.rpy = e;
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

double width(const Interval& x) { return x.sup() - x.inf(); }

// The enclosure of the pose at s holds the 256-bit reference and is narrow.
void check_encloses(const SegmentModel& model, const MpPose& want, const Exact& s, double max_width,
                    const std::string& what) {
  const PoseInterval got = enclose_pose(model, s);
  for (int e = 0; e < 12; ++e)
    BOOST_TEST_CONTEXT(what << " s = " << to_string(s) << " entry " << e << " [" << got[e].inf() << ", "
                            << got[e].sup() << "] vs " << want[e].to_double()) {
      BOOST_TEST(mp_inside(want[e], got[e]));
      BOOST_TEST(width(got[e]) <= max_width);
    }
}

// The scene reader's motion of body `name`.
const Body& body(const Scene& scene, const std::string& name) {
  for (const Body& b : scene.bodies)
    if (b.name == name) return b;
  BOOST_FAIL("no body " << name);
  return scene.bodies.front();
}

}  // namespace

BOOST_AUTO_TEST_SUITE(numbers_range)

// ------------------------------------------------------------------ 5: exact normalisation

BOOST_AUTO_TEST_CASE(rational_bezier_weights_are_normalised_exactly) {
  auto motion = [](const std::string& w0, const std::string& w1) {
    const std::string text = R"({"format": "tmcert-scene/1", "bodies": [{"name": "m", "points": [[1, 2, 3]],
      "motion": {"type": "rational_bezier", "control_points": [[[1,0,0,0],[0,1,0,0],[0,0,1,0]], [[1,0,0,2],[0,1,0,0],[0,0,1,"1/3"]]],
                 "weights": [)" + w0 + ", " + w1 + "]}}]}";
    return *parse_scene_text(text, "weights.json").bodies[0].motion;
  };
  // Equal huge or tiny weights: the curve of weights 1 (the weights become 1, 1).
  for (const auto& [w0, w1] : {std::pair{"1e400", "1e400"}, {"\"1e-400\"", "\"1e-400\""}, {"1e400", "3e400"},
                               {"\"7e-500\"", "\"7e-500\""}}) {
    BOOST_TEST_CONTEXT("weights " << w0 << ", " << w1) {
      const Motion m = motion(w0, w1);
      BOOST_TEST(m.weights[0] == Exact(1));
      BOOST_TEST((m.weights[1] == Exact(1) || m.weights[1] == Exact(3)));
    }
  }
  // Weights in range are kept as written.
  const Motion kept = motion("\"1/3\"", "5");
  BOOST_TEST(kept.weights[0] == Exact(1, 3));
  BOOST_TEST(kept.weights[1] == Exact(5));
  // An unbalanced pair keeps its ratio exactly and its largest weight in (1/2, 2).
  const Motion ratio = motion("1", "1e400");
  BOOST_TEST(ratio.weights[1] / ratio.weights[0] == q("1e400"));
  BOOST_TEST(ratio.weights[1] > Exact(1, 2));
  BOOST_TEST(ratio.weights[1] < Exact(2));
  // The curve is unchanged: the same exact poses as the weights written.
  Motion written = ratio;
  written.weights = {Exact(1), q("1e400")};
  for (int k = 0; k <= 4; ++k)
    BOOST_TEST((motion_pose(ratio, Exact(k, 4)) == motion_pose(written, Exact(k, 4))));
}

BOOST_AUTO_TEST_CASE(nlerp_of_huge_and_tiny_quaternions_is_the_same_motion) {
  // The rational nlerp curve of quaternions scaled by 1e300, 1e3000 or
  // 1e-3000: the poses of the unit-scale curve, weights in range.
  const Pose a1 = pose_q({0, 0, 0}, {1, 0, 0, 0}), b1 = pose_q({1, 2, 3}, {2, 1, 0, 3});
  const auto unit = rational_keyframe_segment(a1, b1, Interpolation::Nlerp, 0, 1);
  BOOST_REQUIRE(unit);
  for (const char* scale : {"1e300", "1e3000", "1e-3000"}) {
    const Exact f = q(scale);
    const Pose a = pose_q({0, 0, 0}, {f, 0, 0, 0}), b = pose_q({1, 2, 3}, {2 * f, f, 0, 3 * f});
    const auto m = rational_keyframe_segment(a, b, Interpolation::Nlerp, 0, 1);
    BOOST_REQUIRE(m);
    BOOST_TEST_CONTEXT("scale " << scale) {
      for (const Exact& w : m->weights) {
        BOOST_TEST(w > Exact(1, 1 << 30));
        BOOST_TEST(w < Exact(1 << 30));
      }
      for (int k = 0; k <= 8; ++k) BOOST_TEST((motion_pose(*m, Exact(k, 8)) == motion_pose(*unit, Exact(k, 8))));
    }
  }
}

BOOST_AUTO_TEST_CASE(mass_weights_beyond_the_range_scale_with_the_tolerance) {
  // Weights 1e400 (or 1e-400) and a tolerance r: weights times 100^-m and
  // r times 10^-m, the same metric up to that factor, so the same verdict
  // as weights 1 with tolerance r (the bar stays 0.6 from the tripod, the
  // tolerance of 1/10 in the metric of weights 1 moves it by at most 1/20).
  auto scene = [](const std::string& w, const std::string& tolerance) {
    return parse_scene_text(R"({"format": "tmcert-scene/1", "bodies": [
             {"name": "tripod", "segments": [[[0,0,0],[2,0,0]], [[0,0,0],[0,2,0]], [[0,0,-2],[0,0,1]]]},
             {"name": "bar", "segments": [[["0.6","0.6",0],["1.2","0.6",0]]], "tolerance": )" + tolerance + R"(,
              "mass": {"points": [[0,0,0],[1,0,0],[0,1,0],[0,0,1]], "weights": [)" + w + "," + w + "," + w + "," + w + R"(]},
              "motion": {"type": "rational_bezier", "control_points": [[[1,0,0,0],[0,1,0,0],[0,0,1,0]], [[1,0,0,0],[0,1,0,0],[0,0,1,"0.5"]]]}}]})",
                            "mass.json");
  };
  const Scene unit = scene("1", "\"1/10\"");
  const Scene huge = scene("1e400", "\"1e199\"");  // 1e199 in the metric of 1e400 is 1/10 in that of 1
  const Scene tiny = scene("\"1e-400\"", "\"1e-201\"");
  for (const Scene* s : {&huge, &tiny}) {
    const Body& bar = body(*s, "bar");
    for (const Exact& w : bar.mass.weights) {
      BOOST_TEST(w > Exact(1, 1 << 30));
      BOOST_TEST(w < Exact(1 << 30));
    }
    // The ratio tolerance^2 / weight is the one written.
    const Body& ref = body(unit, "bar");
    BOOST_TEST(bar.tolerance * bar.tolerance / bar.mass.weights[0] == ref.tolerance * ref.tolerance / ref.mass.weights[0]);
    VerifyOptions options;
    BOOST_TEST(verify_scene(*s, options).verdict == Verdict::Safe);
  }
}

BOOST_AUTO_TEST_CASE(unit_quaternions_of_huge_and_tiny_quaternions_are_narrow) {
  for (const char* scale : {"1e-400", "1e400", "1e-3000", "1"}) {
    Rotation r;
    r.kind = Rotation::Kind::Quaternion;
    const Exact f = q(scale);
    r.quaternion = {f, f, 0, 0};  // 90 degrees about x
    RoundingGuard guard;
    const std::array<Interval, 4> u = unit_quaternion(r);
    BOOST_TEST_CONTEXT("scale " << scale << ": " << u[0].inf() << " " << u[0].sup()) {
      BOOST_TEST(u[0].inf() <= std::sqrt(0.5));
      BOOST_TEST(u[0].sup() >= 0.7071067811865475);
      BOOST_TEST(width(u[0]) < 1e-15);
      BOOST_TEST(width(u[1]) < 1e-15);
      BOOST_TEST(u[2].inf() == 0);
      BOOST_TEST(u[2].sup() == 0);
    }
  }
}

// ------------------------------------------------------------------ 6: screw near angle 0

BOOST_AUTO_TEST_CASE(factorial_series_and_the_screw_coefficient_enclose_their_functions) {
  // f2 = (1 - cos x)/x^2, f3 = (x - sin x)/x^3, C = (1 - (x/2) cot(x/2))/x^2
  // at points where the closed forms are accurate in 256-bit MPFR.
  for (const double x : {1e-3, 0.01, 0.3, 0.5, 1.0, 2.0, 3.1, -0.7}) {
    const Mp X(x);
    const Mp f2 = (Mp(1) - cos(X)) / (X * X), f3 = (X - sin(X)) / (X * X * X);
    const Mp h = X / Mp(2);
    const Mp c = (Mp(1) - h * cos(h) / sin(h)) / (X * X);
    BOOST_TEST_CONTEXT("x = " << x) {
      const auto a = validated::factorial_series(Interval(x), 2), b = validated::factorial_series(Interval(x), 3);
      BOOST_TEST(mp_inside(f2, a[0]));
      BOOST_TEST(mp_inside(f3, b[0]));
      BOOST_TEST(width(a[0]) < 1e-15);
      BOOST_TEST(width(b[0]) < 1e-15);
      const Interval cc = validated::screw_inverse_coefficient(Interval(x));
      BOOST_TEST(mp_inside(c, cc));
      BOOST_TEST(width(cc) < 1e-15);
      // Derivatives against central differences of the 256-bit closed forms.
      const Mp e(1e-20);
      auto F2 = [](const Mp& y) { return (Mp(1) - cos(y)) / (y * y); };
      auto F3 = [](const Mp& y) { return (y - sin(y)) / (y * y * y); };
      const Mp d2 = (F2(X + e) - F2(X - e)) / (Mp(2) * e), d3 = (F3(X + e) - F3(X - e)) / (Mp(2) * e);
      const Mp dd2 = (F2(X + e) - Mp(2) * F2(X) + F2(X - e)) / (e * e);
      BOOST_TEST(std::abs(d2.to_double() - CGAL::to_double(a[1])) < 1e-14);
      BOOST_TEST(std::abs(d3.to_double() - CGAL::to_double(b[1])) < 1e-14);
      BOOST_TEST(std::abs(dd2.to_double() - CGAL::to_double(a[2])) < 1e-12);
      BOOST_TEST(a[1].inf() <= d2.to_double() + 1e-18);
      BOOST_TEST(a[1].sup() >= d2.to_double() - 1e-18);
    }
  }
  // At and around 0: the limits 1/2, 1/6, 1/12, bounded and narrow, also
  // over an interval holding 0.
  for (const Interval x : {Interval(0), Interval(-1e-17, 1e-17), Interval(0, 1e-9)}) {
    const auto a = validated::factorial_series(x, 2), b = validated::factorial_series(x, 3);
    const Interval c = validated::screw_inverse_coefficient(x);
    BOOST_TEST(a[0].inf() <= 0.5);
    BOOST_TEST(a[0].sup() >= 0.5);
    BOOST_TEST(width(a[0]) < 1e-15);
    BOOST_TEST(b[0].inf() <= 1.0 / 6 + 1e-17);
    BOOST_TEST(b[0].sup() >= 1.0 / 6 - 1e-17);
    BOOST_TEST(width(b[0]) < 1e-15);
    BOOST_TEST(c.inf() <= 1.0 / 12 + 1e-17);
    BOOST_TEST(c.sup() >= 1.0 / 12 - 1e-17);
    BOOST_TEST(width(c) < 1e-15);
    BOOST_TEST(width(a[1]) < 1e-9);
    BOOST_TEST(width(a[2]) < 1e-15);
  }
  // Beyond |x| <= 4 the series is not used: the whole line, still an enclosure.
  BOOST_TEST(!std::isfinite(validated::factorial_series(Interval(5), 2)[0].sup()));
}

BOOST_AUTO_TEST_CASE(screw_between_rotations_equal_up_to_rounding_is_bounded_and_tight) {
  // rpy (1, p, 0) and (0, p, -1) with p = pi/2 rounded: equal up to about
  // 5e-17; yaw 0 and 2 pi rounded; an exact quaternion 1e-400 off the
  // identity.  The screw is then the translation up to that angle: every
  // enclosure is narrow and holds the reference (or the translation).
  const Exact p = to_exact(1.5707963267948966);
  const Pose g0 = pose_rpy({0, 0, 0}, {1, p, 0}), g1 = pose_rpy({0, 0, Exact(1, 2)}, {0, p, -1});
  const Pose y0 = pose_rpy({1, 2, 3}, {0, 0, 0}), y1 = pose_rpy({2, 2, Exact(7, 2)}, {0, 0, to_exact(6.283185307179586)});
  for (const auto& [a, b, name] : {std::tuple{g0, g1, "gimbal"}, std::tuple{y0, y1, "yaw 2 pi"}}) {
    const auto model = make_segment_model(keyframe_segment(a, b, Interpolation::Screw));
    for (int i = 0; i <= 8; ++i)
      check_encloses(*model, screw_pose(a, b, Mp(Exact(i, 8))), Exact(i, 8), 1e-12, name);
    // Over the whole segment: bounded (a valid piece) and tight.
    const std::array<Interval, 16> g = {Interval(4), Interval(0), Interval(0), Interval(0), Interval(0), Interval(4),
                                        Interval(0), Interval(0), Interval(0), Interval(0), Interval(4), Interval(0),
                                        Interval(0), Interval(0), Interval(0), Interval(4)};
    const PieceEnclosure whole = enclose_piece(*model, 0, 1, g);
    BOOST_TEST(whole.valid);
    BOOST_TEST(whole.tube < 1e-9);
  }
  const Pose e0 = pose_q({0, 0, 0}, {1, 0, 0, 0}), e1 = pose_q({1, -2, 3}, {1, q("1e-400"), 0, 0});
  const auto tiny = make_segment_model(keyframe_segment(e0, e1, Interpolation::Screw));
  for (int i = 0; i <= 8; ++i) {
    const Exact s(i, 8);
    const PoseInterval got = enclose_pose(*tiny, s);
    const Mat34E linear = {1, 0, 0, s, 0, 1, 0, -2 * s, 0, 0, 1, 3 * s};
    for (int e = 0; e < 12; ++e) {
      BOOST_TEST(width(got[e]) < 1e-14);
      BOOST_TEST(Exact(got[e].inf()) <= linear[e]);  // 1e-400 away from the translation: inside
      BOOST_TEST(Exact(got[e].sup()) >= linear[e]);
    }
  }
}

BOOST_AUTO_TEST_CASE(small_angle_screw_matches_the_se3_formula) {
  // Angles about 6e-4, 9e-4 and 6e-8 (below the switch to the closed form
  // at 2^-10) and 1.2e-3 (above it), with pitch and an offset axis, where
  // the regular forms' terms in phi matter: against the 256-bit SE(3)
  // log/exp reference.
  for (const char* x : {"0.0001", "0.00015", "0.00000001", "0.0002"}) {
    const Pose a = pose_q({1, -2, 3}, {2, 1, 0, -1});
    // b = a's rotation times a small turn about (1, 2, 2)/3.
    const Exact e = q(x);
    const std::array<Exact, 4> d = {1, e, 2 * e, 2 * e}, qa = a.rotation.quaternion;
    const std::array<Exact, 4> qb = {qa[0] * d[0] - qa[1] * d[1] - qa[2] * d[2] - qa[3] * d[3],
                                     qa[0] * d[1] + qa[1] * d[0] + qa[2] * d[3] - qa[3] * d[2],
                                     qa[0] * d[2] - qa[1] * d[3] + qa[2] * d[0] + qa[3] * d[1],
                                     qa[0] * d[3] + qa[1] * d[2] - qa[2] * d[1] + qa[3] * d[0]};
    const Pose b = pose_q({4, 1, -1}, qb);
    const auto model = make_segment_model(keyframe_segment(a, b, Interpolation::Screw));
    for (int i = 0; i <= 16; ++i)
      check_encloses(*model, screw_pose(a, b, Mp(Exact(i, 16))), Exact(i, 16), 1e-9, std::string("angle ") + x);
  }
}

// ------------------------------------------------------------------ 7: default epsilon of nlerp keyframes

BOOST_AUTO_TEST_CASE(nlerp_default_epsilon_comes_from_the_poses) {
  // A unit bar along y turned by nlerp from the identity to the quaternion
  // (1, 10^9, 0, 0) (180 degrees about x, less 2e-9 rad) and a fixed point
  // at the origin: the bar sweeps y, z in [-1, 1] x [0, 1], a box of
  // diagonal sqrt 5.  The curve's control points carry the quaternion's
  // scale (10^9 and beyond).
  const std::string text = R"({"format": "tmcert-scene/1", "bodies": [
    {"name": "bar", "segments": [[[0, 0, 0], [0, 1, 0]]],
     "motion": {"type": "keyframes", "interpolation": "nlerp",
                "poses": [{}, {"rotation": {"quaternion": [1, 1000000000, 0, 0]}}]}},
    {"name": "dot", "points": [[0, 0, 0]]}]})";
  const Scene scene = parse_scene_text(text, "nlerp.json");
  const Body& bar = body(scene, "bar");
  const Exact eps = default_epsilon(bar, body(scene, "dot"));
  BOOST_TEST_MESSAGE("default epsilon " << to_string(eps));
  BOOST_TEST(eps <= Exact(2237, 1000000));   // at most 1/1000 of the sweep's diagonal sqrt 5
  BOOST_TEST(eps >= Exact(1, 1000));         // poses at both ends at least: the diagonal 2
  // Also as one segment of a longer keyframe motion (a trajectory).
  const std::string two = R"({"format": "tmcert-scene/1", "bodies": [
    {"name": "bar", "segments": [[[0, 0, 0], [0, 1, 0]]],
     "motion": {"type": "keyframes", "interpolation": "nlerp",
                "poses": [{}, {"rotation": {"quaternion": [1, 1000000000, 0, 0]}},
                          {"rotation": {"quaternion": [1, 1000000000, 0, 0]}, "translation": [0, 0, "1/100"]}]}},
    {"name": "dot", "points": [[0, 0, 0]]}]})";
  const Scene scene2 = parse_scene_text(two, "nlerp2.json");
  BOOST_TEST(default_epsilon(body(scene2, "bar"), body(scene2, "dot")) <= Exact(2237, 1000000));
}

BOOST_AUTO_TEST_CASE(hints_never_suggest_an_epsilon_beyond_the_check) {
  // A given epsilon of 1e16 for a check whose bodies span 0.08: the hint
  // suggests the check's default (1/1000 of its box), not 1e15; a given
  // 0.05 gets its tenth, 0.005.
  const Scene scene = parse_scene_file(std::string(TMCERT_TEST_DATA) + "/scenes/far-triangle-keeps-check-epsilon.json");
  for (const auto& [given, want] : {std::pair{"1e16", "--epsilon 7.87401e-05"}, {"0.05", "--epsilon 0.005"}}) {
    VerifyOptions options;
    options.epsilon = q(given);
    const std::string text = result_summary(scene, verify_scene(scene, options));
    BOOST_TEST_CONTEXT("--epsilon " << given << ":\n" << text) {
      BOOST_TEST(text.find(want) != std::string::npos);
      BOOST_TEST(text.find("e+15") == std::string::npos);
    }
  }
}

// ------------------------------------------------------------------ 8: approximations

BOOST_AUTO_TEST_CASE(nearest_double_at_the_edges_of_the_range) {
  const double max = std::numeric_limits<double>::max(), tiny = std::numeric_limits<double>::denorm_min();
  BOOST_TEST(*nearest_double(Exact(0)) == 0.0);
  BOOST_TEST(*nearest_double(Exact(1, 10)) == 0.1);
  BOOST_TEST(*nearest_double(Exact(-1, 3)) == -1.0 / 3);
  BOOST_TEST(*nearest_double(Exact(max)) == max);
  Exact limit(1);
  mpq_mul_2exp(limit.mpq(), limit.mpq(), 1024);
  Exact half_ulp(1);
  mpq_mul_2exp(half_ulp.mpq(), half_ulp.mpq(), 970);
  limit -= half_ulp;  // halfway between the largest double and 2^1024
  BOOST_TEST(*nearest_double(limit - 1) == max);
  BOOST_TEST(!nearest_double(limit));   // the tie goes to infinity: beyond the range
  BOOST_TEST(!nearest_double(-limit));
  BOOST_TEST(!nearest_double(q("1e400")));
  BOOST_TEST(!nearest_double(q("1e-400")));
  BOOST_TEST(!nearest_double(Exact(tiny) / 2));  // the tie goes to 0 (even): beyond the range
  BOOST_TEST(*nearest_double(Exact(tiny) * Exact(3, 4)) == tiny);
  BOOST_TEST(*nearest_double(Exact(tiny) * 3 / 2) == 2 * tiny);  // a tie to the even one
  BOOST_TEST(*nearest_double(q("1e-320")) == 1e-320);
  // Ties between normal doubles: 1 + 2^-53 rounds to 1 (even), 1 + 3 2^-53 to 1 + 2^-51.
  Exact eps(1);
  mpq_div_2exp(eps.mpq(), eps.mpq(), 53);
  BOOST_TEST(*nearest_double(1 + eps) == 1.0);
  BOOST_TEST(*nearest_double(1 + 3 * eps) == 1.0 + std::ldexp(1.0, -51));
  // The old route through a 17-digit decimal can be off by one unit: the
  // value just above the midpoint between 1 and its successor.
  BOOST_TEST(*nearest_double(1 + eps + eps * eps) == 1.0 + std::ldexp(1.0, -52));
}

BOOST_AUTO_TEST_CASE(printed_approximations) {
  BOOST_TEST(approximation(Exact(1, 10)) == "0.1");
  BOOST_TEST(approximation(Exact(-3)) == "-3");
  BOOST_TEST(approximation(q("1e400")) == "1.0000000000000000e+400");
  BOOST_TEST(approximation(-q("2.5e-401")) == "-2.5000000000000000e-401");
  BOOST_TEST(approximation(Exact(2, 3) * q("1e-400")) == "6.6666666666666667e-401");
  BOOST_TEST(scientific(Exact(1, 3), 17) == "3.3333333333333333e-01");
  BOOST_TEST(approximation(q("1e-320")) == "1e-320");
}

BOOST_AUTO_TEST_CASE(algebraic_approximations_are_the_nearest_double_or_17_digits) {
  // sqrt(2) 10^-22 (a root far below the width an absolute refinement
  // stops at), sqrt(2), -sqrt(3) 10^-20, and sqrt(2) 10^(+-400) beyond the
  // double range, each isolated in a wide interval first.
  struct Case {
    PolyZ poly;
    const char* lo;
    const char* hi;
    std::string want;
  };
  auto ten = [](int e) {
    Integer p;
    mpz_ui_pow_ui(p.mpz(), 10, static_cast<unsigned long>(e));
    return p;
  };
  const Mp r2 = sqrt(Mp(2)), r3 = sqrt(Mp(3));
  auto nearest = [](const Mp& x) { return shortest(mpfr_get_d(x.get(), MPFR_RNDN)); };
  const Case cases[] = {
      {{Integer(-2), Integer(0), ten(44)}, "0", "1", nearest(r2 / Mp(1e22))},
      {{Integer(-2), Integer(0), Integer(1)}, "1", "2", "1.4142135623730951"},
      {{Integer(-3), Integer(0), ten(40)}, "-1", "0", nearest(-r3 / Mp(1e20))},
      {{-2 * ten(800), Integer(0), Integer(1)}, "0", "1e401", "1.4142135623730950e+400"},
      {{Integer(-2), Integer(0), ten(800)}, "0", "1", "1.4142135623730950e-400"},
      {{Integer(-2), Integer(0), ten(800)}, "-1", "0", "-1.4142135623730950e-400"},
  };
  for (const Case& c : cases) {
    const std::vector<RealRoot> roots = real_roots(c.poly, q(c.lo), q(c.hi));
    BOOST_REQUIRE(roots.size() == 1u);
    BOOST_TEST(approximate(roots[0]) == c.want);
  }
  // Six digits rounded from the root itself: sqrt(2) = 1.41421|356...
  const std::vector<RealRoot> r = real_roots(PolyZ{Integer(-2), Integer(0), Integer(1)}, Exact(1), Exact(2));
  BOOST_TEST(approximate_decimal(r[0]) == "1.41421");
  const std::vector<RealRoot> t = real_roots(PolyZ{Integer(-2), Integer(0), ten(44)}, Exact(0), Exact(1));
  BOOST_TEST(approximate_decimal(t[0]) == "1.41421e-22");
}

BOOST_AUTO_TEST_SUITE_END()
