#include "src/ompl/certified_arm.h"

#include <ompl/base/spaces/RealVectorStateSpace.h>

#include <cmath>
#include <string>

namespace tmcert {

namespace ob = ompl::base;

JointMotions::JointMotions(std::shared_ptr<const PlacedRobot> robot, std::vector<std::string> joints)
    : robot_(std::move(robot)), joints_(std::move(joints)) {
  if (!robot_) throw InputError("JointMotions: a robot is required");
  const RobotModel& model = robot_->model();
  // The column of each joint; validate_joint_path checks the names below.
  JointPath names{joints_, {Exact(0), Exact(1)}, {}, JointInterpolation::Linear, {}, {}};
  for (int k = 0; k < 2; ++k) {
    std::vector<Exact> row;
    for (const std::string& name : joints_) {
      const int j = model.joint_index(name);
      const RobotJoint* joint = j >= 0 ? &model.joints[j] : nullptr;
      // A position inside the limits (0 when allowed), only to validate the
      // names here.
      Exact q = 0;
      if (joint && joint->lower && q < *joint->lower) q = *joint->lower;
      if (joint && joint->upper && *joint->upper < q) q = *joint->upper;
      row.push_back(q);
    }
    names.positions.push_back(row);
  }
  validate_joint_path(model, names);
  for (const std::string& name : joints_) column_joints_.push_back(model.joint_index(name));
  for (std::size_t l = 0; l < model.links.size(); ++l)
    for (std::size_t p = 0; p < model.links[l].parts.size(); ++p) movers_.emplace_back(static_cast<int>(l), p);
  if (movers_.empty()) throw InputError(model.source + ": no link has collision geometry");
}

std::vector<Body> JointMotions::link_bodies() const {
  std::vector<Body> out;
  for (const auto& [l, p] : movers_) {
    const RobotLink& link = robot_->model().links[l];
    Body b = link.parts[p].geometry;
    b.name = robot_->name() + "/" + link.name + link.parts[p].suffix;
    out.push_back(std::move(b));
  }
  return out;
}

std::vector<std::pair<int, int>> JointMotions::self_pairs(
    bool self_collision, const std::vector<std::pair<std::string, std::string>>& allowed_pairs) const {
  // robot_default_checks on "bodies" numbered by mover, with no environment.
  RobotBodies bodies;
  bodies.body.assign(robot_->model().links.size(), -1);
  bodies.parts.resize(robot_->model().links.size());
  for (std::size_t m = 0; m < movers_.size(); ++m) bodies.parts[movers_[m].first].push_back(static_cast<int>(m));
  for (std::size_t l = 0; l < bodies.parts.size(); ++l)
    if (!bodies.parts[l].empty()) bodies.body[l] = bodies.parts[l].front();
  return robot_default_checks(*robot_, bodies, {}, self_collision, allowed_pairs);
}

std::vector<Exact> JointMotions::values(const ob::State* s) const {
  const auto* x = s->as<ob::RealVectorStateSpace::StateType>();
  std::vector<Exact> out;
  for (std::size_t c = 0; c < joints_.size(); ++c) {
    if (!std::isfinite(x->values[c])) throw InputError("state: joint " + joints_[c] + " is not finite");
    out.push_back(Exact(x->values[c]));  // a finite double is a dyadic rational: exact
  }
  return out;
}

std::vector<Trajectory> JointMotions::segment(const ob::State* s1, const ob::State* s2) const {
  const std::vector<Exact> a = values(s1), b = values(s2);
  validate_joint_path(robot_->model(), JointPath{joints_, {Exact(0), Exact(1)}, {a, b}, JointInterpolation::Linear, {}, {}});  // limits
  const std::vector<Exact> qa = joint_values(robot_->model(), column_joints_, a);
  const std::vector<Exact> qb = joint_values(robot_->model(), column_joints_, b);
  std::vector<Trajectory> out;
  for (const auto& [l, p] : movers_) {
    const std::shared_ptr<const ChainDescription>& chain = robot_->chain(l, p);
    std::vector<Exact> from, to;
    for (int j : robot_->chain_joints(l)) {
      from.push_back(qa[j]);
      to.push_back(qb[j]);
    }
    MotionSegment seg;
    seg.t0 = 0;
    seg.t1 = 1;
    // As add_robot builds a link's segment: the rational motion between
    // exact end poses when the chain is affine in the joints there (no
    // revolute joint moves off 0), else the enclosed link motion.
    if (chain->rational_between(from, to)) {
      Motion r;
      r.t0 = 0;
      r.t1 = 1;
      r.control_points = {*chain->exact_pose(from), *chain->exact_pose(to)};
      r.weights = {Exact(1), Exact(1)};
      seg.rational = std::move(r);
    } else {
      auto link = std::make_shared<LinkMotion>();
      link->chain = chain;
      link->from = std::move(from);
      link->to = std::move(to);
      seg.link = std::move(link);
    }
    out.push_back(Trajectory{{std::move(seg)}});
  }
  return out;
}

std::optional<std::vector<Mat34E>> JointMotions::exact_poses(const ob::State* s) const {
  const std::vector<Exact> q = values(s);
  validate_joint_path(robot_->model(), JointPath{joints_, {Exact(0), Exact(1)}, {q, q}, JointInterpolation::Linear, {}, {}});  // limits
  const std::vector<Exact> all = joint_values(robot_->model(), column_joints_, q);
  std::vector<Mat34E> out;
  for (const auto& [l, p] : movers_) {
    std::vector<Exact> v;
    for (int j : robot_->chain_joints(l)) v.push_back(all[j]);
    const std::optional<Mat34E> pose = robot_->chain(l, p)->exact_pose(v);
    if (!pose) return std::nullopt;  // a revolute joint off 0: enclosed only
    out.push_back(*pose);
  }
  return out;
}

std::shared_ptr<CertifiedMotionValidator> use_certified_arm(
    const ob::SpaceInformationPtr& si, std::shared_ptr<const PlacedRobot> robot, std::vector<std::string> joints,
    Body obstacles, bool self_collision, const std::vector<std::pair<std::string, std::string>>& allowed_pairs,
    const VerifyOptions& options) {
  const auto space = std::dynamic_pointer_cast<ob::RealVectorStateSpace>(si->getStateSpace());
  if (!space) throw InputError("use_certified_arm: the state space is not an ompl::base::RealVectorStateSpace");
  if (space->getDimension() != joints.size())
    throw InputError("use_certified_arm: the state space has " + std::to_string(space->getDimension()) +
                     " dimensions for " + std::to_string(joints.size()) + " joints");
  auto motions = std::make_shared<const JointMotions>(std::move(robot), std::move(joints));
  auto environment = shared_environment(std::move(obstacles), motions->link_bodies(),
                                        motions->self_pairs(self_collision, allowed_pairs), options);
  auto validator = std::make_shared<CertifiedMotionValidator>(si, environment, motions);
  si->setStateValidityChecker(std::make_shared<CertifiedStateValidityChecker>(si, validator));
  si->setMotionValidator(validator);
  return validator;
}

}  // namespace tmcert
