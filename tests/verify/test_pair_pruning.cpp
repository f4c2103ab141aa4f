// A check's pruning of its live pairs on one piece
// (src/verify/pair_pruning.h): the root pairs with and without the
// hierarchy, the expansion of node pairs into the feature pairs of all
// pairs, the pruning of a piece that clears every pair or keeps the
// touching ones, and the carry decision's shortfall
// (proofs/search-and-pruning.md, proofs/hierarchy.md).
#include "src/verify/pair_pruning.h"
#include "tests/verify/check_testing.h"

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <tuple>

using namespace tmcert;
using namespace tmcert::testing;

namespace {
std::vector<std::tuple<int, std::uint32_t, std::uint32_t>> keys(const std::vector<detail::PairRef>& pairs) {
  std::vector<std::tuple<int, std::uint32_t, std::uint32_t>> out;
  for (const detail::PairRef& p : pairs) out.emplace_back(static_cast<int>(p.kind), p.i, p.j);
  std::sort(out.begin(), out.end());
  return out;
}
}  // namespace

BOOST_AUTO_TEST_SUITE(verify_pair_pruning)

BOOST_AUTO_TEST_CASE(root_pairs_and_their_expansion_are_all_pairs) {
  CheckFixture f(two_cubes("-3 0 0", "3 0 0"));
  auto check = f.check();
  std::vector<detail::PairRef> roots = check.root_pairs();
  BOOST_REQUIRE(roots.size() == 1u);
  BOOST_TEST(roots[0].nodes);
  check.expand_untested(roots, 0);
  BOOST_TEST(std::none_of(roots.begin(), roots.end(), [](const detail::PairRef& p) { return p.nodes; }));
  f.options.hierarchy = false;
  const std::vector<detail::PairRef> all = check.root_pairs();
  BOOST_TEST(std::none_of(all.begin(), all.end(), [](const detail::PairRef& p) { return p.nodes; }));
  BOOST_TEST((keys(roots) == keys(all)));
  BOOST_TEST(!all.empty());
}

BOOST_AUTO_TEST_CASE(prune_clears_a_piece_far_from_the_post_and_keeps_a_touching_one) {
  for (const bool hierarchy : {true, false}) {
    // The mover stays 3 to 4 away from the post: every pair cleared on the
    // whole motion.
    CheckFixture far(two_cubes("4 0 0", "5 0 0"));
    far.options.hierarchy = hierarchy;
    auto check = far.check();
    const detail::FilteredPolicy<1> policy{far.moving, far.other, far.moving.curve, 0};
    decltype(check)::Spheres<detail::FilteredPolicy<1>> spheres(far.moving, far.other);
    auto piece = policy.root();
    std::optional<detail::FilteredPolicy<1>::Ball> ball;
    auto get_ball = [&]() -> detail::FilteredPolicy<1>::Ball& {
      if (!ball) ball.emplace(policy.ball(piece));
      return *ball;
    };
    std::vector<detail::PairRef> alive = check.root_pairs();
    check.prune(policy, get_ball, piece, alive, false, spheres, 0);
    BOOST_TEST(alive.empty(), "hierarchy " << hierarchy);
    // Through the post: pairs stay alive on the whole motion.
    CheckFixture through(two_cubes("-3 0 0", "3 0 0"));
    through.options.hierarchy = hierarchy;
    auto c2 = through.check();
    const detail::FilteredPolicy<1> p2{through.moving, through.other, through.moving.curve, 0};
    decltype(c2)::Spheres<detail::FilteredPolicy<1>> s2(through.moving, through.other);
    auto piece2 = p2.root();
    std::optional<detail::FilteredPolicy<1>::Ball> ball2;
    auto get_ball2 = [&]() -> detail::FilteredPolicy<1>::Ball& {
      if (!ball2) ball2.emplace(p2.ball(piece2));
      return *ball2;
    };
    std::vector<detail::PairRef> alive2 = c2.root_pairs();
    c2.prune(p2, get_ball2, piece2, alive2, true, s2, 0);
    BOOST_TEST(!alive2.empty(), "hierarchy " << hierarchy);
    BOOST_TEST(std::none_of(alive2.begin(), alive2.end(), [](const detail::PairRef& p) { return p.nodes; }));
    BOOST_TEST(through.result.stats.sphere_tests + through.result.stats.hull_clears > 0u);
  }
}

BOOST_AUTO_TEST_CASE(carry_shortfall_is_twice_the_log_of_fattening_over_gap) {
  SlabTest s;
  s.gap = 1;
  s.fat = 0.5;
  BOOST_TEST(detail::carry_shortfall(s) == 1);  // no shortfall
  s.fat = 4;
  BOOST_TEST(detail::carry_shortfall(s) == 5);  // 1 + 2 log2 4
  s.fat = 1e300;
  s.gap = 1e-300;
  BOOST_TEST(detail::carry_shortfall(s) == 255);  // clamped
}

BOOST_AUTO_TEST_SUITE_END()
