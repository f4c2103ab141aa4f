#include "kernels/validated.h"

#include <gmp.h>
#include <arb.h>
#include <flint/fmpq.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace tmcert::validated {

namespace {

// Working precision in bits: far below double's 53 bits of output, so the
// only loss is the final outward rounding to doubles.
constexpr slong kPrec = 128;

// RAII holder for an arb_t.
struct Ball {
  arb_t v;
  Ball() { arb_init(v); }
  ~Ball() { arb_clear(v); }
  Ball(const Ball&) = delete;
  Ball& operator=(const Ball&) = delete;
};

struct Float {
  arf_t v;
  Float() { arf_init(v); }
  ~Float() { arf_clear(v); }
  Float(const Float&) = delete;
  Float& operator=(const Float&) = delete;
};

const Interval kWhole(-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity());

bool finite(const Interval& x) { return std::isfinite(x.inf()) && std::isfinite(x.sup()); }

// The ball holding every point of [x.inf(), x.sup()] (exact: doubles are
// exact binary floats).
void set(Ball& out, const Interval& x) {
  Float lo, hi;
  arf_set_d(lo.v, x.inf());
  arf_set_d(hi.v, x.sup());
  arb_set_interval_arf(out.v, lo.v, hi.v, kPrec);
}

// The smallest double interval holding the ball (outward rounding); the
// whole line when the ball is not finite.
Interval get(const Ball& x) {
  if (!arb_is_finite(x.v)) return kWhole;
  Float lo, hi;
  arb_get_interval_arf(lo.v, hi.v, x.v, kPrec);
  const double l = arf_get_d(lo.v, ARF_RND_FLOOR), h = arf_get_d(hi.v, ARF_RND_CEIL);
  if (std::isnan(l) || std::isnan(h)) return kWhole;
  return Interval(l, h);
}

// A small per-thread memo of a function's last results, keyed by the bits
// of the argument's ends: Arb is deterministic, so the same argument gets
// the same enclosure whether computed or remembered (an arm's joint angle
// over one slice is the same interval in the chain of every link after
// the joint).  Direct-mapped; a collision overwrites.
class Memo {
 public:
  template <class F>
  Interval get(const Interval& x, F&& compute) {
    std::uint64_t lo, hi;
    const double l = x.inf(), h = x.sup();
    std::memcpy(&lo, &l, sizeof lo);
    std::memcpy(&hi, &h, sizeof hi);
    Entry& e = entries_[((lo * 0x9E3779B97F4A7C15ull) ^ (hi * 0xC2B2AE3D27D4EB4Full)) >> (64 - kBits)];
    if (e.used && e.lo == lo && e.hi == hi) return e.value;
    const Interval value = compute();
    e = Entry{lo, hi, value, true};
    return value;
  }

 private:
  static constexpr int kBits = 8;
  struct Entry {
    std::uint64_t lo = 0, hi = 0;
    Interval value = Interval(0);
    bool used = false;
  };
  std::array<Entry, std::size_t{1} << kBits> entries_{};
};

}  // namespace

Interval sin(const Interval& x) {
  if (!finite(x)) return Interval(-1, 1);
  thread_local Memo memo;
  return memo.get(x, [&] {
    Ball a, s;
    set(a, x);
    arb_sin(s.v, a.v, kPrec);
    return get(s);
  });
}

Interval cos(const Interval& x) {
  if (!finite(x)) return Interval(-1, 1);
  thread_local Memo memo;
  return memo.get(x, [&] {
    Ball a, c;
    set(a, x);
    arb_cos(c.v, a.v, kPrec);
    return get(c);
  });
}

Interval atan2(const Interval& y, const Interval& x) {
  const Interval range = pi();
  const Interval whole(-range.sup(), range.sup());
  if (!finite(x) || !finite(y)) return whole;
  Ball a, b, r;
  set(b, y);
  set(a, x);
  arb_atan2(r.v, b.v, a.v, kPrec);
  const Interval out = get(r);
  return finite(out) ? out : whole;
}

namespace {

// The ball's largest magnitude, as a double rounded up.
double magnitude_bound(const Ball& x) {
  Float m;
  arb_get_abs_ubound_arf(m.v, x.v, kPrec);
  return arf_get_d(m.v, ARF_RND_UP);
}

}  // namespace

std::array<Interval, 3> factorial_series(const Interval& x, int m) {
  const std::array<Interval, 3> whole{kWhole, kWhole, kWhole};
  if (!finite(x) || m < 1 || m > 3) return whole;
  Ball b;
  set(b, x);
  const double X = magnitude_bound(b);
  if (!(X <= 4)) return whole;
  // Terms k < kTerms exactly in ball arithmetic (every point of the ball);
  // the rest of each series, terms (2k)^j x^(2k-j) / (2k+m)! for k >= kTerms
  // in magnitude, falls by a factor below 1/400 per term for |x| <= 4
  // ((1 + 1/k)^2 x^2 / ((2k+m+1)(2k+m+2)) with k >= 40), so it is at most
  // twice its first term.
  constexpr int kTerms = 40;
  Ball x2, power, fact, term, sum0, sum1, sum2, c;
  arb_mul(x2.v, b.v, b.v, kPrec);
  arb_one(power.v);  // x^(2k)
  arb_fac_ui(fact.v, static_cast<ulong>(m), kPrec);  // (2k+m)!
  arb_zero(sum0.v);
  arb_zero(sum1.v);
  arb_zero(sum2.v);
  Ball power_m1, power_m2;  // x^(2k-1), x^(2k-2) for k >= 1
  for (int k = 0; k < kTerms; ++k) {
    if (k > 0) {
      arb_set(power_m2.v, power.v);        // x^(2k-2)
      arb_mul(power_m1.v, power.v, b.v, kPrec);  // x^(2k-1)
      arb_mul(power.v, power.v, x2.v, kPrec);    // x^(2k)
      arb_mul_ui(fact.v, fact.v, static_cast<ulong>((2 * k + m - 1) * (2 * k + m)), kPrec);
    }
    // a_k = (-1)^k / (2k+m)!
    arb_inv(c.v, fact.v, kPrec);
    if (k % 2) arb_neg(c.v, c.v);
    arb_mul(term.v, c.v, power.v, kPrec);
    arb_add(sum0.v, sum0.v, term.v, kPrec);
    if (k > 0) {
      arb_mul(term.v, c.v, power_m1.v, kPrec);
      arb_mul_ui(term.v, term.v, static_cast<ulong>(2 * k), kPrec);
      arb_add(sum1.v, sum1.v, term.v, kPrec);
      arb_mul(term.v, c.v, power_m2.v, kPrec);
      arb_mul_ui(term.v, term.v, static_cast<ulong>(2 * k * (2 * k - 1)), kPrec);
      arb_add(sum2.v, sum2.v, term.v, kPrec);
    }
  }
  // Bounds of the rests: 2 (2N)^j X^(2N-j) / (2N+m)! with N = kTerms.
  Ball xb, rest, n_fact;
  arb_set_d(xb.v, X);
  arb_fac_ui(n_fact.v, static_cast<ulong>(2 * kTerms + m), kPrec);
  Ball* sums[3] = {&sum0, &sum1, &sum2};
  for (int j = 0; j < 3; ++j) {
    arb_pow_ui(rest.v, xb.v, static_cast<ulong>(2 * kTerms - j), kPrec);
    for (int i = 0; i < j; ++i) arb_mul_ui(rest.v, rest.v, static_cast<ulong>(2 * kTerms), kPrec);
    arb_mul_ui(rest.v, rest.v, 2, kPrec);
    arb_div(rest.v, rest.v, n_fact.v, kPrec);
    Float bound;
    arb_get_abs_ubound_arf(bound.v, rest.v, kPrec);
    arb_add_error_arf(sums[j]->v, bound.v);
  }
  return {get(sum0), get(sum1), get(sum2)};
}

Interval screw_inverse_coefficient(const Interval& phi) {
  if (!finite(phi)) return kWhole;
  Ball b;
  set(b, phi);
  const double P = magnitude_bound(b);
  Ball out;
  if (P <= 1) {
    // sum_{n=1}^{N} 2 zeta(2n) phi^(2n-2) / (2 pi)^(2n); every term is
    // positive and the term ratio is at most phi^2 / (2 pi)^2 < 1/39, so
    // the rest is below 2 zeta(2N+2) P^(2N) / (2 pi)^(2N+2) / (1 - 1/39),
    // and zeta < 2.
    constexpr int kTerms = 25;
    Ball two_pi, inv2, power, term, z, ph2;
    arb_const_pi(two_pi.v, kPrec);
    arb_mul_2exp_si(two_pi.v, two_pi.v, 1);
    arb_mul(inv2.v, two_pi.v, two_pi.v, kPrec);
    arb_inv(inv2.v, inv2.v, kPrec);  // 1 / (2 pi)^2
    arb_mul(ph2.v, b.v, b.v, kPrec);
    arb_set(power.v, inv2.v);  // phi^(2n-2) / (2 pi)^(2n)
    arb_zero(out.v);
    for (int n = 1; n <= kTerms; ++n) {
      if (n > 1) {
        arb_mul(power.v, power.v, ph2.v, kPrec);
        arb_mul(power.v, power.v, inv2.v, kPrec);
      }
      arb_zeta_ui(z.v, static_cast<ulong>(2 * n), kPrec);
      arb_mul(term.v, z.v, power.v, kPrec);
      arb_mul_2exp_si(term.v, term.v, 1);
      arb_add(out.v, out.v, term.v, kPrec);
    }
    Ball rest, pb;
    arb_set_d(pb.v, P);
    arb_pow_ui(rest.v, pb.v, static_cast<ulong>(2 * kTerms), kPrec);
    Ball inv_pow;
    arb_pow_ui(inv_pow.v, inv2.v, static_cast<ulong>(kTerms + 1), kPrec);
    arb_mul(rest.v, rest.v, inv_pow.v, kPrec);
    arb_mul_ui(rest.v, rest.v, 4 * 39, kPrec);
    arb_div_ui(rest.v, rest.v, 38, kPrec);
    Float bound;
    arb_get_abs_ubound_arf(bound.v, rest.v, kPrec);
    arb_add_error_arf(out.v, bound.v);
  } else {
    // (1 - h cos h / sin h) / phi^2 with h = phi / 2.
    Ball h, s, c, t;
    arb_mul_2exp_si(h.v, b.v, -1);
    arb_sin_cos(s.v, c.v, h.v, kPrec);
    arb_mul(t.v, h.v, c.v, kPrec);
    arb_div(t.v, t.v, s.v, kPrec);
    arb_sub_ui(t.v, t.v, 1, kPrec);
    arb_neg(t.v, t.v);
    arb_mul(s.v, b.v, b.v, kPrec);
    arb_div(out.v, t.v, s.v, kPrec);
  }
  return get(out);
}

Interval pi() {
  Ball p;
  arb_const_pi(p.v, kPrec);
  return get(p);
}

Interval of(const Exact& q) { return to_interval(q); }

Interval sqrt(const Exact& q) {
  if (q < 0) return kWhole;
  fmpz_t num, den;
  fmpz_init(num);
  fmpz_init(den);
  fmpz_set_mpz(num, q.numerator().mpz());
  fmpz_set_mpz(den, q.denominator().mpz());
  Ball a, r;
  arb_fmpz_div_fmpz(a.v, num, den, kPrec);
  fmpz_clear(num);
  fmpz_clear(den);
  arb_sqrt(r.v, a.v, kPrec);
  return get(r);
}

}  // namespace tmcert::validated
