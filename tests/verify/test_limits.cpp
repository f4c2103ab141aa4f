// Resource limits that fail honestly (docs/scene-format.md "Limits" and
// "--time-limit"): a check that runs past its time limit is undecided with
// reason "limit" on the part it did not search, never safe, and it returns
// promptly; and the interval arithmetic behind the filtered kernel keeps its
// rounding mode (also under the sanitizers of make test).
#include "kernels/number_types.h"
#include "src/io/parse.h"
#include "src/verify/refine.h"
#include "src/verify/verify.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/FPU.h>
#include <boost/test/unit_test.hpp>

#include <chrono>
#include <cmath>
#include <string>

using tmcert::Exact;
using tmcert::Interval;

namespace {

// A probe point that passes over a triangle at height 1/4: safe, and the
// search needs several nodes (a far wall of the fixed body keeps the
// swept-box prefilter from clearing the check at once).
const char* kProbe = R"({"format": "tmcert-scene/1", "epsilon": "1/1000",
  "bodies": [{"name": "tri", "polygons": [[[0,0,0],[4,0,0],[0,4,0]], [[20,0,0],[20,1,0],[20,0,5]]]},
             {"name": "p", "points": [[-1,1,"1/4"]], "segments": [[[-1,0,"1/4"],[-1,2,"1/2"]]],
              "motion": {"type": "rational_bezier", "control_points": [
                [[1,0,0,0],[0,1,0,0],[0,0,1,0]], [[1,0,0,2],[0,1,0,1],[0,0,1,0]],
                [[1,0,0,4],[0,1,0,0],[0,0,1,0]], [[1,0,0,6],[0,1,0,1],[0,0,1,0]],
                [[1,0,0,7],[0,1,0,0],[0,0,1,0]]]}}]})";

// The same pass as a keyframe motion (the path through general.cpp).
const char* kProbeKeyframes = R"({"format": "tmcert-scene/1", "epsilon": "1/1000",
  "bodies": [{"name": "tri", "polygons": [[[0,0,0],[4,0,0],[0,4,0]], [[20,0,0],[20,1,0],[20,0,5]]]},
             {"name": "p", "points": [[-1,1,"1/4"]],
              "motion": {"type": "keyframes", "times": [0, "1/3", "2/3", 1],
                         "poses": [{"translation": [0,0,0]}, {"translation": [2,0,0]},
                                   {"translation": [4,0,0]}, {"translation": [6,0,0], "rotation": {"quaternion": [10,0,0,1]}}]}}]})";

tmcert::SceneResult run(const tmcert::Scene& scene, double time_limit) {
  tmcert::VerifyOptions options;
  options.epsilon = *scene.epsilon;
  options.max_depth = scene.max_depth;
  options.time_limit = time_limit;
  return tmcert::verify_scene(scene, options);
}

// Every check undecided, with at least one "limit" interval, and no witness.
void require_limit(const tmcert::SceneResult& r) {
  BOOST_TEST(r.verdict == tmcert::Verdict::Undecided);
  for (const tmcert::CheckResult& c : r.checks) {
    BOOST_TEST(c.verdict == tmcert::Verdict::Undecided);
    BOOST_TEST(!c.witness);
    bool limit = false;
    for (const tmcert::UndecidedInterval& u : c.undecided) limit = limit || u.reason == tmcert::StopReason::Limit;
    BOOST_TEST(limit);
    BOOST_TEST(c.first_contact.has_value());
  }
}

}  // namespace

BOOST_AUTO_TEST_SUITE(limits)

BOOST_AUTO_TEST_CASE(time_limit_passed_is_undecided_never_safe) {
  for (const char* text : {kProbe, kProbeKeyframes}) {
    const tmcert::Scene scene = tmcert::parse_scene_text(text, "probe.json");
    // Without a limit: safe (so the test below can fail).
    BOOST_TEST(run(scene, 0).verdict == tmcert::Verdict::Safe);
    // A limit passed before the search starts: nothing is cleared.
    require_limit(run(scene, 1e-12));
  }
}

BOOST_AUTO_TEST_CASE(time_limit_returns_promptly) {
  // A point resting 1e-9..1e-7 above a slowly tilting triangle
  // (tests/verify/test_threads.cpp), searched by the ball search alone with
  // epsilon 1e-12 and no node or stop budget to speak of: every piece along
  // the rest stops at about epsilon, some 1e5 pieces and more (minutes to
  // hours).  With a time limit of 1/2 s it must come back at once,
  // undecided with the rest "limit".  The bound on the elapsed time is
  // generous (a loaded machine, sanitizers).
  const tmcert::Scene scene =
      tmcert::parse_scene_file(std::string(TMCERT_TEST_DATA) + "/scenes/resting-within-epsilon.json");
  tmcert::VerifyOptions options;
  options.epsilon = Exact(1, CGAL::Gmpz("1000000000000"));  // 1e-12 (a long long denominator would be cut to 32 bits)
  options.max_depth = 200;
  options.max_nodes = std::uint64_t(1) << 40;
  options.max_stops = std::uint64_t(1) << 40;
  options.exact_resolution = false;
  options.time_limit = 0.5;
  const auto start = std::chrono::steady_clock::now();
  const tmcert::SceneResult r = tmcert::verify_scene(scene, options);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  require_limit(r);
  BOOST_TEST(seconds < 30.0);
  BOOST_TEST(r.checks[0].stats.nodes > 0u);
  BOOST_TEST(std::string(tmcert::to_string(r.checks[0].undecided.back().reason)) == "limit");
}

// Refinement by default bounds the whole check, its first search at the
// starting epsilon included, by the default time limit when none is given
// (SCENE_FORMAT.md "Decisive by default"); a given epsilon has none.
BOOST_AUTO_TEST_CASE(default_time_limit_with_refinement_only) {
  tmcert::VerifyOptions options;
  BOOST_TEST(tmcert::detail::check_time_limit(options) == 0.0);  // a given epsilon: no limit
  BOOST_TEST((tmcert::detail::check_deadline(options, std::chrono::steady_clock::now()) ==
              std::chrono::steady_clock::time_point::max()));
  options.refine = true;
  BOOST_TEST(tmcert::detail::check_time_limit(options) == 30.0);
  BOOST_TEST(tmcert::detail::kDefaultTimeLimit == 30.0);
  const auto now = std::chrono::steady_clock::now();
  BOOST_TEST((tmcert::detail::check_deadline(options, now) == now + std::chrono::seconds(30)));
  options.time_limit = 2.5;  // a given limit wins
  BOOST_TEST(tmcert::detail::check_time_limit(options) == 2.5);
  options.refine = false;
  BOOST_TEST(tmcert::detail::check_time_limit(options) == 2.5);
}

BOOST_AUTO_TEST_CASE(default_time_limit_bounds_the_first_search) {
  // The search of time_limit_returns_promptly (hours without a limit), now
  // refined with no time limit given: the default limit (shortened to 1/2
  // s here) must stop its first search, the rest "limit"; when the default
  // bounded only the refinement, the first search ran on.
  const tmcert::Scene scene =
      tmcert::parse_scene_file(std::string(TMCERT_TEST_DATA) + "/scenes/resting-within-epsilon.json");
  tmcert::VerifyOptions options;
  options.epsilon = Exact(1, CGAL::Gmpz("1000000000000"));
  options.refine = true;
  options.max_depth = 200;
  options.max_nodes = std::uint64_t(1) << 40;
  options.max_stops = std::uint64_t(1) << 40;
  options.exact_resolution = false;
  tmcert::detail::set_default_time_limit_for_tests(0.5);
  const auto start = std::chrono::steady_clock::now();
  const tmcert::SceneResult r = tmcert::verify_scene(scene, options);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  tmcert::detail::set_default_time_limit_for_tests(0);
  require_limit(r);
  BOOST_TEST(seconds < 30.0);
  BOOST_TEST(r.time_limit == 0.5);  // what the report's hints name
  const tmcert::CheckResult& c = r.checks[0];
  BOOST_TEST(c.stats.nodes > 0u);
  BOOST_TEST(c.refine_out_of_time);  // the hint: a larger --time-limit
  BOOST_TEST(!c.refined);            // refinement never began
  BOOST_TEST(std::string(tmcert::to_string(c.undecided.back().reason)) == "limit");
}

BOOST_AUTO_TEST_CASE(interval_rounding_encloses) {
  // Interval arithmetic needs the FPU rounding upward inside RoundingGuard
  // (CGAL::Protect_FPU_rounding, -frounding-math) and restored after.
  const auto before = CGAL::FPU_get_cw();
  {
    tmcert::RoundingGuard guard;
    BOOST_TEST(CGAL::FPU_get_cw() == CGAL_FE_UPWARD);
    const Interval third = Interval(1) / Interval(3);
    BOOST_TEST(third.inf() < third.sup());
    BOOST_TEST(Exact(third.inf()) * 3 < Exact(1));
    BOOST_TEST(Exact(third.sup()) * 3 > Exact(1));
    const Interval root = CGAL::sqrt(Interval(2));
    BOOST_TEST(Exact(root.inf()) * Exact(root.inf()) < Exact(2));
    BOOST_TEST(Exact(root.sup()) * Exact(root.sup()) > Exact(2));
    // A sum whose double result rounds: 1 + 2^-60 is enclosed, not 1.
    const Interval sum = Interval(1) + Interval(std::ldexp(1.0, -60));
    BOOST_TEST(sum.inf() == 1.0);
    BOOST_TEST(sum.sup() > 1.0);
  }
  BOOST_TEST(CGAL::FPU_get_cw() == before);
}

BOOST_AUTO_TEST_CASE(cgal_filtered_predicate_exact_on_near_degenerate_input) {
  // Points collinear up to 1 ulp: plain double evaluation of the
  // orientation determinant gets the sign wrong or zero for many of them;
  // CGAL's filtered kernel (interval filter under the rounding guard, exact
  // fallback) must agree with exact rationals on every one.
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  int checked = 0;
  for (int i = 1; i <= 64; ++i) {
    const double x = 0.5 + i * std::ldexp(1.0, -53);
    const K::Point_2 p(0.5, 0.5), q(12, 12), r(24, 24), s(x, 0.5 + (i % 3 - 1) * std::ldexp(1.0, -53));
    for (const auto& pts : {std::array<K::Point_2, 3>{p, q, s}, std::array<K::Point_2, 3>{s, q, r}}) {
      const auto filtered = CGAL::orientation(pts[0], pts[1], pts[2]);
      const Exact ax(pts[0].x()), ay(pts[0].y()), bx(pts[1].x()), by(pts[1].y()), cx(pts[2].x()), cy(pts[2].y());
      const Exact det = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
      BOOST_TEST(static_cast<int>(filtered) == CGAL::sign(det));
      ++checked;
    }
  }
  BOOST_TEST(checked == 128);
}

BOOST_AUTO_TEST_SUITE_END()
