#include "kernels/real_roots.h"

#include "kernels/decimal.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <utility>

namespace tmcert {

namespace {

// Caps on loops that terminate mathematically (ExactLimit past them).
constexpr int kMaxBisections = 4000;

Integer lcm(const Integer& a, const Integer& b) {
  Integer r;
  mpz_lcm(r.mpz(), a.mpz(), b.mpz());
  return r;
}

Integer gcd_int(const Integer& a, const Integer& b) {
  Integer r;
  mpz_gcd(r.mpz(), a.mpz(), b.mpz());
  return r;
}

Integer content(const PolyZ& p) {
  Integer g(0);
  for (const Integer& c : p) {
    if (c == 0) continue;
    g = gcd_int(g, c);
    if (g == 1) break;
  }
  return g;
}

// A positive multiple of the remainder of a divided by b (deg b >= 0):
// pseudo-division, lc(b)^k * a mod b after k steps, negated when that
// factor is negative.
PolyZ prem(PolyZ a, const PolyZ& b) {
  const int db = degree(b);
  const Integer& lb = b.back();
  int steps = 0;
  while (!a.empty() && degree(a) >= db) {
    const int shift = degree(a) - db;
    const Integer la = a.back();
    for (Integer& c : a) c *= lb;
    for (int k = 0; k <= db; ++k) a[k + shift] -= la * b[k];
    trim(a);
    ++steps;
  }
  if (lb < 0 && steps % 2 == 1)
    for (Integer& c : a) c = -c;
  return a;
}

// The Sturm sequence of a square-free p: p, p', then negated remainders
// (positive multiples of them, so the sign variations are Sturm's).
std::vector<PolyZ> sturm(const PolyZ& p) {
  std::vector<PolyZ> s{p};
  PolyZ d;
  for (int i = 1; i <= degree(p); ++i) d.push_back(p[i] * i);
  trim(d);
  if (d.empty()) return s;
  s.push_back(primitive(d));
  while (degree(s.back()) > 0) {
    const PolyZ& a = s[s.size() - 2];
    const PolyZ& b = s.back();
    PolyZ r = prem(a, b);
    if (r.empty()) break;  // p was not square-free: the last entry is a gcd
    r = primitive(r);
    for (Integer& c : r) c = -c;
    s.push_back(std::move(r));
  }
  return s;
}

int variations(const std::vector<PolyZ>& s, const Exact& x) {
  int count = 0;
  CGAL::Sign last = CGAL::ZERO;
  for (const PolyZ& p : s) {
    const CGAL::Sign v = sign_at(p, x);
    if (v == CGAL::ZERO) continue;
    if (last != CGAL::ZERO && v != last) ++count;
    last = v;
  }
  return count;
}

// Interval enclosure of q over [lo, hi] (exact rational endpoints, Horner
// with exact interval products).
std::pair<Exact, Exact> exact_range(const PolyZ& q, const Exact& lo, const Exact& hi) {
  Exact a(q.back()), b(q.back());
  for (int i = degree(q) - 1; i >= 0; --i) {
    const Exact p[4] = {a * lo, a * hi, b * lo, b * hi};
    a = *std::min_element(p, p + 4) + Exact(q[i]);
    b = *std::max_element(p, p + 4) + Exact(q[i]);
  }
  return {a, b};
}

// The double interval filter of range_sign alone.
CGAL::Sign range_sign_double(const PolyZ& q, const Exact& lo, const Exact& hi) {
  RoundingGuard guard;
  const Interval x(to_interval(lo).inf(), to_interval(hi).sup());  // lo <= hi
  Interval acc = Interval(CGAL::to_interval(q.back()));
  for (int i = degree(q) - 1; i >= 0; --i) acc = acc * x + Interval(CGAL::to_interval(q[i]));
  if (acc.inf() > 0) return CGAL::POSITIVE;
  if (acc.sup() < 0) return CGAL::NEGATIVE;
  return CGAL::ZERO;
}

// The sign of q over [lo, hi] when it is the same everywhere there and
// proven so (ZERO when not proven): a double interval filter, then exact
// rational intervals.
CGAL::Sign range_sign(const PolyZ& q, const Exact& lo, const Exact& hi) {
  if (const CGAL::Sign s = range_sign_double(q, lo, hi); s != CGAL::ZERO) return s;
  const auto [a, b] = exact_range(q, lo, hi);
  if (a > 0) return CGAL::POSITIVE;
  if (b < 0) return CGAL::NEGATIVE;
  return CGAL::ZERO;
}

// simplest_between for 0 < a/b <= c/d in 64-bit integers (b, d > 0): the
// same descent as below (the integer parts of the two continued fractions
// while they agree), folded back into p/q.  Every quantity stays between 0
// and max(a, b, c, d); false if the expansion is deeper than expected (it
// never is: each step at least halves a denominator), leaving the exact path.
bool simplest_between_small(std::int64_t a, std::int64_t b, std::int64_t c, std::int64_t d, Exact& out) {
  std::int64_t terms[130];
  int n = 0;
  for (;;) {
    if (n == 128) return false;
    const std::int64_t q = a / b;  // floor: both positive
    if (q * b == a) {  // lo is the integer q
      terms[n++] = q;
      break;
    }
    if (c - q * d >= d) {  // q + 1 <= hi
      terms[n++] = q + 1;
      break;
    }
    // Both in (q, q + 1): recurse on 1 / (hi - q) <= 1 / (lo - q).
    terms[n++] = q;
    const std::int64_t na = d, nb = c - q * d, nc = b, nd = a - q * b;
    a = na, b = nb, c = nc, d = nd;
  }
  // Fold q0 + 1 / (q1 + 1 / (... + 1 / q_last)).
  CGAL::Gmpz num(static_cast<long>(terms[n - 1])), den(1);
  for (int k = n - 2; k >= 0; --k) {
    CGAL::Gmpz next = CGAL::Gmpz(static_cast<long>(terms[k])) * num + den;
    den = num;
    num = next;
  }
  out = Exact(num, den);
  return true;
}

}  // namespace

Exact simplest_between(const Exact& lo, const Exact& hi) {
  if (lo > 0 && hi > lo && mpz_fits_slong_p(lo.numerator().mpz()) && mpz_fits_slong_p(lo.denominator().mpz()) &&
      mpz_fits_slong_p(hi.numerator().mpz()) && mpz_fits_slong_p(hi.denominator().mpz())) {
    Exact out;
    if (simplest_between_small(mpz_get_si(lo.numerator().mpz()), mpz_get_si(lo.denominator().mpz()),
                               mpz_get_si(hi.numerator().mpz()), mpz_get_si(hi.denominator().mpz()), out))
      return out;
  }
  if (lo <= 0 && hi >= 0) return Exact(0);
  if (hi < 0) return -simplest_between(-hi, -lo);  // one level: then 0 < -hi
  // 0 < lo = a/b <= hi = c/d: the same descent as simplest_between_small,
  // on GMP integers.
  // (CGAL::Gmpz values share their limbs when copied: only its operators,
  // never writes through mpz(), so no copy changes with another.)
  CGAL::Gmpz a = lo.numerator(), b = lo.denominator(), c = hi.numerator(), d = hi.denominator();
  std::vector<CGAL::Gmpz> terms;
  for (;;) {
    if (terms.size() == kSimplestTerms) return (lo + hi) / 2;
    const CGAL::Gmpz q = a / b;  // floor: both positive
    const CGAL::Gmpz r = a - q * b;
    if (r == 0) {  // lo is the integer q
      terms.push_back(q);
      break;
    }
    const CGAL::Gmpz c_minus_qd = c - q * d;
    if (c_minus_qd >= d) {  // q + 1 <= hi
      terms.push_back(q + 1);
      break;
    }
    // Both in (q, q + 1): continue with 1 / (hi - q) <= 1 / (lo - q).
    terms.push_back(q);
    // (a, b, c, d) <- (d, c - q d, b, a - q b).
    c = b;
    a = d;
    b = c_minus_qd;
    d = r;
  }
  // Fold q0 + 1 / (q1 + 1 / (... + 1 / q_last)).
  CGAL::Gmpz num = terms.back(), den(1);
  for (std::size_t k = terms.size() - 1; k-- > 0;) {
    CGAL::Gmpz next = terms[k] * num + den;
    den = std::move(num);
    num = std::move(next);
  }
  return Exact(num, den);
}


namespace {

// The same coefficient-wise code for rational and integer polynomials.
template <class Poly>
void trim_any(Poly& p) {
  while (!p.empty() && p.back() == 0) p.pop_back();
}

template <class Poly>
Poly add_or_sub(const Poly& a, const Poly& b, bool subtract) {
  Poly r(std::max(a.size(), b.size()));
  for (std::size_t i = 0; i < r.size(); ++i) {
    if (i < a.size()) r[i] += a[i];
    if (i < b.size()) {
      if (subtract) r[i] -= b[i];
      else r[i] += b[i];
    }
  }
  trim_any(r);
  return r;
}

}  // namespace

void trim(PolyQ& p) { trim_any(p); }
void trim(PolyZ& p) { trim_any(p); }
PolyQ add(const PolyQ& a, const PolyQ& b) { return add_or_sub(a, b, false); }
PolyQ sub(const PolyQ& a, const PolyQ& b) { return add_or_sub(a, b, true); }
PolyZ add(const PolyZ& a, const PolyZ& b) { return add_or_sub(a, b, false); }
PolyZ sub(const PolyZ& a, const PolyZ& b) { return add_or_sub(a, b, true); }

PolyQ mul(const PolyQ& a, const PolyQ& b) {
  if (a.empty() || b.empty()) return {};
  PolyQ r(a.size() + b.size() - 1);
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i] == 0) continue;
    for (std::size_t j = 0; j < b.size(); ++j) r[i + j] += a[i] * b[j];
  }
  trim(r);
  return r;
}

PolyZ mul(const PolyZ& a, const PolyZ& b) {
  if (a.empty() || b.empty()) return {};
  PolyZ r(a.size() + b.size() - 1);
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i] == 0) continue;
    for (std::size_t j = 0; j < b.size(); ++j) mpz_addmul(r[i + j].mpz(), a[i].mpz(), b[j].mpz());
  }
  trim(r);
  return r;
}

PolyZ primitive(const PolyQ& p) {
  Integer den(1);
  for (const Exact& c : p) den = lcm(den, c.denominator());
  PolyZ z;
  z.reserve(p.size());
  for (const Exact& c : p) z.push_back(c.numerator() * (den / c.denominator()));
  trim(z);
  return primitive(z);
}

PolyZ primitive(const PolyZ& p) {
  PolyZ z = p;
  trim(z);
  const Integer g = content(z);
  if (g > 1)
    for (Integer& c : z) {
      // Into a fresh integer: CGAL::Gmpz copies share their value, and
      // mpz() writes through to every copy.
      Integer q;
      mpz_divexact(q.mpz(), c.mpz(), g.mpz());
      c = q;
    }
  return z;
}

namespace {

// d^deg p(n / d), an integer with the sign of p(n / d) (d > 0).
Integer homogeneous_value(const PolyZ& p, const Integer& n, const Integer& d) {
  Integer acc = p.back(), dpow(1);
  for (int i = degree(p) - 1; i >= 0; --i) {
    dpow *= d;
    acc = acc * n + p[i] * dpow;
  }
  return acc;
}

}  // namespace

CGAL::Sign sign_at(const PolyZ& p, const Exact& x) {
  if (p.empty()) return CGAL::ZERO;
  return CGAL::sign(homogeneous_value(p, x.numerator(), x.denominator()));
}

Exact value_at(const PolyZ& p, const Exact& x) {
  Exact acc(0);
  for (int i = degree(p); i >= 0; --i) acc = acc * x + Exact(p[i]);
  return acc;
}

PolyZ gcd(const PolyZ& a0, const PolyZ& b0) {
  PolyZ a = primitive(a0), b = primitive(b0);
  if (degree(a) < degree(b)) std::swap(a, b);
  while (!b.empty()) {
    PolyZ r = prem(a, b);
    a = std::move(b);
    b = primitive(r);
  }
  if (!a.empty() && a.back() < 0)
    for (Integer& c : a) c = -c;
  return a;
}

PolyZ square_free(const PolyZ& p0) {
  const PolyZ p = primitive(p0);
  if (degree(p) <= 1) return p;
  PolyZ d;
  for (int i = 1; i <= degree(p); ++i) d.push_back(p[i] * i);
  const PolyZ g = gcd(p, d);
  if (degree(g) <= 0) return p;
  // Exact division p / g over Q.
  PolyQ rem(p.begin(), p.end()), q(p.size() - g.size() + 1);
  const int dg = degree(g);
  for (int k = degree(p) - dg; k >= 0; --k) {
    const Exact c = rem[k + dg] / Exact(g.back());
    q[k] = c;
    for (int i = 0; i <= dg; ++i) rem[k + i] -= c * Exact(g[i]);
  }
  return primitive(q);
}

RealRoot rational_root(const Exact& x) {
  RealRoot r;
  r.poly = primitive(PolyQ{-x, Exact(1)});
  r.lo = r.hi = x;
  return r;
}

std::vector<RealRoot> real_roots(const PolyZ& p0, const Exact& a, const Exact& b) {
  const PolyZ p = primitive(p0);
  std::vector<RealRoot> out;
  if (p.empty()) throw std::logic_error("real_roots: zero polynomial");
  if (degree(p) == 0) return out;
  // An enclosure of p over [a, b] without 0: no root (the common case on
  // small pieces, and far cheaper than a Sturm sequence at high degrees).
  if (range_sign_double(p, a, b) != CGAL::ZERO) return out;
  if (sign_at(p, a) == CGAL::ZERO) out.push_back(RealRoot{p, a, a});
  if (a == b) return out;
  if (degree(p) == 1) {
    const Exact x = -Exact(p[0]) / Exact(p[1]);
    if (a < x && x <= b) out.push_back(RealRoot{p, x, x});
    return out;
  }
  const std::vector<PolyZ> s = sturm(p);
  // Depth-first on half-open pieces (lo, hi] with their root counts, left
  // first: roots come out in increasing order.
  struct Piece {
    Exact lo, hi;
    int vlo, vhi;
  };
  std::vector<Piece> stack{{a, b, variations(s, a), variations(s, b)}};
  int steps = 0;
  while (!stack.empty()) {
    Piece c = stack.back();
    stack.pop_back();
    const int count = c.vlo - c.vhi;
    if (count <= 0) continue;
    if (++steps > kMaxBisections) throw ExactLimit("real_roots: too many bisections");
    const CGAL::Sign shi = sign_at(p, c.hi);
    if (count == 1) {
      if (shi == CGAL::ZERO) {
        out.push_back(RealRoot{p, c.hi, c.hi});
        continue;
      }
      const CGAL::Sign slo = sign_at(p, c.lo);
      if (slo != CGAL::ZERO) {
        out.push_back(RealRoot{p, c.lo, c.hi});
        continue;
      }
    }
    const Exact m = (c.lo + c.hi) / 2;
    const int vm = variations(s, m);
    stack.push_back({m, c.hi, vm, c.vhi});
    stack.push_back({c.lo, m, c.vlo, vm});
  }
  return out;
}

namespace {

// One bisection of r's interval given slo, poly's sign at r.lo: it is the
// sign of poly just left of the root (its only root in [lo, hi], poly
// nonzero at lo), so it stays the same while lo moves, and loops of
// bisections evaluate it once.
void bisect(RealRoot& r, CGAL::Sign slo) {
  if (r.is_rational()) return;
  const Exact m = (r.lo + r.hi) / 2;
  const CGAL::Sign sm = sign_at(r.poly, m);
  if (sm == CGAL::ZERO) {
    r.lo = r.hi = m;
    return;
  }
  if (sm == slo) r.lo = m;
  else r.hi = m;
}

}  // namespace

void refine(RealRoot& r) {
  if (r.is_rational()) return;
  bisect(r, sign_at(r.poly, r.lo));
}

namespace {

// Quadratic interval refinement (Abbott's QIR, checked by exact signs;
// proofs/exact-resolution.md §2): the secant of p over [lo, hi] picks one
// of 2^e equal sub-intervals, and the exact signs of p at its ends decide.
// r's root is p's only root in [lo, hi] and p has opposite nonzero signs
// at lo and hi, so an end with lo's sign has the root on its right, any
// other nonzero sign on its left, and a zero is the root. A hit keeps the
// sub-interval and squares 2^e (quadratic convergence near a simple root);
// a miss still trims the interval at the ends it tested and halves e. The
// secant is only a guess: soundness rests on the signs alone.
void qir_step(RealRoot& r, unsigned long& e, unsigned long max_e) {
  const PolyZ& p = r.poly;
  const Integer& nl = r.lo.numerator();
  const Integer& dl = r.lo.denominator();
  const Integer& nh = r.hi.numerator();
  const Integer& dh = r.hi.denominator();
  const Integer vl = homogeneous_value(p, nl, dl);  // dl^deg p(lo), nonzero
  const Integer vh = homogeneous_value(p, nh, dh);
  Integer dlp(1), dhp(1);
  for (int i = 0; i < degree(p); ++i) {
    dlp *= dl;
    dhp *= dh;
  }
  // secant: lo + f (hi - lo), f = p(lo) / (p(lo) - p(hi)) = vl dhp / (vl dhp - vh dlp) in (0, 1)
  Integer num = vl * dhp, den = num - vh * dlp;
  if (den < 0) {
    num = -num;
    den = -den;
  }
  e = std::min(std::max(e, 1ul), max_e);
  Integer index;
  mpz_mul_2exp(num.mpz(), num.mpz(), e);
  mpz_fdiv_q(index.mpz(), num.mpz(), den.mpz());
  const Integer parts = Integer(1) << static_cast<int>(e);
  if (index < 0) index = 0;
  if (index >= parts) index = parts - 1;
  const Exact step = (r.hi - r.lo) / Exact(parts);
  const Exact a = r.lo + Exact(index) * step, b = a + step;
  const CGAL::Sign slo = CGAL::sign(vl);
  Exact lo = r.lo, hi = r.hi;
  bool hit = true;
  for (const Exact& g : {a, b}) {
    if (g <= lo || g >= hi) continue;
    const CGAL::Sign sg = sign_at(p, g);
    if (sg == CGAL::ZERO) {
      r.lo = r.hi = g;
      return;
    }
    if (sg == slo) {
      lo = g;
      hit = hit && g == a;
    } else {
      hi = g;
      hit = hit && g == b;
    }
  }
  r.lo = lo;
  r.hi = hi;
  e = hit ? 2 * e : std::max(1ul, e / 2);
}

}  // namespace

void refine_to(RealRoot& r, const Exact& width) {
  // Quadratic interval refinement when far from the width, else bisection.
  if (r.is_rational()) return;
  const CGAL::Sign slo = sign_at(r.poly, r.lo);  // the same for every valid interval of r
  unsigned long e = 2;
  for (int k = 0; !r.is_rational() && r.hi - r.lo > width; ++k) {
    if (k > kMaxBisections) throw ExactLimit("refine_to: too many bisections");
    const Exact ratio = width / (r.hi - r.lo);
    if (degree(r.poly) >= 2 && ratio * 256 < 1) {
      // no more parts than needed to reach the width: 2^-max_e >= ratio / 2
      const long bits = static_cast<long>(mpz_sizeinbase(ratio.denominator().mpz(), 2)) -
                        static_cast<long>(mpz_sizeinbase(ratio.numerator().mpz(), 2));
      const unsigned long max_e = static_cast<unsigned long>(std::max(1l, bits));
      qir_step(r, e, max_e);
    } else {
      bisect(r, slo);
    }
  }
}

CGAL::Sign enclosure_sign(const PolyZ& q, const Exact& lo, const Exact& hi) {
  return q.empty() ? CGAL::ZERO : range_sign_double(q, lo, hi);
}

CGAL::Sign sign_at(const PolyZ& q, RealRoot& r) {
  if (q.empty()) return CGAL::ZERO;
  if (r.is_rational()) return sign_at(q, r.lo);
  if (const CGAL::Sign s = range_sign(q, r.lo, r.hi); s != CGAL::ZERO) return s;
  const CGAL::Sign slo = sign_at(r.poly, r.lo);
  // At low degrees the gcd below costs a few pseudo-remainders, less than
  // one exact interval enclosure: decide q(r) = 0 first (the contact
  // predicates of linear motions, often exactly zero at a contact).
  const bool gcd_first = degree(q) + degree(r.poly) <= 8;
  if (gcd_first) {
    const PolyZ g = gcd(q, r.poly);
    if (degree(g) >= 1 && sign_at(g, r.lo) != sign_at(g, r.hi)) return CGAL::ZERO;
  }
  // A few bisections first: cheaper than the gcd below when q(r) != 0
  // (high degrees, large coefficients).
  for (int k = 0; k < 24; ++k) {
    bisect(r, slo);
    if (r.is_rational()) return sign_at(q, r.lo);
    if (const CGAL::Sign s = range_sign(q, r.lo, r.hi); s != CGAL::ZERO) return s;
  }
  // q(r) = 0 exactly when r is a root of g = gcd(q, poly): g divides the
  // square-free poly, so r is g's only root in [lo, hi], and g is nonzero
  // at lo and hi; it changes sign there exactly when r is its root.
  if (!gcd_first) {
    const PolyZ g = gcd(q, r.poly);
    if (degree(g) >= 1 && sign_at(g, r.lo) != sign_at(g, r.hi)) return CGAL::ZERO;
  }
  // q(r) != 0: a small enough interval around r proves q's sign.
  for (int k = 0; k < kMaxBisections; ++k) {
    bisect(r, slo);
    if (r.is_rational()) return sign_at(q, r.lo);
    if (const CGAL::Sign s = range_sign(q, r.lo, r.hi); s != CGAL::ZERO) return s;
  }
  throw ExactLimit("sign_at: too many bisections");
}

CGAL::Comparison_result compare(RealRoot& a, RealRoot& b) {
  if (a.is_rational() && b.is_rational()) return CGAL::compare(a.lo, b.lo);
  if (b.is_rational() && !a.is_rational()) return CGAL::opposite(compare(b, a));
  if (a.is_rational()) {
    const Exact& x = a.lo;
    if (x <= b.lo) return CGAL::SMALLER;
    if (x >= b.hi) return CGAL::LARGER;
    const CGAL::Sign s = sign_at(b.poly, x);
    if (s == CGAL::ZERO) return CGAL::EQUAL;  // b's only root in (lo, hi)
    // b's root is below x exactly when poly changes sign on (lo, x).
    return s != sign_at(b.poly, b.lo) ? CGAL::LARGER : CGAL::SMALLER;
  }
  // Equal only if a is a root of b's polynomial, inside b's interval.
  const PolyZ g = gcd(a.poly, b.poly);
  const bool a_root_of_b = degree(g) >= 1 && sign_at(g, a.lo) != sign_at(g, a.hi);
  for (int k = 0; k < kMaxBisections; ++k) {
    if (a.is_rational() || b.is_rational()) return compare(a, b);
    if (a.hi <= b.lo) return CGAL::SMALLER;
    if (b.hi <= a.lo) return CGAL::LARGER;
    if (a_root_of_b && b.lo < a.lo && a.hi < b.hi) return CGAL::EQUAL;  // b.poly's only root in (b.lo, b.hi)
    refine(a);
    if (!a_root_of_b) refine(b);
  }
  throw ExactLimit("compare: too many bisections");
}

namespace {

// True when p has no rational root at all: p mod q has no root in Z/q for
// some small prime q not dividing the leading coefficient (a rational root
// n/d has d | lc, so d is invertible mod q and n/d mod q would be a root).
bool no_rational_root(const PolyZ& p) {
  static const unsigned long primes[] = {3,  5,  7,  11, 13, 17, 19, 23, 29, 31, 37,  41,  43,  47,  53,
                                         59, 61, 67, 71, 73, 79, 83, 89, 97, 101, 103, 107, 109, 113, 127};
  std::vector<unsigned long> c(p.size());
  for (unsigned long q : primes) {
    if (mpz_divisible_ui_p(p.back().mpz(), q)) continue;
    for (std::size_t i = 0; i < p.size(); ++i) c[i] = mpz_fdiv_ui(p[i].mpz(), q);
    bool root = false;
    for (unsigned long x = 0; x < q && !root; ++x) {
      unsigned long acc = 0;
      for (std::size_t i = c.size(); i-- > 0;) acc = (acc * x + c[i]) % q;
      root = acc == 0;
    }
    if (!root) return true;
  }
  return false;
}

}  // namespace

bool settle_rational(RealRoot& r) {
  if (r.is_rational()) return true;
  if (no_rational_root(r.poly)) return false;
  {
    // A rational root with a small denominator is the simplest rational of
    // a narrow interval around it.
    // Tried on narrower and narrower intervals (most such roots, like 1/3
    // or 0.137, are the simplest rational of a wide one).
    RealRoot narrow = r;
    for (const unsigned long bits : {0ul, 8ul, 16ul, 32ul, 64ul}) {
      if (bits > 0) refine_to(narrow, Exact(Integer(1), Integer(1) << bits));
      if (narrow.is_rational()) {
        r = narrow;
        return true;
      }
      const Exact c = simplest_between(narrow.lo, narrow.hi);
      if (sign_at(r.poly, c) == CGAL::ZERO) {
        r.lo = r.hi = c;
        return true;
      }
    }
  }
  // A rational root n/d of the primitive poly has d | lc; two distinct
  // rationals with denominators <= |lc| are at least 1/lc^2 apart, so in
  // an interval narrower than that only the simplest rational can be it.
  Integer lc = r.poly.back();
  if (lc < 0) lc = -lc;
  refine_to(r, Exact(Integer(1), lc * lc * 2));
  if (r.is_rational()) return true;
  const Exact c = simplest_between(r.lo, r.hi);
  if (c.denominator() <= lc && sign_at(r.poly, c) == CGAL::ZERO) {
    r.lo = r.hi = c;
    return true;
  }
  return false;
}

PolyZ compose_affine(const PolyZ& p, const Exact& x0, const Exact& scale) {
  // Horner in the polynomial ring: acc = acc * (x0 + scale x) + c_i.
  PolyQ acc;
  const PolyQ lin{x0, scale};
  for (int i = degree(p); i >= 0; --i) acc = add(mul(acc, lin), PolyQ{Exact(p[i])});
  return primitive(acc);
}

namespace {

// L with |x| in (2^(L-1), 2^(L+1)) for x != 0 (bit lengths of numerator and
// denominator).
long log2_magnitude(const Exact& x) {
  return static_cast<long>(mpz_sizeinbase(x.numerator().mpz(), 2)) -
         static_cast<long>(mpz_sizeinbase(x.denominator().mpz(), 2));
}

Exact power_of_two(long e) {
  Exact out(1);
  if (e >= 0) mpq_mul_2exp(out.mpq(), out.mpq(), static_cast<mp_bitcnt_t>(e));
  else mpq_div_2exp(out.mpq(), out.mpq(), static_cast<mp_bitcnt_t>(-e));
  return out;
}

// Cuts r's interval at m (lo < m < hi) by the exact sign there.
void cut(RealRoot& r, const Exact& m, CGAL::Sign slo) {
  const CGAL::Sign sm = sign_at(r.poly, m);
  if (sm == CGAL::ZERO) r.lo = r.hi = m;
  else if (sm == slo) r.lo = m;
  else r.hi = m;
}

// Narrows r (not rational) until its interval lies on one side of 0 with
// ends within a factor 2 in magnitude, by cuts at 0, at powers of two
// halving the binary exponent range, and, from 0, at big / 2^g with g
// doubling: a root of 1e-3000 takes some forty cuts, not ten thousand
// bisections.  The root is never 0 here (0 is rational: a root at 0 has a
// zero interval).
void narrow_magnitude(RealRoot& r) {
  if (r.is_rational()) return;
  const CGAL::Sign slo = sign_at(r.poly, r.lo);
  if (r.lo < 0 && r.hi > 0) cut(r, Exact(0), slo);
  long g = 1;
  for (int k = 0; !r.is_rational(); ++k) {
    if (k > kMaxBisections) throw ExactLimit("narrow_magnitude: too many cuts");
    const bool negative = r.hi <= 0;
    const Exact small = negative ? -r.hi : r.lo, big = negative ? -r.lo : r.hi;
    if (small != 0 && big <= 2 * small) return;
    Exact m;
    if (small == 0) {
      m = big * power_of_two(-g);
      if (g < (1L << 40)) g *= 2;
    } else {
      const long el = log2_magnitude(small), eh = log2_magnitude(big);
      m = eh - el >= 4 ? power_of_two(el + (eh - el) / 2) : (small + big) / 2;
    }
    cut(r, negative ? -m : m, slo);
  }
}

}  // namespace

std::string approximate(RealRoot r) {
  if (r.is_rational()) return approximation(r.lo);
  narrow_magnitude(r);
  // Rounding to the nearest double, and to 17 significant digits, is
  // monotone: when both ends of the interval give the same result, so
  // does every point between, the root included.  The boundaries between
  // results are rational and the root is not, so refining ends this.
  for (long bits = 64; !r.is_rational(); bits += 64) {
    if (bits > 64 * kMaxBisections) throw ExactLimit("approximate: too many refinements");
    const std::optional<double> a = nearest_double(r.lo), b = nearest_double(r.hi);
    if (a && b && *a == *b) return shortest(*a);
    if (!a && !b) {
      const std::string x = scientific(r.lo, 17);
      if (x == scientific(r.hi, 17)) return x;
    }
    const Exact small = r.hi <= 0 ? -r.hi : r.lo;
    refine_to(r, small * power_of_two(-bits));
  }
  return approximation(r.lo);
}

std::string approximate_decimal(RealRoot r, int significant) {
  if (r.is_rational()) return to_decimal(r.lo, significant).text;
  narrow_magnitude(r);
  for (long bits = 32; !r.is_rational(); bits += 32) {
    if (bits > 32 * kMaxBisections) throw ExactLimit("approximate_decimal: too many refinements");
    const std::string x = to_decimal(r.lo, significant).text;
    if (x == to_decimal(r.hi, significant).text) return x;
    const Exact small = r.hi <= 0 ? -r.hi : r.lo;
    refine_to(r, small * power_of_two(-bits));
  }
  return to_decimal(r.lo, significant).text;
}

}  // namespace tmcert
