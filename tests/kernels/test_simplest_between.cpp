// simplest_between (kernels/real_roots.h, used by src/verify/search.h):
// the rational with the smallest denominator in [lo, hi].  Iterative and bounded: ends with tens of
// thousands of digits (ratios of consecutive Fibonacci numbers, one partial
// quotient per step) used to overflow the stack of the recursive version.
#include "src/verify/search.h"

#include <boost/test/unit_test.hpp>

#include <random>

using tmcert::Exact;

namespace {

Exact q(const char* text) {
  Exact value;
  BOOST_REQUIRE(tmcert::parse_exact(text, value));
  return value;
}

// The recursive definition, as a reference for inputs of moderate depth.
Exact reference(const Exact& lo, const Exact& hi) {
  if (lo <= 0 && hi >= 0) return Exact(0);
  if (hi < 0) return -reference(-hi, -lo);
  CGAL::Gmpz fl;
  mpz_fdiv_q(fl.mpz(), lo.numerator().mpz(), lo.denominator().mpz());
  if (Exact(fl) == lo) return lo;
  if (Exact(fl + 1) <= hi) return Exact(fl + 1);
  return Exact(fl) + Exact(1) / reference(Exact(1) / (hi - Exact(fl)), Exact(1) / (lo - Exact(fl)));
}

// F(n) / F(n + 1) and F(n + 1) / F(n + 2): continued fractions [0; 1, 1, ..., 1].
std::pair<Exact, Exact> fibonacci_ratios(int n) {
  CGAL::Gmpz f0(0), f1(1);
  for (int k = 0; k < n; ++k) {
    CGAL::Gmpz next = f0 + f1;
    f0 = std::move(f1);
    f1 = std::move(next);
  }
  const CGAL::Gmpz f2 = f0 + f1;
  return {Exact(f0, f1), Exact(f1, f2)};
}

}  // namespace

BOOST_AUTO_TEST_SUITE(simplest_rational)

BOOST_AUTO_TEST_CASE(hand_made) {
  using tmcert::detail::simplest_between;
  BOOST_TEST(simplest_between(q("1/4"), q("1/2")) == q("1/2"));
  BOOST_TEST(simplest_between(q("0.3"), q("0.34")) == q("1/3"));
  BOOST_TEST(simplest_between(q("-0.34"), q("-0.3")) == q("-1/3"));
  BOOST_TEST(simplest_between(q("-1"), q("2")) == Exact(0));
  BOOST_TEST(simplest_between(q("7/3"), q("7/3")) == q("7/3"));
  BOOST_TEST(simplest_between(q("2.5"), q("3")) == Exact(3));
  // Beyond 64 bits: the GMP path.
  BOOST_TEST(simplest_between(q("1e30") / 3, q("1e30") / 3) == q("1e30") / 3);
  BOOST_TEST(simplest_between(q("100000000000000000000.3"), q("100000000000000000000.34")) ==
             q("100000000000000000000") + q("1/3"));
}

BOOST_AUTO_TEST_CASE(agrees_with_the_recursive_definition) {
  std::mt19937_64 rng(20261125);
  for (int k = 0; k < 2000; ++k) {
    // Random big rationals, some pairs close together (long expansions).
    CGAL::Gmpz num(static_cast<long>(rng() >> 2)), den(static_cast<long>((rng() >> 2) | 1));
    num *= CGAL::Gmpz(static_cast<long>(rng() >> 3));
    den *= CGAL::Gmpz(static_cast<long>((rng() >> 3) | 1));
    const Exact lo(num, den);
    Exact width(CGAL::Gmpz(static_cast<long>(rng() % 1000 + 1)), den * CGAL::Gmpz(static_cast<long>(rng() % 97 + 1)));
    if (k % 3 == 0) width = Exact(0);
    const Exact a = k % 2 ? lo : -lo - width, b = a + width;
    const Exact got = tmcert::detail::simplest_between(a, b), want = reference(a, b);
    BOOST_TEST(got == want, "[" << a << ", " << b << "]: " << got << " != " << want);
  }
  for (int n : {1, 2, 10, 90, 300, 1000}) {
    const auto [lo, hi] = fibonacci_ratios(n);
    BOOST_TEST(tmcert::detail::simplest_between(lo, hi) == reference(lo, hi), "n = " << n);
  }
}

BOOST_AUTO_TEST_CASE(huge_fibonacci_ratios_end_in_the_interval) {
  // About 100 000 partial quotients (F(100000) has 20 899 digits): deeper
  // than the bound, so the midpoint; no recursion, no stack overflow.
  const auto [lo, hi] = fibonacci_ratios(100000);
  const Exact got = tmcert::detail::simplest_between(lo, hi);
  BOOST_TEST(got == (lo + hi) / 2);
  BOOST_TEST((lo <= got && got <= hi));
  const Exact neg = tmcert::detail::simplest_between(-hi, -lo);
  BOOST_TEST(neg == -got);
  // Within the bound, the simplest rational itself.
  const auto [lo2, hi2] = fibonacci_ratios(static_cast<int>(tmcert::kSimplestTerms) - 30);
  BOOST_TEST(tmcert::detail::simplest_between(lo2, hi2) == reference(lo2, hi2));
}

BOOST_AUTO_TEST_SUITE_END()
