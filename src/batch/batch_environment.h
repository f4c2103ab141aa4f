// The environment of a batch run (docs/scene-format.md "Batch runs"): a
// tmcert-scene/1 document of fixed bodies, read once, against which each
// request moves one body.  Bodies are prepared once per worker
// (src/verify/fixed_environment.h) and every request costs only its search.
#pragma once

#include "src/model/model.h"
#include "src/io/parse.h"
#include "src/verify/verify.h"

#include <cstddef>
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <unordered_map>
#include <utility>
#include <vector>

namespace tmcert {

class FixedEnvironment;

// The outcome of one request: its result line (JSON, no line break) and
// what it counts as in the run's summary.
struct RequestOutcome {
  enum class Kind { Safe, Collision, Undecided, Error };
  Kind kind = Kind::Error;
  std::string line;
};

class BatchEnvironment {
 public:
  // `scene`: the environment (every body but robot links fixed: no motion,
  // or a one-pose motion; no checks), `robots` its robots (parse_scene_file); `base`: the directory inline bodies'
  // mesh files are relative to.  `options.epsilon` must be > 0.  `stats`:
  // give each check its "stats" (work counters and wall-clock seconds: not
  // reproducible); without it results are the same bytes on every run.
  // Throws InputError naming the field when the scene cannot be one.
  BatchEnvironment(Scene scene, std::vector<SceneRobot> robots, const VerifyOptions& options, std::string base,
                   bool stats);
  ~BatchEnvironment();
  BatchEnvironment(const BatchEnvironment&) = delete;
  BatchEnvironment& operator=(const BatchEnvironment&) = delete;

  // Bodies prepared for one thread: FixedEnvironment::check is serialized,
  // so each worker thread has its own.
  class Worker {
   public:
    explicit Worker(const BatchEnvironment& environment);
    ~Worker();
    Worker(const Worker&) = delete;
    Worker& operator=(const Worker&) = delete;

    // The result of request number `index` (0-based among the requests),
    // written as line `line_number` (1-based) of its file.  A bad request
    // is an outcome of kind Error whose line says why, naming the field;
    // never an exception for bad input.
    RequestOutcome run(const std::string& text, std::size_t index, std::size_t line_number);

   private:
    // One check of the moved body (the request's body, or a robot's link
    // moving along its path; `motion`: its one trajectory) against an
    // obstacle of the environment.
    CheckResult check(const Body& moved, const std::vector<Trajectory>& motion, int obstacle, const Exact& clearance,
                      std::tuple<int, int, int> key, const std::string& source);

    const BatchEnvironment& environment_;
    // (robot or -1, moved body or link, obstacle) -> the pair prepared,
    // made on first use; robot -1 and body -1 (an inline body) is never kept.
    std::map<std::tuple<int, int, int>, std::unique_ptr<FixedEnvironment>> prepared_;
    // Environment body -> this worker's copy of it, moved by the requests
    // that move that body (Worker::run).
    std::map<int, Body> movers_;
  };

  const Scene& scene() const { return scene_; }
  const VerifyOptions& options() const { return options_; }

 private:
  Scene scene_;
  std::vector<SceneRobot> robots_list_;
  VerifyOptions options_;
  std::string base_;
  bool stats_;
  std::unordered_map<std::string, int> names_;   // bodies, links included
  std::unordered_map<std::string, int> robots_;  // index into robots_list_
  std::vector<int> robot_of_;                    // per body: its robot, or -1
};

}  // namespace tmcert
