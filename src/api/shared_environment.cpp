// EnvironmentPool (src/api/shared_environment.h): prepared copies of one
// FixedEnvironment, one per concurrent call.  Internal headers only (code in
// namespace tmcert; src/api/internal.h explains why).
#include "src/api/shared_environment.h"

namespace tmcert {

EnvironmentPool::EnvironmentPool(Body obstacles, std::vector<Body> movers, std::vector<std::pair<int, int>> mover_pairs,
                                 const VerifyOptions& options)
    : obstacles_(std::move(obstacles)), movers_(std::move(movers)), pairs_(std::move(mover_pairs)), options_(options) {
  idle_.push_back(prepare());  // the first copy, which also checks the bodies
  copies_ = 1;
  has_primitives_ = idle_.front()->has_primitives();
  for (const Body& b : idle_.front()->bodies()) {
    Body label;
    label.name = b.name;
    labels_.push_back(std::move(label));
  }
}

EnvironmentPool::~EnvironmentPool() = default;

std::unique_ptr<FixedEnvironment> EnvironmentPool::prepare() const {
  return std::make_unique<FixedEnvironment>(obstacles_, movers_, pairs_, options_);
}

std::unique_ptr<FixedEnvironment> EnvironmentPool::take() const {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!idle_.empty()) {
      std::unique_ptr<FixedEnvironment> e = std::move(idle_.back());
      idle_.pop_back();
      return e;
    }
  }
  std::unique_ptr<FixedEnvironment> e = prepare();  // outside the lock: others go on
  std::lock_guard<std::mutex> lock(mutex_);
  ++copies_;
  return e;
}

void EnvironmentPool::give_back(std::unique_ptr<FixedEnvironment> e) const {
  std::lock_guard<std::mutex> lock(mutex_);
  idle_.push_back(std::move(e));
}

// f(copy) on a prepared copy for this call alone, given back however the call ends.
template <typename F>
auto EnvironmentPool::leased(F&& f) const {
  struct Lease {
    const EnvironmentPool& pool;
    std::unique_ptr<FixedEnvironment> prepared;
    ~Lease() { pool.give_back(std::move(prepared)); }
  } lease{*this, take()};
  return f(static_cast<const FixedEnvironment&>(*lease.prepared));
}

MotionCheck EnvironmentPool::check(const std::vector<Trajectory>& motions, bool decide) const {
  return leased([&](const FixedEnvironment& e) { return decide ? e.decide(motions) : e.check(motions); });
}

std::optional<Witness> EnvironmentPool::static_contact(const std::vector<Mat34E>& poses) const {
  return leased([&](const FixedEnvironment& e) { return e.static_contact(poses); });
}

std::size_t EnvironmentPool::copies() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return copies_;
}

}  // namespace tmcert
