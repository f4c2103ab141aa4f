// The checker's document reading (src/certificate/check_document.h):
// malformed, deep and garbage documents are InputError naming the JSON
// path; the readers' limits directly.
#include "tests/certificate/check_support.h"
#include "src/certificate/check_document.h"
#include <fstream>
#include <sstream>

using namespace check_test;

BOOST_AUTO_TEST_SUITE(certificate_check)

BOOST_AUTO_TEST_CASE(malformed_certificates_are_input_errors) {
  const auto base = [] { return load("probe-safe", "probe-safe"); };
  struct Mutation {
    std::function<void(json&)> apply;
    std::string what;
  };
  const std::vector<Mutation> mutations = {
      {[](json& d) { d["format"] = "tmcert-certificate/3"; }, "format: unknown format"},
      // Shared proof nodes (docs/certificate-format.md "Shared proof nodes").
      {[](json& d) { d["checks"][0]["nodes"] = 1; }, "checks[0].nodes: expected an array"},
      {[](json& d) { d["checks"][0]["pieces"][0]["proof"] = 0; },
       "checks[0].pieces[0].proof: 0 is out of range (an index into nodes)"},
      {[](json& d) {
         d["checks"][0]["nodes"] = json::array({{{"sep", {0, 0, 1}}}, 1});
       },
       "checks[0].nodes[1]: 1 is out of range (an earlier entry of nodes)"},
      {[](json& d) { d["checks"][0]["nodes"] = json::array({json::array({0, 0})}); },
       "checks[0].nodes[0][1]: 0 is out of range (an earlier entry of nodes)"},
      {[](json& d) { d["checks"][0]["nodes"] = json::array({json::array({0, {{"sep", {0, 0, "x"}}}})}); },
       "checks[0].nodes[0][1].sep[2]: not a rational"},
      {[](json& d) { d["checks"][0]["pieces"][1]["proof"] = json::array({2, {{"sep", {0, 0, 1}}}}); },
       "checks[0].pieces[1].proof[0]: 2 is out of range (0 or 1)"},
      {[](json& d) { d["checks"][0]["pieces"][1]["proof"] = json::array(); },
       "checks[0].pieces[1].proof[0]: expected a non-negative integer"},
      // probe-safe has 3 x 1 groups: a proof judging 2^11 - 1 nodes (each
      // node split into two copies of the one before) is not one over them.
      {[](json& d) {
         json nodes = json::array({{{"sep", {0, 0, 1}}}});
         for (int k = 0; k < 10; ++k) nodes.push_back(json::array({0, k, k}));
         d["checks"][0]["nodes"] = nodes;
         d["checks"][0]["pieces"][1]["proof"] = 10;
       },
       "checks[0].pieces[1].proof: the proof expands to more than 70 nodes"},
      {[](json& d) { d.erase("format"); }, "format: missing required field"},
      {[](json& d) { d.erase("checks"); }, "checks: missing required field"},
      {[](json& d) { d = json::array(); }, "document: expected an object"},
      {[](json& d) { d["checks"][0]["pieces"][0]["proof"]["sep"] = json::array({"0", "0"}); },
       "checks[0].pieces[0].proof.sep: expected 3 entries, got 2"},
      {[](json& d) { d["checks"][0]["pieces"][0]["proof"]["sep"][0] = 0.5; },
       "checks[0].pieces[0].proof.sep[0]: expected a rational"},
      {[](json& d) { d["checks"][0]["pieces"][0]["proof"]["sep"][0] = "1e99999"; }, "decimal exponent beyond 10000"},
      {[](json& d) { d["checks"][0]["pieces"][0]["proof"]["sep"][0] = "1e10001"; }, "decimal exponent beyond 10000"},
      {[](json& d) { d["checks"][0]["pieces"][0]["proof"]["sep"][0] = std::string(100001, '7'); },
       "number of 100001 characters (at most 100000)"},
      {[](json& d) { d["checks"][0]["pieces"][0]["proof"]["sep"][0] = "1/0"; }, "not a rational: \"1/0\""},
      {[](json& d) { d["checks"][0]["pieces"][0]["proof"]["sep"][0] = "nan"; }, "not a rational"},
      {[](json& d) { d["checks"][0]["pieces"][0]["proof"]["sep"][0] = nullptr; }, "expected a rational"},
      {[](json& d) { d["checks"][0]["pieces"][0]["proof"] = {{"sep", {0, 0, 1}}, {"split", 0}}; },
       "expected exactly one of \"sep\", \"split\" and \"exact\""},
      {[](json& d) { d["checks"][0]["pieces"][1]["proof"]["split"] = 2; }, "proof.split: 2 is out of range (0 or 1)"},
      {[](json& d) { d["checks"][0]["pieces"][1]["proof"]["split"] = -1; }, "out of range"},
      {[](json& d) { d["checks"][0]["pieces"][1]["proof"].erase("parts"); }, "proof.parts: missing required field"},
      {[](json& d) { d["checks"][0]["pieces"][0].erase("proof"); }, "checks[0].pieces[0].proof: missing required field"},
      {[](json& d) { d["checks"][0]["groups"][0][0]["children"] = json::array({1, 0}); },
       "groups[0][0].children[1]: child 0 must be after its group 0"},
      {[](json& d) { d["checks"][0]["groups"][0][1] = {{"children", {1, 2}}}; },
       "groups[0][1].children[0]: child 1 must be after its group 1"},
      {[](json& d) { d["checks"][0]["groups"][0][0]["children"] = json::array({1}); }, "at least two children"},
      {[](json& d) { d["checks"][0]["groups"][0][0]["children"] = json::array({1, 7}); },
       "children[1]: 7 is out of range (3 groups)"},
      {[](json& d) { d["checks"][0]["groups"][0][1]["elements"] = json::array({2}); },
       "groups[0][1].elements[0]: 2 is out of range (\"probe\" has 2 elements)"},
      {[](json& d) { d["checks"][0]["groups"][0][1]["elements"] = json::array(); }, "at least one element"},
      {[](json& d) { d["checks"][0]["groups"][0][1] = json::object(); },
       "expected exactly one of \"elements\" and \"children\""},
      {[](json& d) { d["checks"][0]["groups"][1] = json::array(); }, "groups[1]: no groups"},
      {[](json& d) { d["checks"][0]["groups"].erase(1); }, "groups: expected 2 entries"},
      {[](json& d) { d["checks"][0]["verdict"] = "maybe"; }, "checks[0].verdict: expected \"safe\""},
      {[](json& d) { d["checks"][0]["pieces"] = json::object(); }, "checks[0].pieces: expected an array"},
      {[](json& d) { d["checks"][0].erase("interval"); }, "checks[0].interval: missing required field"},
      {[](json& d) { d["checks"][0]["witness"] = json::object(); }, "a safe check has no witness"},
      {[](json& d) { d["checks"][0]["undecided"] = json::array({json::array({"0", "1"})}); },
       "a safe check has no undecided intervals"},
      {[](json& d) { d["scene_bodies"][0]["elements"] = -2; }, "scene_bodies[0].elements: -2 is out of range"},
      {[](json& d) { d["scene_bodies"][0]["name"] = 3; }, "scene_bodies[0].name: expected a string"},
      {[](json& d) { d["checks"][0]["start"] = {{"solid", "b"}}; }, "checks[0].start: expected an array"},
      {[](json& d) { d["checks"][0]["start"] = json::array({{{"solid", "c"}, {"points", json::array()}}}); },
       "start[0].solid: expected \"a\" or \"b\""},
  };
  for (const Mutation& m : mutations) {
    Case c = base();
    m.apply(c.certificate);
    expect_malformed(c, m.what);
    try {
      check(c);
    } catch (const InputError& e) {
      BOOST_TEST(std::string(e.what()).rfind("cert.json: ", 0) == 0, e.what());  // names the certificate
    }
  }
  // Malformed input is bad input even after a false claim (the document is
  // validated before any claim is judged).
  {
    Case c = base();
    check0(c)["pieces"][0]["proof"]["sep"][2] = "-1";                // false
    check0(c)["pieces"][2]["proof"]["sep"][1] = "one";               // malformed, later
    expect_malformed(c, "checks[0].pieces[2].proof.sep[1]: not a rational: \"one\"");
    Case d = base();
    check0(d)["pieces"][1]["t"][0] = "5/16";                          // a gap
    check0(d)["pieces"][1]["proof"]["parts"][1] = json::array();      // malformed
    check0(d)["pieces"][1]["proof"]["parts"][1] = json::array({"x"});  // malformed
    expect_malformed(d, "checks[0].pieces[1].proof.parts[1][0]: expected a non-negative integer, got a string");
  }
  // Witness and start shapes on their own scenes.
  {
    Case c = load("drop", "drop-collision");
    check0(c)["witness"]["b"]["weights"].erase(2);
    expect_malformed(c, "witness.b.weights: 2 weights, element 0 has 3 vertices");
    Case d = load("drop", "drop-collision");
    check0(d)["witness"]["a"]["element"] = 1;
    expect_malformed(d, "witness.a.element: 1 is out of range (\"drop\" has 1 elements)");
    Case e = load("drop", "drop-collision");
    check0(e).erase("witness");
    expect_malformed(e, "checks[0].witness: missing required field");
    Case f = load("drop", "drop-collision");
    check0(f).erase("first_contact");
    expect_malformed(f, "checks[0].first_contact: missing required field");
    Case g = load("solid-outside", "solid-outside");
    check0(g)["start"][0]["points"][0]["vertex"] = 3;
    expect_malformed(g, "start[0].points[0].vertex: 3 is out of range (element 0 has 3 vertices)");
    Case h = load("solid-outside", "solid-outside");
    check0(h)["start"].push_back(check0(h)["start"][0]);
    expect_malformed(h, "start[1].solid: a second entry for \"b\"");
  }
}

BOOST_AUTO_TEST_CASE(deep_and_garbage_documents_are_input_errors) {
  // A proof tree deeper than the limit (a chain of groups split one by one).
  {
    Case c = load("probe-safe", "probe-safe");
    const int depth = cert::kMaxProofDepth + 5;
    json groups = json::array();
    for (int k = 0; k < depth; ++k) groups.push_back({{"children", {k + 1, k + 2}}});
    // groups[k] = children {k+1, k+2} for k < depth; the last two are leaves.
    groups.push_back({{"elements", {0}}});
    groups.push_back({{"elements", {0, 1}}});
    json proof = {{"sep", {"0", "0", "1"}}};
    for (int k = depth - 1; k >= 0; --k) proof = {{"split", 0}, {"parts", {proof, {{"sep", {"0", "0", "1"}}}}}};
    check0(c)["groups"][0] = groups;
    check0(c)["pieces"][0]["proof"] = proof;
    expect_malformed(c, "proof tree deeper than 256 splits");
    // The same chain through shared nodes (each a split of one group):
    // bad input before any claim is judged.
    json nodes = json::array({{{"sep", {"0", "0", "1"}}}});
    for (int k = 0; k < depth; ++k) nodes.push_back(json::array({0, k, 0}));
    check0(c)["nodes"] = nodes;
    check0(c)["pieces"][0]["proof"] = depth;
    check0(c)["pieces"][2]["proof"]["sep"][2] = "-1";  // a false claim judged before piece 0 would be
    expect_malformed(c, "proof tree deeper than 256 splits (nodes[");
  }
  // Text: deep nesting, truncation, garbage bytes, big integers.
  BOOST_CHECK_THROW(cert::parse_certificate_text(std::string(100000, '[') + std::string(100000, ']'), "x"),
                    InputError);
  BOOST_CHECK_THROW(cert::parse_certificate_text("", "x"), InputError);
  BOOST_CHECK_THROW(cert::parse_certificate_text("{\"format\": ", "x"), InputError);
  BOOST_CHECK_THROW(cert::read_certificate_file(data("does-not-exist.cert.json")), InputError);
  const Scene scene = parse_scene_file(data("probe-safe.json"));
  {
    json d = cert::parse_certificate_text(
        "{\"format\": \"tmcert-certificate/1\", \"scene_bodies\": [{\"name\": \"probe\", \"elements\": "
        "123456789012345678901234567890}, {\"name\": \"tri\", \"elements\": 1}]}",
        "x");
    BOOST_CHECK_THROW(cert::check_certificate(scene, d, "x"), InputError);
  }
  std::ifstream in(data("probe-safe.cert.json"));
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  std::mt19937_64 rng(20261123);
  int input_errors = 0;
  for (int i = 0; i < 400; ++i) {
    std::string t = text;
    switch (i % 4) {
      case 0: t.resize(rng() % t.size()); break;                                             // truncated
      case 1: t[rng() % t.size()] = static_cast<char>(rng() % 256); break;                   // one byte
      case 2: for (int k = 0; k < 8; ++k) t[rng() % t.size()] = static_cast<char>(rng()); break;
      default: {                                                                              // random bytes
        t.assign(rng() % 200, ' ');
        for (char& ch : t) ch = static_cast<char>(rng());
      }
    }
    try {
      const json d = cert::parse_certificate_text(t, "garbage.json");
      const cert::CheckOutcome out = cert::check_certificate(scene, d, "garbage.json");
      (void)out;
    } catch (const InputError& e) {
      ++input_errors;
      BOOST_TEST(std::string(e.what()).rfind("garbage.json: ", 0) == 0, e.what());
    } catch (const std::exception& e) {
      BOOST_ERROR("garbage input " << i << " threw " << e.what());
    }
  }
  BOOST_TEST(input_errors > 300);
}

BOOST_AUTO_TEST_SUITE_END()

// The document reader's pieces directly.
BOOST_AUTO_TEST_SUITE(check_document)

namespace ci = tmcert::certificate::check_internal;

BOOST_AUTO_TEST_CASE(json_types_and_nesting) {
  BOOST_TEST(std::string(ci::describe(json(nullptr))) == "null");
  BOOST_TEST(std::string(ci::describe(json(3))) == "an integer");
  BOOST_TEST(std::string(ci::describe(json(1.5))) == "a number with a fraction or exponent");
  BOOST_TEST(std::string(ci::describe(json::array())) == "an array");
  BOOST_TEST(ci::nesting("[[{\"a\": \"[[[[\"}]]") == 3u);  // brackets in strings do not count
  BOOST_TEST(ci::nesting("\"\\\"[\"") == 0u);              // nor after an escaped quote
  BOOST_TEST(ci::idx("checks", 3) == "checks[3]");
  BOOST_TEST(ci::mem("", "format") == "format");
  BOOST_TEST(ci::mem("checks[3]", "pieces") == "checks[3].pieces");
}

BOOST_AUTO_TEST_CASE(rationals_and_their_limits) {
  const ci::Reader in("c.json");
  BOOST_TEST(in.rational(json("3/4"), "x") == Exact(3, 4));
  BOOST_TEST(in.rational(json("-0.125"), "x") == Exact(-1, 8));
  BOOST_TEST(in.rational(json(7), "x") == Exact(7));
  auto message = [&](const json& value) {
    try {
      in.rational(value, "checks[0].sep[1]");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  BOOST_TEST(message(json(1.5)).find("c.json: checks[0].sep[1]: expected a rational") == 0u, message(json(1.5)));
  BOOST_TEST(message(json("1e10001")).find("decimal exponent beyond 10000") != std::string::npos);
  BOOST_TEST(message(json("1e10000")) == "accepted");
  BOOST_TEST(message(json("1/0")).find("not a rational") != std::string::npos);
  BOOST_TEST(message(json(std::string(cert::kMaxNumberChars + 1, '1'))).find("characters") != std::string::npos);
  BOOST_CHECK_THROW(in.index(json(2), "split", 2, "0 or 1"), InputError);
  BOOST_TEST(in.index(json(1), "split", 2, "0 or 1") == 1u);
}

BOOST_AUTO_TEST_SUITE_END()
