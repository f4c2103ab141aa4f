// The certificate writer's groups (src/certificate/writer_groups.h): a
// binary tree over a body's elements, each leaf one element, each group's
// vertices the union of its children's.
#include "src/certificate/writer_groups.h"
#include "src/io/parse.h"

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <set>

namespace {

using namespace tmcert;
namespace wi = tmcert::certificate::writer_internal;

Vec3E p(int x, int y, int z) { return {Exact(x), Exact(y), Exact(z)}; }

}  // namespace

BOOST_AUTO_TEST_SUITE(writer_groups)

BOOST_AUTO_TEST_CASE(a_tree_over_the_elements) {
  Body b;
  b.segments = {{p(0, 0, 0), p(1, 0, 0)}, {p(1, 0, 0), p(2, 0, 0)}, {p(5, 0, 0), p(6, 0, 0)}};
  b.points = {p(9, 0, 0)};
  const wi::BodyGroups g(b);
  BOOST_TEST(g.elements.size() == 4u);
  BOOST_TEST(g.ids.size() == 6u);  // 0, 1, 2, 5, 6, 9
  BOOST_REQUIRE(g.children.size() == 7u);  // 2n - 1 groups
  // Preorder: every child after its parent; each element in one leaf.
  std::multiset<int> leaves;
  for (std::size_t k = 0; k < g.children.size(); ++k) {
    if (g.element[k] >= 0) {
      leaves.insert(g.element[k]);
      BOOST_TEST((g.children[k] == std::array<int, 2>{-1, -1}));
      continue;
    }
    for (int c : g.children[k]) {
      BOOST_TEST(c > static_cast<int>(k));
      BOOST_TEST(std::includes(g.vertices[k].begin(), g.vertices[k].end(), g.vertices[c].begin(),
                               g.vertices[c].end()));
    }
  }
  BOOST_TEST((leaves == std::multiset<int>{0, 1, 2, 3}));
  BOOST_TEST(g.vertices[0].size() == 6u);  // the root holds every vertex once
  // Median split along x: the first two elements (left) and the last two.
  const nlohmann::json j = g.to_json();
  BOOST_REQUIRE(j.size() == 7u);
  BOOST_TEST(j[0].contains("children"));
  const int left = j[0]["children"][0];
  BOOST_TEST(g.vertices[left].size() == 3u);  // 0, 1, 2
}

BOOST_AUTO_TEST_CASE(one_element_is_one_leaf) {
  Body b;
  b.points = {p(1, 2, 3)};
  const wi::BodyGroups g(b);
  BOOST_REQUIRE(g.children.size() == 1u);
  BOOST_TEST(g.element[0] == 0);
  BOOST_TEST(g.to_json().dump() == "[{\"elements\":[0]}]");
}

BOOST_AUTO_TEST_SUITE_END()
