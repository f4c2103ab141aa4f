// Generated continuous-collision queries with ground truth by construction
// (bench/ccd_queries.h): vertex-face and edge-edge, both primitives moving
// linearly, with degenerate kinds (grazing, coplanar, parallel, contact at
// t = 0 and t = 1, tunneling, collapsing triangles, shrinking segments).
#include "bench/ccd_queries.h"
#include "src/verify/verify.h"

#include <boost/test/unit_test.hpp>

#include <cstdlib>

using namespace tmcert;

BOOST_AUTO_TEST_SUITE(ccd_queries)

BOOST_AUTO_TEST_CASE(no_false_verdicts_and_certified_brackets) {
  const char* env = std::getenv("TMCERT_SEED");
  const unsigned seed = env ? static_cast<unsigned>(std::strtoul(env, nullptr, 10)) : 2026;
  BOOST_TEST_MESSAGE("seed " << seed << " (replay: TMCERT_SEED=" << seed << ")");
  bench::QueryGenerator generator(seed);
  const bench::QuerySet set = generator.generate(800);
  for (const KernelKind kernel : {KernelKind::Filtered, KernelKind::Exact}) {
    VerifyOptions options;
    options.kernel = kernel;
    options.epsilon = Exact(2, 1000000);  // 1e-6 of the coordinate range
    options.max_depth = 60;
    const Verifier verifier(set.scene, options);
    int free = 0, undecided_free = 0, collisions = 0;
    const std::size_t n = kernel == KernelKind::Exact ? set.queries.size() / 4 : set.queries.size();
    for (std::size_t i = 0; i < n; ++i) {
      const bench::Query& q = set.queries[i];
      const CheckResult r = verifier.check(q.body_a, q.body_b);
      BOOST_TEST_CONTEXT("query " << i << " (" << q.kind << "), kernel " << to_string(kernel)) {
        if (q.collides) {
          // Exact resolution: every colliding linear query is proven.
          BOOST_TEST(r.verdict == Verdict::Collision);
          if (q.contact_time && r.first_contact) BOOST_TEST(r.first_contact->first <= *q.contact_time);
        } else {
          ++free;
          BOOST_TEST(r.verdict != Verdict::Collision);
          if (r.verdict == Verdict::Undecided) ++undecided_free;
        }
        if (r.verdict == Verdict::Collision) {
          ++collisions;
          BOOST_TEST(r.witness.has_value());
          // Nothing was left undecided before it: the first contact is exact.
          BOOST_TEST(r.first_contact_exact);
          if (r.witness->root) {  // an irrational time: the bracket is its isolating interval
            BOOST_TEST(r.first_contact->first == r.witness->root->lo);
            BOOST_TEST(r.first_contact->second == r.witness->root->hi);
            if (q.contact_time) BOOST_TEST(r.witness->root->lo < *q.contact_time);
          } else {
            BOOST_TEST(r.first_contact->first == r.witness->t);
            BOOST_TEST(r.first_contact->second == r.witness->t);
            if (q.contact_time) BOOST_TEST(r.witness->t <= *q.contact_time);
          }
        }
      }
    }
    // Non-colliding queries are decided exactly: none undecided.
    BOOST_TEST(undecided_free == 0);
    BOOST_TEST(collisions > 0);  // witnesses are found for interpenetrations and dyadic contacts
  }
}

BOOST_AUTO_TEST_SUITE_END()
