#include "kernels/validated.h"

#include <gmp.h>
#include <arb.h>
#include <flint/fmpq.h>

#include <cmath>
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

}  // namespace

Interval sin(const Interval& x) {
  if (!finite(x)) return Interval(-1, 1);
  Ball a, s;
  set(a, x);
  arb_sin(s.v, a.v, kPrec);
  return get(s);
}

Interval cos(const Interval& x) {
  if (!finite(x)) return Interval(-1, 1);
  Ball a, c;
  set(a, x);
  arb_cos(c.v, a.v, kPrec);
  return get(c);
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
