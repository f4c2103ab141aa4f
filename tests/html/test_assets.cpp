// src/html/assets: the report's files are embedded byte for byte as they
// are in the source tree (three.module.min.js with its relative import
// (every occurrence) rewritten to the bare specifier "three/core"), so the page looks up no
// file at run time.
#include "src/html/assets.h"

#include <boost/test/unit_test.hpp>

#include <fstream>
#include <iterator>
#include <string>
#include <string_view>

namespace {

// A file of the source tree (TMCERT_TEST_DATA is tests/data).
std::string source_file(const std::string& path) {
  std::ifstream in(std::string(TMCERT_TEST_DATA) + "/../../" + path, std::ios::binary);
  BOOST_REQUIRE_MESSAGE(in, path << " is not readable");
  return std::string(std::istreambuf_iterator<char>(in), {});
}

}  // namespace

BOOST_AUTO_TEST_SUITE(report_assets)

BOOST_AUTO_TEST_CASE(embedded_as_in_the_source_tree) {
  using namespace tmcert::html;
  BOOST_TEST(std::string(kReportApp) == source_file("src/html/report_app.js"));
  BOOST_TEST(std::string(kReportStyle) == source_file("src/html/report.css"));
  BOOST_TEST(std::string(kThreeVersion) == source_file("third_party/three/VERSION"));
  BOOST_TEST(std::string(kThreeCore) == source_file("third_party/three/three.core.min.js"));
  BOOST_TEST(std::string(kOrbitControls) == source_file("third_party/three/OrbitControls.js"));
  BOOST_TEST(!kReportApp.empty());
  BOOST_TEST(!kThreeCore.empty());
}

BOOST_AUTO_TEST_CASE(three_module_imports_the_core_by_its_bare_name) {
  using tmcert::html::kThreeModule;
  std::string expected = source_file("third_party/three/three.module.min.js");
  const std::string relative = "from\"./three.core.min.js\"";
  BOOST_REQUIRE(expected.find(relative) != std::string::npos);
  for (std::size_t at = expected.find(relative); at != std::string::npos; at = expected.find(relative, at))
    expected.replace(at, relative.size(), "from\"three/core\"");
  BOOST_TEST(std::string(kThreeModule) == expected);
  BOOST_TEST(kThreeModule.find("from\"./") == std::string_view::npos);
}

BOOST_AUTO_TEST_SUITE_END()
