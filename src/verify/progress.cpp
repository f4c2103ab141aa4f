#include "src/verify/progress.h"

#include <cmath>

namespace tmcert {

ProgressReport RunProgress::report() const {
  ProgressReport r;
  r.checks = checks_.load(std::memory_order_relaxed);
  r.checks_done = checks_done_.load(std::memory_order_relaxed);
  const std::uint64_t units = units_.load(std::memory_order_relaxed);
  if (r.checks > 0) {
    r.fraction = static_cast<double>(units) / (static_cast<double>(r.checks) * static_cast<double>(kUnit));
    // Below 1 until every check is done (rounding of the division included).
    if (r.checks_done < r.checks) r.fraction = std::min(r.fraction, std::nextafter(1.0, 0.0));
    r.fraction = std::clamp(r.fraction, 0.0, 1.0);
  }
  {
    std::lock_guard<std::mutex> lock(mutex_);
    r.activity = step_.empty() ? activity_ : activity_.empty() ? step_ : activity_ + ": " + step_;
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  return r;
}

ProgressWatcher::ProgressWatcher(RunProgress& run, std::function<bool(const ProgressReport&)> callback, double interval)
    : run_(run), callback_(std::move(callback)), interval_(interval) {
  thread_ = std::thread([this] {
    std::unique_lock<std::mutex> lock(mutex_);
    while (!wake_.wait_for(lock, interval_, [this] { return stop_; })) {
      lock.unlock();
      const bool go_on = callback_(run_.report());
      if (!go_on) run_.cancel();
      lock.lock();
    }
  });
}

ProgressWatcher::~ProgressWatcher() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_one();
  thread_.join();
}

}  // namespace tmcert
