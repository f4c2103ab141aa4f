// Progress and cancellation of a run (src/verify/progress.h): a check's
// share stays below its unit until the check is done, so the fraction
// reaches 1 only at the end; a cancelled run never clears what it did not
// search, and verify_scene then gives no result.
#include "src/io/parse.h"
#include "src/verify/progress.h"
#include "src/verify/verify.h"

#include <boost/test/unit_test.hpp>

#include <chrono>
#include <string>
#include <thread>
#include <vector>

using tmcert::ProgressReport;
using tmcert::RunProgress;

namespace {

#ifdef TMCERT_TEST_DATA
const std::string kData = TMCERT_TEST_DATA;
#else
const std::string kData = "tests/data";
#endif

// Two plates hovering over each other (tests/data/scenes/hover-grid-10.json):
// safe after a search of some 1 600 nodes, not by the prefilter.
tmcert::Scene hover() { return tmcert::parse_scene_file(kData + "/scenes/hover-grid-10.json"); }

}  // namespace

BOOST_AUTO_TEST_SUITE(progress)

BOOST_AUTO_TEST_CASE(a_check_share_stays_below_its_unit_until_done) {
  RunProgress run;
  run.set_checks(2);
  {
    RunProgress::Slot first(run);
    first.add(RunProgress::kUnit / 2);
    first.add(RunProgress::kUnit);  // pieces searched again: clamped
    first.add(RunProgress::kUnit);
    const ProgressReport r = run.report();
    BOOST_TEST(r.fraction < 0.5);
    BOOST_TEST(r.checks_done == 0u);
  }  // the slot ends: its whole unit
  ProgressReport r = run.report();
  BOOST_TEST(r.fraction == 0.5);
  BOOST_TEST(r.checks_done == 1u);
  {
    RunProgress::Slot second(run);
    second.add(RunProgress::kUnit - 1);
    BOOST_TEST(run.report().fraction < 1.0);
    second.finish();
    second.finish();  // once only
  }
  r = run.report();
  BOOST_TEST(r.fraction == 1.0);
  BOOST_TEST(r.checks_done == 2u);
}

// A search adds its pieces' shares: after a check that needed a search,
// and before it is finished, its share is below its unit and above 0.
BOOST_AUTO_TEST_CASE(the_search_reports_its_pieces) {
  const tmcert::Scene scene = hover();
  const auto [a, b] = scene.checks.at(0);
  RunProgress run;
  run.count_other_items();  // Verifier::check leaves the slot set here alone
  run.set_checks(1);
  RunProgress::Slot slot(run);
  tmcert::VerifyOptions options;
  options.epsilon = scene.epsilon;
  options.run = &run;
  options.slot = &slot;
  options.slot_span = RunProgress::kUnit;
  const tmcert::CheckResult c = tmcert::verify_check(scene, a, b, options);
  BOOST_TEST(c.verdict == tmcert::Verdict::Safe);
  BOOST_TEST(!c.stats.prefiltered);
  const double f = run.report().fraction;
  BOOST_TEST(f > 0.0);
  BOOST_TEST(f < 1.0);
  BOOST_TEST(run.report().checks_done == 0u);
  slot.finish();
  BOOST_TEST(run.report().fraction == 1.0);
}

// A cancelled run: the check is not cleared (undecided, reason limit), and
// verify_scene throws Cancelled instead of giving a result.
BOOST_AUTO_TEST_CASE(a_cancelled_run_clears_nothing) {
  const tmcert::Scene scene = hover();
  const auto [a, b] = scene.checks.at(0);
  RunProgress run;
  run.cancel();
  tmcert::VerifyOptions options;
  options.epsilon = scene.epsilon;
  options.run = &run;
  const tmcert::CheckResult c = tmcert::Verifier(scene, options).check(a, b);
  BOOST_TEST(c.verdict == tmcert::Verdict::Undecided);
  BOOST_REQUIRE(!c.undecided.empty());
  BOOST_TEST((c.undecided.front().reason == tmcert::StopReason::Limit));
  BOOST_CHECK_THROW(tmcert::verify_scene(scene, options), tmcert::Cancelled);
  // Without the cancellation: safe, every check done, fraction 1, and the
  // activity names the check.
  RunProgress fresh;
  options.run = &fresh;
  const tmcert::SceneResult r = tmcert::verify_scene(scene, options);
  BOOST_TEST(r.verdict == tmcert::Verdict::Safe);
  const ProgressReport report = fresh.report();
  BOOST_TEST(report.fraction == 1.0);
  BOOST_TEST(report.checks_done == 1u);
  BOOST_TEST(report.activity == "checking fixed x moving");
}

// The watcher calls back at its rate until it is destroyed; false cancels.
BOOST_AUTO_TEST_CASE(the_watcher_calls_back_and_cancels) {
  RunProgress run;
  int calls = 0;
  {
    tmcert::ProgressWatcher watcher(run, [&](const ProgressReport&) { return ++calls < 3; }, 0.001);
    while (!run.cancelled()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  BOOST_TEST(calls >= 3);
  const int after = calls;
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  BOOST_TEST(calls == after);  // none after the watcher is gone
}

BOOST_AUTO_TEST_SUITE_END()
