// Refinement by default (issue 23; SCENE_FORMAT.md "Decisive by default";
// proofs/refinement.md): without a given epsilon, the undecided parts of a
// check are searched again at epsilon/10, ... down to epsilon/10^6.
#include "src/certificate/check.h"
#include "src/certificate/writer.h"
#include "src/io/parse.h"
#include "src/verify/fixed_environment.h"
#include "src/verify/refine.h"
#include "src/verify/verify.h"

#include <boost/test/unit_test.hpp>
#include <nlohmann/json.hpp>

#include <chrono>
#include <string>
#include <vector>

using namespace tmcert;

namespace {

Scene scene_named(const std::string& name) {
  return parse_scene_file(std::string(TMCERT_TEST_DATA) + "/scenes/" + name);
}

bool certificate_accepted(const Scene& scene, const SceneResult& r) {
  const nlohmann::json cert = nlohmann::json::parse(certificate::certificate_json(scene, r));
  return certificate::check_certificate(scene, cert, "certificate").ok;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(refinement)

BOOST_AUTO_TEST_CASE(a_slerp_pass_undecided_at_the_default_is_safe_refined) {
  const Scene scene = scene_named("decisive-slerp-pass-above.json");
  BOOST_REQUIRE(!scene.epsilon);
  const Exact start = default_epsilon(scene.bodies[0], scene.bodies[1]);
  BOOST_TEST(start > Exact(1, 200));  // above the true distance 0.005

  VerifyOptions fixed;  // the default epsilon as a fixed one: no refinement
  fixed.epsilon = start;
  const SceneResult old = verify_scene(scene, fixed);
  BOOST_REQUIRE(old.checks.size() == 1u);
  BOOST_TEST(old.verdict == Verdict::Undecided);
  BOOST_TEST(!old.checks[0].refined);
  BOOST_TEST(old.checks[0].epsilon == start);

  VerifyOptions refine;
  refine.refine = true;
  refine.record_cover = true;
  const SceneResult r = verify_scene(scene, refine);
  BOOST_TEST(r.verdict == Verdict::Safe);
  BOOST_TEST(r.refine);
  BOOST_TEST(r.checks[0].refined);
  BOOST_TEST(r.checks[0].epsilon < start);
  BOOST_TEST(r.checks[0].epsilon >= start / 1000000);
  BOOST_TEST(r.epsilon == r.checks[0].epsilon);
  BOOST_TEST(!r.checks[0].first_contact);
  // The certificate of the refined run passes the checker.
  BOOST_TEST(certificate_accepted(scene, r));
}

// A long grazing pass uses up the stop budget at the default epsilon, and
// the crossing after it is never searched; refinement searches the
// unsearched rest again and finds it.
BOOST_AUTO_TEST_CASE(a_crossing_after_a_grazing_pass_is_found_refined) {
  const Scene scene = scene_named("decisive-slerp-graze-then-cross.json");
  VerifyOptions fixed;
  fixed.epsilon = default_epsilon(scene.bodies[0], scene.bodies[1]);
  const SceneResult old = verify_scene(scene, fixed);
  BOOST_TEST(old.verdict == Verdict::Undecided);
  VerifyOptions refine;
  refine.refine = true;
  refine.record_cover = true;
  const SceneResult r = verify_scene(scene, refine);
  BOOST_TEST(r.verdict == Verdict::Collision);
  BOOST_TEST(r.checks[0].refined);
  BOOST_REQUIRE(r.checks[0].witness);
  BOOST_REQUIRE(r.checks[0].first_contact);
  // The segment pierces the triangle at x = 80 for t in [0.79999, 0.80001].
  BOOST_TEST(r.checks[0].witness->t >= Exact(79999, 100000));
  BOOST_TEST(r.checks[0].witness->t <= Exact(80001, 100000));
  // The bracket's lower end: nothing before it is claimed beyond what the
  // first search cleared from the start.
  BOOST_TEST(r.checks[0].first_contact->first >= old.checks[0].first_contact->first);
  BOOST_TEST(certificate_accepted(scene, r));
}

BOOST_AUTO_TEST_CASE(a_given_epsilon_is_not_refined) {
  Scene scene = scene_named("decisive-slerp-pass-above.json");
  VerifyOptions options;
  options.epsilon = Exact(1, 10);
  const SceneResult r = verify_scene(scene, options);
  BOOST_TEST(!r.refine);
  BOOST_TEST(r.verdict == Verdict::Undecided);
  BOOST_TEST(r.epsilon == Exact(1, 10));
  BOOST_TEST(r.checks[0].epsilon == Exact(1, 10));
  BOOST_TEST(!r.checks[0].refined);
}

// The engine of `tmcert batch` robots and of the OMPL adapter refines the
// same way as the verifier.
BOOST_AUTO_TEST_CASE(the_fixed_environment_refines_as_the_verifier) {
  const Scene scene = scene_named("decisive-slerp-pass-above.json");
  BOOST_REQUIRE(scene.bodies[1].trajectory);
  VerifyOptions options;
  options.epsilon = default_epsilon(scene.bodies[0], scene.bodies[1]);
  {
    const FixedEnvironment env(scene.bodies[0], {scene.bodies[1]}, {}, options);
    const MotionCheck got = env.check({*scene.bodies[1].trajectory});
    BOOST_TEST(got.verdict == Verdict::Undecided);
    BOOST_TEST(!got.checks[0].refined);
  }
  options.refine = true;
  const FixedEnvironment env(scene.bodies[0], {scene.bodies[1]}, {}, options);
  const MotionCheck got = env.check({*scene.bodies[1].trajectory});
  BOOST_TEST(got.verdict == Verdict::Safe);
  BOOST_REQUIRE(got.checks.size() == 1u);
  BOOST_TEST(got.checks[0].refined);
  BOOST_TEST(got.checks[0].epsilon < *options.epsilon);
}

BOOST_AUTO_TEST_SUITE_END()

// detail::refine_check itself (src/verify/refine.h), with a recorded
// search in place of the real one: which parts are searched again, at
// which epsilon, from a start proven free or not, and what the result
// becomes.
BOOST_AUTO_TEST_SUITE(refine_check_steps)

namespace {

struct Call {
  Exact t0, t1;
  bool start_free;
  Exact epsilon;
};

// A result of the whole check [0, 1] at epsilon 1/1000, undecided on [a, b].
CheckResult undecided_on(const Exact& a, const Exact& b) {
  CheckResult r;
  r.bodies = {0, 1};
  r.verdict = Verdict::Undecided;
  r.undecided.push_back({a, b, StopReason::Epsilon});
  r.first_contact = std::pair{a, b};
  return r;
}

VerifyOptions refining() {
  VerifyOptions o;
  o.epsilon = Exact(1, 1000);
  o.refine = true;
  return o;
}

// The search's answer on a window: safe, undecided (nodes visited or not)
// or a collision at its middle.
enum class Answer { Safe, Undecided, Stuck, Collision };

detail::WindowSearch recorded(std::vector<Call>& calls, Answer answer) {
  return [&calls, answer](const Exact& t0, const Exact& t1, bool start_free, const VerifyOptions& o) {
    calls.push_back({t0, t1, start_free, *o.epsilon});
    CheckResult part;
    part.stats.nodes = answer == Answer::Stuck ? 0 : 1;
    if (answer == Answer::Undecided || answer == Answer::Stuck) {
      part.undecided.push_back({t0, t1, StopReason::Epsilon});
      part.first_contact = std::pair{t0, t1};
    } else if (answer == Answer::Collision) {
      Witness w;
      w.t = (t0 + t1) / 2;
      w.features = {"a", "b"};
      w.point = {0, 0, 0};
      part.witness = w;
      part.first_contact = std::pair{w.t, w.t};
    }
    return part;
  };
}

}  // namespace

BOOST_AUTO_TEST_CASE(nothing_without_refine_or_when_decided) {
  std::vector<Call> calls;
  VerifyOptions o = refining();
  o.refine = false;
  CheckResult r = undecided_on(Exact(1, 4), Exact(1, 2));
  detail::refine_check(r, 0, 1, false, o, std::chrono::steady_clock::now(), recorded(calls, Answer::Safe));
  BOOST_TEST(calls.empty());
  BOOST_TEST((r.verdict == Verdict::Undecided));
  BOOST_TEST(r.epsilon == Exact(1, 1000));
  BOOST_TEST(!r.refined);
  CheckResult safe;
  safe.verdict = Verdict::Safe;
  detail::refine_check(safe, 0, 1, false, refining(), std::chrono::steady_clock::now(), recorded(calls, Answer::Safe));
  BOOST_TEST(calls.empty());
  BOOST_TEST((safe.verdict == Verdict::Safe));
}

BOOST_AUTO_TEST_CASE(undecided_part_searched_again_at_a_tenth) {
  std::vector<Call> calls;
  CheckResult r = undecided_on(Exact(1, 4), Exact(1, 2));
  detail::refine_check(r, 0, 1, false, refining(), std::chrono::steady_clock::now(), recorded(calls, Answer::Safe));
  BOOST_REQUIRE(calls.size() == 1u);
  BOOST_TEST(calls[0].t0 == Exact(1, 4));
  BOOST_TEST(calls[0].t1 == Exact(1, 2));
  BOOST_TEST(calls[0].start_free);  // everything before 1/4 was cleared from the tested start
  BOOST_TEST(calls[0].epsilon == Exact(1, 10000));
  BOOST_TEST((r.verdict == Verdict::Safe));
  BOOST_TEST(r.undecided.empty());
  BOOST_TEST(!r.first_contact);
  BOOST_TEST(r.refined);
  BOOST_TEST(r.epsilon == Exact(1, 10000));
  BOOST_TEST(!r.refine_exhausted);
  BOOST_TEST(!r.refine_out_of_time);
}

BOOST_AUTO_TEST_CASE(part_at_the_start_is_not_proven_free) {
  std::vector<Call> calls;
  CheckResult r = undecided_on(Exact(0), Exact(1, 2));
  detail::refine_check(r, 0, 1, false, refining(), std::chrono::steady_clock::now(), recorded(calls, Answer::Safe));
  BOOST_REQUIRE(calls.size() == 1u);
  BOOST_TEST(!calls[0].start_free);
}

BOOST_AUTO_TEST_CASE(down_to_the_floor_then_exhausted) {
  std::vector<Call> calls;
  CheckResult r = undecided_on(Exact(1, 4), Exact(1, 2));
  detail::refine_check(r, 0, 1, false, refining(), std::chrono::steady_clock::now(),
                       recorded(calls, Answer::Undecided));
  BOOST_REQUIRE(calls.size() == static_cast<std::size_t>(detail::kRefineLevels));
  Exact eps(1, 1000);
  for (const Call& c : calls) {
    eps /= 10;
    BOOST_TEST(c.epsilon == eps);
  }
  BOOST_TEST(eps == Exact(1, 1000000000));
  BOOST_TEST((r.verdict == Verdict::Undecided));
  BOOST_TEST(r.epsilon == eps);
  BOOST_TEST(r.refine_exhausted);
  BOOST_TEST(!r.refine_out_of_time);
  BOOST_REQUIRE(r.undecided.size() == 1u);
  BOOST_TEST(r.undecided[0].t0 == Exact(1, 4));
  BOOST_TEST(r.undecided[0].t1 == Exact(1, 2));
}

BOOST_AUTO_TEST_CASE(stuck_part_is_not_searched_again) {
  std::vector<Call> calls;
  CheckResult r = undecided_on(Exact(1, 4), Exact(1, 2));
  detail::refine_check(r, 0, 1, false, refining(), std::chrono::steady_clock::now(), recorded(calls, Answer::Stuck));
  BOOST_TEST(calls.size() == 1u);
  BOOST_TEST((r.verdict == Verdict::Undecided));
  BOOST_TEST(r.refine_exhausted);
}

BOOST_AUTO_TEST_CASE(dyadic_check_searches_aligned_pieces) {
  std::vector<Call> calls;
  CheckResult r = undecided_on(Exact(1, 4), Exact(3, 4));
  detail::refine_check(r, 0, 1, true, refining(), std::chrono::steady_clock::now(), recorded(calls, Answer::Safe));
  BOOST_REQUIRE(calls.size() == 2u);
  BOOST_TEST(calls[0].t0 == Exact(1, 4));
  BOOST_TEST(calls[0].t1 == Exact(1, 2));
  BOOST_TEST(calls[1].t0 == Exact(1, 2));
  BOOST_TEST(calls[1].t1 == Exact(3, 4));
  BOOST_TEST((r.verdict == Verdict::Safe));
}

BOOST_AUTO_TEST_CASE(witness_ends_the_refinement) {
  std::vector<Call> calls;
  CheckResult r = undecided_on(Exact(1, 4), Exact(1, 2));
  r.undecided.push_back({Exact(3, 4), Exact(1), StopReason::Epsilon});
  detail::refine_check(r, 0, 1, false, refining(), std::chrono::steady_clock::now(),
                       recorded(calls, Answer::Collision));
  BOOST_TEST(calls.size() == 1u);  // the second part is not searched after the witness
  BOOST_TEST((r.verdict == Verdict::Collision));
  BOOST_REQUIRE(r.witness);
  BOOST_TEST(r.witness->t == Exact(3, 8));
}

BOOST_AUTO_TEST_SUITE_END()
