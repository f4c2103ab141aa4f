// Refinement by default (src/verify/refine.h, proofs/refinement.md).
#include "src/verify/refine.h"

#include "src/verify/search.h"

#include <algorithm>
#include <atomic>
#include <set>
#include <utility>
#include <vector>

namespace tmcert::detail {

namespace {

bool is_integer(const Exact& x) { return x.denominator() == 1; }

// The aligned dyadic pieces [i / 2^d, (i + 1) / 2^d] that make up [a, b]
// (curve parameters in [0, 1] with power-of-two denominators, as the
// search's pieces and their unions are), largest first from the left.
// Empty when [a, b] is not such a union (then it is not re-searched).
std::vector<std::pair<Exact, Exact>> dyadic_pieces(Exact a, const Exact& b) {
  std::vector<std::pair<Exact, Exact>> out;
  while (a < b) {
    Exact size = 1;
    int depth = 0;
    while (!(is_integer(a / size) && a + size <= b)) {
      if (++depth > 62) return {};
      size /= 2;
    }
    out.push_back({a, a + size});
    a += size;
  }
  return out;
}

// A cleared piece given as a scene interval, as the piece [index, index +
// 1] / 2^depth of the check's curve over [t0, t1]; false when it is not one.
bool as_dyadic(CoverPiece& c, const Exact& t0, const Exact& t1) {
  const Exact u0 = (c.t0 - t0) / (t1 - t0), u1 = (c.t1 - t0) / (t1 - t0);
  const Exact inverse = 1 / (u1 - u0);  // 2^depth
  if (!is_integer(inverse) || !(inverse > 0)) return false;
  const CGAL::Gmpz pieces = inverse.numerator();
  if (mpz_popcount(pieces.mpz()) != 1) return false;
  const Exact index = u0 * inverse;
  if (!is_integer(index) || index < 0) return false;
  const std::size_t depth = mpz_scan1(pieces.mpz(), 0);
  if (depth > 62 || !mpz_fits_ulong_p(index.numerator().mpz())) return false;
  c.index = mpz_get_ui(index.numerator().mpz());
  c.depth = static_cast<int>(depth);
  c.timed = false;
  c.t0 = c.t1 = 0;
  return true;
}

// set_default_time_limit_for_tests (0: kDefaultTimeLimit).
std::atomic<double> default_time_limit_for_tests{0};

}  // namespace

double check_time_limit(const VerifyOptions& options) {
  if (options.time_limit > 0) return options.time_limit;
  if (!options.refine) return 0;
  const double shortened = default_time_limit_for_tests.load();
  return shortened > 0 ? shortened : kDefaultTimeLimit;
}

std::chrono::steady_clock::time_point check_deadline(const VerifyOptions& options,
                                                     std::chrono::steady_clock::time_point start) {
  const double seconds = check_time_limit(options);
  if (!(seconds > 0)) return std::chrono::steady_clock::time_point::max();
  return start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(seconds));
}

void set_default_time_limit_for_tests(double seconds) { default_time_limit_for_tests.store(seconds); }

void refine_check(CheckResult& result, const Exact& check_t0, const Exact& check_t1, bool dyadic,
                  const VerifyOptions& options, std::chrono::steady_clock::time_point started,
                  const WindowSearch& search) {
  result.epsilon = *options.epsilon;
  if (!options.refine || result.verdict != Verdict::Undecided || !(check_t0 < check_t1)) return;
  VerifyOptions o = options;
  o.slot = nullptr;  // the check's progress share was reported by its first search
  o.slot_span = 0;
  Exact eps = *options.epsilon;
  // Parts whose re-search visited no node and stayed undecided: the start
  // test there cannot decide (an enclosed pose within rounding of contact),
  // which no epsilon changes.
  std::set<std::pair<Exact, Exact>> stuck;
  int level = 1;
  for (; level <= kRefineLevels && result.verdict == Verdict::Undecided; ++level) {
    if (past_deadline(o)) {
      result.refine_out_of_time = true;
      break;
    }
    std::vector<UndecidedInterval> todo = result.undecided;
    std::sort(todo.begin(), todo.end(), [](const UndecidedInterval& x, const UndecidedInterval& y) { return x.t0 < y.t0; });
    bool any = false;
    for (const UndecidedInterval& u : todo) any = any || !stuck.count({u.t0, u.t1});
    if (!any) {
      result.refine_exhausted = true;
      break;
    }
    eps /= 10;
    o.epsilon = eps;
    CheckResult next;
    next.bodies = result.bodies;
    next.clearance = result.clearance;
    next.stats = result.stats;
    next.cleared = result.cleared;
    bool more = true;
    // One part [w0, w1] searched again, merged after everything before it.
    auto window = [&](const Exact& w0, const Exact& w1) {
      CheckResult part;
      if (past_deadline(o)) {
        part.undecided.push_back({w0, w1, StopReason::Limit});
        part.first_contact = std::pair{w0, w1};
      } else {
        // Everything before w0 is cleared, from the check's tested start:
        // the configuration at w0 is proven free (proofs/refinement.md).
        const bool start_free = next.undecided.empty() && check_t0 < w0;
        part = search(w0, w1, start_free, o);
        if (part.stats.nodes == 0 && !part.witness && !part.undecided.empty()) stuck.insert({w0, w1});
        if (dyadic)
          for (CoverPiece& c : part.cleared)
            if (c.timed && !as_dyadic(c, check_t0, check_t1)) {
              // Not a piece of the curve a certificate can name: the part
              // stays undecided (never happens for aligned windows).
              part = CheckResult{};
              part.undecided.push_back({w0, w1, StopReason::Epsilon});
              part.first_contact = std::pair{w0, w1};
              break;
            }
      }
      more = merge_result(next, part);
    };
    for (const UndecidedInterval& u : todo) {
      if (!more) break;
      if (stuck.count({u.t0, u.t1})) {
        CheckResult part;
        part.undecided.push_back(u);
        part.first_contact = std::pair{u.t0, u.t1};
        more = merge_result(next, part);
        continue;
      }
      if (!dyadic) {
        window(u.t0, u.t1);
        continue;
      }
      const Exact span = check_t1 - check_t0;
      const std::vector<std::pair<Exact, Exact>> pieces =
          dyadic_pieces((u.t0 - check_t0) / span, (u.t1 - check_t0) / span);
      if (pieces.empty()) {  // keep it as it was
        CheckResult part;
        part.undecided.push_back(u);
        part.first_contact = std::pair{u.t0, u.t1};
        more = merge_result(next, part);
        continue;
      }
      for (const auto& [p0, p1] : pieces) {
        if (!more) break;
        window(check_t0 + p0 * span, check_t0 + p1 * span);
      }
    }
    next.verdict = next.witness ? Verdict::Collision : next.undecided.empty() ? Verdict::Safe : Verdict::Undecided;
    if (next.verdict == Verdict::Safe) next.first_contact.reset();
    result = std::move(next);
    result.epsilon = eps;
    result.refined = true;
  }
  if (result.verdict == Verdict::Undecided && !result.refine_out_of_time) {
    // Parts cut short by the time limit in the last level searched count
    // as out of time; otherwise the floor was reached.
    bool limited = past_deadline(o);
    if (limited) result.refine_out_of_time = true;
    else if (level > kRefineLevels) result.refine_exhausted = true;
  }
  if (result.verdict != Verdict::Undecided) result.refine_exhausted = result.refine_out_of_time = false;
  result.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
}

}  // namespace tmcert::detail
