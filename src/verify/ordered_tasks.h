// Internal to src/verify: a check's subdivision (search_check.h): one node's
// tests and stop, the depth-first search of a subtree within node and stop
// budgets, and the search in parameter order whose deeper subtrees run as
// tasks on threads and are merged so that the result is the sequential one
// (proofs/search-and-pruning.md).
#pragma once

#include "src/verify/search_check.h"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <exception>
#include <memory>
#include <optional>
#include <thread>
#include <utility>
#include <vector>

namespace tmcert::detail {

// Tests one node: prunes its pairs; on a stop, descends to feature pairs
// and tries the witness candidates (setting the witness, or recording the
// undecided piece); else splits it into `left` and `right`.
template <int B>
template <class Policy>
typename Check<B>::Outcome Check<B>::visit(const Policy& policy, Item<Policy>& item, Item<Policy>& left,
                                           Item<Policy>& right, Spheres<Policy>& spheres) {
  Node& node = item.node;
  CheckStats& stats = result.stats;
  ++stats.nodes;
  stats.max_depth = std::max(stats.max_depth, node.depth);
  std::optional<typename Policy::Ball> lazy;  // the piece's ball, computed when first needed
  auto get_ball = [&]() -> typename Policy::Ball& {
    if (!lazy) lazy.emplace(policy.ball(item.piece));
    return *lazy;
  };
  prune(policy, get_ball, item.piece, node.alive, false, spheres, node.depth);  // keep the pairs not cleared on this piece
  if (node.alive.empty()) {  // cleared on the whole piece
    cleared(node);
    return Outcome::Cleared;
  }
  if (exact_early(node)) {  // few feature pairs left: decide them exactly now
    if (const auto outcome = decide_exactly(node)) return *outcome;
  }
  typename Policy::Ball& ball = get_ball();
  std::optional<StopReason> stop;
  if (node.depth >= std::min(options.max_depth, kDepthCap)) stop = StopReason::Depth;
  else if (ball.valid() && ball.r2() * rho2_sum < eps2) stop = StopReason::Epsilon;
  if (stop) {
    // A stop is final: descend the hierarchy to feature pairs here.
    if (options.hierarchy) {
      prune(policy, get_ball, item.piece, node.alive, true, spheres, node.depth);
      retest_above(policy, item, node.alive);
    }
    if (node.alive.empty()) {
      cleared(node);
      return Outcome::Cleared;
    }
    if (exact_resolution_applies()) {  // rational motions, no tube
      if (const auto outcome = decide_exactly(node)) return *outcome;
    }
    // Witness candidates: the scene time with the smallest denominator in
    // the piece (a contact at a "round" rational time, such as 1/3 or
    // 0.137, is found exactly there), then the midpoint and the end.  An
    // isolated contact is found only at its own time, which is the
    // simplest one when anything is; a contact lasting over the piece is
    // found at any of them.  Exact static tests at deep dyadic times are
    // what a colliding check spends most on, so the likeliest goes first.
    const Exact mid = node.mid();
    const Exact end = node.u1();
    const Exact simple = curve_u(simplest_between(scene_t(node.u0()), scene_t(end)));
    enlarged_touch = false;
    for (const Exact* u : {&simple, &mid, &end}) {
      if (u != &simple && *u == simple) continue;  // tried already
      if (try_witness(*u, node.alive)) {
        // The piece before the witness was not cleared: undecided, for
        // the stop's reason (the witness ends the claims).
        if (node.u0() < *u) record_range(node.u0(), *u, *stop);
        const Exact lo = result.first_contact ? result.first_contact->first : scene_t(node.u0());
        result.first_contact = std::pair{lo, scene_t(*u)};
        return Outcome::Witness;
      }
    }
    if (enlarged_touch && true_witness_later(node.u0(), node.u1())) return Outcome::Witness;
    record(node, enlarged_touch ? StopReason::EnlargedModel : *stop);
    ++stats.stops;
    return Outcome::Stopped;
  }
  left = Item<Policy>{Node{2 * node.index, node.depth + 1, node.alive}, {}, nullptr};
  right = Item<Policy>{Node{2 * node.index + 1, node.depth + 1, std::move(node.alive)}, {}, nullptr};
  policy.split(item.piece, left.piece, right.piece);
  if (options.hierarchy) {
    // This piece is an ancestor retest_above needs only for feature pairs
    // made below it, which only a node pair alive here can make; without
    // one the sub-pieces keep the chain above (pairs made at this depth or
    // above are re-tested only on pieces above theirs).
    const bool nodes_alive =
        std::any_of(left.node.alive.begin(), left.node.alive.end(), [](const PairRef& p) { return p.nodes; });
    if (nodes_alive)  // the piece is no longer needed here: the ancestor keeps it
      left.parent = right.parent = std::make_shared<const Ancestor<Policy>>(
          Ancestor<Policy>{ball, std::move(item.piece), item.parent, node.depth});
    else
      left.parent = right.parent = item.parent;
  }
  return Outcome::Split;
}

// Depth-first search below `root` in parameter order, at most `budget`
// nodes (then the rest is recorded as undecided "limit").  With `shared`,
// every node is also counted there and the search gives up (returns
// false, its result unusable) once that count passes `shared_limit`.
template <int B>
template <class Policy>
bool Check<B>::dfs(const Policy& policy, Item<Policy> root, std::uint64_t budget, std::uint64_t stop_budget,
                   Spheres<Policy>& spheres, std::atomic<std::uint64_t>* shared, std::uint64_t shared_limit) {
  std::vector<Item<Policy>> stack;
  stack.push_back(std::move(root));
  const std::uint64_t limit = result.stats.nodes + budget;
  const std::uint64_t stop_limit = result.stats.stops + stop_budget;
  while (!stack.empty()) {
    Item<Policy> item = std::move(stack.back());
    stack.pop_back();
    if (result.stats.nodes >= limit || result.stats.stops >= stop_limit ||
        past_deadline(options)) {  // resource limit (nodes, stops, time): not cleared
      record(item.node, StopReason::Limit);
      continue;
    }
    if (shared && ++*shared > shared_limit) return false;
    Item<Policy> left, right;
    switch (visit(policy, item, left, right, spheres)) {
      case Outcome::Witness: return true;
      case Outcome::Split:
        stack.push_back(std::move(right));
        stack.push_back(std::move(left));  // parameter order: left first
        break;
      default: break;
    }
  }
  return true;
}

template <int B>
template <class Policy>
void Check<B>::search(const Policy& policy) {
  // The ordered entries: a task to search, or the finished result of a
  // shallower piece that stopped.
  struct Entry {
    std::optional<Item<Policy>> task;
    CheckResult part;
  };
  std::vector<Entry> entries;  // in parameter order
  // The sphere caches of this thread's last search, reused (a planner's
  // edges and a robot's links are many small checks of the same bodies:
  // fresh caches cost an allocation and zeroing of every entry per check);
  // a search nested in another on this thread gets its own.
  static thread_local std::unique_ptr<Spheres<Policy>> kept;
  static thread_local bool kept_busy = false;
  std::unique_ptr<Spheres<Policy>> own_spheres;
  Spheres<Policy>* chosen = nullptr;
  if (kept_busy) {
    own_spheres = std::make_unique<Spheres<Policy>>(moving, other);
    chosen = own_spheres.get();
  } else {
    if (kept) kept->rebind(moving, other);
    else kept = std::make_unique<Spheres<Policy>>(moving, other);
    chosen = kept.get();
    kept_busy = true;
  }
  struct Release {
    bool* busy;
    ~Release() {
      if (busy) *busy = false;
    }
  } release{chosen == kept.get() ? &kept_busy : nullptr};
  Spheres<Policy>& spheres = *chosen;
  {
    std::vector<Item<Policy>> stack;
    stack.push_back({Node{0, 0, root_pairs()}, policy.root(), nullptr});
    while (!stack.empty()) {
      Item<Policy> item = std::move(stack.back());
      stack.pop_back();
      if (item.node.depth >= kTaskDepth || result.stats.nodes >= options.max_nodes ||
          result.stats.stops >= options.max_stops || past_deadline(options)) {
        entries.push_back({std::move(item), {}});
        continue;
      }
      Item<Policy> left, right;
      if (entries.empty()) {
        // Nothing waits before this piece: its outcome goes straight into
        // the result (the common case of small checks: no copies).
        const Outcome outcome = visit(policy, item, left, right, spheres);
        if (outcome == Outcome::Witness) return;
        if (outcome == Outcome::Split) {
          stack.push_back(std::move(right));
          stack.push_back(std::move(left));
        }
        continue;
      }
      CheckResult part;
      Check sub = fork(part);
      const Outcome outcome = sub.visit(policy, item, left, right, spheres);
      if (outcome == Outcome::Split || outcome == Outcome::Cleared) {
        merge(part);  // statistics only
        if (outcome == Outcome::Split) {
          stack.push_back(std::move(right));
          stack.push_back(std::move(left));
        }
        continue;
      }
      entries.push_back({std::nullopt, std::move(part)});
      if (outcome == Outcome::Witness) break;  // nothing after it matters
    }
  }
  // The tasks run optimistically, in parallel, each with all the node
  // and stop budgets left; the merge then replays the sequential budgets:
  // a task that used more than what the tasks before it left (or gave up
  // because all tasks together passed the node budget) is searched again,
  // alone, with exactly that.  So the result is the sequential one for
  // every thread count.
  std::size_t task_count = 0;
  for (const Entry& e : entries) task_count += e.task ? 1 : 0;
  const std::uint64_t used = result.stats.nodes;
  const std::uint64_t remaining = options.max_nodes > used ? options.max_nodes - used : 0;
  const std::uint64_t stops_remaining =
      options.max_stops > result.stats.stops ? options.max_stops - result.stats.stops : 0;
  std::vector<std::optional<Item<Policy>>> originals(entries.size());
  std::vector<char> complete(entries.size(), 0);
  std::vector<std::exception_ptr> errors(entries.size());
  std::atomic<std::size_t> next{0};
  std::atomic<std::size_t> first_witness{entries.size()};
  std::atomic<std::uint64_t> spent{0};
  for (std::size_t i = 0; i < entries.size(); ++i)
    if (entries[i].task) originals[i] = *entries[i].task;
  auto worker = [&](Spheres<Policy>* own) {
    std::optional<Spheres<Policy>> local;
    for (std::size_t i = next++; i < entries.size(); i = next++) {
      Entry& e = entries[i];
      if (!e.task || i > first_witness.load()) continue;  // after a witness: not needed
      if (!own) own = &local.emplace(moving, other);
      try {
        Check sub = fork(e.part);
        complete[i] = sub.dfs(policy, std::move(*e.task), remaining, stops_remaining, *own, &spent, remaining) ? 1 : 0;
        if (complete[i] && e.part.witness) {
          std::size_t w = first_witness.load();
          while (i < w && !first_witness.compare_exchange_weak(w, i)) {}
        }
      } catch (...) {
        errors[i] = std::current_exception();
      }
    }
  };
  if (task_count > 0) {
    const int threads = std::max(1, std::min<int>(options.threads, static_cast<int>(task_count)));
    std::vector<std::thread> pool;
    for (int t = 1; t < threads; ++t) pool.emplace_back(worker, nullptr);
    worker(&spheres);
    for (std::thread& t : pool) t.join();
  }
  std::uint64_t cumulative = 0;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    Entry& e = entries[i];
    if (originals[i]) {
      if (errors[i]) std::rethrow_exception(errors[i]);
      const std::uint64_t left = remaining > cumulative ? remaining - cumulative : 0;
      // The stops the pieces merged so far (tasks and shallower stops)
      // leave.  The task ran with stops_remaining >= stops_left: its run
      // is the one with stops_left unless it reached stops_left stops
      // with budget to spare (a run with stops_left would have ended
      // there).
      const std::uint64_t stops_left =
          options.max_stops > result.stats.stops ? options.max_stops - result.stats.stops : 0;
      const bool stops_differ = stops_left < stops_remaining && e.part.stats.stops >= stops_left;
      if (!complete[i] || e.part.stats.nodes > left || stops_differ) {
        e.part = CheckResult{};
        Check sub = fork(e.part);
        sub.dfs(policy, std::move(*originals[i]), left, stops_left, spheres);
      }
      cumulative += e.part.stats.nodes;
    }
    if (!merge(e.part)) return;
  }
}

}  // namespace tmcert::detail
