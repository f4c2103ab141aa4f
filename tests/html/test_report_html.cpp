// src/html/report_html: the page's timeline partitions each check's
// interval exactly as the result does (data-t0 / data-t1 are the result's
// exact rationals): certified safe, undecided with its reason, and after a
// collision's witness "not searched"; names are HTML-escaped; the page is
// one self-contained document.
#include "src/html/report_html.h"
#include "src/verify/verify.h"
#include "tests/verify/check_testing.h"

#include <boost/test/unit_test.hpp>

#include <string>

using namespace tmcert;
using tmcert::testing::two_cubes;

namespace {

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

std::string span(const std::string& kind, const std::string& t0, const std::string& t1) {
  return "data-kind=\"" + kind + "\" data-t0=\"" + t0 + "\" data-t1=\"" + t1 + "\"";
}

SceneResult verified(const Scene& scene) {
  VerifyOptions options;
  options.epsilon = Exact(1, 1000);
  return verify_scene(scene, options);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(report_html_page)

BOOST_AUTO_TEST_CASE(collision_timeline_ends_the_claims_at_the_witness) {
  // The mover's face x = -1/2 + (-3 + 6t) reaches the post's face x = -1/2 at t = 1/3.
  Scene scene = two_cubes("-3 0 0", "3 0 0");
  scene.bodies[0].name = "m<o>v&\"er\"";
  const SceneResult r = verified(scene);
  BOOST_REQUIRE(r.verdict == Verdict::Collision);
  const std::string page = report_html(scene, r);
  BOOST_TEST(page.rfind("<!DOCTYPE html>", 0) == 0u);
  BOOST_TEST(has(page, "</html>\n"));
  BOOST_TEST(has(page, "data-verdict=\"collision\""));
  BOOST_TEST(has(page, "<div class=\"bar\" data-t0=\"0\" data-t1=\"1\">"));
  BOOST_TEST(has(page, span("safe", "0", "1/3")));
  BOOST_TEST(has(page, span("not-searched", "1/3", "1")));
  BOOST_TEST(!has(page, "data-kind=\"undecided\""));
  BOOST_TEST(has(page, "data-body-a=\"m&lt;o&gt;v&amp;&quot;er&quot;\""));
  BOOST_TEST(has(page, "<b>m&lt;o&gt;v&amp;&quot;er&quot;</b>"));
}

BOOST_AUTO_TEST_CASE(safe_timeline_covers_the_interval) {
  const Scene scene = two_cubes("-3 3 0", "3 3 0");
  const SceneResult r = verified(scene);
  BOOST_REQUIRE(r.verdict == Verdict::Safe);
  const std::string page = report_html(scene, r);
  BOOST_TEST(has(page, "data-verdict=\"safe\""));
  BOOST_TEST(has(page, span("safe", "0", "1")));
  BOOST_TEST(!has(page, "data-kind=\"not-searched\""));
}

BOOST_AUTO_TEST_CASE(undecided_intervals_keep_their_exact_ends_and_reason) {
  const Scene scene = two_cubes("-3 3 0", "3 3 0");
  SceneResult r = verified(scene);
  BOOST_REQUIRE(r.checks.size() == 1u);
  r.verdict = Verdict::Undecided;
  CheckResult& c = r.checks[0];
  c.verdict = Verdict::Undecided;
  UndecidedInterval u;
  u.t0 = Exact(1, 7);
  u.t1 = Exact(2, 7);
  u.reason = StopReason::Epsilon;
  c.undecided.push_back(u);
  const std::string page = report_html(scene, r);
  BOOST_TEST(has(page, span("safe", "0", "1/7")));
  BOOST_TEST(has(page, span("undecided", "1/7", "2/7") + " data-reason=\"epsilon\""));
  BOOST_TEST(has(page, span("safe", "2/7", "1")));
}

BOOST_AUTO_TEST_SUITE_END()
