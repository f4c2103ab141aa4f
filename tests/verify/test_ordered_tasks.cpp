// The ordered search (src/verify/ordered_tasks.h): node parameters, the
// merge of results in parameter order (abutting undecided intervals of one
// reason joined, a witness ends it), the node budget's "limit" stop, and a
// result that does not depend on the number of threads
// (proofs/search-and-pruning.md).
#include "src/verify/ordered_tasks.h"
#include "tests/verify/check_testing.h"

#include <boost/test/unit_test.hpp>

using namespace tmcert;
using namespace tmcert::testing;

BOOST_AUTO_TEST_SUITE(verify_ordered_tasks)

BOOST_AUTO_TEST_CASE(node_parameters_are_dyadic) {
  const detail::Node n{5, 3, {}};
  BOOST_TEST(n.u0() == Exact(5, 8));
  BOOST_TEST(n.u1() == Exact(6, 8));
  BOOST_TEST(n.mid() == Exact(11, 16));
  const detail::Node deep{(std::uint64_t(1) << 61) + 1, 62, {}};
  BOOST_TEST(deep.u0() == Exact(1, 2) + Exact(1, CGAL::Gmpz("4611686018427387904")));
}

BOOST_AUTO_TEST_CASE(merge_joins_abutting_intervals_and_stops_at_a_witness) {
  CheckResult total;
  CheckResult a;
  a.stats.nodes = 3;
  a.undecided.push_back({Exact(0), Exact(1, 4), StopReason::Epsilon});
  a.first_contact = std::pair{Exact(0), Exact(1, 4)};
  BOOST_TEST(detail::merge_result(total, a));
  CheckResult b;
  b.stats.nodes = 2;
  b.undecided.push_back({Exact(1, 4), Exact(1, 2), StopReason::Epsilon});
  b.undecided.push_back({Exact(1, 2), Exact(3, 4), StopReason::Limit});
  BOOST_TEST(detail::merge_result(total, b));
  BOOST_REQUIRE(total.undecided.size() == 2u);
  BOOST_TEST(total.undecided[0].t1 == Exact(1, 2));
  BOOST_TEST((total.undecided[1].reason == StopReason::Limit));
  BOOST_TEST(total.stats.nodes == 5u);
  CheckResult w;
  w.witness = Witness{Exact(7, 8), {"a", "b"}, Vec3E{Exact(0), Exact(0), Exact(0)}};
  w.first_contact = std::pair{Exact(3, 4), Exact(7, 8)};
  w.first_contact_exact = true;
  BOOST_TEST(!detail::merge_result(total, w));
  BOOST_TEST((total.verdict == Verdict::Collision));
  // The bracket starts at the first undecided time before the witness.
  BOOST_TEST(total.first_contact->first == Exact(0));
  BOOST_TEST(total.first_contact->second == Exact(7, 8));
  BOOST_TEST(!total.first_contact_exact);
}

BOOST_AUTO_TEST_CASE(node_budget_records_limit) {
  CheckFixture f(two_cubes("-3 0.9 0", "3 0.9 0"));
  f.options.max_nodes = 3;
  auto check = f.check();
  check.search(detail::FilteredPolicy<1>{f.moving, f.other, f.moving.curve, 0});
  BOOST_TEST(f.result.stats.nodes <= 3u);
  BOOST_REQUIRE(!f.result.undecided.empty());
  BOOST_TEST((f.result.undecided.back().reason == StopReason::Limit));
}

BOOST_AUTO_TEST_CASE(the_result_does_not_depend_on_threads) {
  auto run = [](int threads) {
    CheckFixture f(two_cubes("-3 0.9 0.2", "3 1.2 -0.1"));
    f.options.threads = threads;
    auto check = f.check();
    check.search(detail::FilteredPolicy<1>{f.moving, f.other, f.moving.curve, 0});
    return std::tuple{f.result.stats.nodes, f.result.witness ? f.result.witness->t : Exact(-1), f.result.undecided.size(),
                      f.result.stats.stops};
  };
  const auto one = run(1);
  BOOST_TEST(std::get<0>(one) > 1u);
  BOOST_TEST((run(3) == one));
}

BOOST_AUTO_TEST_SUITE_END()
