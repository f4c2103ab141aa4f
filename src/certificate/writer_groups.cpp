// The certificate writer's groups (writer_groups.h).
#include "src/certificate/writer_groups.h"
#include "src/certificate/check.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numeric>

namespace tmcert::certificate::writer_internal {

BodyGroups::BodyGroups(const Body& body) : elements(certificate::elements(body)) {
  element_vertices.resize(elements.size());
  std::vector<std::array<double, 3>> centroid(elements.size());
  for (std::size_t e = 0; e < elements.size(); ++e) {
    std::array<double, 3> c{0, 0, 0};
    for (const Vec3E& v : elements[e]) {
      element_vertices[e].push_back(ids.id(v));
      for (int i = 0; i < 3; ++i) c[i] += CGAL::to_double(v[i]) / elements[e].size();
    }
    centroid[e] = c;
  }
  std::vector<int> order(elements.size());
  std::iota(order.begin(), order.end(), 0);
  if (!order.empty()) build(order, 0, order.size(), centroid);
}

int BodyGroups::build(std::vector<int>& order, std::size_t lo, std::size_t hi, const std::vector<std::array<double, 3>>& c) {
  const int g = static_cast<int>(children.size());
  children.push_back({-1, -1});
  element.push_back(-1);
  vertices.emplace_back();
  if (hi - lo == 1) {
    element[g] = order[lo];
    std::vector<std::uint32_t> v = element_vertices[order[lo]];
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
    vertices[g] = std::move(v);
    return g;
  }
  std::array<double, 3> mn{HUGE_VAL, HUGE_VAL, HUGE_VAL}, mx{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (std::size_t k = lo; k < hi; ++k)
    for (int i = 0; i < 3; ++i) {
      mn[i] = std::min(mn[i], c[order[k]][i]);
      mx[i] = std::max(mx[i], c[order[k]][i]);
    }
  int axis = 0;
  for (int i = 1; i < 3; ++i)
    if (mx[i] - mn[i] > mx[axis] - mn[axis]) axis = i;
  const std::size_t mid = lo + (hi - lo) / 2;
  std::nth_element(order.begin() + lo, order.begin() + mid, order.begin() + hi,
                   [&](int x, int y) { return c[x][axis] < c[y][axis] || (c[x][axis] == c[y][axis] && x < y); });
  const int left = build(order, lo, mid, c);
  const int right = build(order, mid, hi, c);
  children[g] = {left, right};
  std::vector<std::uint32_t> v;
  std::set_union(vertices[left].begin(), vertices[left].end(), vertices[right].begin(), vertices[right].end(),
                 std::back_inserter(v));
  vertices[g] = std::move(v);
  return g;
}

json BodyGroups::to_json() const {
  json out = json::array();
  for (std::size_t g = 0; g < children.size(); ++g) {
    if (element[g] >= 0) out.push_back({{"elements", json::array({element[g]})}});
    else out.push_back({{"children", json::array({children[g][0], children[g][1]})}});
  }
  return out;
}

}  // namespace tmcert::certificate::writer_internal
