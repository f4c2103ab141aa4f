// The certified prefilter (swept boxes and separating axes between the hulls
// of swept vertex images) and the node budget: neither may ever turn into a
// false "safe".
#include "bench/ccd_queries.h"
#include "src/verify/prepared.h"
#include "src/verify/verify.h"

#include <boost/test/unit_test.hpp>

#include <random>

using namespace tmcert;

namespace {

// The body placed at curve parameter u, exactly, as simplices.
std::vector<Simplex> placed(const Body& body, const Exact& u) {
  const PreparedBody p(body);
  const Mat34E m = body.motion ? evaluate<1>(homogeneous_curve(*body.motion), u) : Mat34E{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
  std::vector<Simplex> out;
  for (const StaticPart& part : transformed_parts(p, m)) out.insert(out.end(), part.simplices.begin(), part.simplices.end());
  return out;
}

bool touch_at(const Body& a, const Body& b, const Exact& u) {
  for (const Simplex& s : placed(a, u))
    for (const Simplex& t : placed(b, u))
      if (common_point(s, t)) return true;
  return false;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(prefilter)

// Whenever the prefilter claims "never touch", no sampled parameter (and no
// generated contact time) shows a contact; and it does clear a good share.
BOOST_AUTO_TEST_CASE(disjoint_hulls_never_touch) {
  bench::QueryGenerator generator(99);
  const bench::QuerySet set = generator.generate(600);
  int cleared = 0;
  for (const bench::Query& q : set.queries) {
    const Body& a = set.scene.bodies[q.body_a];
    const Body& b = set.scene.bodies[q.body_b];
    if (!disjoint(swept_box(a), swept_box(b))) continue;
    ++cleared;
    BOOST_TEST_CONTEXT(q.kind) {
      BOOST_TEST(!q.collides);
      for (int k = 0; k <= 8; ++k) BOOST_TEST(!touch_at(a, b, Exact(k, 8)));
    }
  }
  BOOST_TEST(cleared > 100);
}

BOOST_AUTO_TEST_CASE(touching_bodies_are_never_prefiltered) {
  // Every generated contact (built at a known time) must pass the filter.
  bench::QueryGenerator generator(5);
  const bench::QuerySet set = generator.generate(600);
  int contacts = 0;
  for (const bench::Query& q : set.queries) {
    if (!q.contact_time) continue;
    ++contacts;
    BOOST_TEST(!disjoint(swept_box(set.scene.bodies[q.body_a]), swept_box(set.scene.bodies[q.body_b])));
  }
  BOOST_TEST(contacts > 100);
}

// swept_box lists each distinct vertex enclosure once for a mesh (a vertex
// is listed in each of its polygons) and so gets the same box; a body
// whose vertex images are kept keeps every listed vertex, repeated ones
// too, since the kept points are indexed by the list (proofs/prefilter.md
// section 2).
BOOST_AUTO_TEST_CASE(swept_box_of_a_mesh_is_that_of_its_distinct_vertices_and_kept_points_stay_listed) {
  Motion motion;
  motion.control_points = {Mat34E{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0}, Mat34E{0, -1, 0, 3, 1, 0, 0, Exact(1, 3), 0, 0, 1, -2}};
  motion.weights = {1, 1};
  const std::vector<Vec3E> corners{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {Exact(1, 7), 2, Exact(-5, 3)}};
  Body mesh;
  mesh.name = "mesh";
  mesh.motion = motion;
  for (int a = 0; a < 5; ++a)
    for (int b = a + 1; b < 5; ++b)
      for (int c = b + 1; c < 5; ++c) mesh.polygons.push_back({corners[a], corners[b], corners[c]});
  Body cloud;
  cloud.name = "cloud";
  cloud.motion = motion;
  cloud.points = corners;
  const SweptBox m = swept_box(mesh), c = swept_box(cloud);
  BOOST_TEST(m.valid);
  BOOST_TEST(c.valid);
  BOOST_TEST((m.lo == c.lo));
  BOOST_TEST((m.hi == c.hi));
  // Kept points: one point listed twice stays two kept points per pose.
  Body twice;
  twice.name = "twice";
  twice.motion = motion;
  twice.points = {corners[4], corners[4]};
  const SweptBox t = swept_box(twice);
  BOOST_TEST(t.vertices == 2);
  BOOST_REQUIRE(t.points.size() == 4u);
  for (std::size_t k = 0; k < 2; ++k)
    for (int i = 0; i < 3; ++i) {
      BOOST_TEST(t.points[2 * k][i].inf() == t.points[2 * k + 1][i].inf());
      BOOST_TEST(t.points[2 * k][i].sup() == t.points[2 * k + 1][i].sup());
      BOOST_TEST(t.points[2 * k][i].inf() <= t.points[2 * k][i].sup());
      BOOST_TEST(t.points[2 * k][i].sup() != 0.0);
    }
}

// A tiny node budget ends the search as "undecided" with reason "limit",
// never "safe".
BOOST_AUTO_TEST_CASE(node_budget_is_undecided_not_safe) {
  bench::QueryGenerator generator(7);
  const bench::QuerySet set = generator.generate(200);
  VerifyOptions options;
  options.epsilon = Exact(1, 1000000);
  options.max_nodes = 3;
  options.exact_resolution = false;  // else most queries are decided at the root, within any budget
  const Verifier verifier(set.scene, options);
  int limited = 0;
  for (const bench::Query& q : set.queries) {
    const CheckResult r = verifier.check(q.body_a, q.body_b);
    bool hit_limit = false;
    for (const UndecidedInterval& u : r.undecided) hit_limit |= u.reason == StopReason::Limit;
    if (hit_limit) {
      ++limited;
      BOOST_TEST(r.verdict != Verdict::Safe);
    }
    if (q.collides) BOOST_TEST(r.verdict != Verdict::Safe);
  }
  BOOST_TEST(limited > 20);
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(refusals)

// A solid body built in C++ whose polygons are not a closed surface is
// refused by the verifier too (containment needs a closed surface; the
// parser checks this for scene files).
BOOST_AUTO_TEST_CASE(open_solid_bodies_are_refused_by_the_verifier) {
  bench::QueryGenerator generator(1);
  bench::QuerySet set = generator.generate(2);
  set.scene.bodies[set.queries[0].body_b].solid = true;
  VerifyOptions options;
  options.epsilon = Exact(1, 1000);
  BOOST_CHECK_THROW(verify_check(set.scene, set.queries[0].body_a, set.queries[0].body_b, options), InputError);
  BOOST_CHECK_THROW(require_supported(set.scene), InputError);
}

BOOST_AUTO_TEST_SUITE_END()
