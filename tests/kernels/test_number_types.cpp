// The number-type helpers: the fast rational-to-interval enclosure gives
// exactly CGAL's (MPFR-rounded) interval, and ExactSum sums exactly.
#include "kernels/number_types.h"

#include <boost/test/unit_test.hpp>

#include <random>
#include <string>

using namespace tmcert;

BOOST_AUTO_TEST_SUITE(number_types)

BOOST_AUTO_TEST_CASE(to_interval_equals_the_mpfr_rounded_interval) {
  std::mt19937_64 gen(20261123);
  std::vector<Exact> values = {Exact(1, 3), Exact(-1, 3), Exact(1, 10), Exact(5, 8), Exact(-7), Exact(1, 1 << 30),
                               Exact(0)};
  Exact big;
  BOOST_REQUIRE(parse_exact("1e400", big));
  values.push_back(big);
  values.push_back(-big);
  BOOST_REQUIRE(parse_exact("1e-400", big));  // below the subnormal range
  values.push_back(big);
  BOOST_REQUIRE(parse_exact("3e-310", big));  // subnormal
  values.push_back(big);
  BOOST_REQUIRE(parse_exact("179769313486231570814527423731704356798070567525844996598917476803157260780028538760589558632766878171540458953514382464234321326889464182768467546703537516986049910576551282076245490090389328944075868508455133942304583236903222948165808559332123348274797826204144723168738177180919299881250404026184124858368", big));
  values.push_back(big);  // DBL_MAX exactly
  values.push_back(big + 1);
  for (int i = 0; i < 20000; ++i) {
    const long num = static_cast<long>(gen() >> (gen() % 64)) * (gen() % 2 ? 1 : -1);
    const long den = static_cast<long>((gen() >> (gen() % 64)) | 1);
    values.push_back(Exact(num, den));
    values.push_back(Exact(static_cast<double>(num) / 1024.0));  // dyadic values
  }
  for (const Exact& q : values) {
    const Interval fast = to_interval(q);
    const Interval ref(CGAL::to_interval(q));
    BOOST_TEST_REQUIRE((fast.inf() == ref.inf() && fast.sup() == ref.sup()), "q = " << to_string(q));
  }
}

BOOST_AUTO_TEST_CASE(exact_sum_is_the_rational_sum) {
  std::mt19937 gen(7);
  ExactSum sum;
  Exact reference = 0;
  for (int i = 0; i < 3000; ++i) {
    const int num = static_cast<int>(gen() % 2001) - 1000;
    const int den = i % 3 == 0 ? 1000 : static_cast<int>(gen() % 97) + 1;  // mostly new denominators
    sum.add(Exact(num, den));
    reference += Exact(num, den);
  }
  BOOST_TEST(sum.value() == reference);
  ExactSum empty;
  BOOST_TEST(empty.value() == Exact(0));
}

BOOST_AUTO_TEST_SUITE_END()
