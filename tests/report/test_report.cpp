// src/report/report.cpp, the human summary: decimals beside exact numbers, the
// contact point, and every undecided interval with its reason and a hint
// that fits the reason (docs/scene-format.md, "Human summary").
#include "src/report/report.h"

#include <boost/test/unit_test.hpp>

#include <string>

using tmcert::CheckResult;
using tmcert::Exact;
using tmcert::SceneResult;
using tmcert::StopReason;
using tmcert::Verdict;

namespace {

tmcert::Scene two_bodies() {
  tmcert::Scene scene;
  for (const char* name : {"a", "b"}) {
    tmcert::Body b;
    b.name = name;
    scene.bodies.push_back(b);
  }
  return scene;
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

BOOST_AUTO_TEST_SUITE(report)

BOOST_AUTO_TEST_CASE(collision_with_its_point_in_decimals_and_exactly) {
  const tmcert::Scene scene = two_bodies();
  SceneResult r;
  r.verdict = Verdict::Collision;
  r.epsilon = Exact(1, 1000);
  CheckResult c;
  c.bodies = {0, 1};
  c.verdict = Verdict::Collision;
  c.epsilon = r.epsilon;
  c.witness = tmcert::Witness{Exact(8471, 4096), {"a polygon 0", "b point 2"}, {Exact(1, 2), Exact(1, 3), Exact(0)}};
  c.first_contact = std::make_pair(Exact(8471, 4096), Exact(8471, 4096));
  c.first_contact_exact = true;
  r.checks.push_back(c);
  const std::string s = tmcert::result_summary(scene, r);
  BOOST_TEST(has(s, "tmcert: collision  [kernel filtered, epsilon 0.001]\n"), s);
  BOOST_TEST(has(s, "  a x b: collision at t = 2.06812 (8471/4096), the exact first contact  ("), s);
  BOOST_TEST(has(s, "    contact: a polygon 0 meets b point 2 at (0.5, 0.333333, 0), exactly (1/2, 1/3, 0)\n"), s);
}

BOOST_AUTO_TEST_CASE(undecided_intervals_with_their_hints) {
  const tmcert::Scene scene = two_bodies();
  SceneResult r;
  r.verdict = Verdict::Undecided;
  r.epsilon_per_check = true;
  r.max_depth = 40;
  r.max_nodes = 1000;
  r.max_stops = 4;
  r.time_limit = 2.5;
  CheckResult c;
  c.bodies = {0, 1};
  c.verdict = Verdict::Undecided;
  c.epsilon = Exact(3, 1000);
  c.stats.nodes = 5;  // it searched (none: its start was what stayed undecided)
  c.first_contact = std::make_pair(Exact(1, 4), Exact(5, 16));
  // Two adjacent epsilon stops (merged into one line), a depth stop, and
  // the rest cut by the time limit.
  c.undecided = {{Exact(1, 4), Exact(9, 32), StopReason::Epsilon},
                 {Exact(9, 32), Exact(5, 16), StopReason::Epsilon},
                 {Exact(1, 2), Exact(17, 32), StopReason::Depth},
                 {Exact(3, 4), Exact(1), StopReason::Limit}};
  r.checks.push_back(c);
  std::string s = tmcert::result_summary(scene, r);
  BOOST_TEST(has(s, "epsilon per check: 1/1000 of its bodies' box]"), s);
  BOOST_TEST(has(s, "  a x b: undecided; no contact before t = 0.25  (epsilon 0.003, "), s);
  BOOST_TEST(has(s, "    undecided t in [0.25, 0.3125] (epsilon): the bodies come within about epsilon (0.003) there; "
                    "try a smaller --epsilon, e.g. --epsilon 0.0003, or --epsilon auto\n"), s);
  BOOST_TEST(has(s, "    undecided t in [0.5, 0.53125] (depth): the subdivision reached its depth limit (40); try --max-depth 62\n"), s);
  BOOST_TEST(has(s, "    undecided t in [0.75, 1] (limit): the check's time limit (2.5 s) ran out before this part was "
                    "searched; try a larger --time-limit\n"), s);

  // The limit reason names the budget that ran out.
  r.checks[0].stats.stops = 4;
  s = tmcert::result_summary(scene, r);
  BOOST_TEST(has(s, "(limit): the stop budget (4 undecided pieces) was used up"), s);
  r.checks[0].stats.stops = 0;
  r.checks[0].stats.nodes = 1000;
  s = tmcert::result_summary(scene, r);
  BOOST_TEST(has(s, "(limit): the node budget (1000 nodes per check) was used up"), s);
  r.max_depth = 62;
  s = tmcert::result_summary(scene, r);
  BOOST_TEST(has(s, "(depth): the subdivision reached its finest depth (62)"), s);

  // At most five lines of intervals, then their count.
  r.checks[0].undecided.clear();
  for (int k = 0; k < 8; ++k)
    r.checks[0].undecided.push_back({Exact(2 * k, 16), Exact(2 * k + 1, 16), StopReason::Epsilon});
  s = tmcert::result_summary(scene, r);
  BOOST_TEST(has(s, "undecided t in [0.5, 0.5625] (epsilon)"), s);
  BOOST_TEST(!has(s, "undecided t in [0.625, 0.6875]"), s);
  BOOST_TEST(has(s, "    ... and 3 more undecided intervals (--json lists them all)\n"), s);
}

// Hints that lead somewhere (issue 23 item 7): no smaller epsilon where it
// cannot help.
BOOST_AUTO_TEST_CASE(no_smaller_epsilon_where_it_cannot_help) {
  const tmcert::Scene scene = two_bodies();
  SceneResult r;
  r.verdict = Verdict::Undecided;
  r.epsilon_per_check = true;
  r.refine = true;
  r.max_depth = 40;
  r.max_nodes = 1000;
  r.max_stops = 4;
  r.time_limit = 30;  // with refinement, none given
  CheckResult c;
  c.bodies = {0, 1};
  c.verdict = Verdict::Undecided;
  c.epsilon = Exact(1, 1000000000);  // the floor: the default (1/1000 here) / 10^6
  c.refined = true;
  c.refine_exhausted = true;
  c.stats.nodes = 50;
  c.first_contact = std::make_pair(Exact(1, 4), Exact(5, 16));
  c.undecided = {{Exact(1, 4), Exact(5, 16), StopReason::Epsilon}};
  r.checks.push_back(c);
  // Refinement reached its floor.
  std::string s = tmcert::result_summary(scene, r);
  BOOST_TEST(has(s, "epsilon per check: 1/1000 of its bodies' box, refined]"), s);
  BOOST_TEST(has(s, " (refined), 50 nodes"), s);
  BOOST_TEST(has(s, "even at the refinement's floor"), s);
  BOOST_TEST(!has(s, "try a smaller --epsilon"), s);
  // The stop budget at the floor.
  r.checks[0].undecided = {{Exact(1, 4), Exact(1), StopReason::Limit}};
  r.checks[0].stats.stops = 4;
  s = tmcert::result_summary(scene, r);
  BOOST_TEST(has(s, "was used up even at the refinement's floor"), s);
  BOOST_TEST(!has(s, "try a smaller --epsilon"), s);
  // Out of time: a larger time limit.
  r.checks[0].refine_exhausted = false;
  r.checks[0].refine_out_of_time = true;
  s = tmcert::result_summary(scene, r);
  BOOST_TEST(has(s, "(limit): the check's time limit (30 s) ran out before this part was searched; try a larger "
                    "--time-limit\n"), s);
  BOOST_TEST(!has(s, "try a smaller --epsilon"), s);
  // Undecided without a single node (its start), a given epsilon: no
  // smaller epsilon either.
  r.refine = false;
  r.checks[0].refined = r.checks[0].refine_out_of_time = false;
  r.checks[0].stats.nodes = 0;
  r.checks[0].stats.stops = 0;
  r.checks[0].undecided = {{Exact(0), Exact(1), StopReason::Epsilon}};
  s = tmcert::result_summary(scene, r);
  BOOST_TEST(has(s, "the start configuration could not be proven free"), s);
  BOOST_TEST(!has(s, "try a smaller --epsilon"), s);
}

// Each hint true (issue 23 item 7): a larger --time-limit where time cut
// the check short, a smaller epsilon only above the refinement's floor and
// where refinement did not already go down to it.  (The two bodies here
// have no geometry: their default epsilon is 1/1000, the floor 1e-9.)
BOOST_AUTO_TEST_CASE(hints_name_the_lever_that_can_decide) {
  const tmcert::Scene scene = two_bodies();
  SceneResult r;
  r.verdict = Verdict::Undecided;
  r.epsilon_per_check = true;
  r.refine = true;
  r.max_depth = 40;
  r.max_nodes = 1000;
  r.max_stops = 4;
  r.time_limit = 30;  // the default with refinement, not given
  CheckResult c;
  c.bodies = {0, 1};
  c.verdict = Verdict::Undecided;
  c.epsilon = Exact(1, 1000);
  c.stats.nodes = 50;
  c.first_contact = std::make_pair(Exact(1, 4), Exact(5, 16));
  // The first search at the default epsilon ran out of time: refinement
  // never began.
  c.refine_out_of_time = true;
  c.undecided = {{Exact(1, 4), Exact(5, 16), StopReason::Epsilon}, {Exact(1, 2), Exact(1), StopReason::Limit}};
  r.checks.push_back(c);
  std::string s = tmcert::result_summary(scene, r);
  BOOST_TEST(has(s, "(epsilon): the bodies come within about epsilon (0.001) there; refinement could not search it "
                    "again: the check's time limit (30 s) ran out; try a larger "
                    "--time-limit\n"), s);
  BOOST_TEST(has(s, "(limit): the check's time limit (30 s) ran out before this part "
                    "was searched; try a larger --time-limit\n"), s);
  BOOST_TEST(!has(s, "refinement stopped"), s);
  BOOST_TEST(!has(s, "smaller --epsilon"), s);
  // Refinement ran out of time at a smaller epsilon.
  r.checks[0].refined = true;
  r.checks[0].epsilon = Exact(1, 100000);
  s = tmcert::result_summary(scene, r);
  BOOST_TEST(has(s, "(epsilon): the bodies come within about epsilon (1e-05) there; refinement stopped at it when "
                    "the check's time limit (30 s) ran out"), s);
  BOOST_TEST(!has(s, "smaller --epsilon"), s);
  // A limit from the node budget while time was left is not the time limit.
  r.checks[0].refine_out_of_time = false;
  r.checks[0].refine_exhausted = true;
  r.checks[0].stats.nodes = 1000;
  s = tmcert::result_summary(scene, r);
  BOOST_TEST(has(s, "(limit): the node budget (1000 nodes per check) was used up"), s);
  BOOST_TEST(!has(s, "--time-limit"), s);
  // Refinement stopped early (above its floor) because its parts' starts
  // stay undecided: not "at the floor", and no smaller epsilon.
  r.checks[0].stats.nodes = 50;
  r.checks[0].undecided = {{Exact(1, 4), Exact(5, 16), StopReason::Epsilon}};
  s = tmcert::result_summary(scene, r);
  BOOST_TEST(has(s, "searching it again at a smaller epsilon could not begin"), s);
  BOOST_TEST(!has(s, "floor"), s);
  BOOST_TEST(!has(s, "smaller --epsilon"), s);
  // after_undecided: refinement at its floor, or out of time.
  r.checks[0].epsilon = Exact(1, 1000000000);  // the floor
  r.checks[0].undecided = {{Exact(1, 4), Exact(5, 16), StopReason::Epsilon},
                           {Exact(5, 16), Exact(1, 2), StopReason::AfterUndecided}};
  s = tmcert::result_summary(scene, r);
  BOOST_TEST(has(s, "(after_undecided): not claimed:"), s);
  BOOST_TEST(has(s, "refinement reached its floor without deciding it"), s);
  BOOST_TEST(!has(s, "smaller --epsilon"), s);
  r.checks[0].refine_exhausted = false;
  r.checks[0].refine_out_of_time = true;
  s = tmcert::result_summary(scene, r);
  BOOST_TEST(has(s, "(after_undecided): not claimed:"), s);
  BOOST_TEST(!has(s, "smaller --epsilon"), s);
  BOOST_TEST(has(s, "try a larger --time-limit"), s);

  // A given epsilon, no refinement, no time limit.
  r.refine = false;
  r.time_limit = 0;
  r.checks[0] = c;
  r.checks[0].refine_out_of_time = false;
  // At the floor already (1e-9 of the check's box): no smaller epsilon,
  // for every reason that would suggest one.
  r.checks[0].epsilon = Exact(1, 1000000000);
  r.checks[0].stats.stops = 4;
  r.checks[0].undecided = {{Exact(1, 4), Exact(5, 16), StopReason::Epsilon},
                           {Exact(5, 16), Exact(1, 2), StopReason::AfterUndecided},
                           {Exact(1, 2), Exact(1), StopReason::Limit}};
  s = tmcert::result_summary(scene, r);
  BOOST_TEST(has(s, "(epsilon): the bodies come within about epsilon there; epsilon (1e-09) is already at or "
                    "below the refinement's floor (1e-9 of the check's box): the bodies touch or nearly touch there\n"),
             s);
  BOOST_TEST(has(s, "(limit): the stop budget (4 undecided pieces) was used up"), s);
  BOOST_TEST(!has(s, "smaller --epsilon"), s);
  // Just above it: a tenth, but not below the floor.
  r.checks[0].epsilon = Exact(3, 1000000000);
  s = tmcert::result_summary(scene, r);
  BOOST_TEST(has(s, "(epsilon): the bodies come within about epsilon (3e-09) there; try a smaller --epsilon, "
                    "e.g. --epsilon 1e-09, or --epsilon auto\n"), s);
  BOOST_TEST(has(s, "(after_undecided): not claimed:"), s);
  BOOST_TEST(has(s, "e.g. --epsilon 1e-09, or --epsilon auto"), s);
}

BOOST_AUTO_TEST_CASE(a_toleranced_undecided_check_notes_the_band_no_lever_decides) {
  tmcert::Scene scene = two_bodies();
  SceneResult r;
  r.verdict = Verdict::Undecided;
  r.epsilon_per_check = true;
  r.refine = true;
  r.time_limit = 30;
  CheckResult c;
  c.bodies = {0, 1};
  c.verdict = Verdict::Undecided;
  c.epsilon = Exact(1, 1000);
  c.stats.nodes = 50;
  c.first_contact = std::make_pair(Exact(1, 4), Exact(5, 16));
  c.undecided = {{Exact(1, 4), Exact(5, 16), StopReason::Epsilon}};
  r.checks.push_back(c);
  const std::string note = "    note: b has a tolerance: a part where only an admissible affine deviation beyond the "
                           "reach of a translation could touch stays undecided at every epsilon and time limit";
  // Without a tolerance: no such note.
  BOOST_TEST(!has(tmcert::result_summary(scene, r), "has a tolerance"));
  scene.bodies[1].tolerance = Exact(1, 10);
  BOOST_TEST(has(tmcert::result_summary(scene, r), note), tmcert::result_summary(scene, r));
  // Decided checks need no note.
  r.checks[0].verdict = Verdict::Safe;
  r.checks[0].undecided.clear();
  BOOST_TEST(!has(tmcert::result_summary(scene, r), "has a tolerance"));
}

BOOST_AUTO_TEST_SUITE_END()
