// include/tmcert/ompl.h: the certified OMPL validator from a public Scene.
// The scene's internal bodies (Scene::impl(), as src/api/*.cpp read it)
// become the internal adapter's robot and obstacles (src/ompl/).
//
// Internal headers come first (src/api/internal.h explains why); code in
// tmcert::api writes internal types as tmcert::X.
#include "src/ompl/certified_arm.h"
#include "src/ompl/certified_motion_validator.h"
#include "src/io/robot.h"
#include "src/io/parse.h"
#include "src/verify/verify.h"

#include "src/api/internal.h"
#include "tmcert/ompl.h"

#include <cmath>
#include <limits>

namespace tmcert::api {

namespace {

// The words of the OMPL adapter's refusals (src/api/environment.cpp).
const ObstacleWords kOmpl{"an OMPL planning scene", "the OMPL validator", "every body but the robot",
                          "the OMPL validator accepts only certified edges"};

const tmcert::SceneRobot& scene_robot(const Scene& scene, const std::string& name) {
  for (const tmcert::SceneRobot& r : scene.impl().robots)
    if (r.robot->name() == name) return r;
  throw InputError(scene.source() + ": robots: no robot named " + tmcert::quote_text(name));
}

}  // namespace

std::shared_ptr<ompl::base::MotionValidator> use_certified_se3(const ompl::base::SpaceInformationPtr& si,
                                                               const Scene& scene, const std::string& robot_body,
                                                               const VerifyOptions& options) {
  return public_errors([&]() -> std::shared_ptr<ompl::base::MotionValidator> {
    const tmcert::Scene& s = *scene.impl().scene;
    require_no_clearance(s, kOmpl);
    const MoverAndObstacles split = split_mover(s, robot_body, kOmpl);
    return tmcert::use_certified_se3(si, s.bodies[split.mover], obstacle_body(s, split.obstacles, kOmpl),
                                     environment_options(s, options, kOmpl));
  });
}

std::shared_ptr<ompl::base::MotionValidator> use_certified_arm(
    const ompl::base::SpaceInformationPtr& si, const Scene& scene, const std::string& robot_name,
    const std::vector<std::string>& joints, bool self_collision,
    const std::vector<std::pair<std::string, std::string>>& allowed_pairs, const VerifyOptions& options) {
  return public_errors([&]() -> std::shared_ptr<ompl::base::MotionValidator> {
    const tmcert::Scene& s = *scene.impl().scene;
    require_no_clearance(s, kOmpl);
    const tmcert::SceneRobot& robot = scene_robot(scene, robot_name);
    std::vector<bool> link(s.bodies.size(), false);
    for (int b : robot.bodies) link[b] = true;
    std::vector<std::size_t> obstacles;
    for (std::size_t i = 0; i < s.bodies.size(); ++i)
      if (!link[i]) obstacles.push_back(i);
    if (obstacles.empty())
      throw InputError(s.source + ": bodies: no obstacle (every body but the robot's links is one)");
    return tmcert::use_certified_arm(si, robot.robot, joints, obstacle_body(s, obstacles, kOmpl), self_collision,
                                     allowed_pairs, environment_options(s, options, kOmpl));
  });
}

ompl::base::RealVectorBounds joint_bounds(const Scene& scene, const std::string& robot_name,
                                          const std::vector<std::string>& joints) {
  return public_errors([&] {
    const tmcert::RobotModel& model = scene_robot(scene, robot_name).robot->model();
    ompl::base::RealVectorBounds bounds(static_cast<unsigned int>(joints.size()));
    constexpr double inf = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < joints.size(); ++k) {
      const std::string field = "joints[" + std::to_string(k) + "]: ";
      const int j = model.joint_index(joints[k]);
      if (j < 0) throw InputError(field + "robot " + tmcert::quote_text(robot_name) + " has no joint " + tmcert::quote_text(joints[k]));
      const tmcert::RobotJoint& joint = model.joints[j];
      if (!joint.lower || !joint.upper)
        throw InputError(field + "joint " + tmcert::quote_text(joints[k]) + " has no <limit> (continuous or fixed)");
      double lo = CGAL::to_double(*joint.lower), hi = CGAL::to_double(*joint.upper);
      if (tmcert::Exact(lo) < *joint.lower) lo = std::nextafter(lo, inf);
      if (tmcert::Exact(hi) > *joint.upper) hi = std::nextafter(hi, -inf);
      bounds.setLow(static_cast<unsigned int>(k), lo);
      bounds.setHigh(static_cast<unsigned int>(k), hi);
    }
    return bounds;
  });
}

EdgeResult certify_edge(const ompl::base::MotionValidator& validator, const ompl::base::State* s1,
                        const ompl::base::State* s2) {
  const auto* certified = dynamic_cast<const tmcert::CertifiedMotionValidator*>(&validator);
  if (!certified)
    throw InputError("certify_edge: not a validator of tmcert::use_certified_se3 or tmcert::use_certified_arm");
  const tmcert::EdgeCertificate edge = s1 == s2 ? certified->certify_state(s1) : certified->certify(s1, s2);
  EdgeResult out;
  out.verdict = static_cast<Verdict>(static_cast<int>(edge.check.verdict));  // same order (src/api/verify.cpp)
  out.problem = edge.problem;
  if (!edge.problem.empty()) return out;
  if (edge.check.first_contact)
    out.first_contact = std::array{to_rational(edge.check.first_contact->first), to_rational(edge.check.first_contact->second)};
  if (edge.check.witness) {
    const std::vector<tmcert::Body>& bodies = certified->pool().labels();
    tmcert::CheckResult decided;  // the static test of a state has no check: its witness's features name the bodies
    for (const tmcert::CheckResult& c : edge.check.checks)
      if (c.verdict == tmcert::Verdict::Collision) {
        decided = c;
        out.bodies = {bodies[c.bodies[0]].name, bodies[c.bodies[1]].name};
        break;
      }
    out.witness = public_witness(bodies, decided, *edge.check.witness);
  }
  return out;
}

}  // namespace tmcert::api
