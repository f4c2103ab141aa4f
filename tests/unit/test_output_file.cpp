// src/cli/output_file: output paths are tried before the work, refused as
// bad input naming the option, and a file created for a run that ends
// without its result is removed again.
#include "src/cli/output_file.h"
#include "src/model/model.h"

#include <boost/test/unit_test.hpp>

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace fs = std::filesystem;
using tmcert::InputError;
using tmcert::OutputFile;

namespace {

struct TempDir {
  fs::path path;
  TempDir() {
    path = fs::temp_directory_path() / ("tmcert-output-file-" + std::to_string(::getpid()));
    fs::create_directories(path);
  }
  ~TempDir() { fs::remove_all(path); }
};

std::string content(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The message of the InputError `make` throws ("" when none).
template <typename F>
std::string refusal(F make) {
  try {
    make();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

BOOST_AUTO_TEST_SUITE(output_file)

BOOST_AUTO_TEST_CASE(unwritable_paths_are_input_errors_naming_the_option) {
  TempDir dir;
  const std::string missing = (dir.path / "no-such-dir" / "x.cert").string();
  const std::string m1 = refusal([&] { OutputFile f("--certificate", missing); });
  BOOST_TEST(m1.find("--certificate: cannot write '" + missing + "'") == 0u, m1);
  const std::string m2 = refusal([&] { OutputFile f("--report", dir.path.string()); });
  BOOST_TEST(m2 == "--report: cannot write '" + dir.path.string() + "': it is a directory");
  const std::string m3 = refusal([&] { OutputFile f("-o", ""); });
  BOOST_TEST(m3 == "-o: the file name is empty");
}

BOOST_AUTO_TEST_CASE(a_file_is_written_or_left_as_it_was) {
  TempDir dir;
  const fs::path fresh = dir.path / "fresh.cert";
  {
    OutputFile f("--certificate", fresh.string());
    BOOST_TEST(fs::exists(fresh));  // tried at once
  }
  BOOST_TEST(!fs::exists(fresh));  // never written: removed
  {
    OutputFile f("--certificate", fresh.string());
    f.write("proof\n");
  }
  BOOST_TEST(content(fresh) == "proof\n");
  {
    OutputFile f("--certificate", fresh.string());  // exists: kept as it is until written
  }
  BOOST_TEST(content(fresh) == "proof\n");
  {
    OutputFile f("--certificate", fresh.string());
    f.write("new");
  }
  BOOST_TEST(content(fresh) == "new");
}

BOOST_AUTO_TEST_SUITE_END()
