// Progress and cancellation of a run (verify_scene, tmcert batch): what the
// search threads publish, cheaply, through atomics, and a watcher thread
// that reads it at a steady rate and hands it to a callback (the command
// line's progress line, the public API's VerifyOptions::progress, the
// Python package's KeyboardInterrupt).
//
// The fraction is honest: each check is worth one unit; a check's search
// adds, for every piece of its parameter interval it finishes (cleared,
// stopped, or left to a limit), the piece's share of the interval, and a
// check's share stays below its unit until the check is finished (pieces
// searched again by the merge of parallel tasks cannot push it over).  So
// the fraction reaches 1 only when every check is done; what runs before
// and after the checks (reading, preparing bodies, writing) is named by the
// activity instead of being hidden behind a fraction.
//
// Cancellation: RunProgress::cancel() makes past_deadline() true for every
// check of the run, so each search stops within about one subdivision
// node's work and records what is left as undecided (never cleared); the
// caller (verify_scene, run_batch) then throws Cancelled instead of
// returning a result.
#pragma once

#include "src/model/model.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>

namespace tmcert {

// A run was cancelled (RunProgress::cancel): no result.
class Cancelled : public std::runtime_error {
 public:
  Cancelled() : std::runtime_error("cancelled") {}
};

// What a watcher hands to its callback.
struct ProgressReport {
  double fraction = 0;         // of the checks' work, in [0, 1); 1 only once every check is done
  std::size_t checks_done = 0;
  std::size_t checks = 0;      // 0 before the checks are known
  std::string activity;        // what the run does now, for people
  double seconds = 0;          // since the RunProgress was made
};

class RunProgress {
 public:
  // One check's worth of progress.
  static constexpr std::uint64_t kUnit = std::uint64_t{1} << 32;

  RunProgress() : start_(std::chrono::steady_clock::now()) {}

  // What the run does ("checking a x b"), and a step within it
  // ("preparing body ..."; empty: none); the report shows "activity: step".
  void set_activity(std::string activity) {
    std::lock_guard<std::mutex> lock(mutex_);
    activity_ = std::move(activity);
    step_.clear();
  }
  void set_step(std::string step) {
    std::lock_guard<std::mutex> lock(mutex_);
    step_ = std::move(step);
  }
  // The number of checks the run will do (a batch adds as it reads).
  void set_checks(std::size_t n) { checks_.store(n, std::memory_order_relaxed); }
  void add_checks(std::size_t n) { checks_.fetch_add(n, std::memory_order_relaxed); }

  // The items counted are checks (verify_scene; default), or something
  // else (a batch's requests): then Verifier::check leaves them alone.
  void count_other_items() { checks_are_items_ = false; }
  bool checks_are_items() const { return checks_are_items_; }
  // One such item is done (a Slot's whole unit at once).
  void item_done() {
    units_.fetch_add(kUnit, std::memory_order_relaxed);
    checks_done_.fetch_add(1, std::memory_order_relaxed);
  }

  void cancel() { cancelled_.store(true, std::memory_order_relaxed); }
  bool cancelled() const { return cancelled_.load(std::memory_order_relaxed); }

  ProgressReport report() const;

  // One check's share, on the stack of the thread that runs the check.
  class Slot {
   public:
    explicit Slot(RunProgress& run) : run_(run) {}
    ~Slot() { finish(); }
    Slot(const Slot&) = delete;
    Slot& operator=(const Slot&) = delete;
    // `units` more of this check are done (clamped below kUnit).
    void add(std::uint64_t units) {
      std::uint64_t u = units_.load(std::memory_order_relaxed), next;
      do {
        next = std::min(u + std::min(units, kUnit), kUnit - 1);
        if (next == u) return;
      } while (!units_.compare_exchange_weak(u, next, std::memory_order_relaxed));
      run_.units_.fetch_add(next - u, std::memory_order_relaxed);
    }
    // The check is done: its whole unit.
    void finish() {
      if (finished_) return;
      finished_ = true;
      run_.units_.fetch_add(kUnit - units_.exchange(kUnit, std::memory_order_relaxed), std::memory_order_relaxed);
      run_.checks_done_.fetch_add(1, std::memory_order_relaxed);
    }

   private:
    RunProgress& run_;
    std::atomic<std::uint64_t> units_{0};
    bool finished_ = false;
  };

 private:
  std::chrono::steady_clock::time_point start_;
  mutable std::mutex mutex_;
  std::string activity_, step_;
  std::atomic<std::size_t> checks_{0}, checks_done_{0};
  std::atomic<std::uint64_t> units_{0};
  std::atomic<bool> cancelled_{false};
  bool checks_are_items_ = true;  // set before the run starts
};

// Calls `callback` with the run's report every `interval` seconds from a
// thread of its own, from construction until destruction (never two calls
// at once); a callback that returns false cancels the run.  Exceptions of
// the callback are not caught (they end the process): callbacks that can
// fail catch their own.
class ProgressWatcher {
 public:
  ProgressWatcher(RunProgress& run, std::function<bool(const ProgressReport&)> callback, double interval);
  ~ProgressWatcher();
  ProgressWatcher(const ProgressWatcher&) = delete;
  ProgressWatcher& operator=(const ProgressWatcher&) = delete;

 private:
  RunProgress& run_;
  std::function<bool(const ProgressReport&)> callback_;
  std::chrono::duration<double> interval_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stop_ = false;
  std::thread thread_;
};

}  // namespace tmcert
