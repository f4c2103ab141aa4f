// kernels/uncertain.h: the sign of an interval is certain only when the
// interval decides it, and the certain questions never take an undecided
// sign for a decided one.
#include "kernels/uncertain.h"

#include <boost/test/unit_test.hpp>

#include <limits>

using tmcert::Interval;
using tmcert::UncertainSign;

BOOST_AUTO_TEST_SUITE(uncertain_sign)

BOOST_AUTO_TEST_CASE(certain_only_when_the_interval_decides) {
  BOOST_TEST(tmcert::certainly_is(tmcert::uncertain_sign(Interval(1, 2)), CGAL::POSITIVE));
  BOOST_TEST(tmcert::certainly_is(tmcert::uncertain_sign(Interval(-2, -1)), CGAL::NEGATIVE));
  BOOST_TEST(tmcert::certainly_is(tmcert::uncertain_sign(Interval(0)), CGAL::ZERO));
  for (const Interval& x : {Interval(-1, 1), Interval(0, 1), Interval(-1, 0)}) {
    const UncertainSign s = tmcert::uncertain_sign(x);
    BOOST_TEST(!s.is_certain());
    BOOST_TEST(!tmcert::certainly_is(s, CGAL::ZERO));
    BOOST_TEST(!tmcert::certainly_not(s, CGAL::ZERO));
  }
  // An undecided sign may be anything (as CGAL's sign of an interval):
  // even [0, 1] is not taken as certainly not negative.
  BOOST_TEST(!tmcert::certainly_not(tmcert::uncertain_sign(Interval(0, 1)), CGAL::NEGATIVE));
  BOOST_TEST(!tmcert::certainly_not(tmcert::uncertain_sign(Interval(-1, 1)), CGAL::NEGATIVE));
  BOOST_TEST(tmcert::certainly_not(tmcert::uncertain_sign(Interval(1, 2)), CGAL::ZERO));
  BOOST_TEST(tmcert::certainly_not(tmcert::uncertain_sign(Interval(1, 2)), CGAL::NEGATIVE));
}

BOOST_AUTO_TEST_CASE(nan_bounds_are_undecided) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const UncertainSign s = tmcert::uncertain_sign(Interval(nan, nan));
  BOOST_TEST(!s.is_certain());
  BOOST_TEST(!tmcert::certainly_not(s, CGAL::ZERO));
}

BOOST_AUTO_TEST_SUITE_END()
