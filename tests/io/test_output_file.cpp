// src/io/output_file: output paths are checked before the work (bad
// input naming the option), nothing is created or changed before the
// result is written, a FIFO is opened once, the same file is found under
// any name, and a write that fails is OutputError leaving no partial file.
#include "src/io/output_file.h"

#include "src/model/model.h"
#include "src/io/parse.h"
#include "src/io/read_file.h"

#include <boost/test/unit_test.hpp>

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace fs = std::filesystem;
using tmcert::FileIdentity;
using tmcert::InputError;
using tmcert::OutputError;
using tmcert::OutputFile;

namespace {

struct TempDir {
  fs::path path;
  TempDir() {
    path = fs::temp_directory_path() / ("tmcert-output-file-" + std::to_string(::getpid()));
    fs::remove_all(path);
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

void put(const fs::path& p, const std::string& text) {
  std::ofstream out(p, std::ios::binary);
  out << text;
}

// The message of the exception E that `make` throws ("" when none).
template <typename E = InputError, typename F>
std::string refusal(F make) {
  try {
    make();
  } catch (const E& e) {
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
  put(dir.path / "file", "x");
  const std::string below_file = (dir.path / "file" / "x.cert").string();
  BOOST_TEST(refusal([&] { OutputFile f("-o", below_file); }).find("-o: cannot write '" + below_file + "'") == 0u);
}

BOOST_AUTO_TEST_CASE(nothing_is_created_or_changed_before_the_result) {
  TempDir dir;
  const fs::path fresh = dir.path / "fresh.cert";
  {
    OutputFile f("--certificate", fresh.string());
    BOOST_TEST(!fs::exists(fresh));  // checked, not created
  }
  BOOST_TEST(!fs::exists(fresh));
  {
    OutputFile f("--certificate", fresh.string());
    f.write("proof\n");
  }
  BOOST_TEST(content(fresh) == "proof\n");
  {
    OutputFile f("--certificate", fresh.string());  // exists: kept as it is unless written
  }
  BOOST_TEST(content(fresh) == "proof\n");
  {
    OutputFile f("--certificate", fresh.string());
    f.write("new");
  }
  BOOST_TEST(content(fresh) == "new");
  // Streaming that ends without finish() (the run failed while writing):
  // the partial file is removed.
  {
    OutputFile f("-o", fresh.string());
    f.begin();
    f.append("partial");
  }
  BOOST_TEST(!fs::exists(fresh));
}

BOOST_AUTO_TEST_CASE(a_failed_write_is_an_output_error_and_leaves_no_file) {
  if (!fs::exists("/dev/full")) return;
  OutputFile f("--certificate", "/dev/full");  // a device: accepted at the check
  const std::string m = refusal<OutputError>([&] { f.write("proof\n"); });
  BOOST_TEST(m.find("--certificate: cannot write '/dev/full': ") == 0u, m);
  BOOST_TEST(fs::exists("/dev/full"));  // a special file is never removed
  // OutputError is a resource limit (exit 4), never bad input.
  BOOST_TEST(refusal<tmcert::ResourceLimit>([&] {
               OutputFile g("-o", "/dev/full");
               g.write("x");
             }).empty() == false);
}

BOOST_AUTO_TEST_CASE(the_same_file_under_any_name) {
  TempDir dir;
  const fs::path a = dir.path / "a.json";
  put(a, "{}");
  fs::create_symlink(a, dir.path / "link.json");
  fs::create_hard_link(a, dir.path / "hard.json");
  const std::optional<FileIdentity> input = tmcert::file_identity(a.string());
  BOOST_REQUIRE(input);
  for (const fs::path& name : {a, dir.path / "link.json", dir.path / "hard.json", dir.path / "." / "a.json",
                               dir.path / "sub" / ".." / "a.json"}) {
    if (name.string().find("sub") != std::string::npos) fs::create_directories(dir.path / "sub");
    OutputFile f("--certificate", name.string());
    const std::string m = refusal([&] { tmcert::require_distinct({&f}, {*input}); });
    BOOST_TEST(m.find("--certificate: '" + name.string() + "' is the input file '" + a.string() + "'") == 0u, m);
  }
  BOOST_TEST(content(a) == "{}");
  // Two outputs: existing (by inode) or not yet (by resolved path).
  {
    OutputFile c("--certificate", a.string()), r("--report", (dir.path / "link.json").string());
    BOOST_TEST(refusal([&] { tmcert::require_distinct({&c, &r}, {}); }).find("is the same file as --certificate") !=
               std::string::npos);
  }
  {
    const fs::path cwd = fs::current_path();
    fs::current_path(dir.path);
    OutputFile c("--certificate", "new.json"), r("--report", "./sub/../new.json");
    const std::string m = refusal([&] { tmcert::require_distinct({&c, &r}, {}); });
    fs::current_path(cwd);
    BOOST_TEST(m == "--report: './sub/../new.json' is the same file as --certificate 'new.json'; give each output its own file");
  }
  {
    OutputFile c("--certificate", (dir.path / "one.json").string()), r("--report", (dir.path / "two.json").string());
    BOOST_TEST(refusal([&] { tmcert::require_distinct({&c, &r}, {*input}); }).empty());
  }
}

BOOST_AUTO_TEST_CASE(a_fifo_is_opened_once) {
  TempDir dir;
  const fs::path fifo = dir.path / "fifo";
  BOOST_REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  // No reader: refused at once (no blocking).
  BOOST_TEST(refusal([&] { OutputFile f("--certificate", fifo.string()); }).find("no process has this FIFO open for reading") !=
             std::string::npos);
  // A reader that reads to the end of file: it must get the whole content,
  // not the end of file of a first open and close at the check.
  const fs::path got = dir.path / "got";
  const pid_t reader = ::fork();
  BOOST_REQUIRE(reader >= 0);
  if (reader == 0) {
    const int in = ::open(fifo.c_str(), O_RDONLY);
    const int out = ::open(got.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    char buffer[256];
    for (::ssize_t n; in >= 0 && (n = ::read(in, buffer, sizeof buffer)) > 0;)
      if (::write(out, buffer, static_cast<std::size_t>(n)) != n) ::_exit(2);
    ::_exit(0);
  }
  std::string message;
  for (int tries = 0; tries < 500; ++tries) {  // until the reader has opened it
    message = refusal([&] {
      OutputFile f("--certificate", fifo.string());
      ::usleep(100000);  // the run
      f.write("proof\n");
    });
    if (message.find("no process has this FIFO open") == std::string::npos) break;
    ::usleep(10000);
  }
  BOOST_TEST(message.empty(), message);
  if (!message.empty()) {  // never opened: let the reader's open return, so that the test ends
    const int fd = ::open(fifo.c_str(), O_WRONLY | O_NONBLOCK);
    if (fd >= 0) ::close(fd);
  }
  int status = 0;
  ::waitpid(reader, &status, 0);
  BOOST_TEST(content(got) == "proof\n");
  BOOST_TEST(fs::is_fifo(fifo));  // never removed
}

BOOST_AUTO_TEST_CASE(a_scene_records_its_input_files) {
  const std::string data = TMCERT_TEST_DATA;
  const std::string file = data + "/scenes/solid-inside.json";
  const tmcert::Scene scene = tmcert::parse_scene_file(file);
  // The scene file and its mesh.
  BOOST_TEST(scene.input_files.size() == 2u);
  BOOST_TEST(scene.input_files.at(0).same(*tmcert::file_identity(file)));
  BOOST_TEST(scene.input_files.at(1).path.find(".off") != std::string::npos, scene.input_files.at(1).path);
}

BOOST_AUTO_TEST_SUITE_END()
