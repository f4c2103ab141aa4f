// Filtered dispatch (CGAL's Filtered_predicate pattern, DESIGN.md section 7):
// run the interval version under the rounding guard; if any comparison it
// needed was uncertain, run the same template with exact rationals.
#pragma once

#include "kernels/number_types.h"

#include <cstdint>

namespace tmcert {

struct FilterCounters {
  std::uint64_t calls = 0;
  std::uint64_t exact_fallbacks = 0;
  FilterCounters& operator+=(const FilterCounters& o) {
    calls += o.calls;
    exact_fallbacks += o.exact_fallbacks;
    return *this;
  }
};

// `interval_call` must evaluate the predicate over Interval and may throw
// CGAL::Uncertain_conversion_exception; `exact_call` evaluates it exactly.
template <class IntervalCall, class ExactCall>
auto filtered(IntervalCall&& interval_call, ExactCall&& exact_call, FilterCounters& counters)
    -> decltype(exact_call()) {
  ++counters.calls;
  {
    RoundingGuard guard;
    try {
      return interval_call();
    } catch (const CGAL::Uncertain_conversion_exception&) {
      // fall through to the exact stage, with the rounding mode restored
    }
  }
  ++counters.exact_fallbacks;
  return exact_call();
}

}  // namespace tmcert
