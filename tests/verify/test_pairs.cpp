// src/verify/pairs: the pairs a check carries.  A feature pair of kind
// VertexFace pairs the moving body's vertices with the other's faces,
// EdgeEdge edges with edges, FaceVertex faces with vertices; all_pairs lists
// every one of them once, by kind, then i, then j.
#include "src/verify/pairs.h"
#include "tests/verify/check_testing.h"

#include <boost/test/unit_test.hpp>

#include <set>
#include <tuple>

using namespace tmcert;
using namespace tmcert::detail;
using tmcert::testing::two_cubes;

BOOST_AUTO_TEST_SUITE(pairs)

BOOST_AUTO_TEST_CASE(constructors) {
  const PairRef n = node_pair(3, 5);
  BOOST_TEST(n.nodes);
  BOOST_TEST(n.i == 3u);
  BOOST_TEST(n.j == 5u);
  BOOST_TEST(n.born == 0);
  BOOST_TEST(n.carried == 0);
  const PairRef f = feature_pair(ContactKind::EdgeEdge, 4, 6, 2);
  BOOST_TEST(!f.nodes);
  BOOST_TEST((f.kind == ContactKind::EdgeEdge));
  BOOST_TEST(f.i == 4u);
  BOOST_TEST(f.j == 6u);
  BOOST_TEST(f.born == 2);
  BOOST_TEST(f.carried == 0);
}

BOOST_AUTO_TEST_CASE(tables_of_each_kind) {
  const Scene scene = two_cubes("-3 0 0", "3 0 0");
  const PreparedBody m(scene.bodies[0]), f(scene.bodies[1]);
  BOOST_TEST(&moving_table(m, ContactKind::VertexFace) == &m.vertices);
  BOOST_TEST(&moving_table(m, ContactKind::EdgeEdge) == &m.edges);
  BOOST_TEST(&moving_table(m, ContactKind::FaceVertex) == &m.faces);
  BOOST_TEST(&other_table(f, ContactKind::VertexFace) == &f.faces);
  BOOST_TEST(&other_table(f, ContactKind::EdgeEdge) == &f.edges);
  BOOST_TEST(&other_table(f, ContactKind::FaceVertex) == &f.vertices);
  BOOST_TEST(&moving_exact(m, ContactKind::VertexFace) == &m.exact().vertices);
  BOOST_TEST(&moving_exact(m, ContactKind::EdgeEdge) == &m.exact().edges);
  BOOST_TEST(&moving_exact(m, ContactKind::FaceVertex) == &m.exact().faces);
  BOOST_TEST(&other_exact(f, ContactKind::VertexFace) == &f.exact().faces);
  BOOST_TEST(&other_exact(f, ContactKind::EdgeEdge) == &f.exact().edges);
  BOOST_TEST(&other_exact(f, ContactKind::FaceVertex) == &f.exact().vertices);
  // A cube: 8 vertices and 12 edges (faces as the table splits them).
  BOOST_TEST(m.vertices.size() == 8u);
  BOOST_TEST(m.edges.size() == 12u);
  BOOST_TEST(m.faces.size() >= 6u);
  BOOST_TEST(m.exact().vertices.size() == m.vertices.size());
  BOOST_TEST(f.exact().faces.size() == f.faces.size());
}

BOOST_AUTO_TEST_CASE(all_pairs_lists_every_pair_once_in_order) {
  const Scene scene = two_cubes("-3 0 0", "3 0 0");
  const PreparedBody m(scene.bodies[0]), f(scene.bodies[1]);
  const std::vector<PairRef> all = all_pairs(m, f);
  std::size_t expected = 0;
  for (ContactKind k : {ContactKind::VertexFace, ContactKind::EdgeEdge, ContactKind::FaceVertex})
    expected += moving_table(m, k).size() * other_table(f, k).size();
  BOOST_TEST(all.size() == expected);
  std::set<std::tuple<int, std::uint32_t, std::uint32_t>> seen;
  std::tuple<int, std::uint32_t, std::uint32_t> last{-1, 0, 0};
  for (const PairRef& p : all) {
    BOOST_TEST(!p.nodes);
    BOOST_TEST(p.born == 0);
    const auto key = std::make_tuple(static_cast<int>(p.kind), p.i, p.j);
    BOOST_TEST((last < key));
    last = key;
    seen.insert(key);
    BOOST_TEST(p.i < moving_table(m, p.kind).size());
    BOOST_TEST(p.j < other_table(f, p.kind).size());
  }
  BOOST_TEST(seen.size() == expected);
  BOOST_TEST((all.front().kind == ContactKind::VertexFace));
  BOOST_TEST((all.back().kind == ContactKind::FaceVertex));
}

BOOST_AUTO_TEST_SUITE_END()
