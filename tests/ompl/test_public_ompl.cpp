// The OMPL adapter on the public API (include/tmcert/ompl.h): scenes built
// with SceneBuilder, edges whose truth is known by construction, and the
// input errors.  Public headers only, as a user writes it.
#include <boost/test/unit_test.hpp>

#include <tmcert/ompl.h>
#include <tmcert/tmcert.h>

#include <ompl/base/DiscreteMotionValidator.h>
#include <ompl/base/ScopedState.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/spaces/SE3StateSpace.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#ifndef TMCERT_SOURCE_DIR
#define TMCERT_SOURCE_DIR "."
#endif

namespace ob = ompl::base;

namespace {

// An axis-aligned box [lo, hi] (dyadic doubles, exact) as six quads.
tmcert::BodyBuilder& add_box(tmcert::BodyBuilder& b, const std::array<double, 3>& lo, const std::array<double, 3>& hi) {
  std::vector<double> xyz;
  for (int k = 0; k < 8; ++k)
    for (int a = 0; a < 3; ++a) xyz.push_back((k >> a) & 1 ? hi[a] : lo[a]);
  return b.polygons(xyz, {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}});
}

// A wall |x| <= 1/8, |y|, |z| <= 1; a cube of half side 1/8 (the robot);
// a post, the box |x|, |z| <= 1/8, 23/8 <= y <= 25/8, placed at x = 5 by a
// one-pose motion.
tmcert::Scene rigid_scene() {
  tmcert::SceneBuilder b;
  add_box(b.add_body("wall"), {-0.125, -1, -1}, {0.125, 1, 1});
  add_box(b.add_body("cube"), {-0.125, -0.125, -0.125}, {0.125, 0.125, 0.125});
  tmcert::BodyBuilder& post = b.add_body("post");
  add_box(post, {-0.125, 2.875, -0.125}, {0.125, 3.125, 0.125});
  post.motion(tmcert::RationalBezier{{tmcert::AffineMap{1, 0, 0, 5, 0, 1, 0, 0, 0, 0, 1, 0}}, {}, {0, 1}});
  return b.build();
}

struct Se3 {
  std::shared_ptr<ob::SE3StateSpace> space = std::make_shared<ob::SE3StateSpace>();
  ob::SpaceInformationPtr si;
  std::shared_ptr<ob::MotionValidator> validator;
  explicit Se3(const tmcert::Scene& scene) {
    ob::RealVectorBounds bounds(3);
    bounds.setLow(-10);
    bounds.setHigh(10);
    space->setBounds(bounds);
    si = std::make_shared<ob::SpaceInformation>(space);
    tmcert::VerifyOptions options;
    options.epsilon = "1/1000";
    validator = tmcert::use_certified_se3(si, scene, "cube", options);
    si->setup();
  }
  ob::ScopedState<ob::SE3StateSpace> at(double x, double y, double z) const {
    ob::ScopedState<ob::SE3StateSpace> s(space);
    s->setXYZ(x, y, z);
    s->rotation().setIdentity();
    return s;
  }
};

std::string name(tmcert::Verdict v) { return tmcert::to_string(v); }

template <typename F>
void require_input_error(F&& f, const std::vector<std::string>& parts) {
  try {
    f();
    BOOST_FAIL("no InputError");
  } catch (const tmcert::InputError& e) {
    const std::string message = e.what();
    for (const std::string& p : parts) BOOST_TEST(message.find(p) != std::string::npos, message << " lacks " << p);
  }
}

}  // namespace

BOOST_AUTO_TEST_SUITE(public_ompl)

// Through the wall: contact when the cube's face x + 1/8 reaches -1/8, at
// x = -1/4, edge parameter 3/8.  Beside it: safe.
BOOST_AUTO_TEST_CASE(se3_edges) {
  const Se3 f(rigid_scene());
  const auto a = f.at(-1, 0, 0), b = f.at(1, 0, 0), c = f.at(-1, 0.5, 0.5);
  BOOST_TEST(!f.validator->checkMotion(a.get(), b.get()));
  BOOST_TEST(f.validator->checkMotion(a.get(), c.get()));
  BOOST_TEST(f.si->isValid(a.get()));
  BOOST_TEST(!f.si->isValid(f.at(0, 0, 0).get()));

  const tmcert::EdgeResult hit = tmcert::certify_edge(*f.validator, a.get(), b.get());
  BOOST_TEST(name(hit.verdict) == "collision");
  BOOST_TEST(hit.problem.empty());
  BOOST_REQUIRE(hit.first_contact.has_value());
  BOOST_TEST((*hit.first_contact)[0].approx <= 0.375);
  BOOST_TEST((*hit.first_contact)[1].approx >= 0.375);
  BOOST_REQUIRE(hit.witness.has_value());
  BOOST_TEST(std::abs(hit.witness->t.approx() - 0.375) < 1e-9);
  BOOST_TEST(((hit.bodies == std::array<std::string, 2>{"obstacles", "cube"}) ||
              (hit.bodies == std::array<std::string, 2>{"cube", "obstacles"})));

  const tmcert::EdgeResult free = tmcert::certify_edge(*f.validator, a.get(), c.get());
  BOOST_TEST(name(free.verdict) == "safe");
  BOOST_TEST(!free.first_contact.has_value());
  BOOST_TEST(!free.witness.has_value());

  const tmcert::EdgeResult inside = tmcert::certify_edge(*f.validator, b.get(), b.get());  // a state: free
  BOOST_TEST(name(inside.verdict) == "safe");
}

// The post is where its one-pose motion puts it (x = 5), not at x = 0.
BOOST_AUTO_TEST_CASE(se3_posed_obstacle) {
  const Se3 f(rigid_scene());
  BOOST_TEST(f.validator->checkMotion(f.at(-0.5, 3, 0).get(), f.at(0.5, 3, 0).get()));
  const auto s = f.at(4, 3, 0), g = f.at(6, 3, 0);
  BOOST_TEST(name(tmcert::certify_edge(*f.validator, s.get(), g.get()).verdict) == "collision");
}

BOOST_AUTO_TEST_CASE(input_errors) {
  const tmcert::Scene scene = rigid_scene();
  auto space = std::make_shared<ob::SE3StateSpace>();
  auto si = std::make_shared<ob::SpaceInformation>(space);
  require_input_error([&] { tmcert::use_certified_se3(si, scene, "nope"); }, {"no body named", "nope"});

  tmcert::SceneBuilder moving;
  add_box(moving.add_body("cube"), {-0.125, -0.125, -0.125}, {0.125, 0.125, 0.125});
  add_box(moving.add_body("door"), {-1, -1, -1}, {1, 1, -0.5}).motion(tmcert::Motion::translation({0, 0, 0}, {0, 0, 1}));
  require_input_error([&] { tmcert::use_certified_se3(si, moving.build(), "cube"); },
                      {"bodies[1]", "door", "motion", "fixed"});

  tmcert::VerifyOptions bad;
  bad.epsilon = "-1";
  require_input_error([&] { tmcert::use_certified_se3(si, scene, "cube", bad); }, {"epsilon"});
  tmcert::VerifyOptions fast;
  fast.kernel = tmcert::Kernel::Fast;
  require_input_error([&] { tmcert::use_certified_se3(si, scene, "cube", fast); }, {"kernel", "not certified"});

  auto joints = std::make_shared<ob::RealVectorStateSpace>(3);
  auto si_joints = std::make_shared<ob::SpaceInformation>(joints);
  require_input_error([&] { tmcert::use_certified_se3(si_joints, scene, "cube"); }, {"SE3StateSpace"});
  require_input_error([&] { tmcert::use_certified_arm(si_joints, scene, "arm", {"j1"}); }, {"no robot named", "arm"});

  ob::DiscreteMotionValidator sampling(si);
  ob::ScopedState<ob::SE3StateSpace> s(space);
  require_input_error([&] { tmcert::certify_edge(sampling, s.get(), s.get()); }, {"use_certified_se3"});
}

// The arm of examples/ompl: the straight joint edge from j1 = -1.2 to 1.2
// sweeps the forearm through the pillar; a small step at the start is free.
BOOST_AUTO_TEST_CASE(arm_edges) {
  const std::vector<std::string> joints = {"j1", "j2", "j3", "j4", "j5", "j6"};
  const std::vector<double> q0 = {-1.2, 1.0, 0.8, 0, 0.3, 0};
  tmcert::SceneBuilder b;
  add_box(b.add_body("pillar"), {0.29, -0.03, 0}, {0.35, 0.03, 0.5});
  b.add_robot("arm", std::string(TMCERT_SOURCE_DIR) + "/examples/ompl/arm6.urdf").path(joints, {0, 1}, {{q0.begin(), q0.end()}, {q0.begin(), q0.end()}});
  const tmcert::Scene scene = b.build();

  // Limits -3.1 and 3.1 (not doubles) round inward; -2 and 2 are exact.
  const ob::RealVectorBounds bounds = tmcert::joint_bounds(scene, "arm", joints);
  BOOST_TEST(bounds.high[0] == std::nextafter(3.1, 0.0));
  BOOST_TEST(bounds.low[0] == -std::nextafter(3.1, 0.0));
  BOOST_TEST(bounds.low[1] == -2.0);
  BOOST_TEST(bounds.high[1] == 2.0);
  require_input_error([&] { tmcert::joint_bounds(scene, "arm", {"j1", "elbow"}); }, {"joints[1]", "elbow"});

  auto space = std::make_shared<ob::RealVectorStateSpace>(joints.size());
  space->setBounds(bounds);
  auto si = std::make_shared<ob::SpaceInformation>(space);
  tmcert::VerifyOptions options;
  options.epsilon = "1/10000";
  const auto validator = tmcert::use_certified_arm(si, scene, "arm", joints, true, {}, options);
  si->setup();
  ob::ScopedState<ob::RealVectorStateSpace> start(space), goal(space), step(space);
  for (std::size_t k = 0; k < joints.size(); ++k) start[k] = goal[k] = step[k] = q0[k];
  goal[0] = 1.2;
  step[0] = -1.1;
  const tmcert::EdgeResult through = tmcert::certify_edge(*validator, start.get(), goal.get());
  BOOST_TEST(name(through.verdict) == "collision");
  BOOST_TEST((through.bodies[0] == "obstacles" || through.bodies[1] == "obstacles"));
  BOOST_TEST((through.bodies[0].rfind("arm/", 0) == 0 || through.bodies[1].rfind("arm/", 0) == 0));
  BOOST_TEST(validator->checkMotion(start.get(), step.get()));
}

BOOST_AUTO_TEST_SUITE_END()
