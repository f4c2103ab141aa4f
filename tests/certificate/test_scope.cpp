// src/certificate/scope.h: a check's parameter interval, and which scenes
// certificates cover.
#include "src/certificate/scope.h"

#include <boost/test/unit_test.hpp>

using namespace tmcert;
using tmcert::certificate::check_interval;
using tmcert::certificate::uncertifiable;

namespace {

const Mat34E kIdentity{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};

Motion motion_over(Exact t0, Exact t1, int points) {
  Motion m;
  m.t0 = t0;
  m.t1 = t1;
  for (int k = 0; k < points; ++k) {
    Mat34E c = kIdentity;
    c[3] = k;
    m.control_points.push_back(c);
    m.weights.push_back(1);
  }
  return m;
}

Body body(const std::string& name, std::optional<Motion> motion) {
  Body b;
  b.name = name;
  b.motion = std::move(motion);
  return b;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(certificate_scope)

BOOST_AUTO_TEST_CASE(the_interval_of_a_check) {
  const Body still = body("still", std::nullopt);
  const Body posed = body("posed", motion_over(Exact(3), Exact(4), 1));  // one control point: a pose
  const Body a = body("a", motion_over(Exact(2), Exact(5), 2));
  const Body b = body("b", motion_over(Exact(-1), Exact(1, 2), 3));
  // Both fixed at the identity: [0, 1].
  BOOST_TEST((check_interval(still, still) == std::pair<Exact, Exact>{0, 1}));
  // The moving body's interval, the first one's when both move.
  BOOST_TEST((check_interval(a, still) == std::pair<Exact, Exact>{2, 5}));
  BOOST_TEST((check_interval(still, a) == std::pair<Exact, Exact>{2, 5}));
  BOOST_TEST((check_interval(b, a) == std::pair<Exact, Exact>{-1, Exact(1, 2)}));
  // A pose's interval counts only when nothing moves.
  BOOST_TEST((check_interval(posed, a) == std::pair<Exact, Exact>{2, 5}));
  BOOST_TEST((check_interval(still, posed) == std::pair<Exact, Exact>{3, 4}));
}

BOOST_AUTO_TEST_CASE(rational_scenes_are_certifiable) {
  Scene scene;
  scene.bodies = {body("a", motion_over(Exact(0), Exact(1), 2)), body("b", std::nullopt)};
  scene.checks = {{0, 1}};
  BOOST_TEST(uncertifiable(scene).empty());
  scene.bodies[1].solid = true;  // exact poses at the start: still certifiable
  BOOST_TEST(uncertifiable(scene).empty());
  // A solid check where one body's motion does not reach the check's start
  // (b moves over [5, 6], the check starts at a's 0): no pose there.
  scene.bodies[1] = body("b", motion_over(Exact(5), Exact(6), 2));
  scene.bodies[1].solid = true;
  BOOST_TEST(uncertifiable(scene) == "check [\"a\", \"b\"] has a solid body and the pose of \"b\" at its start is "
                                     "neither exact nor enclosed");
  scene.bodies[1].solid = false;  // without a solid body nothing is placed at the start
  BOOST_TEST(uncertifiable(scene).empty());
}

BOOST_AUTO_TEST_SUITE_END()
