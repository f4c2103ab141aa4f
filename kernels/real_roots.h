// Exact real roots of integer polynomials in one variable: square-free
// parts, gcds, Sturm isolation in a closed rational interval, exact signs
// of other polynomials at an isolated root, and exact comparison of roots
// (proofs/exact-resolution.md).  Everything is exact (GMP integers and
// rationals); interval arithmetic only ever skips work whose exact answer
// it has proven.
#pragma once

#include "kernels/number_types.h"

#include <CGAL/Gmpz.h>

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace tmcert {

using Integer = CGAL::Gmpz;
// Polynomials, constant term first, without trailing zeros (the zero
// polynomial is empty).
using PolyQ = std::vector<Exact>;
using PolyZ = std::vector<Integer>;

// Thrown when an exact computation passes its iteration cap (it never
// should: every loop below terminates mathematically); callers turn it into
// "not decided", never into an answer.
struct ExactLimit : std::runtime_error {
  using std::runtime_error::runtime_error;
};

void trim(PolyQ& p);
void trim(PolyZ& p);
inline int degree(const PolyZ& p) { return static_cast<int>(p.size()) - 1; }  // -1 for zero

PolyQ add(const PolyQ& a, const PolyQ& b);
PolyQ sub(const PolyQ& a, const PolyQ& b);
PolyQ mul(const PolyQ& a, const PolyQ& b);
PolyZ add(const PolyZ& a, const PolyZ& b);
PolyZ sub(const PolyZ& a, const PolyZ& b);
PolyZ mul(const PolyZ& a, const PolyZ& b);

// The positive multiple of p with coprime integer coefficients (the zero
// polynomial stays zero): same roots, same signs everywhere.
PolyZ primitive(const PolyQ& p);
PolyZ primitive(const PolyZ& p);

// The sign of p at the rational x, exactly.
CGAL::Sign sign_at(const PolyZ& p, const Exact& x);
// p(x) exactly.
Exact value_at(const PolyZ& p, const Exact& x);

// gcd(a, b): primitive with a positive leading coefficient; gcd(0, 0) = 0;
// a nonzero constant when coprime ({1}).
PolyZ gcd(const PolyZ& a, const PolyZ& b);
// The square-free part p / gcd(p, p'), primitive (p nonzero).
PolyZ square_free(const PolyZ& p);

// A real root of `poly`.  Rational when lo == hi (the root is lo).
// Otherwise lo < root < hi, poly is square-free and nonzero at lo and hi
// with opposite signs, and the root is poly's only root in [lo, hi].
struct RealRoot {
  PolyZ poly;
  Exact lo, hi;
  bool is_rational() const { return lo == hi; }
};

RealRoot rational_root(const Exact& x);

// The distinct real roots of the nonzero, square-free p in the closed
// interval [a, b] (a <= b), in increasing order (Sturm sequences).
std::vector<RealRoot> real_roots(const PolyZ& p, const Exact& a, const Exact& b);

// Halves the isolating interval of r (or finds r rational).
void refine(RealRoot& r);
// Refines r until hi - lo <= width (or r is found rational).
void refine_to(RealRoot& r, const Exact& width);

// The sign of q on all of [lo, hi] when a double interval enclosure proves
// it, else ZERO (meaning: not proven; q may still not vanish there).
CGAL::Sign enclosure_sign(const PolyZ& q, const Exact& lo, const Exact& hi);

// The exact sign of q at r (refines r as needed).
CGAL::Sign sign_at(const PolyZ& q, RealRoot& r);

// The exact order of two roots (refines them as needed).
CGAL::Comparison_result compare(RealRoot& a, RealRoot& b);

// The rational with the smallest denominator in the closed interval
// [lo, hi] (continued fractions, i.e. the Stern-Brocot descent), for
// lo <= hi.  Iterative: one step per partial quotient, at most
// kSimplestTerms of them; an expansion deeper than that (ends with tens of
// thousands of digits, e.g. ratios of consecutive Fibonacci numbers) gives
// the midpoint instead, which is in [lo, hi] as well (the callers only need
// a point of the interval; the simplest one is a preference).
inline constexpr std::size_t kSimplestTerms = 1024;
Exact simplest_between(const Exact& lo, const Exact& hi);

// Makes r rational (lo == hi) when its value is rational; true if so.
bool settle_rational(RealRoot& r);

// p(x0 + x * scale) with integer coefficients (primitive), for mapping a
// polynomial in the curve parameter to the scene parameter (scale != 0).
PolyZ compose_affine(const PolyZ& p, const Exact& x0, const Exact& scale);

// The approximation results print for r (kernels/decimal.h's
// approximation() of the real number): the shortest decimal of the double
// nearest to r, or beyond the double range r's 17-significant-digit
// decimal with exponent.  Refines a copy of r until every point of its
// interval has the same one.  Throws ExactLimit past a cap it never meets
// for an isolated root (the boundaries between results are rational).
std::string approximate(RealRoot r);
// r rounded to `significant` digits as to_decimal writes it (the human
// summary's six digits rounded from the exact value), likewise.
std::string approximate_decimal(RealRoot r, int significant = 6);

}  // namespace tmcert
