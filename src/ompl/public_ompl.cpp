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

// The options of an edge: the public options by the command line's rules,
// epsilon as the options give it, else the scene's, else the default of the
// whole scene (as `tmcert batch`: FixedEnvironment needs one for all edges).
tmcert::VerifyOptions edge_options(const tmcert::Scene& scene, const VerifyOptions& o) {
  if (o.kernel == Kernel::Fast)
    throw InputError("kernel: the fast kernel is not certified; the OMPL validator accepts only certified edges");
  // Without an epsilon (or "auto"): the whole scene's default, refined.
  tmcert::VerifyOptions options = internal_options(scene, o, tmcert::EpsilonScope::WholeScene);
  options.threads = 1;          // an edge is one search; planners run edges in their own threads
  options.record_cover = false;  // no certificates of edges
  return options;
}

const std::string& scene_name(const tmcert::Scene& scene) { return scene.source; }

// A fixed body's geometry placed by its one-pose motion, if any (x -> A x + a
// for the control point [A | a]), exactly.
tmcert::Vec3E placed(const tmcert::Mat34E& m, const tmcert::Vec3E& x) {
  tmcert::Vec3E out;
  for (int r = 0; r < 3; ++r) out[r] = m[4 * r] * x[0] + m[4 * r + 1] * x[1] + m[4 * r + 2] * x[2] + m[4 * r + 3];
  return out;
}

// The obstacles (bodies `indices` of the scene) as one fixed body, each
// placed by its one-pose motion.  A body that moves, has a tolerance, or
// is solid next to other obstacles (their union is then no longer the
// solid the containment test expects) is rejected, naming the body.
tmcert::Body obstacle_body(const tmcert::Scene& scene, const std::vector<std::size_t>& indices) {
  tmcert::Body out;
  out.name = "obstacles";
  const auto field = [&](std::size_t i) {
    return scene_name(scene) + ": bodies[" + std::to_string(i) + "] (" + tmcert::quote_text(scene.bodies[i].name) + ")";
  };
  for (std::size_t i : indices) {
    const tmcert::Body& b = scene.bodies[i];
    if (b.moves())
      throw InputError(field(i) + ".motion: the obstacles of an OMPL planning scene must be fixed (every body but the robot)");
    if (b.tolerance != 0) throw InputError(field(i) + ".tolerance: tolerances are not supported by the OMPL validator");
    if (b.solid && indices.size() > 1)
      throw InputError(field(i) + ".solid: a solid obstacle must be the only obstacle of an OMPL planning scene");
    if (b.primitive)  // its collisions must be proven on its true shape, in its own frame
      throw InputError(field(i) + ": a robot link's URDF cylinder or sphere cannot be an obstacle of an OMPL planning scene");
    const bool posed = b.motion.has_value() || b.trajectory.has_value();
    if (b.trajectory)  // a one-pose trajectory does not occur (keyframes of one pose reduce to a motion)
      throw InputError(field(i) + ".motion: the obstacles of an OMPL planning scene must be fixed (every body but the robot)");
    const tmcert::Mat34E pose = posed ? b.motion->control_points.front() : tmcert::Mat34E{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
    const auto at = [&](const tmcert::Vec3E& x) { return posed ? placed(pose, x) : x; };
    const int offset = static_cast<int>(out.polygons.size());
    for (const auto& polygon : b.polygons) {
      std::vector<tmcert::Vec3E> p;
      for (const tmcert::Vec3E& x : polygon) p.push_back(at(x));
      out.polygons.push_back(std::move(p));
    }
    for (const tmcert::ConvexPiece& piece : b.pieces) {
      tmcert::ConvexPiece p{offset + piece.polygon, {}};
      for (const tmcert::Vec3E& x : piece.vertices) p.vertices.push_back(at(x));
      out.pieces.push_back(std::move(p));
    }
    for (const auto& s : b.segments) out.segments.push_back({at(s[0]), at(s[1])});
    for (const tmcert::Vec3E& x : b.points) out.points.push_back(at(x));
    for (std::size_t k = 0; k < b.mass.points.size(); ++k) {
      out.mass.points.push_back(at(b.mass.points[k]));
      out.mass.weights.push_back(b.mass.weights[k]);
    }
    out.solid = b.solid;
    out.enlarged.insert(out.enlarged.end(), b.enlarged.begin(), b.enlarged.end());
  }
  return out;
}

// The scene's clearances are not honoured by the validator: reject them.
void require_no_clearance(const tmcert::Scene& scene) {
  if (scene.clearance != 0) throw InputError(scene_name(scene) + ": clearance: not supported by the OMPL validator");
  for (std::size_t k = 0; k < scene.check_clearance.size(); ++k)
    if (scene.check_clearance[k] && *scene.check_clearance[k] != 0)
      throw InputError(scene_name(scene) + ": checks[" + std::to_string(k) +
                       "].clearance: not supported by the OMPL validator");
}

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
    require_no_clearance(s);
    std::optional<std::size_t> robot;
    std::vector<std::size_t> obstacles;
    for (std::size_t i = 0; i < s.bodies.size(); ++i)
      if (s.bodies[i].name == robot_body) robot = i;
      else obstacles.push_back(i);
    if (!robot) throw InputError(s.source + ": bodies: no body named " + tmcert::quote_text(robot_body));
    if (obstacles.empty()) throw InputError(s.source + ": bodies: no obstacle (every body but the robot is one)");
    return tmcert::use_certified_se3(si, s.bodies[*robot], obstacle_body(s, obstacles), edge_options(s, options));
  });
}

std::shared_ptr<ompl::base::MotionValidator> use_certified_arm(
    const ompl::base::SpaceInformationPtr& si, const Scene& scene, const std::string& robot_name,
    const std::vector<std::string>& joints, bool self_collision,
    const std::vector<std::pair<std::string, std::string>>& allowed_pairs, const VerifyOptions& options) {
  return public_errors([&]() -> std::shared_ptr<ompl::base::MotionValidator> {
    const tmcert::Scene& s = *scene.impl().scene;
    require_no_clearance(s);
    const tmcert::SceneRobot& robot = scene_robot(scene, robot_name);
    std::vector<bool> link(s.bodies.size(), false);
    for (int b : robot.bodies) link[b] = true;
    std::vector<std::size_t> obstacles;
    for (std::size_t i = 0; i < s.bodies.size(); ++i)
      if (!link[i]) obstacles.push_back(i);
    if (obstacles.empty())
      throw InputError(s.source + ": bodies: no obstacle (every body but the robot's links is one)");
    return tmcert::use_certified_arm(si, robot.robot, joints, obstacle_body(s, obstacles), self_collision,
                                     allowed_pairs, edge_options(s, options));
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
    const std::vector<tmcert::Body>& bodies = certified->environment().bodies();
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
