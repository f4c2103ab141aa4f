// The prepared copies behind tmcert::Environment (include/tmcert/
// environment.h), for the code that certifies motions the public Motion
// cannot say (a robot's links on a joint path, several movers, mover pairs):
// the certified OMPL validator (src/ompl/).  Only internal headers here, so
// that code in namespace tmcert can include it (src/api/internal.h explains
// why the public headers would get in its way).
#pragma once

#include "src/verify/fixed_environment.h"

#include <cstddef>
#include <memory>
#include <mutex>
#include <optional>
#include <utility>
#include <vector>

namespace tmcert::api {
class Environment;
}

namespace tmcert {

// Fixed obstacles and movers prepared once (src/verify/fixed_environment.h),
// their motions certified from any number of threads at once: a call takes
// a prepared copy that no other call uses (or prepares one when every copy
// is busy: memory grows with the largest number of concurrent calls) and
// gives it back; the calls give the results of sequential calls.
class EnvironmentPool {
 public:
  // As FixedEnvironment's constructor (the first copy is prepared here,
  // which checks the bodies and options).  Throws InputError.
  EnvironmentPool(Body obstacles, std::vector<Body> movers, std::vector<std::pair<int, int>> mover_pairs,
                  const VerifyOptions& options);
  ~EnvironmentPool();

  // FixedEnvironment::check (decide false) or FixedEnvironment::decide
  // (decide true: sampled configurations and the edge's slices first, up
  // to the first proof of contact) of the movers along `motions`.
  MotionCheck check(const std::vector<Trajectory>& motions, bool decide) const;
  // FixedEnvironment::static_contact.
  std::optional<Witness> static_contact(const std::vector<Mat34E>& poses) const;
  // FixedEnvironment::has_primitives.
  bool has_primitives() const { return has_primitives_; }
  // The bodies' names (0: the obstacles, 1 + k: mover k), which
  // CheckResult::bodies index; only the names are kept.
  const std::vector<Body>& labels() const { return labels_; }
  // How many copies exist (at least 1).
  std::size_t copies() const;

 private:
  std::unique_ptr<FixedEnvironment> prepare() const;
  std::unique_ptr<FixedEnvironment> take() const;
  void give_back(std::unique_ptr<FixedEnvironment> e) const;
  template <typename F>
  auto leased(F&& f) const;

  Body obstacles_;
  std::vector<Body> movers_;
  std::vector<std::pair<int, int>> pairs_;
  VerifyOptions options_;
  std::vector<Body> labels_;
  bool has_primitives_ = false;
  mutable std::mutex mutex_;
  mutable std::vector<std::unique_ptr<FixedEnvironment>> idle_;  // copies not in use
  mutable std::size_t copies_ = 0;
};

// The pool behind a public Environment.
const EnvironmentPool& pool_of(const api::Environment& environment);

// A public Environment of any movers and mover pairs (InputError as
// EnvironmentPool's constructor, in the internal words).
std::shared_ptr<const api::Environment> shared_environment(Body obstacles, std::vector<Body> movers,
                                                           std::vector<std::pair<int, int>> mover_pairs,
                                                           const VerifyOptions& options);

}  // namespace tmcert
