// Validated transcendental functions on intervals: sin, cos, atan2, and
// exact rationals enclosed at high precision.  Every result is computed by
// Arb (ball arithmetic with rigorous error bounds, FLINT's libflint-arb) and
// rounded outward to a CGAL interval, so it encloses the exact real value
// for every point of the input interval.  Never libm, never Boost.Interval's
// transcendental functions (their rounding is not guaranteed).
// proofs/enclosures.md section 1.
//
// The functions take and return tmcert::Interval and may be called inside
// or outside a RoundingGuard (Arb does not depend on the FPU rounding mode,
// and the conversion to doubles rounds explicitly).
#pragma once

#include "kernels/number_types.h"

namespace tmcert::validated {

// Enclosures of the function over every point of `x` (an interval with a
// NaN or infinite end gives the whole line, which clears nothing).
Interval sin(const Interval& x);
Interval cos(const Interval& x);
// atan2(y, x) in (-pi, pi]; x and y must not both contain 0 (else the whole
// range [-pi, pi] is returned, which is still an enclosure).
Interval atan2(const Interval& y, const Interval& x);
// pi, enclosed.
Interval pi();
// A rational enclosed by an interval of width at most one unit in the last
// place (the same as to_interval; here for symmetry).
Interval of(const Exact& q);
// sqrt(q) for a rational q >= 0, enclosed.
Interval sqrt(const Exact& q);

}  // namespace tmcert::validated
