// The certified OMPL motion validator on edges whose truth is known by
// construction (src/ompl/certified_motion_validator.h,
// proofs/ompl-validator.md).
#define BOOST_TEST_MODULE tmcert_ompl
#include <boost/test/unit_test.hpp>

#include "src/ompl/certified_arm.h"
#include "src/ompl/certified_motion_validator.h"
#include "src/io/parse.h"

#include <ompl/base/DiscreteMotionValidator.h>
#include <ompl/base/ScopedState.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/spaces/SE3StateSpace.h>
#include <ompl/util/Console.h>

#include <cmath>
#include <random>
#include <string>

namespace ob = ompl::base;
using namespace tmcert;

namespace {

// An axis-aligned box [lo, hi] (decimal strings) as six polygons (JSON).
std::string box_polygons(const std::array<std::string, 3>& lo, const std::array<std::string, 3>& hi) {
  auto p = [&](int x, int y, int z) {
    return "[\"" + (x ? hi[0] : lo[0]) + "\",\"" + (y ? hi[1] : lo[1]) + "\",\"" + (z ? hi[2] : lo[2]) + "\"]";
  };
  return "[" + p(0, 0, 0) + "," + p(0, 1, 0) + "," + p(0, 1, 1) + "," + p(0, 0, 1) + "],[" + p(1, 0, 0) + "," +
         p(1, 1, 0) + "," + p(1, 1, 1) + "," + p(1, 0, 1) + "],[" + p(0, 0, 0) + "," + p(1, 0, 0) + "," + p(1, 0, 1) +
         "," + p(0, 0, 1) + "],[" + p(0, 1, 0) + "," + p(1, 1, 0) + "," + p(1, 1, 1) + "," + p(0, 1, 1) + "],[" +
         p(0, 0, 0) + "," + p(1, 0, 0) + "," + p(1, 1, 0) + "," + p(0, 1, 0) + "],[" + p(0, 0, 1) + "," + p(1, 0, 1) +
         "," + p(1, 1, 1) + "," + p(0, 1, 1) + "]";
}

// Robot and obstacle bodies from their polygons (JSON arrays).
std::pair<Body, Body> bodies(const std::string& robot, const std::string& obstacles) {
  const Scene s = parse_scene_text("{\"format\": \"tmcert-scene/1\", \"bodies\": [{\"name\": \"robot\", \"polygons\": [" +
                                       robot + "]}, {\"name\": \"obstacles\", \"polygons\": [" + obstacles + "]}]}",
                                   "test");
  return {s.bodies[0], s.bodies[1]};
}

struct Fixture {
  std::shared_ptr<ob::SE3StateSpace> space = std::make_shared<ob::SE3StateSpace>();
  ob::SpaceInformationPtr si;
  std::shared_ptr<CertifiedMotionValidator> validator;

  Fixture(const std::string& robot, const std::string& obstacles, Exact epsilon = Exact(1, 1000)) {
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    ob::RealVectorBounds b(3);
    b.setLow(-10);
    b.setHigh(10);
    space->setBounds(b);
    si = std::make_shared<ob::SpaceInformation>(space);
    auto [r, o] = bodies(robot, obstacles);
    VerifyOptions options;
    options.epsilon = epsilon;
    validator = use_certified_se3(si, r, o, options);
    si->setup();
  }
  ob::ScopedState<ob::SE3StateSpace> state(double x, double y, double z, double qw = 1, double qx = 0, double qy = 0,
                                           double qz = 0) const {
    ob::ScopedState<ob::SE3StateSpace> s(space);
    s->setXYZ(x, y, z);
    s->rotation().w = qw;
    s->rotation().x = qx;
    s->rotation().y = qy;
    s->rotation().z = qz;
    return s;
  }
};

const std::string kCube = box_polygons({"-3/20", "-3/20", "-3/20"}, {"3/20", "3/20", "3/20"});
// A slab |x| <= 1/20, |y|, |z| <= 1: no hole.
const std::string kWall = box_polygons({"-1/20", "-1", "-1"}, {"1/20", "1", "1"});

}  // namespace

BOOST_AUTO_TEST_CASE(safe_edge_is_accepted) {
  Fixture f(kCube, kWall);
  // Translation and a rotation, everywhere at least 1/2 from the wall.
  const auto a = f.state(-2, 0, 0), b = f.state(-1, 1, 0, std::cos(0.3), 0, std::sin(0.3), 0);
  BOOST_TEST(f.validator->checkMotion(a.get(), b.get()));
  std::pair<ob::State*, double> last{nullptr, -1};
  BOOST_TEST(f.validator->checkMotion(a.get(), b.get(), last));
  BOOST_TEST(last.second == -1);  // untouched when valid
  BOOST_TEST(f.validator->getValidMotionCount() == 2u);
}

BOOST_AUTO_TEST_CASE(colliding_translation_is_rejected_with_certified_last_valid) {
  Fixture f(kCube, kWall);
  // The cube's face x = 3/20 meets the wall's face x = -1/20 when the
  // centre is at x = -1/5, at fraction 2/5 of the edge from x = -1 to 1.
  const auto a = f.state(-1, 0, 0), b = f.state(1, 0, 0);
  const EdgeCertificate edge = f.validator->certify(a.get(), b.get());
  BOOST_TEST(edge.check.verdict == Verdict::Collision);
  BOOST_REQUIRE(edge.check.first_contact);
  BOOST_TEST(edge.check.first_contact->first <= Exact(2, 5));
  BOOST_TEST(Exact(2, 5) <= edge.check.first_contact->second);
  BOOST_REQUIRE(edge.check.witness);
  BOOST_TEST(edge.check.witness->point[0] == Exact(-1, 20));  // on the wall's near face

  ob::ScopedState<ob::SE3StateSpace> last_state(f.space);
  std::pair<ob::State*, double> last{last_state.get(), -1};
  BOOST_TEST(!f.validator->checkMotion(a.get(), b.get(), last));
  BOOST_TEST(last.second > 0.0);
  BOOST_TEST(last.second < 0.4);
  // The returned state and the segment to it are certified.
  BOOST_TEST(f.validator->certify(a.get(), last_state.get()).check.verdict == Verdict::Safe);
  BOOST_TEST(f.validator->certify_state(last_state.get()).check.verdict == Verdict::Safe);
  BOOST_TEST(last_state->getX() < -0.2);
}

BOOST_AUTO_TEST_CASE(end_state_in_contact_is_rejected) {
  Fixture f(kCube, kWall);
  // Free until fraction 64/65, then in contact up to the end state (the
  // cube's face at x = -3/80, inside the slab).
  const auto a = f.state(-1, 0, 0), b = f.state(-0.1875, 0, 0);
  BOOST_TEST(f.validator->certify_state(a.get()).check.verdict == Verdict::Safe);
  BOOST_TEST(f.validator->certify_state(b.get()).check.verdict == Verdict::Collision);
  BOOST_TEST(!f.validator->checkMotion(a.get(), b.get()));
  const EdgeCertificate edge = f.validator->certify(a.get(), b.get());
  BOOST_REQUIRE(edge.check.first_contact);
  BOOST_TEST(edge.check.first_contact->first <= Exact(64, 65));
  BOOST_TEST(Exact(64, 65) <= edge.check.first_contact->second);
}

BOOST_AUTO_TEST_CASE(start_state_in_contact_gives_the_start_back) {
  // OMPL's precondition (s1 valid) violated: nothing of the edge is
  // certified, lastValid is s1 at fraction 0.
  Fixture f(kCube, kWall);
  const auto a = f.state(0, 0, 0), b = f.state(1, 0, 0);
  const EdgeCertificate edge = f.validator->certify(a.get(), b.get());
  BOOST_TEST(edge.check.verdict == Verdict::Collision);
  BOOST_REQUIRE(edge.check.safe_until);
  BOOST_TEST(*edge.check.safe_until == 0);
  ob::ScopedState<ob::SE3StateSpace> last_state(f.space);
  std::pair<ob::State*, double> last{last_state.get(), -1};
  BOOST_TEST(!f.validator->checkMotion(a.get(), b.get(), last));
  BOOST_TEST(last.second == 0.0);
  BOOST_TEST(last_state->getX() == 0.0);
}

BOOST_AUTO_TEST_CASE(states_are_read_exactly) {
  Fixture f(kCube, kWall);
  // The double nearest -0.2 is -0.2 - 1.1e-17: the cube's face stops just
  // short of the wall's face x = -1/20 (a rounding reading would touch).
  BOOST_REQUIRE(Exact(-0.2) < Exact(-1, 5));
  const auto a = f.state(-1, 0, 0), b = f.state(-0.2, 0, 0);
  BOOST_TEST(f.validator->certify_state(b.get()).check.verdict == Verdict::Safe);
  // The edge's end is within 1.1e-17 of contact: decided exactly (a
  // rational motion), safe.
  BOOST_TEST(f.validator->certify(a.get(), b.get()).check.verdict == Verdict::Safe);
  // One ulp further the faces overlap.
  const auto c = f.state(std::nextafter(-0.2, 0.0), 0, 0);
  BOOST_TEST(f.validator->certify_state(c.get()).check.verdict == Verdict::Collision);
}

BOOST_AUTO_TEST_CASE(thin_obstacle_stepped_over_by_discrete_validator_is_caught) {
  // A plate of zero thickness at x = 0; a small cube (side 1/50) crossing
  // it.  OMPL's DiscreteMotionValidator (resolution 1% of the extent of
  // [-10, 10]^3 x SO(3)) samples the edge every 0.35 and misses it.
  const std::string small = box_polygons({"-1/100", "-1/100", "-1/100"}, {"1/100", "1/100", "1/100"});
  Fixture f(small, "[[0,-1,-1],[0,1,-1],[0,1,1],[0,-1,1]]");
  const auto a = f.state(-1, 0, 0), b = f.state(1.1, 0, 0);
  ob::DiscreteMotionValidator discrete(f.si);
  BOOST_TEST(discrete.checkMotion(a.get(), b.get()));  // what sampling says
  BOOST_TEST(!f.validator->checkMotion(a.get(), b.get()));
  const EdgeCertificate edge = f.validator->certify(a.get(), b.get());
  BOOST_TEST(edge.check.verdict == Verdict::Collision);
  BOOST_REQUIRE(edge.check.witness);
  BOOST_TEST(edge.check.witness->point[0] == Exact(0));
}

BOOST_AUTO_TEST_CASE(slerp_takes_the_shorter_arc_like_ompl) {
  // A one-sided bar (x from 0 to 1) turning by 90 degrees about z, from
  // +x to +y; its end quaternion written negated (OMPL's interpolate then
  // negates it back: the shorter arc).  The shorter arc sweeps the
  // quadrant x, y >= 0; the longer one (270 degrees) the other three.
  const std::string bar = box_polygons({"0", "-1/20", "-1/20"}, {"1", "1/20", "1/20"});
  const double c = std::cos(M_PI / 4), s = std::sin(M_PI / 4);
  {
    // An obstacle at -90 degrees: only the longer arc would hit it.
    Fixture f(bar, "[[\"-1/10\",\"-7/10\",\"-1/5\"],[\"1/10\",\"-7/10\",\"-1/5\"],[\"1/10\",\"-7/10\",\"1/5\"],[\"-1/10\",\"-7/10\",\"1/5\"]]");
    const auto a = f.state(0, 0, 0), b = f.state(0, 0, 0, -c, 0, 0, -s);
    BOOST_TEST(f.validator->checkMotion(a.get(), b.get()));
  }
  {
    // An obstacle at 45 degrees: the shorter arc hits it.
    Fixture f(bar, "[[\"1/2\",\"1/2\",\"-1/5\"],[\"3/5\",\"2/5\",\"-1/5\"],[\"3/5\",\"2/5\",\"1/5\"],[\"1/2\",\"1/2\",\"1/5\"]]");
    const auto a = f.state(0, 0, 0), b = f.state(0, 0, 0, -c, 0, 0, -s);
    BOOST_TEST(f.validator->certify_state(a.get()).check.verdict == Verdict::Safe);
    BOOST_TEST(f.validator->certify_state(b.get()).check.verdict == Verdict::Safe);
    const EdgeCertificate edge = f.validator->certify(a.get(), b.get());
    BOOST_TEST(edge.check.verdict == Verdict::Collision);
    // The contact is near 45 degrees (the obstacle spans about 38.7 to 51.3).
    BOOST_REQUIRE(edge.check.first_contact);
    BOOST_TEST(CGAL::to_double(edge.check.first_contact->first) > 0.3);
    BOOST_TEST(CGAL::to_double(edge.check.first_contact->second) < 0.6);
    ob::ScopedState<ob::SE3StateSpace> last_state(f.space);
    std::pair<ob::State*, double> last{last_state.get(), -1};
    BOOST_TEST(!f.validator->checkMotion(a.get(), b.get(), last));
    BOOST_TEST(last.second > 0.0);
    BOOST_TEST(last.second < CGAL::to_double(edge.check.first_contact->first));
    BOOST_TEST(f.validator->certify(a.get(), last_state.get()).check.verdict == Verdict::Safe);
  }
}

BOOST_AUTO_TEST_CASE(undecided_edge_counts_as_invalid) {
  // The cube crosses above the wall (top face y = 1) turning from 0 to 90
  // degrees about x; at the crossing (t = 1/2, 45 degrees) its lowest edge
  // is 0.15 sqrt 2 below its centre, which passes 2^-30 above that: a gap
  // far below epsilon = 1/10, so the search stops undecided.  Truly safe,
  // yet not proven: the edge must count as invalid.
  const double gap = std::ldexp(1.0, -30);
  Fixture f(kCube, kWall, Exact(1, 10));
  const double y = 1 + 0.15 * std::sqrt(2.0) + gap;
  const auto a = f.state(-1, y, 0), b = f.state(1, y, 0, std::cos(M_PI / 4), std::sin(M_PI / 4), 0, 0);
  const EdgeCertificate edge = f.validator->certify(a.get(), b.get());
  BOOST_TEST(edge.check.verdict == Verdict::Undecided);
  BOOST_TEST(!f.validator->checkMotion(a.get(), b.get()));
}

BOOST_AUTO_TEST_CASE(bad_states_are_never_valid) {
  Fixture f(kCube, kWall);
  const auto a = f.state(-2, 0, 0);
  const auto zero = f.state(-2, 0, 0, 0, 0, 0, 0);
  const auto nan = f.state(std::nan(""), 0, 0);
  BOOST_TEST(!f.validator->checkMotion(a.get(), zero.get()));
  BOOST_TEST(!f.validator->checkMotion(a.get(), nan.get()));
  BOOST_TEST(!f.validator->certify(a.get(), nan.get()).problem.empty());
  // Exactly 180 degrees apart: no shorter arc.
  const auto turned = f.state(-2, 0, 0, 0, 0, 0, 1);
  BOOST_TEST(!f.validator->checkMotion(a.get(), turned.get()));
  BOOST_TEST(f.validator->certify(a.get(), turned.get()).problem.find("180") != std::string::npos);
}

// ---------------------------------------------------------------- joint space

BOOST_AUTO_TEST_CASE(joint_space_edge_with_known_first_contact) {
  // One revolute joint about z; the link a bar from x = 0 to 1 (|y|, |z| <=
  // 1/20).  A post [0.6, 0.7] x [0.6, 0.7] (|z| <= 1/2): turning from 0 to
  // 90 degrees, the bar's face y' = 1/20 first meets the post's corner
  // (0.7, 0.6), at theta = atan2(0.6, 0.7) - asin(0.05 / |(0.7, 0.6)|).
  const std::string urdf = R"(<robot name="one"><link name="base"/>
    <link name="bar"><collision><origin xyz="0.5 0 0"/><geometry><box size="1 0.1 0.1"/></geometry></collision></link>
    <joint name="q" type="revolute"><parent link="base"/><child link="bar"/><axis xyz="0 0 1"/>
      <limit lower="-3" upper="3" effort="1" velocity="1"/></joint></robot>)";
  const auto robot = std::make_shared<const PlacedRobot>(load_urdf_text(urdf, "one.urdf", "."), "one", Pose{});
  const auto [unused, post] =
      bodies(kCube, box_polygons({"0.6", "0.6", "-0.5"}, {"0.7", "0.7", "0.5"}));
  auto space = std::make_shared<ob::RealVectorStateSpace>(1);
  space->setBounds(-3, 3);
  auto si = std::make_shared<ob::SpaceInformation>(space);
  VerifyOptions options;
  options.epsilon = Exact(1, 10000);
  const auto validator = use_certified_arm(si, robot, {"q"}, post, false, {}, options);
  si->setup();
  ob::ScopedState<ob::RealVectorStateSpace> a(space), b(space), c(space), last_state(space);
  a[0] = 0;
  b[0] = M_PI / 2;
  c[0] = 0.5;
  BOOST_TEST(validator->checkMotion(a.get(), c.get()));  // up to about 29 degrees: clear
  const EdgeCertificate edge = validator->certify(a.get(), b.get());
  BOOST_TEST(edge.check.verdict == Verdict::Collision);
  BOOST_REQUIRE(edge.check.first_contact);
  const double theta = std::atan2(0.6, 0.7) - std::asin(0.05 / std::hypot(0.7, 0.6));
  const double fraction = theta / b[0];
  BOOST_TEST(CGAL::to_double(edge.check.first_contact->first) <= fraction + 1e-9);
  BOOST_TEST(fraction - 1e-9 <= CGAL::to_double(edge.check.first_contact->second));
  std::pair<ob::State*, double> last{last_state.get(), -1};
  BOOST_TEST(!validator->checkMotion(a.get(), b.get(), last));
  BOOST_TEST(last.second > 0.0);
  BOOST_TEST(last.second < fraction);
  BOOST_TEST(validator->certify(a.get(), last_state.get()).check.verdict == Verdict::Safe);
  // Outside the joint's limits: never valid.
  ob::ScopedState<ob::RealVectorStateSpace> out(space);
  out[0] = 3.5;
  BOOST_TEST(!validator->checkMotion(a.get(), out.get()));
  BOOST_TEST(!validator->certify(a.get(), out.get()).problem.empty());
}

BOOST_AUTO_TEST_CASE(joint_space_agrees_with_the_verifier_on_the_robot_scene) {
  // The 6-joint arm of examples/ompl/arm6.urdf beside a post, random edges:
  // the validator's verdict against verify_scene on a scene with the same
  // joint path (add_robot, the robot's default checks with
  // self-collision).  The Verifier settles a solid link's start
  // containment at an enclosed pose only by disjoint whole-body boxes, the
  // validator by the component vertices' boxes (finer, the same exact
  // criterion): so they must never contradict (safe against collision),
  // and agree whenever the Verifier decides.  Seeded.
  const auto robot = std::make_shared<const PlacedRobot>(load_urdf(TMCERT_SOURCE_DIR "/examples/ompl/arm6.urdf"), "arm",
                                                         Pose{});
  const std::vector<std::string> joints = {"j1", "j2", "j3", "j4", "j5", "j6"};
  const auto [unused, post] = bodies(kCube, box_polygons({"0.25", "-0.05", "0"}, {"0.35", "0.05", "0.35"}));
  auto space = std::make_shared<ob::RealVectorStateSpace>(6);
  space->setBounds(-2, 2);
  auto si = std::make_shared<ob::SpaceInformation>(space);
  VerifyOptions options;
  options.epsilon = Exact(1, 2000);
  const auto validator = use_certified_arm(si, robot, joints, post, true, {}, options);
  si->setup();
  const unsigned seed = 20261127;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> q(-1.5, 1.5);
  int decided = 0, safe = 0, collision = 0;
  for (int k = 0; k < 16; ++k) {
    ob::ScopedState<ob::RealVectorStateSpace> a(space), b(space);
    // The arm leaning towards the post (j1 near 0, j2 and j3 forward).
    const double lo[6] = {-0.6, 0.3, 0.0, -1.5, -1.5, -1.5}, hi[6] = {0.6, 1.2, 1.2, 1.5, 1.5, 1.5};
    for (int j = 0; j < 6; ++j) {
      a[j] = lo[j] + (hi[j] - lo[j]) * (q(rng) + 1.5) / 3;
      b[j] = std::max(-2.0, std::min(2.0, a[j] + 0.5 * q(rng)));
    }
    const Verdict got = validator->certify(a.get(), b.get()).check.verdict;
    Scene scene;
    scene.source = "arm";
    scene.bodies.push_back(post);
    JointPath path{joints, {Exact(0), Exact(1)}, {{}, {}}, JointInterpolation::Linear, {}, {}};
    for (int j = 0; j < 6; ++j) {
      path.positions[0].push_back(Exact(a[j]));
      path.positions[1].push_back(Exact(b[j]));
    }
    const RobotBodies rb = add_robot(scene, *robot, path);
    scene.checks = robot_default_checks(*robot, rb, {0}, true, {});
    const Verdict expected = verify_scene(scene, options).verdict;
    BOOST_TEST(!(got == Verdict::Safe && expected == Verdict::Collision), "seed " << seed << ", edge " << k);
    BOOST_TEST(!(got == Verdict::Collision && expected == Verdict::Safe), "seed " << seed << ", edge " << k);
    if (expected != Verdict::Undecided) {
      ++decided;
      BOOST_TEST(got == expected, "seed " << seed << ", edge " << k);
    }
    BOOST_TEST_MESSAGE("edge " << k << ": " << to_string(got) << ", verifier " << to_string(expected));
    safe += got == Verdict::Safe;
    collision += got == Verdict::Collision;
  }
  BOOST_TEST(decided > 4);
  BOOST_TEST(safe > 0);
  BOOST_TEST(collision > 0);
}
