#include "src/batch/run_batch.h"

#include "src/batch/batch_environment.h"
#include "src/io/output_file.h"
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

#include <sys/stat.h>
#include <unistd.h>

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
// scheduler (or `tail -f`) sees results as they come.  A write that fails
// is OutputError (exit 4) naming the file or the standard output.
class Writer {
 public:
  explicit Writer(OutputFile* file) : file_(file), last_flush_(Clock::now()) {}
  void line(const std::string& text) {
    buffer_ += text;
    buffer_ += '\n';
    if (buffer_.size() >= (1u << 16) || Clock::now() - last_flush_ >= std::chrono::seconds(1)) flush();
  }
  void flush() {
    if (file_) file_->append(buffer_);
    else write_stdout(buffer_);
    buffer_.clear();
    last_flush_ = Clock::now();
  }
  // When the next flush is due.
  Clock::time_point next_flush() const { return last_flush_ + std::chrono::seconds(1); }

 private:
  OutputFile* file_;  // none: the standard output
  std::string buffer_;
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

// Progress and cancellation: an outcome is written only when the run was
// not cancelled once it was complete (checked after it is done, so no line
// computed under a cancellation is written).
void written(RunProgress* run) {
  if (run) run->item_done();
}
void stop_if_cancelled(RunProgress* run, Writer& writer) {
  if (run && run->cancelled()) {
    writer.flush();
    throw Cancelled();
  }
}

// The shard's requests, read one at a time (blank lines and other shards'
// requests skipped).
class RequestReader {
 public:
  RequestReader(std::istream& in, std::string name, const Shard& shard, std::string line, std::size_t line_number,
                RunProgress* run)
      : in_(in), name_(std::move(name)), shard_(shard), line_(std::move(line)), line_number_(line_number), run_(run) {}

  // The next request of the shard; false at the end of the input.
  bool next(Pending& p) {
    while (next_line(in_, line_, line_number_)) {
      if (blank(line_)) continue;
      const std::size_t index = requests_++;
      if (!shard_.owns(index)) continue;
      p.text = std::move(line_);
      p.index = index;
      p.line_number = line_number_;
      if (run_) run_->add_checks(1);
      return true;
    }
    if (in_.bad()) throw ResourceLimit(name_ + ": reading failed");
    return false;
  }
  // Every request of the file, in every shard, read so far.
  std::size_t requests() const { return requests_; }

 private:
  std::istream& in_;
  std::string name_;
  const Shard& shard_;
  std::string line_;
  std::size_t line_number_;
  RunProgress* run_;
  std::size_t requests_ = 0;
};

// One thread: each request run and written before the next is read.
void run_serial(RequestReader& reader, BatchEnvironment::Worker& worker, Writer& writer, Counts& counts,
                RunProgress* run) {
  Pending p;
  while (reader.next(p)) {
    stop_if_cancelled(run, writer);
    const RequestOutcome o = worker.run(p.text, p.index, p.line_number);
    stop_if_cancelled(run, writer);
    counts.add(o.kind);
    writer.line(o.line);
    written(run);
  }
}

// Several threads: a window of the next requests (at most `window` read
// and not yet written) in a ring; each worker thread takes the oldest
// request nobody runs yet, and this thread reads requests into the window
// and writes each result as soon as it and all before it are done.  No
// worker waits for another: only a request older than the whole window
// (one that takes as long as about `window` others) holds the workers
// back.  The threads live for the whole run.
class Pool {
 public:
  Pool(std::vector<std::unique_ptr<BatchEnvironment::Worker>>& workers, std::size_t window) : ring_(window) {
    threads_.reserve(workers.size());
    for (auto& w : workers) threads_.emplace_back([this, &w] { work(*w); });
  }
  ~Pool() { stop(); }
  Pool(const Pool&) = delete;
  Pool& operator=(const Pool&) = delete;

  void run(RequestReader& reader, Writer& writer, Counts& counts, RunProgress* run) {
    bool more = true;
    Pending p;
    for (;;) {
      // Fill the window.
      while (more && tail_ - head_ < ring_.size()) {
        more = reader.next(p);
        if (!more) break;
        std::lock_guard<std::mutex> lock(mutex_);
        Slot& slot = ring_[tail_ % ring_.size()];
        slot.request = std::move(p);
        slot.done = false;
        ++tail_;
        if (idle_ > 0) work_ready_.notify_one();
      }
      if (head_ == tail_) break;  // every request written
      // The oldest result, once done; the output is flushed at least once a
      // second while waiting for it.
      RequestOutcome outcome;
      {
        std::unique_lock<std::mutex> lock(mutex_);
        Slot& slot = ring_[head_ % ring_.size()];
        while (!slot.done && !failure_) {
          if (head_done_.wait_until(lock, writer.next_flush()) == std::cv_status::timeout) {
            lock.unlock();
            writer.flush();
            lock.lock();
          }
        }
        if (failure_) break;
        outcome = std::move(slot.outcome);
        ++head_;
      }
      if (run && run->cancelled()) break;
      counts.add(outcome.kind);
      writer.line(outcome.line);
      written(run);
    }
    stop();
    if (failure_) std::rethrow_exception(failure_);
    stop_if_cancelled(run, writer);
  }

 private:
  struct Slot {
    Pending request;
    RequestOutcome outcome;
    bool done = false;
  };

  void work(BatchEnvironment::Worker& worker) {
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
      ++idle_;
      work_ready_.wait(lock, [&] { return stopping_ || failure_ || next_ < tail_; });
      --idle_;
      if (stopping_ || failure_) return;
      const std::size_t k = next_++;
      Slot& slot = ring_[k % ring_.size()];
      lock.unlock();
      RequestOutcome outcome;
      std::exception_ptr failure;
      try {
        outcome = worker.run(slot.request.text, slot.request.index, slot.request.line_number);
      } catch (...) {  // an internal error or a resource limit ends the run (exit 4)
        failure = std::current_exception();
      }
      lock.lock();
      if (failure) {
        if (!failure_) failure_ = failure;
        head_done_.notify_one();
        return;
      }
      slot.outcome = std::move(outcome);
      slot.done = true;
      if (k == head_) head_done_.notify_one();
    }
  }

  // The workers stop taking requests (those running finish theirs).
  void stop() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stopping_ = true;
    }
    work_ready_.notify_all();
    for (std::thread& t : threads_)
      if (t.joinable()) t.join();
  }

  std::vector<Slot> ring_;
  std::size_t head_ = 0;  // the oldest request not written
  std::size_t next_ = 0;  // the oldest request no worker has taken
  std::size_t tail_ = 0;  // one past the newest request read
  std::size_t idle_ = 0;  // workers waiting for a request
  bool stopping_ = false;
  std::exception_ptr failure_;
  std::mutex mutex_;
  std::condition_variable work_ready_, head_done_;
  std::vector<std::thread> threads_;
};

}  // namespace

int run_batch(const BatchOptions& options, BatchCounts* counts_out) {
  const auto started = Clock::now();
  RunProgress* const run = options.run;
  if (run) {
    run->count_other_items();
    run->set_activity("reading the environment");
  }
  // Bad files are exit 3 before any work: the output is checked first
  // (src/io/output_file.h), and written (truncated) only once the
  // environment is read and the output is known to be none of the inputs:
  // the requests file (or the standard input's file), the environment
  // scene and its meshes and URDFs.
  std::optional<OutputFile> file_out;
  if (!options.output.empty()) file_out.emplace("-o", options.output);
  std::vector<FileIdentity> inputs;
  auto add_input = [&](const std::optional<FileIdentity>& f) {
    if (f) inputs.push_back(*f);
  };

  std::ifstream file_in;
  const bool from_stdin = options.requests == "-";
  std::error_code ec;
  if (!from_stdin) {
    if (std::filesystem::is_directory(options.requests, ec))
      throw InputError(options.requests + ": is a directory, not a requests file");
    file_in.open(options.requests, std::ios::binary);
    if (!file_in) throw InputError(options.requests + ": cannot open the requests file");
    add_input(file_identity(options.requests));
  } else {
    struct stat info;  // the standard input's file, when it is a regular one
    if (::fstat(STDIN_FILENO, &info) == 0 && S_ISREG(info.st_mode))
      inputs.push_back({static_cast<std::uint64_t>(info.st_dev), static_cast<std::uint64_t>(info.st_ino), "<stdin>"});
  }
  if (!options.scene.empty()) add_input(file_identity(options.scene));
  if (file_out) require_distinct({&*file_out}, inputs);
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
    scene = parse_scene_file(options.scene, ReadOptions{options.package_paths}, &robots);
  } else {
    bool found = false;
    while (next_line(in, line, line_number))
      if (!blank(line)) {
        found = true;
        break;
      }
    if (!found) throw InputError(requests_name + ": no environment (the first line must be a tmcert-scene/1 document, "
                                                 "or give --scene)");
    scene = parse_scene_text(line, requests_name + " line " + std::to_string(line_number), base, robots,
                             ReadOptions{options.package_paths});
  }
  if (file_out) {
    require_distinct({&*file_out}, scene.input_files);
    file_out->begin();
  }
  // What the reader did to the environment's data (docs/scene-format.md,
  // "Data from real pipelines"), once, on stderr.
  if (!options.quiet) {
    for (const std::string& note : scene.notes) std::cerr << "tmcert batch: note: " << note << "\n";
    for (const std::string& warning : scene.warnings) std::cerr << "tmcert batch: warning: " << warning << "\n";
  }
  if (run) run->set_activity("preparing the environment");
  VerifyOptions verify = build_options(options.verify, scene, EpsilonScope::WholeScene, options.spelling);
  verify.run = options.run;
  verify.threads = 1;  // requests run in parallel instead
  const BatchEnvironment environment(std::move(scene), std::move(robots), verify, base, options.stats);

  const int threads = std::max(1, options.verify.threads);
  std::vector<std::unique_ptr<BatchEnvironment::Worker>> workers;
  for (int k = 0; k < threads; ++k) workers.push_back(std::make_unique<BatchEnvironment::Worker>(environment));
  Writer writer(file_out ? &*file_out : nullptr);
  Counts counts;
  RequestReader reader(in, requests_name, options.shard, std::move(line), line_number, run);
  try {
    if (run) run->set_activity("running requests");
    if (threads == 1) {
      run_serial(reader, *workers[0], writer, counts, run);
    } else {
      // The window bounds the memory a huge input takes.
      Pool pool(workers, 64 * static_cast<std::size_t>(threads));
      pool.run(reader, writer, counts, run);
    }
    writer.flush();
  } catch (const Cancelled&) {
    // A cancelled run's output ends after its last complete line, which
    // stands (include/tmcert/batch.h): the results file is closed, not
    // removed as after a failure.
    writer.flush();
    if (file_out) file_out->finish();
    throw;
  }
  if (file_out) file_out->finish();
  const std::size_t requests = reader.requests();

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
