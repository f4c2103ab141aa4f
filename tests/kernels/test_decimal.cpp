// kernels/decimal: decimals of exact numbers, rounded in integer
// arithmetic (tests/kernels/ mirrors kernels/).
#include "kernels/decimal.h"

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>

using tmcert::Exact;
using tmcert::to_decimal;

namespace {

Exact q(const std::string& text) {
  Exact x;
  BOOST_REQUIRE(tmcert::parse_exact(text, x));
  return x;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(decimal)

BOOST_AUTO_TEST_CASE(hand_made_cases) {
  struct Case {
    const char* value;
    const char* text;
    bool exact;
  };
  const Case cases[] = {
      {"0", "0", true},
      {"3", "3", true},
      {"-3", "-3", true},
      {"1/2", "0.5", true},
      {"1/50", "0.02", true},
      {"8471/4096", "2.06812", false},
      {"248723/100000000", "0.00248723", true},
      {"1/3", "0.333333", false},
      {"-2/3", "-0.666667", false},
      {"2/3000000", "6.66667e-07", false},
      {"1/10000", "0.0001", true},
      {"1/100000", "1e-05", true},
      {"123456", "123456", true},
      {"1234567", "1.23457e+06", false},
      {"999999.5", "1e+06", false},        // rounds up to the next power of ten
      {"0.0000999999999", "0.0001", false},
      {"1234565", "1.23456e+06", false},   // a tie: to even
      {"-1234575", "-1.23458e+06", false},
      {"1e-300", "1e-300", true},          // beyond what doubles print well
      {"1e400", "1e+400", true},           // beyond the double range
      {"12345678901234567890123/1000000000000000000000000000000", "1.23457e-08", false},
  };
  for (const Case& c : cases) {
    const tmcert::Decimal d = to_decimal(q(c.value));
    BOOST_TEST(d.text == c.text, c.value << ": " << d.text << ", expected " << c.text);
    BOOST_TEST(d.exact == c.exact, c.value);
  }
  BOOST_TEST(tmcert::readable(q("8471/4096")) == "2.06812 (8471/4096)");
  BOOST_TEST(tmcert::readable(q("1/2")) == "0.5");
  BOOST_TEST(to_decimal(q("1/3"), 17).text == "0.33333333333333333");
  BOOST_TEST(to_decimal(q("2/3"), 1).text == "0.7");
}

// Against glibc's printf, which prints the exact value of a double rounded
// correctly (ties to even): random doubles over a wide range of exponents
// (large ones have few fraction bits, so 17 digits meet exact ties).
BOOST_AUTO_TEST_CASE(agrees_with_printf_on_doubles) {
  const unsigned seed = 20261127;
  std::mt19937_64 rng(seed);
  for (int k = 0; k < 3000; ++k) {
    const std::uint64_t significand = (rng() >> 11) | (std::uint64_t(1) << 52);
    const int exponent = static_cast<int>(rng() % 400) - 252;
    double x = std::ldexp(static_cast<double>(significand), exponent);
    if (rng() & 1) x = -x;
    for (int digits : {1, 6, 17}) {
      char expected[64];
      std::snprintf(expected, sizeof expected, "%.*g", digits, x);
      const std::string got = to_decimal(Exact(x), digits).text;
      BOOST_TEST(got == expected, "seed " << seed << ", case " << k << ": " << std::hexfloat << x << " to "
                                          << digits << " digits: " << got << ", printf " << expected);
    }
    BOOST_TEST(*tmcert::nearest_double(Exact(x)) == x, "seed " << seed << ", case " << k);
    BOOST_TEST(tmcert::approximation(Exact(x)) == tmcert::shortest(x), "seed " << seed << ", case " << k);
  }
}

// Messages that compare values (joint limits): decimals, never a bare p/q.
BOOST_AUTO_TEST_CASE(decimal_text_for_messages) {
  BOOST_TEST(tmcert::decimal_text(q("7/2")) == "3.5");
  BOOST_TEST(tmcert::decimal_text(q("-2.8973")) == "-2.8973");
  BOOST_TEST(tmcert::decimal_text(q("0")) == "0");
  // A double is its shortest round-trip decimal, marked as a double.
  BOOST_TEST(tmcert::decimal_text(Exact(-44.9775)) == "-44.9775 (a double)");
  BOOST_TEST(tmcert::decimal_text(Exact(0.1)) == "0.1 (a double)");
  BOOST_TEST(tmcert::decimal_text(Exact(0.25)) == "0.25");  // exactly a short decimal
  BOOST_TEST(tmcert::decimal_text(q("1/3")) == "about 0.33333333333333333");
}

BOOST_AUTO_TEST_SUITE_END()
