// The verifier's exact de Casteljau subdivision of a Bezier curve given by
// its (homogeneous) control points, each a fixed-size array of exact
// rationals (Exact): one copy for the search and the certificate writer
// (the certificate checker keeps its own, src/certificate/check_numbers.h).
// Exact arithmetic: the control points of a part are the curve's own,
// whatever the order of the operations.
#pragma once

#include "kernels/number_types.h"

#include <cstddef>
#include <vector>

namespace tmcert {

// The control points of the curve's part over [0, s] (keep_left) or
// [s, 1], for the curve over [0, 1] and s in [0, 1]: de Casteljau's
// triangle at s, whose first column is the left part and whose diagonal is
// the right part.  `p` has at least one point.
template <class Point>
std::vector<Point> de_casteljau_split(std::vector<Point> p, const Exact& s, bool keep_left) {
  const std::size_t n = p.size();
  std::vector<Point> out(n);
  for (std::size_t level = 0; level < n; ++level) {
    if (keep_left) out[level] = p[0];
    else out[n - 1 - level] = p[n - 1 - level];
    for (std::size_t k = 0; k + 1 < n - level; ++k)
      for (std::size_t e = 0; e < p[k].size(); ++e) p[k][e] += s * (p[k + 1][e] - p[k][e]);
  }
  return out;
}

// The control points of the curve's part over [a, b], 0 <= a < b <= 1
// (at b first, then at a / b on the left part; the curve itself when
// [a, b] = [0, 1]).
template <class Point>
std::vector<Point> de_casteljau_restrict(std::vector<Point> p, const Exact& a, const Exact& b) {
  if (b != 1) p = de_casteljau_split(std::move(p), b, true);
  if (a != 0) p = de_casteljau_split(std::move(p), a / b, false);
  return p;
}

}  // namespace tmcert
