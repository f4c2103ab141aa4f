// The partition of a check's interval (SCENE_FORMAT.md, "Every interval
// claim holds"; proofs/partition.md): every part the result leaves cleared
// (neither undecided nor at or after the witness) is free of contact.  The
// scenes of issue 21, finding 1: a point entering a solid after an undecided
// stop at an enclosed pose, at a keyframe join, with two moving bodies; and
// finding 2: the witness ends the claims ("not_searched").
#include "src/certificate/check.h"
#include "src/certificate/writer.h"
#include "src/report/report.h"
#include "src/io/parse.h"
#include "src/verify/verify.h"

#include <boost/test/unit_test.hpp>
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace {

using namespace tmcert;

std::string scene_path(const std::string& name) { return std::string(TMCERT_TEST_DATA) + "/scenes/" + name; }

SceneResult verified(const Scene& scene, int threads = 1) {
  VerifyOptions options;
  if (scene.epsilon) options.epsilon = *scene.epsilon;
  options.max_depth = scene.max_depth;
  options.threads = threads;
  return verify_scene(scene, options);
}

// The result claims t cleared: t is before the witness (if any) and in no
// undecided interval.
bool claimed_cleared(const CheckResult& r, const Exact& t) {
  if (r.witness && t >= r.witness->t) return false;
  for (const UndecidedInterval& u : r.undecided)
    if (u.t0 <= t && t <= u.t1) return false;
  return true;
}

bool has_reason(const CheckResult& r, StopReason reason) {
  for (const UndecidedInterval& u : r.undecided)
    if (u.reason == reason) return true;
  return false;
}

// Nothing in [from, 1] is claimed cleared (checked at 64 instants and 1).
void nothing_cleared_after(const CheckResult& r, const Exact& from) {
  for (int k = 0; k <= 64; ++k) {
    const Exact t = from + (Exact(1) - from) * Exact(k, 64);
    BOOST_TEST(!claimed_cleared(r, t), "t = " << to_string(t) << " is claimed cleared");
  }
}

}  // namespace

BOOST_AUTO_TEST_SUITE(partition)

// The point is inside the solid cube for every t in (2/3, 1]; the crossing
// at t = 2/3 happens at an enclosed (rpy keyframe) pose, where it cannot be
// proven: the search stops undecided around 2/3, and after it no contact
// begins.  Before the fix [171/256, 1] was certified free.
BOOST_AUTO_TEST_CASE(point_inside_a_solid_after_an_enclosed_stop_is_not_cleared) {
  const Scene scene = parse_scene_file(scene_path("solid-entered-after-undecided-rpy.json"));
  const SceneResult r = verified(scene);
  BOOST_REQUIRE_EQUAL(r.checks.size(), 1u);
  const CheckResult& c = r.checks[0];
  BOOST_TEST(c.verdict != Verdict::Safe);
  nothing_cleared_after(c, Exact(2, 3) + Exact(1, 1000000));
  BOOST_TEST(has_reason(c, StopReason::AfterUndecided));
  // What comes before the stop stays certified.
  BOOST_TEST(claimed_cleared(c, Exact(1, 2)));
  // The search's merge does not depend on the thread count.
  const SceneResult r4 = verified(scene, 4);
  const CheckResult& c4 = r4.checks[0];
  BOOST_REQUIRE_EQUAL(c4.undecided.size(), c.undecided.size());
  for (std::size_t k = 0; k < c.undecided.size(); ++k) {
    BOOST_TEST(c4.undecided[k].t0 == c.undecided[k].t0);
    BOOST_TEST(c4.undecided[k].t1 == c.undecided[k].t1);
    BOOST_TEST(to_string(c4.undecided[k].reason) == to_string(c.undecided[k].reason));
  }
}

// The same point enters by t = 1/2 and rests inside, turning, until 1 (a
// second keyframe segment): the join's start test looked at the surfaces
// only, and [1/2, 1] was certified free.
BOOST_AUTO_TEST_CASE(a_join_after_an_undecided_part_tests_the_solids_inside) {
  const Scene scene = parse_scene_file(scene_path("solid-entered-after-undecided-join.json"));
  const SceneResult r = verified(scene);
  const CheckResult& c = r.checks[0];
  BOOST_TEST(c.verdict != Verdict::Safe);
  nothing_cleared_after(c, Exact(1, 3) + Exact(1, 1000000));
  BOOST_TEST(claimed_cleared(c, Exact(1, 4)));
}

// With an exact pose at the join (identity rotation), the start test of the
// part after it proves the point inside: a collision at t = 1/2.
BOOST_AUTO_TEST_CASE(a_join_with_an_exact_pose_inside_a_solid_is_a_collision) {
  const Scene scene = parse_scene_file(scene_path("solid-entered-join-exact-pose.json"));
  const SceneResult r = verified(scene);
  const CheckResult& c = r.checks[0];
  BOOST_TEST(c.verdict == Verdict::Collision);
  BOOST_REQUIRE(c.witness.has_value());
  BOOST_TEST(c.witness->t == Exact(1, 2));
  BOOST_TEST(c.witness->features[1] == "cube interior");
  BOOST_REQUIRE(c.first_contact.has_value());
  BOOST_TEST(c.first_contact->second == Exact(1, 2));
  BOOST_TEST(!c.first_contact_exact);  // something before it was left undecided
  nothing_cleared_after(c, Exact(1, 3) + Exact(1, 1000000));
}

// Two moving bodies (a solid box and a point, both turning by rpy
// keyframes): the point is inside the box from about t = 0.83 on.
BOOST_AUTO_TEST_CASE(two_moving_bodies_after_an_enclosed_stop) {
  const Scene scene = parse_scene_file(scene_path("solid-entered-two-moving-rpy.json"));
  const SceneResult r = verified(scene);
  const CheckResult& c = r.checks[0];
  BOOST_TEST(c.verdict != Verdict::Safe);
  nothing_cleared_after(c, Exact(84, 100));
  BOOST_TEST(claimed_cleared(c, Exact(1, 2)));
}

// The rational analogue: the crossing is found exactly, and after the
// witness nothing is claimed ("not_searched" up to the end).
BOOST_AUTO_TEST_CASE(rational_entry_is_an_exact_collision_and_ends_the_claims) {
  const Scene scene = parse_scene_file(scene_path("solid-entered-rational.json"));
  const SceneResult r = verified(scene);
  const CheckResult& c = r.checks[0];
  BOOST_TEST(c.verdict == Verdict::Collision);
  BOOST_REQUIRE(c.witness.has_value());
  BOOST_TEST(c.witness->t == Exact(2, 3));
  BOOST_TEST(c.interval.second == Exact(1));
  const nlohmann::json doc = nlohmann::json::parse(result_json(scene, r));
  const nlohmann::json& check = doc["checks"][0];
  BOOST_TEST(check["not_searched"] == nlohmann::json::array({"2/3", "1"}));
  BOOST_TEST(check["undecided"].empty());
}

// Finding 2: a collision found at a stop's witness candidate leaves the
// piece before the witness undecided (the first contact lies in it or at
// the witness), and nothing after the witness is claimed (bodies may
// separate again after it: examples/octagons-collision.json does at about
// t = 0.6685).
BOOST_AUTO_TEST_CASE(the_witness_ends_the_claims) {
  const Scene scene = parse_scene_file(std::string(TMCERT_TEST_DATA) + "/../../examples/planner-bar-slerp.json");
  const SceneResult r = verified(scene);
  const CheckResult& c = r.checks[0];
  BOOST_REQUIRE(c.verdict == Verdict::Collision);
  BOOST_REQUIRE(c.first_contact.has_value());
  // [first_contact.lo, witness) is undecided, not cleared.
  const Exact lo = c.first_contact->first, t = c.witness->t;
  BOOST_REQUIRE(lo < t);
  for (int k = 0; k < 16; ++k) BOOST_TEST(!claimed_cleared(c, lo + (t - lo) * Exact(k, 16)));
  const nlohmann::json doc = nlohmann::json::parse(result_json(scene, r));
  const nlohmann::json& check = doc["checks"][0];
  BOOST_TEST(check["not_searched"][0] == nlohmann::json(to_string(t)));
  BOOST_TEST(check["not_searched"][1] == nlohmann::json(to_string(c.interval.second)));
}

// Certificates: the pieces after an undecided interval are claimed with
// start claims at their run's start (exact poses).  Where that instant's
// pose is only enclosed, the writer leaves the run to the undecided
// intervals; the checker accepts the certificate either way.
BOOST_AUTO_TEST_CASE(certificates_claim_runs_after_undecided_intervals_only_with_start_claims) {
  {
    const Scene scene = parse_scene_file(scene_path("solid-clearance-undecided-then-clear.json"));
    VerifyOptions options;
    options.record_cover = true;
    const SceneResult r = verify_scene(scene, options);
    BOOST_REQUIRE(r.checks[0].verdict == Verdict::Undecided);
    const nlohmann::json cert = nlohmann::json::parse(certificate::certificate_json(scene, r));
    const nlohmann::json& c = cert["checks"][0];
    // A start claim at t0 and one where the run after the undecided interval starts.
    BOOST_REQUIRE_EQUAL(c["start"].size(), 2u);
    BOOST_TEST(c["start"][1]["t"] == nlohmann::json(to_string(r.checks[0].undecided.back().t1)));
    BOOST_TEST(certificate::check_certificate(scene, cert, "cert").ok);
  }
  {
    const Scene scene = parse_scene_file(scene_path("solid-graze-enclosed-run-start.json"));
    VerifyOptions options;
    options.record_cover = true;
    const SceneResult r = verify_scene(scene, options);
    const CheckResult& c = r.checks[0];
    BOOST_REQUIRE(c.verdict == Verdict::Undecided);
    BOOST_REQUIRE(c.undecided.back().t1 < Exact(1));  // the verifier certifies the run after it
    const nlohmann::json cert = nlohmann::json::parse(certificate::certificate_json(scene, r));
    const nlohmann::json& u = cert["checks"][0]["undecided"];
    BOOST_TEST(u.back()[1] == nlohmann::json("1"));  // the certificate does not claim it
    BOOST_TEST(cert["checks"][0]["start"].size() == 1u);
    BOOST_TEST(certificate::check_certificate(scene, cert, "cert").ok);
  }
}

BOOST_AUTO_TEST_SUITE_END()
