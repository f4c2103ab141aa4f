// src/verify/search_check: a node's piece of the curve parameter
// [index, index + 1] / 2^depth, and merge_result, which appends the result
// of the range right after everything merged so far: statistics add up,
// abutting undecided intervals of the same reason join, the first-contact
// bracket is the earliest, and a witness ends the merge.
#include "src/verify/search_check.h"

#include <boost/test/unit_test.hpp>

using namespace tmcert;
using namespace tmcert::detail;

namespace {

CheckResult undecided(const Exact& a, const Exact& b, StopReason why) {
  CheckResult r;
  r.verdict = Verdict::Undecided;
  r.undecided.push_back({a, b, why});
  r.first_contact = std::pair{a, b};
  r.stats.nodes = 2;
  r.stats.stops = 1;
  r.stats.max_depth = 3;
  return r;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(search_check)

BOOST_AUTO_TEST_CASE(node_pieces_are_dyadic) {
  const Node n{5, 3, {}};
  BOOST_TEST(n.u0() == Exact(5, 8));
  BOOST_TEST(n.u1() == Exact(6, 8));
  BOOST_TEST(n.mid() == Exact(11, 16));
  BOOST_TEST(n.at(8) == Exact(1));
  const Node deep{(std::uint64_t{1} << kDepthCap) - 1, kDepthCap, {}};
  BOOST_TEST(deep.u1() == Exact(1));
  BOOST_TEST(deep.u0() < deep.u1());
  Exact width = 1;
  for (int k = 0; k < kDepthCap; ++k) width /= 2;
  BOOST_TEST(deep.u1() - deep.u0() == width);
}

BOOST_AUTO_TEST_CASE(undecided_intervals_join_where_they_abut_with_one_reason) {
  CheckResult total;
  BOOST_TEST(merge_result(total, undecided(0, Exact(1, 4), StopReason::Epsilon)));
  BOOST_TEST(merge_result(total, undecided(Exact(1, 4), Exact(1, 2), StopReason::Epsilon)));  // joins
  BOOST_TEST(merge_result(total, undecided(Exact(1, 2), Exact(5, 8), StopReason::Depth)));    // other reason
  BOOST_TEST(merge_result(total, undecided(Exact(3, 4), Exact(1), StopReason::Depth)));       // a gap
  BOOST_REQUIRE(total.undecided.size() == 3u);
  BOOST_TEST(total.undecided[0].t0 == 0);
  BOOST_TEST(total.undecided[0].t1 == Exact(1, 2));
  BOOST_TEST(total.undecided[1].t1 == Exact(5, 8));
  BOOST_TEST(total.undecided[2].t0 == Exact(3, 4));
  // Statistics add up (the deepest level is the maximum); the bracket is the first one.
  BOOST_TEST(total.stats.nodes == 8u);
  BOOST_TEST(total.stats.stops == 4u);
  BOOST_TEST(total.stats.max_depth == 3);
  BOOST_REQUIRE(total.first_contact);
  BOOST_TEST(total.first_contact->first == 0);
  BOOST_TEST(total.first_contact->second == Exact(1, 4));
  BOOST_TEST(!total.witness);
}

BOOST_AUTO_TEST_CASE(witness_ends_the_merge_and_keeps_the_earliest_bracket) {
  CheckResult total;
  BOOST_TEST(merge_result(total, undecided(Exact(1, 8), Exact(1, 4), StopReason::Epsilon)));
  CheckResult hit;
  Witness w;
  w.t = Exact(3, 8);
  w.features = {"a", "b"};
  w.point = {0, 0, 0};
  hit.witness = w;
  hit.first_contact = std::pair{Exact(3, 8), Exact(3, 8)};
  hit.first_contact_exact = true;
  BOOST_TEST(!merge_result(total, hit));
  BOOST_TEST((total.verdict == Verdict::Collision));
  BOOST_REQUIRE(total.witness);
  BOOST_TEST(total.witness->t == Exact(3, 8));
  // The bracket spans from the undecided part's start to the witness.
  BOOST_TEST(total.first_contact->first == Exact(1, 8));
  BOOST_TEST(total.first_contact->second == Exact(3, 8));
  BOOST_TEST(!total.first_contact_exact);  // something undecided came before it
  // Alone, the witness's bracket is exact.
  CheckResult alone;
  BOOST_TEST(!merge_result(alone, hit));
  BOOST_TEST(alone.first_contact_exact);
}

BOOST_AUTO_TEST_SUITE_END()
