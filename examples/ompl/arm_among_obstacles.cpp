// OMPL's RRTConnect plans a 6-joint arm (examples/ompl/arm6.urdf, box
// links) in joint space from one side of a pillar to the other, with
// tmcert's certified motion validator (linear joint motion, every link
// against the obstacles and, self-collision on, against the links that are
// neither its parent nor its child); then every edge of the returned path
// is certified again and printed.
//
// Obstacles: a floor plate at z = -1/100 and a pillar 0.06 x 0.06 x 0.5 at
// x = 0.32, in the sweep of the arm's reach between the start
// (j1 = -1.2) and the goal (j1 = 1.2).
//
// Exit status: 0 when a path was found and every edge of it is certified
// safe, 1 otherwise.  Usage: ompl_arm_among_obstacles [--seed N]
// [--time SECONDS] [--urdf FILE]
#include "src/ompl/certified_arm.h"
#include "src/scene/parse.h"

#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <chrono>
#include <cstdlib>
#include <iostream>
#include <string>

#ifndef TMCERT_SOURCE_DIR
#define TMCERT_SOURCE_DIR "."
#endif

namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace {

const char* kObstacles = R"({"format": "tmcert-scene/1", "bodies": [{"name": "obstacles", "polygons": [
  [[-1,-1,"-0.01"],[1,-1,"-0.01"],[1,1,"-0.01"],[-1,1,"-0.01"]],
  [["0.29","-0.03",0],["0.29","0.03",0],["0.29","0.03","0.5"],["0.29","-0.03","0.5"]],
  [["0.35","-0.03",0],["0.35","0.03",0],["0.35","0.03","0.5"],["0.35","-0.03","0.5"]],
  [["0.29","-0.03",0],["0.35","-0.03",0],["0.35","-0.03","0.5"],["0.29","-0.03","0.5"]],
  [["0.29","0.03",0],["0.35","0.03",0],["0.35","0.03","0.5"],["0.29","0.03","0.5"]],
  [["0.29","-0.03","0.5"],["0.35","-0.03","0.5"],["0.35","0.03","0.5"],["0.29","0.03","0.5"]]]}]})";

}  // namespace

int main(int argc, char** argv) {
  std::uint32_t seed = 20261125;
  double seconds = 20;
  std::string urdf = std::string(TMCERT_SOURCE_DIR) + "/examples/ompl/arm6.urdf";
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--seed" && i + 1 < argc) seed = static_cast<std::uint32_t>(std::strtoul(argv[++i], nullptr, 10));
    else if (a == "--time" && i + 1 < argc) seconds = std::strtod(argv[++i], nullptr);
    else if (a == "--urdf" && i + 1 < argc) urdf = argv[++i];
    else {
      std::cerr << "usage: ompl_arm_among_obstacles [--seed N] [--time SECONDS] [--urdf FILE]\n";
      return 3;
    }
  }
  ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
  ompl::RNG::setSeed(seed);

  std::shared_ptr<const tmcert::PlacedRobot> arm;
  tmcert::Body obstacles;
  try {
    arm = std::make_shared<const tmcert::PlacedRobot>(tmcert::load_urdf(urdf), "arm", tmcert::Pose{});
    obstacles = tmcert::parse_scene_text(kObstacles, "obstacles").bodies[0];
  } catch (const tmcert::InputError& e) {
    std::cerr << e.what() << "\n";
    return 3;
  }
  const std::vector<std::string> joints = {"j1", "j2", "j3", "j4", "j5", "j6"};
  auto space = std::make_shared<ob::RealVectorStateSpace>(joints.size());
  ob::RealVectorBounds bounds(joints.size());
  for (std::size_t k = 0; k < joints.size(); ++k) {  // the URDF limits
    const tmcert::RobotJoint& j = arm->model().joints[arm->model().joint_index(joints[k])];
    bounds.setLow(k, CGAL::to_double(*j.lower));
    bounds.setHigh(k, CGAL::to_double(*j.upper));
  }
  space->setBounds(bounds);
  og::SimpleSetup setup(space);
  tmcert::VerifyOptions options;
  options.epsilon = tmcert::Exact(1, 10000);  // 0.1 mm
  const auto validator =
      tmcert::use_certified_arm(setup.getSpaceInformation(), arm, joints, obstacles, true, {}, options);

  ob::ScopedState<ob::RealVectorStateSpace> start(space), goal(space);
  const double q0[6] = {-1.2, 1.0, 0.8, 0, 0.3, 0}, q1[6] = {1.2, 1.0, 0.8, 0, 0.3, 0};
  for (int k = 0; k < 6; ++k) {
    start[k] = q0[k];
    goal[k] = q1[k];
  }
  setup.setStartAndGoalStates(start, goal);
  setup.setPlanner(std::make_shared<og::RRTConnect>(setup.getSpaceInformation()));
  std::cout << "the straight joint edge from start to goal: "
            << tmcert::to_string(validator->certify(start.get(), goal.get()).check.verdict) << "\n";

  const auto t0 = std::chrono::steady_clock::now();
  const ob::PlannerStatus status = setup.solve(seconds);
  const double planning = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (status != ob::PlannerStatus::EXACT_SOLUTION) {
    std::cout << "no exact solution within " << seconds << " s (" << status.asString() << ")\n";
    return 1;
  }
  const og::PathGeometric& path = setup.getSolutionPath();
  std::cout << "RRTConnect with the certified validator: " << path.getStateCount() << " states, " << planning
            << " s, " << validator->getCheckedMotionCount() << " edges checked (" << validator->getValidMotionCount()
            << " certified safe)\n";
  int failures = 0;
  for (std::size_t k = 0; k < path.getStateCount(); ++k) {
    const auto* q = path.getState(k)->as<ob::RealVectorStateSpace::StateType>();
    std::cout << "  state " << k << ": q = (";
    for (std::size_t j = 0; j < joints.size(); ++j) std::cout << (j ? ", " : "") << q->values[j];
    std::cout << ")\n";
    if (k + 1 == path.getStateCount()) break;
    const tmcert::EdgeCertificate edge = validator->certify(path.getState(k), path.getState(k + 1));
    std::cout << "    edge " << k << " -> " << k + 1 << ": " << tmcert::to_string(edge.check.verdict);
    if (!edge.problem.empty()) std::cout << " (" << edge.problem << ")";
    std::cout << "\n";
    if (edge.check.verdict != tmcert::Verdict::Safe) ++failures;
  }
  std::cout << (failures == 0 ? "every edge of the path is certified safe\n"
                              : std::to_string(failures) + " edge(s) not certified safe\n");
  return failures == 0 ? 0 : 1;
}
