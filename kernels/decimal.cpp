#include "kernels/decimal.h"

#include <gmp.h>

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <memory>

namespace tmcert {

namespace {

// RAII for mpz_t temporaries.
struct Z {
  mpz_t v;
  Z() { mpz_init(v); }
  ~Z() { mpz_clear(v); }
  Z(const Z&) = delete;
  Z& operator=(const Z&) = delete;
};

std::string digits_of(mpz_srcptr z) {
  std::unique_ptr<char, void (*)(void*)> text(mpz_get_str(nullptr, 10, z), free);
  return std::string(text.get());
}

// a * 10^k for k >= 0.
void times_power_of_ten(mpz_ptr out, mpz_srcptr a, long k) {
  Z p;
  mpz_ui_pow_ui(p.v, 10, static_cast<unsigned long>(k));
  mpz_mul(out, a, p.v);
}

}  // namespace

namespace {

// |q| (q != 0) rounded to `significant` digits, ties to even: the digit
// string m (significant digits, 10^(s-1) <= m < 10^s) and the decimal
// exponent e of its first digit, so |q| ~ m * 10^(e - s + 1); `exact` when
// no rounding happened.
struct Rounded {
  std::string digits;
  long exponent;
  bool exact;
};

Rounded round_significant(const Exact& q, int significant) {
  Z n, d;
  mpz_abs(n.v, mpq_numref(q.mpq()));
  mpz_set(d.v, mpq_denref(q.mpq()));

  // The decimal exponent e with 10^e <= n/d < 10^(e+1): first from the
  // lengths, then corrected exactly (the lengths can be off by one).
  long e = static_cast<long>(mpz_sizeinbase(n.v, 10)) - static_cast<long>(mpz_sizeinbase(d.v, 10));
  auto at_least = [&](long x) {  // n/d >= 10^x
    Z lhs, rhs;
    if (x >= 0) {
      mpz_set(lhs.v, n.v);
      times_power_of_ten(rhs.v, d.v, x);
    } else {
      times_power_of_ten(lhs.v, n.v, -x);
      mpz_set(rhs.v, d.v);
    }
    return mpz_cmp(lhs.v, rhs.v) >= 0;
  };
  while (!at_least(e)) --e;
  while (at_least(e + 1)) ++e;

  // m = n/d * 10^k rounded, k = significant - 1 - e, so 10^(s-1) <= m <= 10^s.
  const long k = significant - 1 - e;
  Z num, den, m, r;
  if (k >= 0) {
    times_power_of_ten(num.v, n.v, k);
    mpz_set(den.v, d.v);
  } else {
    mpz_set(num.v, n.v);
    times_power_of_ten(den.v, d.v, -k);
  }
  mpz_tdiv_qr(m.v, r.v, num.v, den.v);
  const bool exact = mpz_sgn(r.v) == 0;
  // Round half to even (as printf rounds the exact value of a double).
  mpz_mul_2exp(r.v, r.v, 1);
  const int half = mpz_cmp(r.v, den.v);
  if (half > 0 || (half == 0 && mpz_odd_p(m.v))) mpz_add_ui(m.v, m.v, 1);
  std::string s = digits_of(m.v);
  if (static_cast<long>(s.size()) > significant) {  // rounded up to 10^s
    s.pop_back();
    ++e;
  }
  return {s, e, exact};
}

std::string exponent_text(long e) {
  const long a = e < 0 ? -e : e;
  return std::string("e") + (e < 0 ? "-" : "+") + (a < 10 ? "0" : "") + std::to_string(a);
}

}  // namespace

Decimal to_decimal(const Exact& q, int significant) {
  if (significant < 1) significant = 1;
  const int sign = mpq_sgn(q.mpq());
  if (sign == 0) return {"0", true};
  Rounded rounded = round_significant(q, significant);
  std::string& s = rounded.digits;
  const long e = rounded.exponent;
  while (s.size() > 1 && s.back() == '0') s.pop_back();

  std::string text = sign < 0 ? "-" : "";
  if (e >= -4 && e < significant) {
    if (e >= 0) {
      const std::size_t int_digits = static_cast<std::size_t>(e) + 1;
      if (s.size() <= int_digits) {
        text += s + std::string(int_digits - s.size(), '0');
      } else {
        text += s.substr(0, int_digits) + "." + s.substr(int_digits);
      }
    } else {
      text += "0." + std::string(static_cast<std::size_t>(-e - 1), '0') + s;
    }
  } else {
    text += s.substr(0, 1);
    if (s.size() > 1) text += "." + s.substr(1);
    text += exponent_text(e);
  }
  return {text, rounded.exact};
}

std::string scientific(const Exact& q, int significant) {
  if (significant < 1) significant = 1;
  const int sign = mpq_sgn(q.mpq());
  if (sign == 0) return "0." + std::string(static_cast<std::size_t>(significant - 1), '0') + "e+00";
  const Rounded r = round_significant(q, significant);
  std::string text = sign < 0 ? "-" : "";
  text += r.digits.substr(0, 1);
  if (r.digits.size() > 1) text += "." + r.digits.substr(1);
  return text + exponent_text(r.exponent);
}

std::string readable(const Exact& q) {
  Decimal d = to_decimal(q);
  if (d.exact) return d.text;
  return d.text + " (" + to_string(q) + ")";
}

std::string decimal_text(const Exact& q) {
  const Decimal d = to_decimal(q, 17);
  if (d.exact) return d.text;
  // Exactly a double: the denominator a power of two, and the nearest
  // double equal to q.
  const double x = mpq_get_d(q.mpq());  // truncates; exact when q is a double
  if (std::isfinite(x) && Exact(x) == q) {
    char buffer[64];
    const auto r = std::to_chars(buffer, buffer + sizeof buffer, x);  // shortest round trip
    return std::string(buffer, r.ptr) + " (a double)";
  }
  return "about " + d.text;
}

std::optional<double> nearest_double(const Exact& q) {
  const int sign = mpq_sgn(q.mpq());
  if (sign == 0) return 0.0;
  // The tightest enclosure: q itself when it is a double, else the two
  // adjacent doubles around it ([DBL_MAX, inf] beyond the largest, [0,
  // the smallest subnormal] below it; CGAL rounds subnormals exactly).
  const Interval box = to_interval(q);
  const double lo = box.inf(), hi = box.sup();
  if (lo == hi) return lo;
  constexpr double kMax = std::numeric_limits<double>::max();
  if (std::isinf(lo) || std::isinf(hi)) {
    // IEEE rounding to nearest gives the largest double below 2^1024 -
    // 2^970 (halfway to the next power of two) and infinity from there on
    // (the tie goes to infinity: the largest double's significand is odd).
    Exact limit(1);
    mpq_mul_2exp(limit.mpq(), limit.mpq(), 1024);
    Exact step(1);
    mpq_mul_2exp(step.mpq(), step.mpq(), 970);
    limit -= step;
    if (CGAL::abs(q) < limit) return sign > 0 ? kMax : -kMax;
    return std::nullopt;
  }
  const Exact below = q - Exact(lo), above = Exact(hi) - q;
  double out;
  if (below < above) out = lo;
  else if (above < below) out = hi;
  else out = (std::bit_cast<std::uint64_t>(lo) & 1) == 0 ? lo : hi;  // a tie: the even significand
  if (out == 0) return std::nullopt;  // q != 0 would print as zero
  return out;
}

std::string shortest(double d) {
  char buffer[64];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, d).ptr;
  return std::string(buffer, end);
}

std::string approximation(const Exact& q) {
  if (const std::optional<double> d = nearest_double(q)) return shortest(*d);
  return scientific(q, 17);
}

}  // namespace tmcert
