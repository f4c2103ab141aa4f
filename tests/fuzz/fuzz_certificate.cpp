// Fuzz target: the certificate checker (tests/fuzz/README.md).  The first
// byte of the input picks one of the scenes of tests/data/certificates, the
// rest is a certificate for it (the corpus holds the valid certificates of
// those scenes, so mutants are near misses of real proofs and, through the
// first byte, certificates transplanted to another scene).
//
// Property: a certificate the checker accepts proves its verdicts.  Every
// check it accepts as "safe" or "collision" must have that verdict in
// `verify` with the exact kernel on the same scene (computed once per
// scene; checks the exact kernel leaves undecided are not compared).  A
// malformed certificate must be rejected or be bad input (InputError);
// any other exception, a crash or a sanitizer report is a bug.
#include "src/certificate/check.h"
#include "src/io/parse.h"
#include "src/verify/verify.h"
#include "tests/fuzz/fuzz.h"

#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace {

struct Truth {
  tmcert::Scene scene;
  // Verdict of the exact kernel per ordered pair of body names.
  std::map<std::pair<std::string, std::string>, tmcert::Verdict> verdicts;
};

const char* const kScenes[] = {"probe-safe.json", "drop.json",         "solid-outside.json", "solid-inside.json",
                               "solid-singular.json", "two-moving.json", "solid-two-shells.json"};

const std::vector<std::unique_ptr<Truth>>& truths() {
  static const std::vector<std::unique_ptr<Truth>> all = [] {
    std::vector<std::unique_ptr<Truth>> out;
    for (const char* name : kScenes) {
      auto t = std::make_unique<Truth>();
      t->scene = tmcert::parse_scene_file(tmcert::fuzz::test_data() + "/certificates/" + name);
      tmcert::VerifyOptions options;
      options.kernel = tmcert::KernelKind::Exact;
      options.epsilon = t->scene.epsilon ? *t->scene.epsilon : tmcert::default_epsilon(t->scene);
      options.max_depth = t->scene.max_depth;
      const tmcert::SceneResult result = tmcert::verify_scene(t->scene, options);
      for (const tmcert::CheckResult& c : result.checks) {
        const std::string a = t->scene.bodies[c.bodies[0]].name, b = t->scene.bodies[c.bodies[1]].name;
        t->verdicts[{a, b}] = c.verdict;
        t->verdicts[{b, a}] = c.verdict;
      }
      out.push_back(std::move(t));
    }
    return out;
  }();
  return all;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0 || size > (1u << 20)) return 0;
  const Truth& truth = *truths()[data[0] % truths().size()];
  const std::string text(reinterpret_cast<const char*>(data + 1), size - 1);
  try {
    const nlohmann::json doc = tmcert::certificate::parse_certificate_text(text, "fuzz.cert.json");
    const tmcert::certificate::CheckOutcome outcome = tmcert::certificate::check_certificate(truth.scene, doc, "fuzz.cert.json");
    if (!outcome.ok) return 0;
    // Accepted: every verdict it states must be the true one.
    if (!doc.is_object() || !doc.contains("checks") || !doc["checks"].is_array())
      tmcert::fuzz::fail("a certificate without a checks array was accepted");
    for (const auto& c : doc["checks"]) {
      const std::string verdict = c.at("verdict").get<std::string>();
      if (verdict != "safe" && verdict != "collision") continue;
      const auto& bodies = c.at("bodies");
      const auto key = std::pair{bodies.at(0).get<std::string>(), bodies.at(1).get<std::string>()};
      const auto it = truth.verdicts.find(key);
      if (it == truth.verdicts.end())
        tmcert::fuzz::fail("accepted a claim about a check the scene does not have: " + key.first + " x " + key.second);
      if (it->second == tmcert::Verdict::Undecided) continue;
      const tmcert::Verdict claimed = verdict == "safe" ? tmcert::Verdict::Safe : tmcert::Verdict::Collision;
      if (claimed != it->second)
        tmcert::fuzz::fail("accepted a false \"" + verdict + "\" for " + key.first + " x " + key.second +
                           " (exact kernel: " + tmcert::to_string(it->second) + ")");
    }
  } catch (const tmcert::InputError&) {
    // bad input, reported: fine
  } catch (const std::exception& e) {
    tmcert::fuzz::fail(std::string("unexpected exception: ") + e.what());
  } catch (...) {
    tmcert::fuzz::fail("unexpected exception");
  }
  return 0;
}
