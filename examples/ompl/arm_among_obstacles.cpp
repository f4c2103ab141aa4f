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
#include <tmcert/ompl.h>
#include <tmcert/tmcert.h>

#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <chrono>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#ifndef TMCERT_SOURCE_DIR
#define TMCERT_SOURCE_DIR "."
#endif

namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace {

// The arm at the origin and the obstacles (exact decimals).  A scene's
// robot has a joint path; the planner ignores it (here: standing at q0).
tmcert::Scene planning_scene(const std::string& urdf, const std::vector<std::string>& joints,
                             const std::vector<tmcert::Number>& q0) {
  tmcert::SceneBuilder b;
  b.add_body("floor").polygon({{-1, -1, "-0.01"}, {1, -1, "-0.01"}, {1, 1, "-0.01"}, {-1, 1, "-0.01"}});
  b.add_body("pillar")
      .polygon({{"0.29", "-0.03", 0}, {"0.29", "0.03", 0}, {"0.29", "0.03", "0.5"}, {"0.29", "-0.03", "0.5"}})
      .polygon({{"0.35", "-0.03", 0}, {"0.35", "0.03", 0}, {"0.35", "0.03", "0.5"}, {"0.35", "-0.03", "0.5"}})
      .polygon({{"0.29", "-0.03", 0}, {"0.35", "-0.03", 0}, {"0.35", "-0.03", "0.5"}, {"0.29", "-0.03", "0.5"}})
      .polygon({{"0.29", "0.03", 0}, {"0.35", "0.03", 0}, {"0.35", "0.03", "0.5"}, {"0.29", "0.03", "0.5"}})
      .polygon({{"0.29", "-0.03", "0.5"}, {"0.35", "-0.03", "0.5"}, {"0.35", "0.03", "0.5"}, {"0.29", "0.03", "0.5"}});
  b.add_robot("arm", urdf).path(joints, {0, 1}, {q0, q0});
  return b.build();
}

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

  const std::vector<std::string> joints = {"j1", "j2", "j3", "j4", "j5", "j6"};
  const double q0[6] = {-1.2, 1.0, 0.8, 0, 0.3, 0}, q1[6] = {1.2, 1.0, 0.8, 0, 0.3, 0};
  auto space = std::make_shared<ob::RealVectorStateSpace>(joints.size());
  og::SimpleSetup setup(space);
  std::shared_ptr<ob::MotionValidator> validator;
  try {
    const tmcert::Scene scene = planning_scene(urdf, joints, std::vector<tmcert::Number>(q0, q0 + 6));
    space->setBounds(tmcert::joint_bounds(scene, "arm", joints));  // the URDF limits, rounded inward
    tmcert::VerifyOptions options;
    options.epsilon = tmcert::Number("1/10000");  // 0.1 mm
    // Every link against the floor and the pillar, and self-collision on.
    validator = tmcert::use_certified_arm(setup.getSpaceInformation(), scene, "arm", joints, true, {}, options);
  } catch (const tmcert::InputError& e) {
    std::cerr << e.what() << "\n";
    return 3;
  }

  ob::ScopedState<ob::RealVectorStateSpace> start(space), goal(space);
  for (int k = 0; k < 6; ++k) {
    start[k] = q0[k];
    goal[k] = q1[k];
  }
  setup.setStartAndGoalStates(start, goal);
  setup.setPlanner(std::make_shared<og::RRTConnect>(setup.getSpaceInformation()));
  std::cout << "the straight joint edge from start to goal: "
            << tmcert::to_string(tmcert::certify_edge(*validator, start.get(), goal.get()).verdict) << "\n";

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
    const tmcert::EdgeResult edge = tmcert::certify_edge(*validator, path.getState(k), path.getState(k + 1));
    std::cout << "    edge " << k << " -> " << k + 1 << ": " << tmcert::to_string(edge.verdict);
    if (!edge.problem.empty()) std::cout << " (" << edge.problem << ")";
    std::cout << "\n";
    if (edge.verdict != tmcert::Verdict::Safe) ++failures;
  }
  std::cout << (failures == 0 ? "every edge of the path is certified safe\n"
                              : std::to_string(failures) + " edge(s) not certified safe\n");
  return failures == 0 ? 0 : 1;
}
