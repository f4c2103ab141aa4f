// Sign of the minimum of a bivariate quadratic over a convex polygon.
//
// This is the one numerical core of every contact test (DESIGN.md section 4,
// proofs/quadratic-minimum.md).  It is written once over the number type FT:
//   * FT = Exact (CGAL::Gmpq): the exact sign;
//   * FT = Interval (CGAL::Interval_nt<false>, under RoundingGuard): every
//     comparison yields CGAL::Uncertain<bool>, and an uncertain one throws
//     CGAL::Uncertain_conversion_exception when a branch needs it; the
//     filtered dispatch then re-runs the same template exactly;
//   * FT = double: the fast, uncertified path.
#pragma once

#include <CGAL/Interval_nt.h>
#include <CGAL/Uncertain.h>
#include <CGAL/enum.h>

#include <algorithm>
#include <type_traits>

#include <array>
#include <cstddef>

namespace tmcert {

template <class FT>
using Pt2 = std::array<FT, 2>;

// q(s) = h11 s1^2 + 2 h12 s1 s2 + h22 s2^2 + b1 s1 + b2 s2 + c
template <class FT>
struct Quadratic2 {
  FT h11, h12, h22, b1, b2, c;

  FT operator()(const FT& s1, const FT& s2) const {
    return s1 * (h11 * s1 + FT(2) * h12 * s2 + b1) + s2 * (h22 * s2 + b2) + c;
  }
};

// A convex polygon in the parameter plane: `count` vertices in order, with
// orientation +1 (counter-clockwise) or -1 (clockwise).  A single vertex or a
// segment (count 1 or 2) is allowed.
template <class FT>
struct ConvexDomain {
  const Pt2<FT>* vertices = nullptr;
  std::size_t count = 0;
  int orientation = 1;
};

namespace detail {

// The sign of the smallest of candidate values seen so far; an early
// NEGATIVE ends the search (the minimum is negative).
// Over intervals, a candidate whose sign is not certain (or whose presence
// could not be settled) marks the result `uncertain`: the search goes on,
// since a later candidate that is certainly negative still decides the
// minimum (NEGATIVE); otherwise the exact run decides.
struct MinSign {
  CGAL::Sign sign = CGAL::POSITIVE;
  bool uncertain = false;
  bool negative() const { return sign == CGAL::NEGATIVE; }
};

template <class FT>
void take(MinSign& m, const FT& value) {
  if constexpr (std::is_same_v<FT, CGAL::Interval_nt<false>>) {
    if (value.sup() < 0) {
      m.sign = CGAL::NEGATIVE;
    } else if (value.inf() > 0) {
      // positive: nothing to record
    } else if (value.inf() == 0 && value.sup() == 0) {
      if (m.sign == CGAL::POSITIVE) m.sign = CGAL::ZERO;  // exactly zero
    } else {
      m.uncertain = true;  // straddles zero, or NaN
    }
  } else {
    if (value < FT(0)) m.sign = CGAL::NEGATIVE;
    else if (m.sign == CGAL::POSITIVE && !(value > FT(0))) m.sign = CGAL::ZERO;
  }
}

// An uncertain comparison the enclosures below could not settle: hand over
// to the exact run (the filtered dispatch catches this).
[[noreturn]] inline void undecided() {
  throw CGAL::Uncertain_conversion_exception("min_sign: a candidate needs exact arithmetic");
}

// Interval extensions of q: they enclose its range over a superset of the
// candidate set, so a certainly positive lower end proves q > 0 there.
// Exact and double comparisons are never uncertain: they never ask.
template <class FT>
bool positive_on_edge(const FT& alpha, const FT& beta, const FT& gamma) {
  if constexpr (std::is_same_v<FT, CGAL::Interval_nt<false>>) {
    const FT t(0, 1);
    return (gamma + t * (beta + alpha * t)).inf() > 0;
  } else {
    return false;
  }
}

template <class FT>
bool positive_on_box(const Quadratic2<FT>& q, const ConvexDomain<FT>& d) {
  if constexpr (std::is_same_v<FT, CGAL::Interval_nt<false>>) {
    double lo1 = d.vertices[0][0].inf(), hi1 = d.vertices[0][0].sup();
    double lo2 = d.vertices[0][1].inf(), hi2 = d.vertices[0][1].sup();
    for (std::size_t i = 1; i < d.count; ++i) {
      lo1 = std::min(lo1, d.vertices[i][0].inf());
      hi1 = std::max(hi1, d.vertices[i][0].sup());
      lo2 = std::min(lo2, d.vertices[i][1].inf());
      hi2 = std::max(hi2, d.vertices[i][1].sup());
    }
    if (!(lo1 <= hi1) || !(lo2 <= hi2)) return false;  // NaN bounds: no claim
    return q(FT(lo1, hi1), FT(lo2, hi2)).inf() > 0;
  } else {
    return false;
  }
}

}  // namespace detail

// Returns the sign of min { q(s) : s in D }.
//
// The minimum of a continuous function over a compact convex polygon is
// attained at a vertex, at a critical point of q restricted to the relative
// interior of an edge, or at an interior critical point of q.  The last two
// can be local minima only where the restricted second derivative is
// positive (edge: alpha > 0; interior: Hessian positive definite); where it
// is not, the minimum lies on the boundary and is found by the other cases.
// Each candidate's value is a rational function of the inputs whose sign is
// computed without division where possible.  Over intervals, a candidate
// whose existence or position is uncertain is settled, where possible, by
// an interval extension of q over a superset (the edge, the domain's box)
// being certainly positive; otherwise the exact run decides.
namespace detail {
template <class FT>
CGAL::Sign min_sign_candidates(const Quadratic2<FT>& q, const ConvexDomain<FT>& d, MinSign& m);
}  // namespace detail

template <class FT>
CGAL::Sign min_sign(const Quadratic2<FT>& q, const ConvexDomain<FT>& d) {
  detail::MinSign m;
  const CGAL::Sign sign = detail::min_sign_candidates(q, d, m);
  if (m.uncertain && sign != CGAL::NEGATIVE) detail::undecided();
  return sign;
}

namespace detail {

// The candidate of one edge, v + t e for t in [0, 1], where q is
// alpha t^2 + beta t + gamma (gamma = q(v)): its interior minimum, if any.
// Returns true when the minimum is now NEGATIVE (the search ends).
template <class FT>
bool edge_candidate(const FT& alpha, const FT& beta, const FT& gamma, MinSign& m) {
  using Bool = decltype(FT(0) < FT(0));  // bool, or CGAL::Uncertain<bool> over intervals
  const FT zero(0);
  const Bool curved = alpha > zero;
  if (CGAL::certainly_not(curved)) return false;  // no interior minimum on this edge
  if (CGAL::certainly(curved)) {
    // Critical t* = -beta / (2 alpha) lies in (0, 1)  <=>  0 < -beta < 2 alpha.
    const Bool inside = (beta < zero) & (-beta < FT(2) * alpha);
    if (CGAL::certainly_not(inside)) return false;
    // Minimum gamma - beta^2 / (4 alpha) has the sign of 4 alpha gamma - beta^2.
    const FT value = FT(4) * alpha * gamma - beta * beta;
    if (CGAL::certainly(inside)) {
      detail::take(m, value);
      return m.negative();
    }
    if (CGAL::certainly(value > zero)) return false;  // positive wherever t* is
  }
  // Only intervals get here (an uncertain comparison): q positive on the
  // whole edge settles it; otherwise the exact run decides.
  if (!detail::positive_on_edge(alpha, beta, gamma)) m.uncertain = true;
  return false;
}

// The interior candidate: the critical point s* of q when the Hessian is
// positive definite and `inside_of(s1, s2)` (a Bool: s* in the closed
// polygon).  Returns false when it could not be settled (only intervals:
// the caller then tries the bounding box).
template <class FT, class Inside>
bool interior_candidate(const Quadratic2<FT>& q, Inside&& inside_of, MinSign& m) {
  using Bool = decltype(FT(0) < FT(0));
  const FT zero(0);
  const FT det = q.h11 * q.h22 - q.h12 * q.h12;
  const Bool definite = (q.h11 > zero) & (det > zero);
  if (CGAL::certainly_not(definite)) return true;
  if (CGAL::certainly(definite)) {
    // Critical point s* solves [h11 h12; h12 h22] s = -b / 2.
    const FT s1 = (q.h12 * q.b2 - q.h22 * q.b1) / (FT(2) * det);
    const FT s2 = (q.h12 * q.b1 - q.h11 * q.b2) / (FT(2) * det);
    const Bool inside = inside_of(s1, s2);
    if (CGAL::certainly_not(inside)) return true;
    // q(s*) = c + (b . s*) / 2.
    const FT value = FT(2) * q.c + q.b1 * s1 + q.b2 * s2;
    if (CGAL::certainly(inside)) {
      detail::take(m, value);
      return true;
    }
    if (CGAL::certainly(value > zero)) return true;  // positive wherever s* is
  }
  return false;
}

inline bool is_value(const CGAL::Interval_nt<false>& x, double v) { return x.inf() == v && x.sup() == v; }
inline bool is_value(double x, double v) { return x == v; }

// The standard triangle (0,0), (1,0), (0,1) and the unit square (0,0),
// (1,0), (1,1), (0,1), both counter-clockwise: every triangle's and every
// edge pair's domain (make_face in src/verify/prepared.cpp, contact_sign).
enum class UnitDomain { None, Triangle, Square };

// Which unit domain `d` is, written exactly so (None for any other polygon).
template <class FT>
UnitDomain unit_domain(const ConvexDomain<FT>& d) {
  if (d.orientation != 1 || (d.count != 3 && d.count != 4)) return UnitDomain::None;
  const auto* v = d.vertices;
  if (!is_value(v[0][0], 0) || !is_value(v[0][1], 0) || !is_value(v[1][0], 1) || !is_value(v[1][1], 0))
    return UnitDomain::None;
  if (d.count == 3) return is_value(v[2][0], 0) && is_value(v[2][1], 1) ? UnitDomain::Triangle : UnitDomain::None;
  return is_value(v[2][0], 1) && is_value(v[2][1], 1) && is_value(v[3][0], 0) && is_value(v[3][1], 1)
             ? UnitDomain::Square
             : UnitDomain::None;
}

// The candidates on a unit domain (Triangle or Square): those of the general
// polygon below with the 0/1 coordinates folded into the sums (fewer
// interval products).  Returns false when the interior could not be
// settled.
template <class FT>
bool min_sign_unit(const Quadratic2<FT>& q, UnitDomain kind, MinSign& m) {
  const FT zero(0), one(1), two(2);
  // Vertices: q(0,0) = c, q(1,0) = h11 + b1 + c, q(0,1) = h22 + b2 + c,
  // q(1,1) = q(1,0) + h22 + b2 + 2 h12.
  const FT q00 = q.c, q10 = q.h11 + q.b1 + q.c, q01 = q.h22 + q.b2 + q.c;
  const FT q11 = kind == UnitDomain::Square ? q10 + q.h22 + q.b2 + two * q.h12 : zero;
  detail::take(m, q00);
  detail::take(m, q10);
  if (kind == UnitDomain::Square) detail::take(m, q11);
  detail::take(m, q01);
  if (m.negative()) return true;
  // Edges from v along e: alpha = e^T H e, beta = (gradient at v).e with
  // gradient (2 h11 s1 + 2 h12 s2 + b1, 2 h12 s1 + 2 h22 s2 + b2), gamma = q(v).
  if (edge_candidate(q.h11, q.b1, q00, m)) return true;  // (0,0) -> (1,0)
  if (kind == UnitDomain::Triangle) {
    // (1,0) -> (0,1): e = (-1, 1), gradient at (1,0) = (2 h11 + b1, 2 h12 + b2).
    const FT alpha = q.h11 - two * q.h12 + q.h22;
    const FT beta = (two * q.h12 + q.b2) - (two * q.h11 + q.b1);
    if (edge_candidate(alpha, beta, q10, m)) return true;
  } else {
    // (1,0) -> (1,1): e = (0, 1), second entry at (1,0) = 2 h12 + b2.
    if (edge_candidate(q.h22, two * q.h12 + q.b2, q10, m)) return true;
    // (1,1) -> (0,1): e = (-1, 0), first entry at (1,1) = 2 h11 + 2 h12 + b1.
    if (edge_candidate(q.h11, -(two * (q.h11 + q.h12) + q.b1), q11, m)) return true;
  }
  // (0,1) -> (0,0): e = (0, -1), second entry at (0,1) = 2 h22 + b2.
  if (edge_candidate(q.h22, -(two * q.h22 + q.b2), q01, m)) return true;
  // Interior: s1 >= 0, s2 >= 0 and s1 + s2 <= 1 (triangle) or s1, s2 <= 1.
  return interior_candidate(
      q,
      [&](const FT& s1, const FT& s2) {
        if (kind == UnitDomain::Triangle) return (s1 >= zero) & (s2 >= zero) & (one - s1 - s2 >= zero);
        return (s1 >= zero) & (s2 >= zero) & (one - s1 >= zero) & (one - s2 >= zero);
      },
      m);
}

// The candidates on a general polygon.  Returns false when the interior
// could not be settled (only intervals).
template <class FT>
bool min_sign_polygon(const Quadratic2<FT>& q, const ConvexDomain<FT>& d, MinSign& m) {
  const FT zero(0);
  // Vertices.
  for (std::size_t i = 0; i < d.count; ++i) {
    detail::take(m, q(d.vertices[i][0], d.vertices[i][1]));
    if (m.negative()) return true;
  }
  if (d.count < 2) return true;
  // Edges: q(v + t e) = alpha t^2 + beta t + gamma, t in [0, 1].
  const std::size_t edges = d.count == 2 ? 1 : d.count;
  for (std::size_t i = 0; i < edges; ++i) {
    const Pt2<FT>& v = d.vertices[i];
    const Pt2<FT>& w = d.vertices[(i + 1) % d.count];
    const FT e1 = w[0] - v[0], e2 = w[1] - v[1];
    const FT alpha = q.h11 * e1 * e1 + FT(2) * q.h12 * e1 * e2 + q.h22 * e2 * e2;
    // Gradient of q at v, dotted with e.
    const FT g1 = FT(2) * (q.h11 * v[0] + q.h12 * v[1]) + q.b1;
    const FT g2 = FT(2) * (q.h12 * v[0] + q.h22 * v[1]) + q.b2;
    const FT beta = g1 * e1 + g2 * e2;
    if (edge_candidate(alpha, beta, q(v[0], v[1]), m)) return true;
  }
  if (d.count < 3) return true;
  // Interior: only a positive definite Hessian has an interior minimum;
  // inside the closed polygon: no edge sees s* on its outer side.
  return interior_candidate(
      q,
      [&](const FT& s1, const FT& s2) {
        decltype(FT(0) < FT(0)) inside(true);
        for (std::size_t i = 0; i < d.count; ++i) {
          const Pt2<FT>& v = d.vertices[i];
          const Pt2<FT>& w = d.vertices[(i + 1) % d.count];
          const FT side = (w[0] - v[0]) * (s2 - v[1]) - (w[1] - v[1]) * (s1 - v[0]);
          inside = inside & (d.orientation > 0 ? side >= zero : side <= zero);
          if (CGAL::certainly_not(inside)) break;
        }
        return inside;
      },
      m);
}

// The candidates of min_sign; over intervals, candidates it cannot settle
// set m.uncertain instead of ending the search.
template <class FT>
CGAL::Sign min_sign_candidates(const Quadratic2<FT>& q, const ConvexDomain<FT>& d, MinSign& m) {
  bool settled;
  if constexpr (std::is_same_v<FT, CGAL::Interval_nt<false>> || std::is_same_v<FT, double>) {
    const UnitDomain kind = unit_domain(d);
    settled = kind != UnitDomain::None ? min_sign_unit(q, kind, m) : min_sign_polygon(q, d, m);
  } else {
    settled = min_sign_polygon(q, d, m);
  }
  if (settled || m.negative()) return m.sign;
  // Only intervals get here: q positive on the domain's bounding box
  // settles it; otherwise the exact run decides.
  if (!detail::positive_on_box(q, d)) m.uncertain = true;
  return m.sign;
}

}  // namespace detail

}  // namespace tmcert
