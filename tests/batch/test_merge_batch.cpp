// src/batch/merge_batch: the k-way merge reads each line's index without
// parsing the line where it has tmcert's form, parses any other line whole,
// refuses a file cut short, and never leaves part of a merge in the output.
#include "src/batch/merge_batch.h"
#include "src/model/model.h"

#include <boost/test/unit_test.hpp>

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using tmcert::InputError;
using tmcert::merge_batch;
using tmcert::result_line_index;

namespace {

struct TempDir {
  fs::path path;
  TempDir() {
    path = fs::temp_directory_path() / ("tmcert-merge-batch-" + std::to_string(::getpid()));
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempDir() { fs::remove_all(path); }
  std::string file(const std::string& name, const std::string& text) const {
    std::ofstream(path / name, std::ios::binary) << text;
    return (path / name).string();
  }
};

std::string content(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The message of the InputError merge_batch throws ("" when none).
std::string refusal(const std::vector<std::string>& shards, const std::string& output) {
  try {
    merge_batch(shards, output);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::size_t entries(const fs::path& dir) {
  return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
}

// -1: not of tmcert's form, else the index read.
long long index_of(const std::string& line) {
  std::size_t index = 0;
  return result_line_index(line.data(), line.size(), index) ? static_cast<long long>(index) : -1;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(merge_batch_suite)

BOOST_AUTO_TEST_CASE(index_of_tmcert_lines) {
  BOOST_TEST(index_of(R"({"index":0,"id":"e0","verdict":"safe","checks":[]})") == 0);
  BOOST_TEST(index_of(R"({"index":40000,"id":7,"error":"line 3: x"})") == 40000);
  BOOST_TEST(index_of(R"(  { "index" : 12 , "id":1 } )") == 12);
  BOOST_TEST(index_of("{\"index\":3}\r") == 3);
  BOOST_TEST(index_of(R"({"index":18446744073709551615,"a":1})") == 18446744073709551615ull);
  // Anything else is left to the whole parse.
  BOOST_TEST(index_of(R"({"id":1,"index":3})") == -1);      // index not first
  BOOST_TEST(index_of(R"({"index":03,"id":1})") == -1);     // leading zero
  BOOST_TEST(index_of(R"({"index":3.0,"id":1})") == -1);    // not an integer
  BOOST_TEST(index_of(R"({"index":3e1,"id":1})") == -1);
  BOOST_TEST(index_of(R"({"index":-3,"id":1})") == -1);
  BOOST_TEST(index_of(R"({"index":"3","id":1})") == -1);
  BOOST_TEST(index_of(R"({"index":18446744073709551616,"a":1})") == -1);  // beyond 64 bits
  BOOST_TEST(index_of(R"({"index":3,"id":1,"verdict":"sa)") == -1);      // cut short
  BOOST_TEST(index_of(R"({"index":3} junk})") == -1);
  BOOST_TEST(index_of(R"({"index":3}})") == -1);
  BOOST_TEST(index_of(R"({"index":3)") == -1);
  BOOST_TEST(index_of("") == -1);
  BOOST_TEST(index_of("[1]") == -1);
}

// Lines of other forms are parsed and merged; the bytes are copied (a
// carriage return kept, a missing final line break added).
BOOST_AUTO_TEST_CASE(merges_any_json_lines_byte_for_byte) {
  TempDir dir;
  const std::string a = dir.file("a.jsonl", "{\"index\":0,\"id\":0}\n{\"id\":2, \"index\":2}\r\n");
  const std::string b = dir.file("b.jsonl", " {\"index\" : 1 }\n{\"index\":3,\"x\":[1,2]}");
  const fs::path out = dir.path / "out.jsonl";
  BOOST_TEST(merge_batch({b, a}, out.string()) == 4u);
  BOOST_TEST(content(out) ==
             "{\"index\":0,\"id\":0}\n {\"index\" : 1 }\n{\"id\":2, \"index\":2}\r\n{\"index\":3,\"x\":[1,2]}\n");
}

// A shard cut short in its last line (a run killed while writing) is
// refused, naming its file and line, though its index can be read.
BOOST_AUTO_TEST_CASE(last_line_cut_short) {
  TempDir dir;
  const std::string a = dir.file("a.jsonl", "{\"index\":0,\"id\":0}\n");
  const std::string b = dir.file("b.jsonl", "{\"index\":1,\"id\":1,\"verdict\":\"sa");
  const std::string message = refusal({a, b}, (dir.path / "out.jsonl").string());
  BOOST_TEST(message.find("b.jsonl line 1: not a result line") != std::string::npos, message);
  // So is a line that does not end its object, with its line break.
  const std::string c = dir.file("c.jsonl", "{\"index\":0,\"id\":1,\"verdict\":\"sa\n");
  BOOST_TEST(refusal({c}, (dir.path / "out.jsonl").string()).find("c.jsonl line 1: not a result line") !=
             std::string::npos);
}

// A refused merge leaves the output as it was: an existing file keeps its
// content, a missing one is not created, no temporary file is left.
BOOST_AUTO_TEST_CASE(refused_merge_writes_nothing) {
  TempDir dir;
  const std::string a = dir.file("a.jsonl", "{\"index\":0}\n{\"index\":2}\n");  // index 1 missing
  const fs::path out = dir.path / "out.jsonl";
  BOOST_TEST(refusal({a}, out.string()).find("no file holds index 1") != std::string::npos);
  BOOST_TEST(!fs::exists(out));
  BOOST_TEST(entries(dir.path) == 1u);
  dir.file("out.jsonl", "old\n");
  BOOST_TEST(refusal({a}, out.string()).find("no file holds index 1") != std::string::npos);
  BOOST_TEST(content(out) == "old\n");
  BOOST_TEST(entries(dir.path) == 2u);
}

// The output replaced keeps its permissions, and a symbolic link its
// target (which gets the merge).
BOOST_AUTO_TEST_CASE(replaced_output_keeps_permissions_and_links) {
  TempDir dir;
  const std::string a = dir.file("a.jsonl", "{\"index\":0}\n{\"index\":1}\n");
  const fs::path out = dir.path / "out.jsonl";
  dir.file("out.jsonl", "old\n");
  fs::permissions(out, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  BOOST_TEST(merge_batch({a}, out.string()) == 2u);
  BOOST_TEST(content(out) == content(a));
  BOOST_TEST((fs::status(out).permissions() == (fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read)));
  const fs::path link = dir.path / "link.jsonl";
  fs::create_symlink(out, link);
  const std::string b = dir.file("b.jsonl", "{\"index\":0,\"b\":1}\n");
  BOOST_TEST(merge_batch({b}, link.string()) == 1u);
  BOOST_TEST(fs::is_symlink(link));
  BOOST_TEST(content(out) == "{\"index\":0,\"b\":1}\n");
  BOOST_TEST(entries(dir.path) == 4u);
}

BOOST_AUTO_TEST_SUITE_END()
