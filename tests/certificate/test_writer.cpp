// Certificates written after a verification are accepted by the checker,
// and altered ones are rejected (docs/certificate-format.md,
// proofs/certificates.md).
#include "src/certificate/check.h"
#include "src/certificate/writer.h"
#include "src/io/parse.h"
#include "src/verify/verify.h"

#include "kernels/real_roots.h"

#include <boost/test/unit_test.hpp>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <map>
#include <functional>
#include <string>
#include <vector>

namespace {

using namespace tmcert;
using json = nlohmann::json;

std::string data(const std::string& name) { return std::string(TMCERT_TEST_DATA) + "/" + name; }
std::string example(const std::string& name) { return std::string(TMCERT_TEST_DATA) + "/../../examples/" + name; }

struct Verified {
  Scene scene;
  SceneResult result;
  json certificate;
};

Verified verified(const std::string& path, KernelKind kernel = KernelKind::Filtered) {
  Verified v{parse_scene_file(path), {}, {}};
  VerifyOptions options;
  options.kernel = kernel;
  options.epsilon = v.scene.epsilon ? *v.scene.epsilon : default_epsilon(v.scene);
  options.max_depth = v.scene.max_depth;
  options.record_cover = true;
  v.result = verify_scene(v.scene, options);
  v.certificate = json::parse(certificate::certificate_json(v.scene, v.result));
  return v;
}

Exact rational_of(const json& x) {
  Exact q;
  BOOST_REQUIRE(parse_exact(x.get<std::string>(), q));
  return q;
}

bool accepted(const Verified& v, const json& certificate) {
  try {
    return certificate::check_certificate(v.scene, certificate, "certificate").ok;
  } catch (const InputError&) {
    return false;
  }
}

// Every scene with a known verdict: the certificate of its verification is
// accepted, and says the same verdicts.
// Scenes listed in tests/data/scenes/UNCERTIFIABLE ("<file><TAB><substring>"):
// certificates do not cover them (a solid body whose start pose is neither
// exact nor enclosed); file name -> expected message.
std::map<std::string, std::string> uncertifiable() {
  std::map<std::string, std::string> out;
  std::ifstream in(std::string(TMCERT_TEST_DATA) + "/scenes/UNCERTIFIABLE");
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    const std::size_t tab = line.find('\t');
    if (tab != std::string::npos) out[line.substr(0, tab)] = line.substr(tab + 1);
  }
  return out;
}

std::vector<std::string> scenes() {
  std::vector<std::string> out;
  const auto skip = uncertifiable();
  for (const auto& entry : std::filesystem::directory_iterator(std::string(TMCERT_TEST_DATA) + "/scenes"))
    if (entry.path().extension() == ".json" && !skip.count(entry.path().filename().string()))
      out.push_back(entry.path().string());
  for (const char* name : {"octagons-clear.json", "octagons-near.json", "octagons-collision.json",
                           "vertex-face-linear.json"})
    out.push_back(example(name));
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(certificate_roundtrip)

BOOST_AUTO_TEST_CASE(certificates_of_every_test_scene_are_accepted) {
  int safe = 0, collision = 0, undecided = 0, pieces = 0;
  for (const std::string& path : scenes()) {
    BOOST_TEST_CONTEXT(path) {
      for (KernelKind kernel : {KernelKind::Filtered, KernelKind::Exact}) {
        if (kernel == KernelKind::Exact && path.find("grid") != std::string::npos) continue;
        const Verified v = verified(path, kernel);
        const certificate::CheckOutcome outcome = certificate::check_certificate(v.scene, v.certificate, path);
        BOOST_TEST(outcome.ok, outcome.message);
        BOOST_REQUIRE_EQUAL(v.certificate["checks"].size(), v.result.checks.size());
        for (std::size_t k = 0; k < v.result.checks.size(); ++k) {
          BOOST_TEST(v.certificate["checks"][k]["verdict"].get<std::string>() ==
                     to_string(v.result.checks[k].verdict));
          const Verdict verdict = v.result.checks[k].verdict;
          safe += verdict == Verdict::Safe;
          collision += verdict == Verdict::Collision;
          undecided += verdict == Verdict::Undecided;
          pieces += static_cast<int>(v.certificate["checks"][k]["pieces"].size());
        }
      }
    }
  }
  // The set exercises every verdict and real proofs, not only trivial ones.
  BOOST_TEST(safe > 3);
  BOOST_TEST(collision > 3);
  BOOST_TEST(pieces > 20);
  BOOST_TEST_MESSAGE("checks: " << safe << " safe, " << collision << " collision, " << undecided << " undecided; "
                                << pieces << " pieces");
}

// The scenes certificates do not cover are refused with a message naming
// the body or check (docs/scene-format.md), not certified wrongly.
BOOST_AUTO_TEST_CASE(uncovered_scenes_get_no_certificate) {
  // None at present (URDF cylinders and spheres are certified since
  // check_primitive.h): whatever is listed must be refused.
  const auto listed = uncertifiable();
  for (const auto& [file, substring] : listed) {
    BOOST_TEST_CONTEXT(file) {
      const Scene scene = parse_scene_file(std::string(TMCERT_TEST_DATA) + "/scenes/" + file);
      BOOST_TEST(certificate::uncertifiable(scene).size() > 0u);
      std::string message;
      try {
        certificate::certificate_json(scene, SceneResult{});
      } catch (const InputError& e) {
        message = e.what();
      }
      BOOST_TEST(message.find(substring) != std::string::npos, "message: " << message);
    }
  }
}

BOOST_AUTO_TEST_CASE(the_fast_kernel_gets_no_certificate) {
  Scene scene = parse_scene_file(example("octagons-clear.json"));
  VerifyOptions options;
  options.kernel = KernelKind::Fast;
  options.epsilon = default_epsilon(scene);
  options.record_cover = true;
  const SceneResult result = verify_scene(scene, options);
  BOOST_CHECK_THROW(certificate::certificate_json(scene, result), InputError);
}

// Visits every separation direction of a proof tree (an inline tree:
// object forms only).
void each_direction(json& proof, const std::function<void(json&)>& f) {
  if (proof.contains("sep")) return f(proof["sep"]);
  for (json& part : proof["parts"]) each_direction(part, f);
}

// A check's proof `node` written out inline (shared nodes resolved, splits
// in the object form): the same claims without "nodes".
json inline_proof(const json& nodes, const json& node) {
  if (node.is_number_integer()) return inline_proof(nodes, nodes[node.get<std::size_t>()]);
  if (!node.is_array()) return node;
  json parts = json::array();
  for (std::size_t i = 1; i < node.size(); ++i) parts.push_back(inline_proof(nodes, node[i]));
  return {{"split", node[0]}, {"parts", std::move(parts)}};
}

json negated(const json& direction) {
  json out = json::array();
  for (const json& x : direction) out.push_back(to_string(-(x.is_string() ? rational_of(x) : Exact(x.get<long>()))));
  return out;
}

// A witness at an irrational time (octagons-collision: the exact first
// contact at t = 0.3026..., a root of a cubic): accepted as written, and
// rejected after any change to its root, interval or sub-features.
BOOST_AUTO_TEST_CASE(algebraic_witnesses_are_checked_exactly) {
  const Verified v = verified(example("octagons-collision.json"));
  BOOST_REQUIRE(v.result.checks[0].witness && v.result.checks[0].witness->root);
  BOOST_REQUIRE(accepted(v, v.certificate));
  const json& w = v.certificate["checks"][0]["witness"];
  BOOST_REQUIRE(w["t"].is_object());
  int tried = 0, rejected = 0;
  auto expect_rejected = [&](const std::function<void(json&)>& change, const std::string& what) {
    json altered = v.certificate;
    change(altered["checks"][0]["witness"]);
    ++tried;
    const bool ok = accepted(v, altered);
    BOOST_TEST(!ok, "accepted after: " << what);
    rejected += !ok;
  };
  auto integer = [](const json& x) { return CGAL::Gmpz(x.get<std::string>()); };
  auto text = [](const CGAL::Gmpz& z) { return to_string(Exact(z)); };
  // Each coefficient changed by one: another polynomial, whose root (if
  // any in the interval) is not a contact.
  for (std::size_t k = 0; k < w["t"]["root_of"].size(); ++k)
    expect_rejected([&](json& x) { x["t"]["root_of"][k] = text(integer(x["t"]["root_of"][k]) + 1); },
                    "root_of[" + std::to_string(k) + "] + 1");
  // The polynomial squared (not square-free), and times (t - lo) (a root at the end).
  expect_rejected([&](json& x) {
    PolyQ p;
    for (const json& c : x["t"]["root_of"]) p.push_back(Exact(integer(c)));
    const PolyZ q = primitive(mul(p, p));
    x["t"]["root_of"] = json::array();
    for (const CGAL::Gmpz& c : q) x["t"]["root_of"].push_back(text(c));
  }, "root_of squared");
  // The interval moved off the root, reversed, or widened past the check.
  expect_rejected([&](json& x) { x["t"]["interval"][0] = x["t"]["interval"][1]; x["t"]["interval"][1] = "1"; },
                  "interval moved above the root");
  expect_rejected([&](json& x) { std::swap(x["t"]["interval"][0], x["t"]["interval"][1]); }, "interval reversed");
  expect_rejected([&](json& x) { x["t"]["interval"][1] = "100"; }, "interval past the check");
  // Other sub-features: another vertex of the same element on each side.
  for (const char* side : {"a", "b"}) {
    expect_rejected([&](json& x) {
      json& vs = x[side]["vertices"];
      if (vs.size() == 1) vs[0] = vs[0].get<int>() == 0 ? 1 : 0;
      else vs = json::array({vs[0].get<int>() == 0 ? 1 : 0});
    }, std::string("another vertex on side ") + side);
  }
  expect_rejected([&](json& x) { x["a"]["vertices"] = json::array({0, 1, 2}); }, "three vertices, not all");
  BOOST_TEST(rejected == tried);
}

// Exact first contacts (exact resolution) are certified with before_witness
// (exact "no contact" claims before the witness time): the bracket is the
// witness time itself (a rational t: [t, t]; an algebraic one: its
// interval); the safe hover at 1e-17 needs an exact claim.  Without
// before_witness, or with the bracket moved, they are rejected.
BOOST_AUTO_TEST_CASE(exact_first_contacts_are_certified) {
  int algebraic = 0, rational = 0;
  for (const char* name : {"cubic-crossing-irrational", "crossing-at-one-third", "parallel-edges-sliding",
                           "vertex-sliding-into-face", "edges-cross-at-sqrt-half", "grazing-touch-half"}) {
    BOOST_TEST_CONTEXT(name) {
      const Verified v = verified(data(std::string("scenes/") + name + ".json"));
      BOOST_REQUIRE(v.result.checks[0].verdict == Verdict::Collision && v.result.checks[0].first_contact_exact);
      BOOST_TEST(accepted(v, v.certificate));
      const json& c = v.certificate["checks"][0];
      BOOST_REQUIRE(c.contains("before_witness"));
      const json& t = c["witness"]["t"];
      if (t.is_object()) {
        ++algebraic;
        BOOST_TEST(c["first_contact"] == t["interval"]);
      } else {
        ++rational;
        BOOST_TEST(c["first_contact"] == json::array({t, t}));
      }
      json altered = v.certificate;
      altered["checks"][0].erase("before_witness");
      BOOST_TEST(!accepted(v, altered));
      altered = v.certificate;
      altered["checks"][0]["before_witness"]["from"] = altered["checks"][0]["first_contact"][1];
      BOOST_TEST(!accepted(v, altered));
    }
  }
  BOOST_TEST(algebraic >= 2);
  BOOST_TEST(rational >= 2);
  const Verified hover = verified(data("scenes/hover-1e-17.json"));
  BOOST_TEST(hover.certificate.dump().find("\"exact\":\"no_contact\"") != std::string::npos);
  BOOST_TEST(accepted(hover, hover.certificate));
}

BOOST_AUTO_TEST_CASE(altered_certificates_are_rejected) {
  const Verified clear = verified(example("octagons-near.json"));
  // A rational witness (t = 1/3, with its exact point); octagons-collision's
  // is at an irrational time (algebraic_witnesses_are_checked_exactly).
  const Verified collision = verified(data("scenes/crossing-at-one-third.json"));
  BOOST_REQUIRE(accepted(clear, clear.certificate));
  BOOST_REQUIRE(accepted(collision, collision.certificate));
  BOOST_REQUIRE(clear.certificate["checks"][0]["pieces"].size() >= 2);

  int rejected = 0, tried = 0;
  auto expect_rejected = [&](const Verified& v, const json& altered, const std::string& what) {
    ++tried;
    const bool ok = accepted(v, altered);
    BOOST_TEST(!ok, "accepted after: " << what);
    rejected += !ok;
  };

  // Each separation direction negated, one at a time (a negated separating
  // direction can never separate): in the shared nodes, and in each piece's
  // proof written out inline (the same certificate without shared nodes,
  // accepted as written).
  {
    const json& c = clear.certificate["checks"][0];
    BOOST_TEST(clear.certificate["format"] == "tmcert-certificate/2");
    int seps = 0;
    for (std::size_t k = 0; k < c["nodes"].size(); ++k) {
      if (!c["nodes"][k].contains("sep")) continue;
      ++seps;
      json altered = clear.certificate;
      json& n = altered["checks"][0]["nodes"][k]["sep"];
      n = negated(n);
      expect_rejected(clear, altered, "negated direction in nodes[" + std::to_string(k) + "]");
    }
    BOOST_TEST(seps >= 2);
    json written_out = clear.certificate;
    written_out["checks"][0].erase("nodes");
    for (json& p : written_out["checks"][0]["pieces"]) p["proof"] = inline_proof(c["nodes"], p["proof"]);
    BOOST_TEST(accepted(clear, written_out));
    for (const char* format : {"tmcert-certificate/1", "tmcert-certificate/2"}) {
      written_out["format"] = format;
      BOOST_TEST(accepted(clear, written_out), format);
    }
    const json& pieces = written_out["checks"][0]["pieces"];
    for (std::size_t p = 0; p < pieces.size(); ++p) {
      json altered = written_out;
      bool done = false;
      each_direction(altered["checks"][0]["pieces"][p]["proof"], [&](json& n) {
        if (done) return;
        n = negated(n);
        done = true;
      });
      expect_rejected(clear, altered, "negated direction in piece " + std::to_string(p));
    }
  }
  // A piece boundary moved: a gap in the cover.
  {
    json altered = clear.certificate;
    json& t = altered["checks"][0]["pieces"][1]["t"];
    t[0] = to_string((rational_of(t[0]) + rational_of(t[1])) / 2);
    expect_rejected(clear, altered, "gap between pieces 0 and 1");
  }
  // The last piece dropped: the cover no longer reaches t1.
  {
    json altered = clear.certificate;
    altered["checks"][0]["pieces"].erase(altered["checks"][0]["pieces"].size() - 1);
    expect_rejected(clear, altered, "last piece dropped");
  }
  // A collision certificate claimed as safe.
  {
    json altered = collision.certificate;
    altered["checks"][0]["verdict"] = "safe";
    expect_rejected(collision, altered, "collision relabelled safe");
  }
  // The witness point moved.
  {
    json altered = collision.certificate;
    json& x = altered["checks"][0]["witness"]["point"][0];
    x = to_string(rational_of(x) + Exact(1, 1000000));
    expect_rejected(collision, altered, "witness point moved");
  }
  // The certificate of one scene against another.
  expect_rejected(collision, clear.certificate, "certificate of octagons-near checked against crossing-at-one-third");
  BOOST_TEST(rejected == tried);
}

// Certificates of planner motions, tolerances and clearances
// (docs/certificate-format.md, "Planner motions, tolerances and
// clearances"): accepted as written, rejected after each change that breaks
// what they prove.
std::string scene_file(const std::string& name) { return std::string(TMCERT_TEST_DATA) + "/scenes/" + name; }

BOOST_AUTO_TEST_CASE(planner_certificates_are_checked) {
  int tried = 0, rejected = 0;
  auto expect_rejected = [&](const Scene& scene, const json& certificate, const std::string& what) {
    ++tried;
    bool ok = false;
    try {
      ok = certificate::check_certificate(scene, certificate, "certificate").ok;
    } catch (const InputError&) {
    }
    BOOST_TEST(!ok, "accepted after: " << what);
    rejected += !ok;
  };
  // Margins: the same separations no longer prove a larger tolerance or
  // clearance (the scenes' minimum distances are 1/10 + 1/50 and 1/5).
  {
    const Verified v = verified(scene_file("planner-tolerance-safe.json"));
    BOOST_REQUIRE(accepted(v, v.certificate));
    Scene wider = v.scene;
    for (Body& b : wider.bodies) b.tolerance = b.tolerance * 4;
    expect_rejected(wider, v.certificate, "tolerance quadrupled");
  }
  {
    const Verified v = verified(scene_file("planner-clearance-safe.json"));
    BOOST_REQUIRE(accepted(v, v.certificate));
    Scene wider = v.scene;
    wider.clearance = wider.clearance * 4;
    expect_rejected(wider, v.certificate, "clearance quadrupled");
  }
  // A toleranced contact: the displacement must stay within the tolerance
  // and must bring the bodies together.
  {
    const Verified v = verified(scene_file("planner-tolerance-collision.json"));
    BOOST_REQUIRE(accepted(v, v.certificate));
    const json& w = v.certificate["checks"][0]["witness"];
    BOOST_REQUIRE(w.contains("displacement"));
    for (int k = 0; k < 3; ++k) {
      json altered = v.certificate;
      json& d = altered["checks"][0]["witness"]["displacement"][k];
      d = to_string(rational_of(d) * 3 + Exact(1, 7));
      expect_rejected(v.scene, altered, "displacement coordinate " + std::to_string(k) + " changed");
    }
    json altered = v.certificate;
    altered["checks"][0]["witness"].erase("displacement");
    altered["checks"][0]["witness"].erase("displaced");
    expect_rejected(v.scene, altered, "displacement dropped");
  }
  // A clearance violation at exact poses: both points on their bodies and
  // within d (the planner scene's plate turns by slerp: its witness is at
  // an enclosed pose, tests/certificate/test_check_judge.cpp).
  {
    const Verified v = verified(scene_file("clearance-translation-030-violated.json"));
    BOOST_REQUIRE(accepted(v, v.certificate));
    BOOST_REQUIRE(v.certificate["checks"][0]["witness"].contains("points"));
    for (int k = 0; k < 2; ++k) {
      json altered = v.certificate;
      json& x = altered["checks"][0]["witness"]["points"][k][0];
      x = to_string(rational_of(x) + Exact(1, 1000));
      expect_rejected(v.scene, altered, "clearance point " + std::to_string(k) + " moved");
    }
    Scene tighter = v.scene;
    tighter.clearance = 0;
    tighter.check_clearance.assign(tighter.checks.size(), std::nullopt);
    expect_rejected(tighter, v.certificate, "clearance violation checked without the clearance");
  }
  // A witness at an enclosed pose (slerp between rpy keyframes): the edge
  // must cross the triangle for every pose of the enclosure.
  {
    const Verified v = verified(scene_file("planner-wall1-rpy-slerp.json"));
    BOOST_REQUIRE(accepted(v, v.certificate));
    const json& w = v.certificate["checks"][0]["witness"];
    BOOST_REQUIRE(w.contains("point_box"));
    const Exact t = rational_of(w["t"]);
    for (const Exact& other : {Exact(0), t / 2, (t + 1) / 2}) {
      json altered = v.certificate;
      altered["checks"][0]["witness"]["t"] = to_string(other);
      expect_rejected(v.scene, altered, "enclosed witness moved to t = " + to_string(other));
    }
    json altered = v.certificate;
    json& side = altered["checks"][0]["witness"]["a"]["vertices"];
    side = side.size() == 2 ? json::array({0, 1, 2}) : json::array({0, 1});
    expect_rejected(v.scene, altered, "enclosed witness with the edge and triangle swapped");
  }
  // Pieces must lie inside one segment of each motion: two pieces merged
  // across the join of a piecewise motion are rejected.
  {
    const Verified v = verified(scene_file("planner-piecewise-safe.json"));
    BOOST_REQUIRE(accepted(v, v.certificate));
    const json& pieces = v.certificate["checks"][0]["pieces"];
    std::size_t k = 0;
    while (k + 1 < pieces.size() && rational_of(pieces[k]["t"][1]) != 1) ++k;
    BOOST_REQUIRE(k + 1 < pieces.size());
    json altered = v.certificate;
    json& list = altered["checks"][0]["pieces"];
    list[k]["t"][1] = list[k + 1]["t"][1];
    list.erase(k + 1);
    expect_rejected(v.scene, altered, "pieces merged across the join at t = 1");
  }
  // The certificate of a safe transcendental motion against the same
  // motion through another wall (the bar hits it): its separations fail.
  {
    const Verified safe = verified(scene_file("planner-wall2-slerp.json"));
    const Scene hit = parse_scene_file(scene_file("planner-wall1-slerp.json"));
    BOOST_REQUIRE(accepted(safe, safe.certificate));
    expect_rejected(hit, safe.certificate, "certificate of planner-wall2-slerp checked against planner-wall1-slerp");
  }
  BOOST_TEST(tried >= 12);
  BOOST_TEST(rejected == tried);
}

BOOST_AUTO_TEST_SUITE_END()
