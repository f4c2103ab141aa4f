// --threads: the pieces of one check run as tasks on several threads, and
// the result (verdict, witness, first-contact bracket, undecided pieces and
// the work statistics) is the same for every thread count, also when the
// node budget runs out (proofs/search-and-pruning.md).
#include "src/scene/parse.h"
#include "src/verify/verify.h"

#include <boost/test/unit_test.hpp>

#include <string>

using namespace tmcert;

namespace {

const std::string kExamples = std::string(TMCERT_TEST_DATA) + "/../../examples/";

void require_same(const CheckResult& a, const CheckResult& b, const std::string& what) {
  BOOST_TEST_INFO(what);
  BOOST_TEST(to_string(a.verdict) == to_string(b.verdict));
  BOOST_TEST(a.first_contact.has_value() == b.first_contact.has_value());
  if (a.first_contact && b.first_contact) {
    BOOST_TEST(to_string(a.first_contact->first) == to_string(b.first_contact->first));
    BOOST_TEST(to_string(a.first_contact->second) == to_string(b.first_contact->second));
  }
  BOOST_TEST(a.witness.has_value() == b.witness.has_value());
  if (a.witness && b.witness) {
    BOOST_TEST(to_string(a.witness->t) == to_string(b.witness->t));
    BOOST_TEST((a.witness->point == b.witness->point));
    BOOST_TEST((a.witness->features == b.witness->features));
  }
  BOOST_TEST_REQUIRE(a.undecided.size() == b.undecided.size());
  for (std::size_t i = 0; i < a.undecided.size(); ++i) {
    BOOST_TEST(to_string(a.undecided[i].t0) == to_string(b.undecided[i].t0));
    BOOST_TEST(to_string(a.undecided[i].t1) == to_string(b.undecided[i].t1));
    BOOST_TEST(to_string(a.undecided[i].reason) == to_string(b.undecided[i].reason));
  }
  BOOST_TEST(a.stats.nodes == b.stats.nodes);
  BOOST_TEST(a.stats.max_depth == b.stats.max_depth);
  BOOST_TEST(a.stats.contact.calls == b.stats.contact.calls);
  BOOST_TEST(a.stats.sphere_tests == b.stats.sphere_tests);
  BOOST_TEST(a.stats.static_tests == b.stats.static_tests);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(threads)

BOOST_AUTO_TEST_CASE(the_result_does_not_depend_on_the_thread_count) {
  for (const char* name : {"vertex-face-linear.json", "octagons-collision.json", "gripper/gripper-collision.json"}) {
    const Scene scene = parse_scene_file(kExamples + name);
    for (const std::uint64_t budget : {std::uint64_t(2'000'000), std::uint64_t(40), std::uint64_t(12)}) {
      VerifyOptions options;
      options.epsilon = scene.epsilon ? *scene.epsilon : default_epsilon(scene);
      options.max_depth = scene.max_depth;
      options.max_nodes = budget;
      const SceneResult one = verify_scene(scene, options, 1);
      // Deep enough for tasks below depth 5 (else the test would not test them).
      if (budget > 1000) BOOST_TEST_REQUIRE(one.checks[0].stats.max_depth >= 5);
      for (const int n : {2, 3, 8}) {
        const SceneResult many = verify_scene(scene, options, n);
        BOOST_TEST(to_string(one.verdict) == to_string(many.verdict));
        require_same(one.checks[0], many.checks[0],
                     std::string(name) + ", budget " + std::to_string(budget) + ", " + std::to_string(n) + " threads");
      }
    }
  }
}

// With a budget that runs out, the undecided "limit" pieces are those of
// the sequential search: nothing is cleared or witnessed past the budget.
BOOST_AUTO_TEST_CASE(a_small_node_budget_ends_undecided_with_limit_pieces) {
  const Scene scene = parse_scene_file(kExamples + "octagons-collision.json");
  VerifyOptions options;
  options.epsilon = *scene.epsilon;
  options.max_depth = scene.max_depth;
  options.max_nodes = 12;
  const SceneResult r = verify_scene(scene, options, 4);
  BOOST_TEST(to_string(r.verdict) == "undecided");
  bool limit = false;
  for (const UndecidedInterval& u : r.checks[0].undecided) limit = limit || u.reason == StopReason::Limit;
  BOOST_TEST(limit);
  BOOST_TEST(r.checks[0].stats.nodes <= 12u);
}

BOOST_AUTO_TEST_SUITE_END()
