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

#include <array>

namespace tmcert::validated {

// Enclosures of the function over every point of `x` (an interval with a
// NaN or infinite end gives the whole line, which clears nothing).
Interval sin(const Interval& x);
Interval cos(const Interval& x);
// atan2(y, x) in (-pi, pi]; x and y must not both contain 0 (else the whole
// range [-pi, pi] is returned, which is still an enclosure).
Interval atan2(const Interval& y, const Interval& x);
// The entire functions f_m(x) = sum_{k>=0} (-1)^k x^(2k) / (2k+m)! for
// m = 1, 2, 3, i.e. sin(x)/x, (1 - cos x)/x^2 and (x - sin x)/x^3 (all
// regular at 0, where they are 1, 1/2 and 1/6), with their first and
// second derivatives {f, f', f''}, enclosed for every x in the interval by
// the series (40 terms and a bound of the rest) when |x| <= 4; the whole
// line for a wider or non-finite x.  proofs/enclosures.md section 2.
std::array<Interval, 3> factorial_series(const Interval& x, int m);
// C(phi) = (1 - (phi/2) cot(phi/2)) / phi^2 (1/12 at 0), the coefficient
// of K^2 in the inverse of SE(3)'s left Jacobian, enclosed for every phi
// in the interval: by its series sum_{n>=1} 2 zeta(2n) phi^(2n-2) / (2 pi)^(2n)
// when |phi| <= 1, else by the closed form (the whole line where that is
// not finite).  proofs/enclosures.md section 3.
Interval screw_inverse_coefficient(const Interval& phi);
// pi, enclosed.
Interval pi();
// A rational enclosed by an interval of width at most one unit in the last
// place (the same as to_interval; here for symmetry).
Interval of(const Exact& q);
// sqrt(q) for a rational q >= 0, enclosed.
Interval sqrt(const Exact& q);

}  // namespace tmcert::validated
