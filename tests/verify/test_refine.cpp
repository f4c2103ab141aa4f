// Refinement by default (issue 23; SCENE_FORMAT.md "Decisive by default";
// proofs/refinement.md): without a given epsilon, the undecided parts of a
// check are searched again at epsilon/10, ... down to epsilon/10^6.
#include "src/certificate/check.h"
#include "src/certificate/writer.h"
#include "src/io/parse.h"
#include "src/verify/fixed_environment.h"
#include "src/verify/verify.h"

#include <boost/test/unit_test.hpp>
#include <nlohmann/json.hpp>

#include <string>

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
