// A check's tests at one curve parameter (src/verify/witness_search.h): the
// static test under the curve's poses, the witnesses a stop tries (common
// point, a vertex inside a solid, the closest pair within a clearance) and
// the apartness of the whole configuration (proofs/witness.md,
// proofs/containment.md, proofs/partition.md).
#include "src/verify/witness_search.h"
#include "tests/verify/check_testing.h"

#include <boost/test/unit_test.hpp>

using namespace tmcert;
using namespace tmcert::testing;

BOOST_AUTO_TEST_SUITE(verify_witness_search)

// The mover (side 1) goes from x = -3 to x = 3 through the post (side 1):
// they touch from x = -1 (u = 1/3) to x = 1 (u = 2/3).
BOOST_AUTO_TEST_CASE(static_test_follows_the_curve) {
  CheckFixture f(two_cubes("-3 0 0", "3 0 0"));
  auto check = f.check();
  BOOST_TEST(!check.static_test(Exact(0), nullptr));
  BOOST_TEST(!check.static_test(Exact(1, 3) - Exact(1, 1000000), nullptr));
  BOOST_TEST(check.static_test(Exact(1, 3), nullptr).has_value());  // faces touch
  BOOST_TEST(check.static_test(Exact(1, 2), nullptr).has_value());
  BOOST_TEST(!check.static_test(Exact(1), nullptr));
  BOOST_TEST(f.result.stats.static_configurations == 5u);
}

BOOST_AUTO_TEST_CASE(try_witness_sets_the_witness_at_u) {
  CheckFixture f(two_cubes("-3 0 0", "3 0 0"));
  auto check = f.check();
  const std::vector<detail::PairRef> all = check.root_pairs();
  BOOST_TEST(!check.try_witness(Exact(1, 4), all));
  BOOST_TEST(!f.result.witness);
  BOOST_REQUIRE(check.try_witness(Exact(1, 2), all));
  BOOST_REQUIRE(f.result.witness);
  BOOST_TEST(f.result.witness->t == Exact(1, 2));  // scene time = u on [0, 1]
  BOOST_TEST((f.result.verdict == Verdict::Collision));
  // The point is in both cubes at t = 1/2 (the mover at the origin).
  for (int c = 0; c < 3; ++c) {
    BOOST_TEST(f.result.witness->point[c] >= Exact(-1, 2));
    BOOST_TEST(f.result.witness->point[c] <= Exact(1, 2));
  }
}

BOOST_AUTO_TEST_CASE(a_vertex_inside_a_solid_is_contact) {
  // A small solid cube sits inside the big solid post at t = 1/2 without
  // any surface contact: only the inside finds it.
  Scene s = two_cubes("-10 0 0", "10 0 0", "-3", "3", true);
  CheckFixture f(std::move(s));
  auto check = f.check();
  BOOST_TEST(!check.static_test(Exact(1, 2), nullptr));
  BOOST_TEST((check.interior_witness(Exact(1, 2)) == detail::Apartness::Contact));
  BOOST_REQUIRE(f.result.witness);
  BOOST_TEST(f.result.witness->features[1] == "post interior");
  CheckFixture g(two_cubes("-10 0 0", "10 0 0", "-3", "3", true));
  auto far = g.check();
  BOOST_TEST((far.interior_witness(Exact(0)) == detail::Apartness::Free));
  BOOST_TEST((far.free_at(Exact(1, 2)) == detail::Apartness::Contact));
}

BOOST_AUTO_TEST_CASE(distance_witness_needs_the_clearance) {
  // The mover passes 1/10 above the post (y offset 1 + 1/10).
  CheckFixture f(two_cubes("-3 1.1 0", "3 1.1 0"));
  auto check = f.check();
  BOOST_TEST(!check.distance_witness(Exact(1, 2), nullptr));  // no clearance asked
  check.extras.clearance2 = Exact(1, 100);                    // clearance exactly 1/10
  BOOST_REQUIRE(check.distance_witness(Exact(1, 2), nullptr));
  BOOST_REQUIRE(f.result.witness);
  BOOST_REQUIRE(f.result.witness->points);
  const auto& p = *f.result.witness->points;
  Exact d2 = 0;
  for (int c = 0; c < 3; ++c) d2 += (p[0][c] - p[1][c]) * (p[0][c] - p[1][c]);
  BOOST_TEST(d2 == Exact(1, 100));
  CheckFixture g(two_cubes("-3 1.1 0", "3 1.1 0"));
  auto tight = g.check();
  tight.extras.clearance2 = Exact(1, 100) - Exact(1, 1000000);
  BOOST_TEST(!tight.distance_witness(Exact(1, 2), nullptr));
}

BOOST_AUTO_TEST_SUITE_END()
