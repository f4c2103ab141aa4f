// Three-valued results without int sentinels.  A predicate evaluated over
// intervals knows its answer only when the interval decides it; such a
// result is CGAL's Uncertain<T> (CGAL/Uncertain.h: a certain value, or a
// range of values any of which may be true), here Uncertain<CGAL::Sign>,
// the sign of an interval, as CGAL's Filtered_predicate uses it.  A
// caller asks only the certain questions below, and takes the exact path
// otherwise: an undecided sign can never pass for a decided one.
#pragma once

#include "kernels/number_types.h"

#include <CGAL/Uncertain.h>

namespace tmcert {

using UncertainSign = CGAL::Uncertain<CGAL::Sign>;

// The sign of an interval: certain when the interval excludes 0 or is
// [0, 0]; else indeterminate (also for a NaN bound).
inline UncertainSign uncertain_sign(const Interval& x) {
  if (x.inf() > 0) return CGAL::POSITIVE;
  if (x.sup() < 0) return CGAL::NEGATIVE;
  if (x.inf() == 0 && x.sup() == 0) return CGAL::ZERO;
  return UncertainSign::indeterminate();
}

// The sign is certainly `v`.
inline bool certainly_is(const UncertainSign& s, CGAL::Sign v) { return s.is_certain() && s.inf() == v; }

// The sign is certainly not `v` (`v` is outside its possible values).
inline bool certainly_not(const UncertainSign& s, CGAL::Sign v) { return v < s.inf() || s.sup() < v; }

}  // namespace tmcert
