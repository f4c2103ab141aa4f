// Second-order Taylor jets over intervals: a value and its first two
// derivatives with respect to one parameter, each an interval.  Evaluating a
// formula on Jet{s, 1, 0} with s a point interval encloses f(s), f'(s) and
// f''(s); with s an interval S, the `dd` part encloses f'' over all of S
// (interval arithmetic is inclusion isotone), which is what a Taylor
// remainder bound needs.  proofs/enclosures.md section 2.
//
// Arithmetic must run under RoundingGuard (it is Interval arithmetic).
#pragma once

#include "kernels/number_types.h"
#include "kernels/validated.h"

#include <algorithm>
#include <cmath>

namespace tmcert {

struct Jet {
  Interval v = Interval(0), d = Interval(0), dd = Interval(0);

  Jet() = default;
  Jet(const Interval& value) : v(value) {}  // a constant
  Jet(const Interval& value, const Interval& first, const Interval& second) : v(value), d(first), dd(second) {}
  // The parameter itself at s (or over s).
  static Jet variable(const Interval& s) { return Jet(s, Interval(1), Interval(0)); }
};

inline Jet operator+(const Jet& a, const Jet& b) { return {a.v + b.v, a.d + b.d, a.dd + b.dd}; }
inline Jet operator-(const Jet& a, const Jet& b) { return {a.v - b.v, a.d - b.d, a.dd - b.dd}; }
inline Jet operator-(const Jet& a) { return {-a.v, -a.d, -a.dd}; }
// (fg)' = f'g + fg', (fg)'' = f''g + 2f'g' + fg''.
inline Jet operator*(const Jet& a, const Jet& b) {
  return {a.v * b.v, a.d * b.v + a.v * b.d, a.dd * b.v + Interval(2) * a.d * b.d + a.v * b.dd};
}
inline Jet operator*(const Interval& c, const Jet& a) { return {c * a.v, c * a.d, c * a.dd}; }
// (f/g)' = (f' - q g') / g, (f/g)'' = (f'' - 2 q' g' - q g'') / g with q = f/g.
inline Jet operator/(const Jet& a, const Jet& b) {
  const Interval q = a.v / b.v;
  const Interval q1 = (a.d - q * b.d) / b.v;
  const Interval q2 = (a.dd - Interval(2) * q1 * b.d - q * b.dd) / b.v;
  return {q, q1, q2};
}
inline Jet& operator+=(Jet& a, const Jet& b) { return a = a + b; }

// sin(f)' = cos(f) f', sin(f)'' = cos(f) f'' - sin(f) f'^2; cos likewise.
inline Jet sin(const Jet& a) {
  const Interval s = validated::sin(a.v), c = validated::cos(a.v);
  return {s, c * a.d, c * a.dd - s * CGAL::square(a.d)};
}
inline Jet cos(const Jet& a) {
  const Interval s = validated::sin(a.v), c = validated::cos(a.v);
  return {c, -s * a.d, -s * a.dd - c * CGAL::square(a.d)};
}

// sinc(x) = sin(x)/x (1 at 0), well defined and enclosed near 0 where
// sin(x)/x on intervals would divide by an interval holding 0.  For
// |x| <= 2^-9 (every point of x.v) the alternating series
// 1 - x^2/6 + x^4/120 - ... is used with its first omitted term as the
// bound of the rest, for the value and for the first two derivatives (the
// derived series alternate with decreasing terms there too:
// proofs/enclosures.md section 2); elsewhere sin(x)/x.
inline Jet sinc(const Jet& x) {
  const double m = std::max(std::abs(x.v.inf()), std::abs(x.v.sup()));
  if (!(m <= 0x1p-9)) return sin(x) / x;
  const Interval v = x.v, v2 = CGAL::square(v), v3 = v2 * v, v4 = CGAL::square(v2), v5 = v4 * v;
  // p(v) = 1 - v^2/6 + v^4/120, p' = -v/3 + v^3/30, p'' = -1/3 + v^2/10, and
  // remainders bounded by v^6/5040, 6|v|^5/5040, 30 v^4/5040.
  const Interval r0 = Interval(-1, 1) * (v4 * v2 / Interval(5040));
  const Interval r1 = Interval(-1, 1) * (Interval(6) * CGAL::abs(v5) / Interval(5040));
  const Interval r2 = Interval(-1, 1) * (Interval(30) * v4 / Interval(5040));
  const Interval f = Interval(1) - v2 / Interval(6) + v4 / Interval(120) + r0;
  const Interval f1 = -v / Interval(3) + v3 / Interval(30) + r1;
  const Interval f2 = Interval(-1) / Interval(3) + v2 / Interval(10) + r2;
  // Chain rule: (f o x)' = f'(x) x', (f o x)'' = f''(x) x'^2 + f'(x) x''.
  return {f, f1 * x.d, f2 * CGAL::square(x.d) + f1 * x.dd};
}

// The jet of f_m(x) (validated::factorial_series): sinc for m = 1,
// (1 - cos x)/x^2 for m = 2, (x - sin x)/x^3 for m = 3, regular at 0 and
// enclosed by their series for |x| <= 4 (the whole line beyond), by the
// chain rule as for sinc.
inline Jet factorial_series(const Jet& x, int m) {
  const std::array<Interval, 3> f = validated::factorial_series(x.v, m);
  return {f[0], f[1] * x.d, f[2] * CGAL::square(x.d) + f[1] * x.dd};
}

}  // namespace tmcert
