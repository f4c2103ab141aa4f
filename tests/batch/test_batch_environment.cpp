// src/batch/batch_environment: the environment of a batch run, read once,
// against which each request moves one body.  A request's result line is
// the same bytes however often it is run (bodies prepared once and
// reused), its kind matches its verdict, and a bad request is an Error
// outcome naming its field and line, never an exception.
#include "src/batch/batch_environment.h"

#include <boost/test/unit_test.hpp>

#include <string>
#include <vector>

using namespace tmcert;

namespace {

const std::string kExample = std::string(TMCERT_TEST_DATA) + "/../../examples/batch";

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

struct Environment {
  std::unique_ptr<BatchEnvironment> env;
  Environment() {
    std::vector<SceneRobot> robots;
    Scene scene = parse_scene_file(kExample + "/environment.json", robots);
    VerifyOptions options;
    options.epsilon = Exact(1, 100);
    env = std::make_unique<BatchEnvironment>(std::move(scene), std::move(robots), options, kExample, false);
  }
};

const std::string kSafe =
    R"({"id":"e0","body":"cube","motion":{"type":"keyframes","poses":[{"translation":[-1,-3,1]},{"translation":[3,-3,1]}]}})";
const std::string kCollision =
    R"({"id":"e1","body":"cube","motion":{"type":"keyframes","poses":[{"translation":[0,0,1]},{"translation":[3,3,1]}]}})";

}  // namespace

BOOST_AUTO_TEST_SUITE(batch_environment)

BOOST_AUTO_TEST_CASE(requests_give_their_verdicts) {
  const Environment e;
  BOOST_TEST(e.env->scene().bodies.size() >= 3u);
  BatchEnvironment::Worker worker(*e.env);
  const RequestOutcome safe = worker.run(kSafe, 0, 1);
  BOOST_TEST((safe.kind == RequestOutcome::Kind::Safe));
  BOOST_TEST(safe.line.rfind(R"({"index":0,"id":"e0","verdict":"safe")", 0) == 0u);
  BOOST_TEST(!has(safe.line, "\n"));
  BOOST_TEST(!has(safe.line, "\"seconds\""));  // no stats asked: reproducible bytes
  const RequestOutcome hit = worker.run(kCollision, 1, 2);
  BOOST_TEST((hit.kind == RequestOutcome::Kind::Collision));
  BOOST_TEST(hit.line.rfind(R"({"index":1,"id":"e1","verdict":"collision")", 0) == 0u);
  BOOST_TEST(has(hit.line, R"("witness":{"t":"1/4")"));
}

BOOST_AUTO_TEST_CASE(same_bytes_on_every_run_and_worker) {
  const Environment e;
  BatchEnvironment::Worker first(*e.env), second(*e.env);
  const std::string once = first.run(kCollision, 5, 6).line;
  BOOST_TEST(first.run(kCollision, 5, 6).line == once);  // the prepared pair reused
  BOOST_TEST(second.run(kCollision, 5, 6).line == once);
  BOOST_TEST(first.run(kSafe, 5, 6).line != once);
}

BOOST_AUTO_TEST_CASE(bad_requests_are_error_outcomes) {
  const Environment e;
  BatchEnvironment::Worker worker(*e.env);
  const RequestOutcome unknown = worker.run(
      R"({"id":"x","body":"nobody","motion":{"type":"keyframes","poses":[{"translation":[0,0,1]},{"translation":[1,0,1]}]}})",
      3, 7);
  BOOST_TEST((unknown.kind == RequestOutcome::Kind::Error));
  BOOST_TEST(has(unknown.line, "\"error\":"));
  BOOST_TEST(has(unknown.line, "nobody"));
  BOOST_TEST(has(unknown.line, "line 7"));
  const RequestOutcome broken = worker.run("{\"id\": 1, \"body\": ", 4, 8);
  BOOST_TEST((broken.kind == RequestOutcome::Kind::Error));
  BOOST_TEST(has(broken.line, "\"error\":"));
  // The worker still answers afterwards.
  BOOST_TEST((worker.run(kSafe, 5, 9).kind == RequestOutcome::Kind::Safe));
}

BOOST_AUTO_TEST_SUITE_END()
