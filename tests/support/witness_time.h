// Test helpers: comparing witness times exactly when they may be
// algebraic numbers (exact resolution writes an irrational time as a
// polynomial and an isolating interval, which another run may write with
// another polynomial and interval).
#pragma once

#include "src/verify/verify.h"

#include <algorithm>

namespace tmcert::testing {

// Whether a witness's time is at or after t (its exact time: the root for an
// algebraic witness, whose polynomial changes sign only at the root inside
// its interval).
inline bool witness_not_before(const Exact& t, const Witness& w) {
  if (!w.root) return t <= w.t;
  const AlgebraicTime& a = *w.root;
  if (t <= a.lo) return true;
  if (t >= a.hi) return false;
  auto value = [&](const Exact& x) {
    Exact v(0);
    for (std::size_t k = a.root_of.size(); k-- > 0;) v = v * x + Exact(a.root_of[k]);
    return v;
  };
  const int at_t = CGAL::sign(value(t)), at_lo = CGAL::sign(value(a.lo));
  return at_t == 0 || at_t == at_lo;  // no sign change in (lo, t): the root is at or after t
}

// Two witnesses at the same exact time.
inline bool same_witness_time(const Witness& x, const Witness& y) {
  if (!x.root || !y.root) return !x.root && !y.root && x.t == y.t;
  // Both irrational: each interval's ends on the right sides of the other root.
  return witness_not_before(x.root->lo, y) && !witness_not_before(x.root->hi, y) &&
         witness_not_before(y.root->lo, x) && !witness_not_before(y.root->hi, x) &&
         std::max(x.root->lo, y.root->lo) < std::min(x.root->hi, y.root->hi) && [&] {
           // and the same root: x's polynomial vanishes at y's root (a sign change of
           // gcd-free evaluation is not available here: narrow y's interval with x's sign
           // changes on the overlap instead).
           Exact lo = std::max(x.root->lo, y.root->lo), hi = std::min(x.root->hi, y.root->hi);
           auto value = [](const AlgebraicTime& a, const Exact& t) {
             Exact v(0);
             for (std::size_t k = a.root_of.size(); k-- > 0;) v = v * t + Exact(a.root_of[k]);
             return v;
           };
           for (int k = 0; k < 200; ++k) {
             // both roots lie in (lo, hi); if they differ, some bisection separates them
             const Exact m = (lo + hi) / 2;
             const int sx = CGAL::sign(value(*x.root, m)) * CGAL::sign(value(*x.root, lo));
             const int sy = CGAL::sign(value(*y.root, m)) * CGAL::sign(value(*y.root, lo));
             if (sx == 0 && sy == 0) return true;
             if ((sx < 0) != (sy < 0) || sx == 0 || sy == 0) return false;
             if (sx < 0) hi = m;
             else lo = m;
           }
           return true;  // equal to 2^-200 of the overlap: taken as the same (a test tolerance)
         }();
}

}  // namespace tmcert::testing
