// OMPL's RRTConnect plans a rigid cube through a square hole in a wall,
// with tmcert's certified motion validator and state validity checker in
// place of sampling checks; then every edge of the returned path is
// certified again and printed.
//
// The wall is the slab |x| <= 1/20 spanning |y|, |z| <= 5/2 with a hole
// |y|, |z| <= 1/4; the cube has side 3/10 (its diagonal, 0.52, does not fit
// through the hole in every orientation).  Start (-1, 6/5, 1/2), goal
// (1, 6/5, -4/5): the straight line between them hits the wall.
//
// Exit status: 0 when a path was found and every edge of it is certified
// safe, 1 otherwise (no path in the time limit, or an edge not certified).
// Usage: ompl_rigid_passage [--seed N] [--time SECONDS]
#include <tmcert/ompl.h>
#include <tmcert/tmcert.h>

#include <ompl/base/spaces/SE3StateSpace.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <chrono>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace {

// A rectangle of the plane `axis` = c, spanning [a0, a1] x [b0, b1] in the
// two other coordinates (in cyclic order), as JSON.
std::string rect(int axis, const std::string& c, const std::string& a0, const std::string& a1, const std::string& b0,
                 const std::string& b1) {
  auto point = [&](const std::string& a, const std::string& b) {
    std::string p[3];
    p[axis] = c;
    p[(axis + 1) % 3] = a;
    p[(axis + 2) % 3] = b;
    return "[\"" + p[0] + "\",\"" + p[1] + "\",\"" + p[2] + "\"]";
  };
  return "[" + point(a0, b0) + "," + point(a1, b0) + "," + point(a1, b1) + "," + point(a0, b1) + "]";
}

std::string scene_text() {
  const std::string w = "1/20", L = "5/2", h = "1/4", r = "3/20";
  std::ostringstream wall, cube;
  bool first = true;
  auto add = [&](std::ostringstream& out, const std::string& poly) {
    if (!first) out << ",";
    first = false;
    out << poly;
  };
  for (const std::string x : {"-" + w, w}) {  // both faces of the slab, around the hole
    add(wall, rect(0, x, "-" + L, "-" + h, "-" + L, L));
    add(wall, rect(0, x, h, L, "-" + L, L));
    add(wall, rect(0, x, "-" + h, h, "-" + L, "-" + h));
    add(wall, rect(0, x, "-" + h, h, h, L));
  }
  add(wall, rect(1, "-" + h, "-" + h, h, "-" + w, w));  // the hole's sides: y = -h, y = h (z, x)
  add(wall, rect(1, h, "-" + h, h, "-" + w, w));
  add(wall, rect(2, "-" + h, "-" + w, w, "-" + h, h));  // z = -h, z = h (x, y)
  add(wall, rect(2, h, "-" + w, w, "-" + h, h));
  first = true;
  for (int axis = 0; axis < 3; ++axis)
    for (const std::string c : {"-" + r, r}) add(cube, rect(axis, c, "-" + r, r, "-" + r, r));
  return "{\"format\": \"tmcert-scene/1\", \"bodies\": [{\"name\": \"wall\", \"polygons\": [" + wall.str() +
         "]}, {\"name\": \"cube\", \"polygons\": [" + cube.str() + "]}]}";
}

void print_state(const ob::State* s) {
  const auto* x = s->as<ob::SE3StateSpace::StateType>();
  const auto& q = x->rotation();
  std::cout << "(" << x->getX() << ", " << x->getY() << ", " << x->getZ() << ") q(w,x,y,z) = (" << q.w << ", " << q.x
            << ", " << q.y << ", " << q.z << ")";
}

}  // namespace

int main(int argc, char** argv) {
  std::uint32_t seed = 20261125;
  double seconds = 20;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--seed" && i + 1 < argc) seed = static_cast<std::uint32_t>(std::strtoul(argv[++i], nullptr, 10));
    else if (a == "--time" && i + 1 < argc) seconds = std::strtod(argv[++i], nullptr);
    else {
      std::cerr << "usage: ompl_rigid_passage [--seed N] [--time SECONDS]\n";
      return 3;
    }
  }
  ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
  ompl::RNG::setSeed(seed);

  auto space = std::make_shared<ob::SE3StateSpace>();
  ob::RealVectorBounds bounds(3);
  bounds.setLow(0, -1.5);
  bounds.setHigh(0, 1.5);
  for (int i = 1; i < 3; ++i) {  // inside the wall's extent: the hole is the only way through
    bounds.setLow(i, -2);
    bounds.setHigh(i, 2);
  }
  space->setBounds(bounds);
  og::SimpleSetup setup(space);
  std::shared_ptr<ob::MotionValidator> validator;
  try {
    const tmcert::Scene scene = tmcert::Scene::from_json(scene_text(), "rigid_passage");
    tmcert::VerifyOptions options;
    options.epsilon = tmcert::Number("1/1000");
    // The cube moves; every other body of the scene (the wall) is an obstacle.
    validator = tmcert::use_certified_se3(setup.getSpaceInformation(), scene, "cube", options);
  } catch (const tmcert::InputError& e) {
    std::cerr << e.what() << "\n";
    return 3;
  }

  ob::ScopedState<ob::SE3StateSpace> start(space), goal(space);
  start->setXYZ(-1, 1.2, 0.5);
  start->rotation().setIdentity();
  goal->setXYZ(1, 1.2, -0.8);
  goal->rotation().setIdentity();
  setup.setStartAndGoalStates(start, goal);
  setup.setPlanner(std::make_shared<og::RRTConnect>(setup.getSpaceInformation()));

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

  // Every edge again, independently of what the planner did.
  int failures = 0;
  for (std::size_t k = 0; k < path.getStateCount(); ++k) {
    std::cout << "  state " << k << ": ";
    print_state(path.getState(k));
    std::cout << "\n";
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
