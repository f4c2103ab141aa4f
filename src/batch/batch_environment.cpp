#include "src/batch/batch_environment.h"

#include "src/report/report.h"
#include "src/io/robot.h"
#include "src/io/parse.h"
#include "src/verify/fixed_environment.h"

#include <nlohmann/json.hpp>

#include <algorithm>

namespace tmcert {

namespace {

// A message as a JSON string: never throws (a user string cut inside a
// UTF-8 sequence by quote_text is replaced, not refused).
std::string json_string(const std::string& s) {
  return nlohmann::json(s).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

// A body's motion as a trajectory (FixedEnvironment::check takes those).
Trajectory as_trajectory(const std::optional<Motion>& motion, const std::optional<Trajectory>& trajectory) {
  if (trajectory) return *trajectory;
  MotionSegment seg;
  seg.t0 = motion->t0;
  seg.t1 = motion->t1;
  seg.rational = *motion;
  return Trajectory{{seg}};
}

// "path.positions[1][2]" for a JointPathError of a request's path.
std::string path_field(const JointPathError& e) {
  std::string field = "path." + e.field;
  if (e.field == "joints" || e.field == "path") field = "path";  // the environment's joints do not fit this path; a limit between waypoints
  for (std::size_t i : e.index) field += "[" + std::to_string(i) + "]";
  return field;
}

}  // namespace

BatchEnvironment::BatchEnvironment(Scene scene, std::vector<SceneRobot> robots, const VerifyOptions& options,
                                   std::string base, bool stats)
    : scene_(std::move(scene)), robots_list_(std::move(robots)), options_(options), base_(std::move(base)),
      stats_(stats) {
  if (!options_.epsilon || !(*options_.epsilon > 0)) throw InputError("epsilon: must be given and > 0");
  robot_of_.assign(scene_.bodies.size(), -1);
  for (std::size_t r = 0; r < robots_list_.size(); ++r) {
    robots_.emplace(robots_list_[r].robot->name(), static_cast<int>(r));
    for (int b : robots_list_[r].bodies) robot_of_[b] = static_cast<int>(r);
  }
  for (std::size_t i = 0; i < scene_.bodies.size(); ++i) {
    const Body& b = scene_.bodies[i];
    names_.emplace(b.name, static_cast<int>(i));
    if (robot_of_[i] < 0 && b.moves())
      throw InputError(scene_.source + ": bodies[" + std::to_string(i) +
                       "].motion: the bodies of a batch environment are fixed (each request gives the moved "
                       "body's motion)");
  }
  // Each request names its checks: the environment's would say nothing.
  // Only robot links move in it, so its default checks all involve a link;
  // a check of two other bodies was written, and is refused.
  for (const auto& [a, b] : scene_.checks)
    if (robot_of_[a] < 0 && robot_of_[b] < 0)
      throw InputError(scene_.source + ": checks: not used in a batch environment (each request names the bodies "
                                       "it is checked against, by default every other body)");
}

BatchEnvironment::~BatchEnvironment() = default;

BatchEnvironment::Worker::Worker(const BatchEnvironment& environment) : environment_(environment) {}

BatchEnvironment::Worker::~Worker() = default;

CheckResult BatchEnvironment::Worker::check(const Body& moved, const std::vector<Trajectory>& motion, int obstacle,
                                            const Exact& clearance, std::tuple<int, int, int> key,
                                            const std::string& source) {
  const BatchEnvironment& env = environment_;
  const Body& other = env.scene_.bodies[obstacle];
  if (clearance > 0 || moved.tolerance > 0 || other.tolerance > 0) {
    // Clearances and tolerances: the general check of the pair as a scene
    // of its own (FixedEnvironment has neither); both bodies are prepared
    // for this check.
    Scene pair;
    pair.source = source;
    pair.bodies = {moved, other};
    pair.bodies[0].motion.reset();
    pair.bodies[0].trajectory = motion.at(0);
    pair.checks = {{0, 1}};
    pair.clearance = clearance;
    return Verifier(pair, env.options_).check(0, 1, clearance);
  }
  auto prepare = [&] {
    return std::make_unique<FixedEnvironment>(other, std::vector<Body>{moved}, std::vector<std::pair<int, int>>{},
                                              env.options_);
  };
  std::unique_ptr<FixedEnvironment> own;
  const FixedEnvironment* fixed = nullptr;
  if (std::get<0>(key) < 0 && std::get<1>(key) < 0) {  // an inline body: prepared for its request only
    own = prepare();
    fixed = own.get();
  } else {
    std::unique_ptr<FixedEnvironment>& cached = prepared_[key];
    if (!cached) cached = prepare();
    fixed = cached.get();
  }
  return fixed->check(motion).checks.at(0);  // bodies {1: the moved body, 0: the obstacle}
}

RequestOutcome BatchEnvironment::Worker::run(const std::string& text, std::size_t index, std::size_t line_number) {
  const BatchEnvironment& env = environment_;
  const Scene& scene = env.scene_;
  const std::string source = "line " + std::to_string(line_number);
  RequestLine request;
  RequestOutcome out;
  const std::string head = "{\"index\":" + std::to_string(index) + ",\"id\":";
  try {
    parse_request_line(text, source, env.base_, request);
    // What moves: a body of the environment, the request's own body, or
    // the links of a robot of the environment.
    int mover = -1, robot = -1;
    if (!request.robot.empty()) {
      const auto it = env.robots_.find(request.robot);
      if (it == env.robots_.end())
        throw InputError(source + ": robot: unknown robot " + quote_text(request.robot) + " (not in the environment)");
      robot = it->second;
    } else if (request.inline_body) {
      if (env.names_.count(request.body))
        throw InputError(source + ": body.name: " + quote_text(request.body) +
                         " is a body of the environment (give its name instead, or another name)");
    } else {
      const auto it = env.names_.find(request.body);
      if (it == env.names_.end())
        throw InputError(source + ": body: unknown body " + quote_text(request.body) + " (not in the environment)");
      mover = it->second;
      if (env.robot_of_[mover] >= 0)
        throw InputError(source + ": body: " + quote_text(request.body) +
                         " is a link of a robot (move the robot along a path instead)");
    }
    // The obstacles: the bodies named, or every other body; never a
    // robot's link (where a robot stands is a request's business).
    std::vector<int> obstacles;
    for (std::size_t k = 0; k < request.checks.size(); ++k) {
      const auto it = env.names_.find(request.checks[k]);
      const std::string field = source + ": checks[" + std::to_string(k) + "]: ";
      if (it == env.names_.end())
        throw InputError(field + "unknown body " + quote_text(request.checks[k]) + " (not in the environment)");
      if (it->second == mover) throw InputError(field + "a body cannot be checked against itself");
      if (env.robot_of_[it->second] >= 0)
        throw InputError(field + quote_text(request.checks[k]) + " is a link of a robot, not an obstacle");
      obstacles.push_back(it->second);
    }
    if (request.checks.empty())
      for (int b = 0; b < static_cast<int>(scene.bodies.size()); ++b)
        if (b != mover && env.robot_of_[b] < 0) obstacles.push_back(b);
    const Exact& clearance = request.clearance ? *request.clearance : scene.clearance;  // not a copy (below)

    // The moved bodies and their motions: one body, or a robot's links.
    Scene moved;
    std::vector<std::pair<int, int>> self_pairs;  // pairs of links (indices into moved.bodies)
    if (robot >= 0) {
      const SceneRobot& r = env.robots_list_[robot];
      const JointPath path{r.joints,           request.path_times,      request.path_positions,
                           request.path_interpolation, request.path_velocities, request.path_accelerations};
      RobotBodies links;
      try {
        links = add_robot(moved, *r.robot, path);
      } catch (const JointPathError& e) {
        throw InputError(source + ": " + path_field(e) + ": " + e.what());
      }
      if (r.self_collision) self_pairs = robot_default_checks(*r.robot, links, {}, true, r.allowed_pairs);
    } else if (request.inline_body) {
      moved.bodies.push_back(std::move(*request.inline_body));
      moved.bodies[0].motion = std::move(request.motion);
      moved.bodies[0].trajectory = std::move(request.trajectory);
    }
    // A body of the environment moves as this worker's own copy of it, made
    // on its first request, with the request's motion.  Not a copy per
    // request: a copy shares the handles of the body's exact numbers, whose
    // reference counts the environment's body shares with every worker:
    // with several threads each copy and its destruction were atomic
    // writes to the same memory from every thread.
    Body* own = nullptr;
    if (mover >= 0) {
      auto it = movers_.find(mover);
      if (it == movers_.end()) it = movers_.emplace(mover, scene.bodies[mover]).first;
      own = &it->second;
      own->motion = std::move(request.motion);
      own->trajectory = std::move(request.trajectory);
    }
    if (obstacles.empty() && self_pairs.empty())
      throw InputError(source + ": " + (robot >= 0 ? "robot" : "body") +
                       ": the environment has nothing to check it against");

    // Each check's bodies for the report, in the order of the check.
    Scene names;
    names.bodies.resize(2);
    Verdict verdict = Verdict::Safe;
    std::string checks;
    auto add = [&](CheckResult r, const Body& a, const Body& b) {
      r.bodies = {0, 1};
      names.bodies[0].name = a.name;
      names.bodies[0].enlarged = a.enlarged;
      names.bodies[1].name = b.name;
      names.bodies[1].enlarged = b.enlarged;
      nlohmann::ordered_json check = nlohmann::ordered_json::parse(check_json(names, r));
      if (!env.stats_) check.erase("stats");  // work counters and seconds: only on request
      if (!checks.empty()) checks += ',';
      checks += check.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
      if (r.verdict == Verdict::Collision) verdict = Verdict::Collision;
      else if (r.verdict == Verdict::Undecided && verdict == Verdict::Safe) verdict = Verdict::Undecided;
    };
    for (std::size_t m = 0; m < (own ? 1 : moved.bodies.size()); ++m) {
      const Body& body = own ? *own : moved.bodies[m];
      // One vector for every obstacle (FixedEnvironment::check takes one):
      // not a copy of the motion's exact numbers per check.
      const std::vector<Trajectory> motion{as_trajectory(body.motion, body.trajectory)};
      for (const int o : obstacles) {
        const std::tuple<int, int, int> key{robot, robot >= 0 ? static_cast<int>(m) : mover, o};
        add(check(body, motion, o, clearance, key, source), body, scene.bodies[o]);
      }
    }
    if (!self_pairs.empty()) {
      // Two links both move: checked as in a scene of the robot's links.
      moved.source = source;
      const Verifier links(moved, env.options_);
      for (const auto& [a, b] : self_pairs) add(links.check(a, b, clearance), moved.bodies[a], moved.bodies[b]);
    }
    out.kind = verdict == Verdict::Safe        ? RequestOutcome::Kind::Safe
               : verdict == Verdict::Collision ? RequestOutcome::Kind::Collision
                                               : RequestOutcome::Kind::Undecided;
    out.line = head + request.id + ",\"verdict\":\"" + to_string(verdict) + "\"";
    if (env.options_.kernel == KernelKind::Fast) out.line += ",\"certified\":false";
    // What the reader did to the line's own data (an inline body's mesh,
    // rpy angles): as a result document's "notes" and "warnings".
    for (const auto& [key, list] : {std::pair{"notes", &request.notes}, std::pair{"warnings", &request.warnings}}) {
      if (list->empty()) continue;
      out.line += std::string(",\"") + key + "\":[";
      for (std::size_t k = 0; k < list->size(); ++k) out.line += (k ? "," : "") + json_string((*list)[k]);
      out.line += "]";
    }
    out.line += ",\"checks\":[" + checks + "]}";
  } catch (const InputError& e) {
    std::string what = e.what();
    if (what.rfind(source + ": ", 0) != 0) what = source + ": " + what;
    out.kind = RequestOutcome::Kind::Error;
    out.line = head + request.id + ",\"error\":" + json_string(what) + "}";
  }
  return out;
}

}  // namespace tmcert
