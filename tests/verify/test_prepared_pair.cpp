// src/verify/prepared_pair: one check of two bodies prepared beforehand.
// The result names the ids given, finds the first contact exactly, and a
// window searches only its part of the interval.
#include "src/verify/prepared_pair.h"
#include "src/verify/prepared.h"
#include "tests/verify/check_testing.h"

#include <boost/test/unit_test.hpp>

using namespace tmcert;
using tmcert::testing::two_cubes;

namespace {

VerifyOptions options() {
  VerifyOptions o;
  o.epsilon = Exact(1, 1000);
  return o;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(prepared_pair)

BOOST_AUTO_TEST_CASE(first_contact_with_the_ids_given) {
  // The mover's face x = -1/2 + (-3 + 6t) meets the post's x = -1/2 at t = 1/3.
  const Scene scene = two_cubes("-3 0 0", "3 0 0");
  const PreparedBody mover(scene.bodies[0]), post(scene.bodies[1]);
  const CheckResult r = detail::check_prepared_pair(mover, post, {7, 9}, Exact(0), options());
  BOOST_TEST((r.verdict == Verdict::Collision));
  BOOST_TEST(r.bodies[0] == 7);
  BOOST_TEST(r.bodies[1] == 9);
  BOOST_REQUIRE(r.witness);
  BOOST_TEST(r.witness->t == Exact(1, 3));
  BOOST_TEST(!r.witness->root);
  BOOST_TEST(r.witness->point[0] == Exact(-1, 2));
}

BOOST_AUTO_TEST_CASE(passing_by_is_safe) {
  const Scene scene = two_cubes("-3 3 0", "3 3 0");
  const PreparedBody mover(scene.bodies[0]), post(scene.bodies[1]);
  const CheckResult r = detail::check_prepared_pair(mover, post, {0, 1}, Exact(0), options());
  BOOST_TEST((r.verdict == Verdict::Safe));
  BOOST_TEST(!r.witness);
  BOOST_TEST(r.undecided.empty());
}

BOOST_AUTO_TEST_CASE(window_searches_only_its_part) {
  const Scene scene = two_cubes("-3 0 0", "3 0 0");
  const PreparedBody mover(scene.bodies[0]), post(scene.bodies[1]);
  // Before the contact: safe on [0, 1/4].
  const CheckResult before = detail::check_prepared_pair(mover, post, {0, 1}, Exact(0), options(), false,
                                                         std::pair<Exact, Exact>{Exact(0), Exact(1, 4)});
  BOOST_TEST((before.verdict == Verdict::Safe));
  // Across it: the same first contact.
  const CheckResult across = detail::check_prepared_pair(mover, post, {0, 1}, Exact(0), options(), false,
                                                         std::pair<Exact, Exact>{Exact(1, 4), Exact(1, 2)});
  BOOST_TEST((across.verdict == Verdict::Collision));
  BOOST_REQUIRE(across.witness);
  BOOST_TEST(across.witness->t == Exact(1, 3));
}

BOOST_AUTO_TEST_CASE(clearance_counts_a_near_pass) {
  // The mover passes the post at a gap of 1/4 (its faces y = 3/4 and y = 1/2):
  // safe without a clearance, not safe with a clearance of 1/2.
  const Scene scene = two_cubes("-3 1.25 0", "3 1.25 0");
  const PreparedBody mover(scene.bodies[0]), post(scene.bodies[1]);
  const CheckResult free = detail::check_prepared_pair(mover, post, {0, 1}, Exact(0), options());
  BOOST_TEST((free.verdict == Verdict::Safe));
  const CheckResult near = detail::check_prepared_pair(mover, post, {0, 1}, Exact(1, 2), options());
  BOOST_TEST((near.verdict != Verdict::Safe));
  BOOST_TEST(near.clearance == Exact(1, 2));
}

BOOST_AUTO_TEST_SUITE_END()
