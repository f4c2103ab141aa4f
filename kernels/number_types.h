// The three number types tmcert computes with, and the rounding guard.
//
//  * Exact    - CGAL::Gmpq, exact rationals: the reference.
//  * Interval - CGAL::Interval_nt<false>: needs the FPU rounding mode set
//               upward, which only RoundingGuard (an RAII object) does.
//               Comparisons return CGAL::Uncertain<bool>; converting an
//               uncertain one to bool throws CGAL::Uncertain_conversion_exception,
//               which the filtered dispatch turns into an exact re-run.
//  * double   - the fast, uncertified path.
#pragma once

#include <CGAL/Gmpq.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/FPU.h>
#include <CGAL/Uncertain.h>
#include <CGAL/enum.h>

#include <array>
#include <cstdint>
#include <functional>
#include <unordered_map>
#include <vector>
#include <cmath>
#include <limits>
#include <string>

namespace tmcert {

using Exact = CGAL::Gmpq;
using Interval = CGAL::Interval_nt<false>;

// Sets the rounding mode toward +infinity for the lifetime of the object and
// restores the previous mode afterwards.  Interval arithmetic is valid only
// inside such a scope.
using RoundingGuard = CGAL::Protect_FPU_rounding<true>;

using Vec3E = std::array<Exact, 3>;
// A 3x4 affine map [A | a], row-major: m[4*r + c]; x -> A x + a.
using Mat34E = std::array<Exact, 12>;

// Smallest interval containing an exact rational.  Valid in any rounding
// mode.  Fast path: mpq_get_d truncates toward zero, so a normal result d
// and its neighbour away from zero bracket q (a point when q is a double);
// zero, subnormal and out-of-range values go through CGAL's MPFR rounding.
// Both give the same interval (tests/kernels/test_number_types.cpp).
inline Interval to_interval(const Exact& q) {
  mpq_srcptr r = q.mpq();
  const int s = mpq_sgn(r);
  if (s == 0) return Interval(0);
  const double d = mpq_get_d(r);
  if (!(std::fabs(d) >= std::numeric_limits<double>::min()) || !std::isfinite(d))
    return Interval(CGAL::to_interval(q));
  mpz_srcptr den = mpq_denref(r);
  const bool dyadic = mpz_scan1(den, 0) + 1 == mpz_sizeinbase(den, 2);
  mpz_srcptr num = mpq_numref(r);
  if (dyadic && mpz_sizeinbase(num, 2) - mpz_scan1(num, 0) <= 53) return Interval(d);  // q is exactly d
  const double away = std::nextafter(d, s > 0 ? std::numeric_limits<double>::infinity()
                                              : -std::numeric_limits<double>::infinity());
  if (!std::isfinite(away)) return Interval(CGAL::to_interval(q));
  return s > 0 ? Interval(d, away) : Interval(away, d);
}

// Exact value of a finite double (every finite double is a rational).
inline Exact to_exact(double d) { return Exact(d); }

// A sum of many rationals kept over one running denominator: adding a term
// whose denominator divides it costs an integer division and a multiply-add
// instead of the gcds of a rational addition (sums of decimals, whose
// denominators are powers of ten, rarely need a new denominator).  Exact.
class ExactSum {
 public:
  ExactSum() : den_(1) {}
  ExactSum(const ExactSum&) = delete;  // CGAL::Gmpz shares its representation
  ExactSum& operator=(const ExactSum&) = delete;
  // Adds num / den (den > 0; need not be in lowest terms).
  void add(const CGAL::Gmpz& num, const CGAL::Gmpz& den);
  void add(const Exact& q) { add(q.numerator(), q.denominator()); }
  Exact value() const { return Exact(num_, den_); }

 private:
  CGAL::Gmpz num_, den_;
};

// Distinct exact points, numbered in order of first appearance (hashed by
// their double approximations, compared exactly).
class PointIds {
 public:
  std::uint32_t id(const Vec3E& p) {
    const auto [it, fresh] = ids_.emplace(p, static_cast<std::uint32_t>(points_.size()));
    if (fresh) points_.push_back(p);
    return it->second;
  }
  const Vec3E& point(std::uint32_t id) const { return points_[id]; }
  std::size_t size() const { return points_.size(); }

 private:
  struct Hash {
    std::size_t operator()(const Vec3E& p) const {
      std::size_t h = 0;
      for (const Exact& x : p) h = h * 1000003u ^ std::hash<double>()(mpq_get_d(x.mpq()));
      return h;
    }
  };
  std::unordered_map<Vec3E, std::uint32_t, Hash> ids_;
  std::vector<Vec3E> points_;
};

// "p/q" in lowest terms, or "p" when the denominator is 1.
std::string to_string(const Exact& q);

// Parses "p", "p/q" (integers with optional sign) or a decimal such as
// "-1.25e-3" exactly.  Returns false, leaving `out` unspecified, on anything
// else (including "nan", "inf", empty strings and a zero denominator).
bool parse_exact(const std::string& text, Exact& out);

// The size limit on numbers of input scenes and meshes (docs/scene-format.md,
// "Limits"): numerator and denominator of the value in lowest terms below
// 10^kMaxInputDigits, i.e. at most that many decimal digits each.  Exact
// tests on values far beyond it run for minutes.
inline constexpr unsigned long kMaxInputDigits = 10'000;
bool within_input_limit(const Exact& q);

}  // namespace tmcert
