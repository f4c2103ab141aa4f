// The default epsilon is per check (issue 15): 1/1000 of the box of the
// check's own two bodies, so that a body far away elsewhere in the scene
// does not coarsen a check it is not part of.
#include "src/io/parse.h"
#include "src/verify/verify.h"

#include <boost/test/unit_test.hpp>

#include <string>

using namespace tmcert;

namespace {

const std::string kScene = std::string(TMCERT_TEST_DATA) + "/scenes/far-triangle-keeps-check-epsilon.json";

int body_index(const Scene& scene, const std::string& name) {
  for (std::size_t i = 0; i < scene.bodies.size(); ++i)
    if (scene.bodies[i].name == name) return static_cast<int>(i);
  BOOST_FAIL("no body " << name);
  return -1;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(default_epsilon_per_check)

BOOST_AUTO_TEST_CASE(each_check_uses_the_box_of_its_two_bodies) {
  const Scene scene = parse_scene_file(kScene);
  BOOST_REQUIRE(!scene.epsilon);
  const int plate = body_index(scene, "plate"), probe = body_index(scene, "probe"), marker = body_index(scene, "marker");
  // The plate and its rim span (0..0.06, 0..0.05, 0..0.01), the probe stays
  // inside that in x and y: the diagonal is sqrt(0.0061) (the end keyframe
  // turns the probe by 90 degrees about z, within the box too).
  Exact expected;
  BOOST_REQUIRE(parse_exact("0.0000787401", expected));
  BOOST_TEST(default_epsilon(scene.bodies[plate], scene.bodies[probe]) == expected);
  // The marker 50 m away makes the scene's box 1000 times larger.
  BOOST_TEST(default_epsilon(scene) == Exact(501001, 10000000));

  VerifyOptions options;  // no epsilon: per check
  const SceneResult r = verify_scene(scene, options);
  BOOST_TEST(r.epsilon_per_check);
  BOOST_REQUIRE(r.checks.size() == 2u);
  for (const CheckResult& c : r.checks)
    BOOST_TEST(c.epsilon == default_epsilon(scene.bodies[c.bodies[0]], scene.bodies[c.bodies[1]]));
  // The scene's epsilon is the largest of the checks' own.
  BOOST_TEST(r.epsilon == std::max(r.checks[0].epsilon, r.checks[1].epsilon));
  const CheckResult& near = r.checks[0].bodies[1] == marker || r.checks[0].bodies[0] == marker ? r.checks[1] : r.checks[0];
  // 0.3 mm of clearance against about 0.08 mm of epsilon: safe.
  BOOST_TEST(near.verdict == Verdict::Safe);
  BOOST_TEST(r.verdict == Verdict::Safe);

  // The old rule, the scene's box for every check, leaves that check
  // undecided: the per-check value is what decides it.
  VerifyOptions scene_wide;
  scene_wide.epsilon = default_epsilon(scene);
  const SceneResult old = verify_scene(scene, scene_wide);
  BOOST_TEST(!old.epsilon_per_check);
  BOOST_TEST(old.verdict == Verdict::Undecided);
  for (const CheckResult& c : old.checks) BOOST_TEST(c.epsilon == *scene_wide.epsilon);
}

BOOST_AUTO_TEST_CASE(a_given_epsilon_applies_to_every_check) {
  Scene scene = parse_scene_file(kScene);
  scene.epsilon = Exact(1, 100000);
  VerifyOptions options;
  options.epsilon = scene.epsilon;
  const SceneResult r = verify_scene(scene, options);
  BOOST_TEST(!r.epsilon_per_check);
  BOOST_TEST(r.epsilon == Exact(1, 100000));
  for (const CheckResult& c : r.checks) BOOST_TEST(c.epsilon == Exact(1, 100000));
}

BOOST_AUTO_TEST_SUITE_END()
