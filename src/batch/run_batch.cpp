#include "src/batch/run_batch.h"

#include "src/batch/batch_environment.h"
#include "src/io/parse.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace tmcert {

namespace {

using Clock = std::chrono::steady_clock;

// A request line of the shard, waiting to run.
struct Pending {
  std::string text;
  std::size_t index = 0;        // among all requests
  std::size_t line_number = 0;  // in the file, 1-based
};

bool blank(const std::string& line) {
  return std::all_of(line.begin(), line.end(), [](char c) { return c == ' ' || c == '\t' || c == '\r'; });
}

// Reads lines, dropping a trailing carriage return (files written on Windows).
bool next_line(std::istream& in, std::string& line, std::size_t& line_number) {
  if (!std::getline(in, line)) return false;
  ++line_number;
  if (!line.empty() && line.back() == '\r') line.pop_back();
  return true;
}

// Writes result lines in order and flushes at least once a second, so a
// scheduler (or `tail -f`) sees results as they come.
class Writer {
 public:
  explicit Writer(std::ostream& out) : out_(out), last_flush_(Clock::now()) {}
  void line(const std::string& text) {
    out_ << text << '\n';
    if (Clock::now() - last_flush_ >= std::chrono::seconds(1)) flush();
  }
  void flush() {
    out_.flush();
    last_flush_ = Clock::now();
  }

 private:
  std::ostream& out_;
  Clock::time_point last_flush_;
};

struct Counts {
  std::size_t safe = 0, collision = 0, undecided = 0, error = 0;
  void add(RequestOutcome::Kind k) {
    switch (k) {
      case RequestOutcome::Kind::Safe: ++safe; break;
      case RequestOutcome::Kind::Collision: ++collision; break;
      case RequestOutcome::Kind::Undecided: ++undecided; break;
      case RequestOutcome::Kind::Error: ++error; break;
    }
  }
  std::size_t total() const { return safe + collision + undecided + error; }
};

// Runs a chunk of requests on the workers (one thread each) and writes
// their results in order, each as soon as it and all before it are done.
// Cancelled runs write nothing more: an outcome is written only when the
// run was not cancelled once it was complete (checked after it is done, so
// no line computed under a cancellation is written).
void written(RunProgress* run) {
  if (run) run->item_done();
}
void stop_if_cancelled(RunProgress* run, Writer& writer) {
  if (run && run->cancelled()) {
    writer.flush();
    throw Cancelled();
  }
}

void run_chunk(const std::vector<Pending>& chunk, std::vector<std::unique_ptr<BatchEnvironment::Worker>>& workers,
               Writer& writer, Counts& counts, RunProgress* run) {
  if (workers.size() == 1) {
    for (const Pending& p : chunk) {
      stop_if_cancelled(run, writer);
      const RequestOutcome o = workers[0]->run(p.text, p.index, p.line_number);
      stop_if_cancelled(run, writer);
      counts.add(o.kind);
      writer.line(o.line);
      written(run);
    }
    return;
  }
  std::vector<RequestOutcome> outcomes(chunk.size());
  std::vector<char> done(chunk.size(), 0);
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  std::exception_ptr failure;
  std::mutex mutex;
  std::condition_variable ready;
  auto work = [&](BatchEnvironment::Worker& worker) {
    for (std::size_t k; !failed && (k = next++) < chunk.size();) {
      try {
        outcomes[k] = worker.run(chunk[k].text, chunk[k].index, chunk[k].line_number);
      } catch (...) {  // an internal error or a resource limit ends the run (exit 4)
        std::lock_guard<std::mutex> lock(mutex);
        if (!failure) failure = std::current_exception();
        failed = true;
      }
      {
        std::lock_guard<std::mutex> lock(mutex);
        done[k] = 1;
      }
      ready.notify_one();
    }
  };
  std::vector<std::thread> threads;
  for (auto& w : workers) threads.emplace_back(work, std::ref(*w));
  for (std::size_t k = 0; k < chunk.size() && !failed; ++k) {
    {
      std::unique_lock<std::mutex> lock(mutex);
      ready.wait(lock, [&] { return done[k] != 0 || failed; });
    }
    if (failed) break;
    if (run && run->cancelled()) {
      failed = true;  // the workers stop taking requests
      break;
    }
    counts.add(outcomes[k].kind);
    writer.line(outcomes[k].line);
    written(run);
  }
  for (std::thread& t : threads) t.join();
  if (failure) std::rethrow_exception(failure);
  stop_if_cancelled(run, writer);
}

}  // namespace

int run_batch(const BatchOptions& options, BatchCounts* counts_out) {
  const auto started = Clock::now();
  RunProgress* const run = options.verify.run;
  if (run) {
    run->count_other_items();
    run->set_activity("reading the environment");
  }
  // Bad files are exit 3 before any work: the output first.
  std::ofstream file_out;
  if (!options.output.empty()) {
    file_out.open(options.output, std::ios::binary | std::ios::trunc);
    if (!file_out) throw InputError("-o: cannot write " + quote_text(options.output));
  }
  std::ostream& out = options.output.empty() ? std::cout : file_out;

  std::ifstream file_in;
  const bool from_stdin = options.requests == "-";
  std::error_code ec;
  if (!from_stdin) {
    if (std::filesystem::is_directory(options.requests, ec))
      throw InputError(options.requests + ": is a directory, not a requests file");
    file_in.open(options.requests, std::ios::binary);
    if (!file_in) throw InputError(options.requests + ": cannot open the requests file");
  }
  std::istream& in = from_stdin ? std::cin : file_in;
  const std::string requests_name = from_stdin ? std::string("<stdin>") : options.requests;
  // Inline bodies' meshes (and the first line's environment's) are
  // relative to the requests file.
  const std::string base = from_stdin ? std::string() : std::filesystem::path(options.requests).parent_path().string();

  std::string line;
  std::size_t line_number = 0;
  Scene scene;
  std::vector<SceneRobot> robots;
  if (!options.scene.empty()) {
    scene = parse_scene_file(options.scene, robots);
  } else {
    bool found = false;
    while (next_line(in, line, line_number))
      if (!blank(line)) {
        found = true;
        break;
      }
    if (!found) throw InputError(requests_name + ": no environment (the first line must be a tmcert-scene/1 document, "
                                                 "or give --scene)");
    scene = parse_scene_text(line, requests_name + " line " + std::to_string(line_number), base, robots);
  }
  // What the reader did to the environment's data (docs/scene-format.md,
  // "Data from real pipelines"), once, on stderr.
  if (!options.quiet) {
    for (const std::string& note : scene.notes) std::cerr << "tmcert batch: note: " << note << "\n";
    for (const std::string& warning : scene.warnings) std::cerr << "tmcert batch: warning: " << warning << "\n";
  }
  if (run) run->set_activity("preparing the environment");
  VerifyOptions verify = options.verify;
  verify.epsilon = options.epsilon ? *options.epsilon : scene.epsilon ? *scene.epsilon : default_epsilon(scene);
  verify.max_depth = options.max_depth ? *options.max_depth : scene.max_depth;
  verify.threads = 1;  // requests run in parallel instead
  const BatchEnvironment environment(std::move(scene), std::move(robots), verify, base, options.stats);

  const int threads = std::max(1, options.threads);
  std::vector<std::unique_ptr<BatchEnvironment::Worker>> workers;
  for (int k = 0; k < threads; ++k) workers.push_back(std::make_unique<BatchEnvironment::Worker>(environment));
  Writer writer(out);
  Counts counts;
  // Chunks bound the memory a huge input takes; results are written as
  // they finish within a chunk.
  const std::size_t chunk_size = 64 * static_cast<std::size_t>(threads);
  std::vector<Pending> chunk;
  std::size_t requests = 0;  // every request of the file, in every shard
  while (next_line(in, line, line_number)) {
    if (blank(line)) continue;
    const std::size_t index = requests++;
    if (!options.shard.owns(index)) continue;
    chunk.push_back({std::move(line), index, line_number});
    if (run) run->add_checks(1);
    if (chunk.size() == chunk_size) {
      if (run) run->set_activity("running requests");
      run_chunk(chunk, workers, writer, counts, run);
      chunk.clear();
      writer.flush();
    }
  }
  if (in.bad()) throw ResourceLimit(requests_name + ": reading failed");
  if (run) run->set_activity("running requests");
  run_chunk(chunk, workers, writer, counts, run);
  writer.flush();
  if (!out) throw InputError(options.output.empty() ? std::string("cannot write the results to standard output")
                                                    : "-o: cannot write " + quote_text(options.output));

  const double seconds = std::chrono::duration<double>(Clock::now() - started).count();
  char rate[64];
  std::snprintf(rate, sizeof rate, "%.2f s, %.1f requests/s", seconds,
                seconds > 0 ? static_cast<double>(counts.total()) / seconds : 0.0);
  if (counts_out) {
    counts_out->requests = requests;
    counts_out->safe = counts.safe;
    counts_out->collision = counts.collision;
    counts_out->undecided = counts.undecided;
    counts_out->error = counts.error;
  }
  if (!options.quiet)
  std::cerr << "tmcert batch: shard " << options.shard.index << "/" << options.shard.count << ": " << counts.total()
            << " of " << requests << " requests: " << counts.safe << " safe, " << counts.collision << " collision, "
            << counts.undecided << " undecided, " << counts.error << " bad; " << rate
            << (verify.kernel == KernelKind::Fast ? " (kernel fast: not certified)" : "") << "\n";
  if (counts.collision > 0) return 1;
  if (counts.undecided > 0 || counts.error > 0) return 2;
  return 0;
}

}  // namespace tmcert
