// Shared by the certificate checker's unit tests (tests/certificate/):
// the hand-built certificates of tests/data/certificates (numbers checked
// by hand in the comments of each scene), and expectations on the
// checker's outcome.
#pragma once

#include "src/certificate/check.h"
#include "src/io/parse.h"

#include <boost/test/unit_test.hpp>
#include <nlohmann/json.hpp>

#include <chrono>
#include <fstream>
#include <functional>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace check_test {

using namespace tmcert;
using json = nlohmann::json;
namespace cert = tmcert::certificate;


inline std::string data(const std::string& name) { return std::string(TMCERT_TEST_DATA) + "/certificates/" + name; }

inline Exact q(const std::string& text) {
  Exact value;
  BOOST_REQUIRE_MESSAGE(parse_exact(text, value), text);
  return value;
}
// A rational written as a JSON string or integer.
inline Exact rat(const json& x) { return x.is_string() ? q(x.get<std::string>()) : Exact(static_cast<long>(x.get<std::int64_t>())); }

inline Vec3E v(const std::string& x, const std::string& y, const std::string& z) { return {q(x), q(y), q(z)}; }

struct Case {
  Scene scene;
  json certificate;
};

inline Case load(const std::string& scene, const std::string& certificate) {
  return {parse_scene_file(data(scene + ".json")), cert::read_certificate_file(data(certificate + ".cert.json"))};
}

inline cert::CheckOutcome check(const Case& c) { return cert::check_certificate(c.scene, c.certificate, "cert.json"); }

// Rejected (ok = false) with a message containing `what`.
inline void expect_rejected(const Case& c, const std::string& what) {
  const cert::CheckOutcome out = check(c);
  BOOST_TEST(!out.ok, "expected a rejection containing '" << what << "'");
  BOOST_TEST(out.message.find(what) != std::string::npos, "message: " << out.message << "\n  expected: " << what);
  BOOST_TEST(out.message.find('\n') == std::string::npos);
  BOOST_TEST(out.message.rfind("cert.json: ", 0) == 0, out.message);
}

// Malformed: InputError with a message containing `what`.
inline void expect_malformed(const Case& c, const std::string& what) {
  try {
    const cert::CheckOutcome out = check(c);
    BOOST_ERROR("expected InputError containing '" << what << "', got ok=" << out.ok << " " << out.message);
  } catch (const InputError& e) {
    const std::string m = e.what();
    BOOST_TEST(m.find(what) != std::string::npos, "message: " << m << "\n  expected: " << what);
  }
}

inline json& check0(Case& c) { return c.certificate["checks"][0]; }

inline const std::vector<std::pair<std::string, std::string>> kValid = {
    {"probe-safe", "probe-safe"},       {"drop", "drop-collision"},
    {"drop", "drop-undecided"},         {"two-moving", "two-moving"},
    {"solid-outside", "solid-outside"}, {"solid-inside", "solid-inside-collision"},
    {"solid-singular", "solid-singular"}, {"drop", "drop-exact"},
    {"slide-beside", "slide-exact"},    {"solid-crossing", "solid-crossing-undecided"}};

}  // namespace check_test
