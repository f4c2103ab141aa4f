#include "src/batch/batch_environment.h"

#include "src/cli/report.h"
#include "src/scene/parse.h"
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

// The motion as a trajectory (FixedEnvironment::check takes trajectories).
Trajectory as_trajectory(const RequestLine& request) {
  if (request.trajectory) return *request.trajectory;
  MotionSegment seg;
  seg.t0 = request.motion->t0;
  seg.t1 = request.motion->t1;
  seg.rational = *request.motion;
  return Trajectory{{seg}};
}

// The moved body with the request's motion (the general path's scene).
Body with_motion(const Body& body, const RequestLine& request) {
  Body b = body;
  b.motion = request.motion;
  b.trajectory = request.trajectory;
  return b;
}

}  // namespace

BatchEnvironment::BatchEnvironment(Scene scene, const VerifyOptions& options, std::string base, bool stats)
    : scene_(std::move(scene)), options_(options), base_(std::move(base)), stats_(stats) {
  if (!(options_.epsilon > 0)) throw InputError("epsilon: must be > 0");
  for (std::size_t i = 0; i < scene_.bodies.size(); ++i) {
    const Body& b = scene_.bodies[i];
    if (b.trajectory && !b.trajectory->segments.empty() && b.trajectory->segments.front().link)
      throw InputError(scene_.source + ": robots: robots cannot be part of a batch environment (its bodies are fixed)");
    if (b.moves())
      throw InputError(scene_.source + ": bodies[" + std::to_string(i) +
                       "].motion: the bodies of a batch environment are fixed (each request gives the moved "
                       "body's motion)");
    names_.emplace(b.name, static_cast<int>(i));
  }
  if (!scene_.checks.empty())
    throw InputError(scene_.source + ": checks: not used in a batch environment (each request names the bodies "
                                     "it is checked against, by default every other body)");
}

BatchEnvironment::~BatchEnvironment() = default;

BatchEnvironment::Worker::Worker(const BatchEnvironment& environment) : environment_(environment) {}

BatchEnvironment::Worker::~Worker() = default;

RequestOutcome BatchEnvironment::Worker::run(const std::string& text, std::size_t index, std::size_t line_number) {
  const BatchEnvironment& env = environment_;
  const Scene& scene = env.scene_;
  const std::string source = "line " + std::to_string(line_number);
  RequestLine request;
  RequestOutcome out;
  const std::string head = "{\"index\":" + std::to_string(index) + ",\"id\":";
  try {
    parse_request_line(text, source, env.base_, request);
    // The moved body: a body of the environment, or the request's own.
    int mover = -1;
    if (request.inline_body) {
      if (env.names_.count(request.body))
        throw InputError(source + ": body.name: " + quote_text(request.body) +
                         " is a body of the environment (give its name instead, or another name)");
    } else {
      const auto it = env.names_.find(request.body);
      if (it == env.names_.end())
        throw InputError(source + ": body: unknown body " + quote_text(request.body) + " (not in the environment)");
      mover = it->second;
    }
    const Body& moved = request.inline_body ? *request.inline_body : scene.bodies[mover];
    std::vector<int> obstacles;
    for (std::size_t k = 0; k < request.checks.size(); ++k) {
      const auto it = env.names_.find(request.checks[k]);
      const std::string field = source + ": checks[" + std::to_string(k) + "]: ";
      if (it == env.names_.end())
        throw InputError(field + "unknown body " + quote_text(request.checks[k]) + " (not in the environment)");
      if (it->second == mover) throw InputError(field + "a body cannot be checked against itself");
      obstacles.push_back(it->second);
    }
    if (request.checks.empty())
      for (int b = 0; b < static_cast<int>(scene.bodies.size()); ++b)
        if (b != mover) obstacles.push_back(b);
    if (obstacles.empty())
      throw InputError(source + ": body: the environment has no other body to check " + quote_text(request.body) +
                       " against");
    const Exact clearance = request.clearance ? *request.clearance : scene.clearance;

    // The check's bodies for the report: the moved body, then the obstacle.
    Scene names;
    names.bodies.resize(2);
    names.bodies[0].name = moved.name;
    names.bodies[0].enlarged = moved.enlarged;
    const Trajectory trajectory = as_trajectory(request);
    Verdict verdict = Verdict::Safe;
    std::string checks;
    for (const int o : obstacles) {
      const Body& obstacle = scene.bodies[o];
      CheckResult r;
      if (clearance > 0 || moved.tolerance > 0 || obstacle.tolerance > 0) {
        // Clearances and tolerances: the general check of the pair as a
        // scene of its own (FixedEnvironment has neither); both bodies
        // are prepared for this request.
        Scene pair;
        pair.source = source;
        pair.bodies = {with_motion(moved, request), obstacle};
        pair.checks = {{0, 1}};
        pair.clearance = clearance;
        r = Verifier(pair, env.options_).check(0, 1, clearance);
      } else {
        std::unique_ptr<FixedEnvironment> own;
        const FixedEnvironment* fixed = nullptr;
        if (mover >= 0) {
          std::unique_ptr<FixedEnvironment>& cached = prepared_[{mover, o}];
          if (!cached) cached = std::make_unique<FixedEnvironment>(obstacle, std::vector<Body>{moved},
                                                                   std::vector<std::pair<int, int>>{}, env.options_);
          fixed = cached.get();
        } else {  // an inline body is prepared for its request only
          own = std::make_unique<FixedEnvironment>(obstacle, std::vector<Body>{moved},
                                                   std::vector<std::pair<int, int>>{}, env.options_);
          fixed = own.get();
        }
        r = fixed->check({trajectory}).checks.at(0);  // bodies {1: the mover, 0: the obstacle}
      }
      r.bodies = {0, 1};
      names.bodies[1].name = obstacle.name;
      names.bodies[1].enlarged = obstacle.enlarged;
      nlohmann::ordered_json check = nlohmann::ordered_json::parse(check_json(names, r));
      if (!env.stats_) check.erase("stats");  // work counters and seconds: only on request
      if (!checks.empty()) checks += ',';
      checks += check.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
      if (r.verdict == Verdict::Collision) verdict = Verdict::Collision;
      else if (r.verdict == Verdict::Undecided && verdict == Verdict::Safe) verdict = Verdict::Undecided;
    }
    out.kind = verdict == Verdict::Safe        ? RequestOutcome::Kind::Safe
               : verdict == Verdict::Collision ? RequestOutcome::Kind::Collision
                                               : RequestOutcome::Kind::Undecided;
    out.line = head + request.id + ",\"verdict\":\"" + to_string(verdict) + "\"";
    if (env.options_.kernel == KernelKind::Fast) out.line += ",\"certified\":false";
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
