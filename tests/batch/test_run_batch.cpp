// src/batch/run_batch: with several threads the results are the bytes of
// one thread, and a cancelled run ends after whole lines only, with
// Cancelled.
#include "src/batch/run_batch.h"
#include "src/verify/progress.h"

#include <boost/test/unit_test.hpp>

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace fs = std::filesystem;

namespace {

const std::string kExample = std::string(TMCERT_TEST_DATA) + "/../../examples/batch";

struct TempDir {
  fs::path path;
  TempDir() {
    path = fs::temp_directory_path() / ("tmcert-run-batch-" + std::to_string(::getpid()));
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

// `copies` rounds of the example's requests, with a bad line among them.
fs::path requests(const TempDir& dir, int copies) {
  std::vector<std::string> lines;
  std::ifstream in(kExample + "/requests.jsonl");
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  lines.push_back(R"({"id":"bad","body":"ghost"})");
  const fs::path file = dir.path / "requests.jsonl";
  std::ofstream out(file);
  for (int k = 0; k < copies; ++k)
    for (const std::string& line : lines) out << line << "\n";
  return file;
}

tmcert::BatchOptions options(const fs::path& requests, const fs::path& output, int threads) {
  tmcert::BatchOptions o;
  o.requests = requests.string();
  o.scene = kExample + "/environment.json";
  o.output = output.string();
  o.verify.threads = threads;
  o.quiet = true;
  return o;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(run_batch_suite)

// More requests than the window of 64 per thread: the ring wraps.
BOOST_AUTO_TEST_CASE(threads_give_the_bytes_of_one) {
  TempDir dir;
  const fs::path file = requests(dir, 50);  // 300 requests
  BOOST_TEST(tmcert::run_batch(options(file, dir.path / "1.jsonl", 1)) == 1);
  const std::string one = content(dir.path / "1.jsonl");
  BOOST_TEST(std::count(one.begin(), one.end(), '\n') == 300);
  for (int n : {2, 3, 4}) {
    tmcert::BatchCounts counts;
    BOOST_TEST(tmcert::run_batch(options(file, dir.path / "n.jsonl", n), &counts) == 1);
    BOOST_TEST(content(dir.path / "n.jsonl") == one, n << " threads");
    BOOST_TEST(counts.requests == 300u);
    BOOST_TEST(counts.error == 50u);
  }
}

// Cancelled before the first result: nothing written, with one thread or
// several.
BOOST_AUTO_TEST_CASE(cancelled_before_the_first_result) {
  TempDir dir;
  const fs::path file = requests(dir, 2);
  for (int n : {1, 3}) {
    tmcert::RunProgress run;
    run.count_other_items();
    run.cancel();
    tmcert::BatchOptions o = options(file, dir.path / "out.jsonl", n);
    o.run = &run;
    BOOST_CHECK_THROW(tmcert::run_batch(o), tmcert::Cancelled);
    BOOST_TEST(content(dir.path / "out.jsonl").empty(), n << " threads");
  }
}

// Cancelled while it runs: the output is whole lines, the start of the
// full run's (or all of it, when the run ended first).
BOOST_AUTO_TEST_CASE(cancelled_while_running) {
  TempDir dir;
  const fs::path file = requests(dir, 100);  // 600 requests
  BOOST_TEST(tmcert::run_batch(options(file, dir.path / "all.jsonl", 1)) == 1);
  const std::string all = content(dir.path / "all.jsonl");
  for (int n : {1, 2}) {
    tmcert::RunProgress run;
    run.count_other_items();
    tmcert::BatchOptions o = options(file, dir.path / "out.jsonl", n);
    o.run = &run;
    std::atomic<bool> over{false};
    std::thread canceller([&] {
      while (!over && run.report().checks_done < 20) std::this_thread::sleep_for(std::chrono::microseconds(200));
      run.cancel();
    });
    bool cancelled = false;
    try {
      tmcert::run_batch(o);
    } catch (const tmcert::Cancelled&) {
      cancelled = true;
    }
    over = true;
    canceller.join();
    const std::string out = content(dir.path / "out.jsonl");
    BOOST_TEST(all.compare(0, out.size(), out) == 0, n << " threads");
    BOOST_TEST((out.empty() || out.back() == '\n'));
    if (cancelled) BOOST_TEST(out.size() < all.size());
    BOOST_TEST_MESSAGE(n << " threads: " << (cancelled ? "cancelled" : "done") << " after " << out.size() << " of " << all.size() << " bytes");
  }
}

BOOST_AUTO_TEST_SUITE_END()
