// The start check and the partition (src/verify/search.h): a contact at the
// start is the witness at t0 with an exact bracket; a separated start lets
// the search clear the motion; a witness later ends the claims there.
#include "tests/verify/check_testing.h"

#include <boost/test/unit_test.hpp>

using namespace tmcert;
using namespace tmcert::testing;

BOOST_AUTO_TEST_SUITE(verify_search)

BOOST_AUTO_TEST_CASE(contact_at_the_start_is_the_witness_at_t0) {
  CheckFixture f(two_cubes("0.5 0 0", "3 0 0"));
  f.check().run();
  BOOST_REQUIRE(f.result.witness);
  BOOST_TEST(f.result.witness->t == Exact(0));
  BOOST_TEST(f.result.first_contact_exact);
  BOOST_TEST(f.result.stats.nodes == 0u);
}

BOOST_AUTO_TEST_CASE(a_separated_motion_is_cleared_entirely) {
  CheckFixture f(two_cubes("2 0 0", "5 0 0"));
  f.options.record_cover = true;
  f.check().run();
  BOOST_TEST(!f.result.witness);
  BOOST_TEST(f.result.undecided.empty());
  BOOST_TEST(!f.result.cleared.empty());
}

BOOST_AUTO_TEST_CASE(the_first_contact_is_bracketed_before_the_witness) {
  CheckFixture f(two_cubes("-3 0 0", "3 0 0"));
  f.check().run();
  BOOST_REQUIRE(f.result.witness);
  BOOST_REQUIRE(f.result.first_contact);
  // Contact begins at t = 1/3: the bracket holds it.
  BOOST_TEST(f.result.first_contact->first <= Exact(1, 3));
  BOOST_TEST(f.result.first_contact->second >= Exact(1, 3));
  BOOST_TEST(f.result.witness->t >= Exact(1, 3));
  BOOST_TEST(f.result.witness->t <= Exact(2, 3));
}

BOOST_AUTO_TEST_SUITE_END()
