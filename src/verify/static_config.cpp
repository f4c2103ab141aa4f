// Tests of one configuration of two bodies (static_config.h).
#include "src/verify/static_config.h"

namespace tmcert::detail {

std::optional<DistanceHit> closest_within(const std::vector<StaticPart>& a, const Mat34E* ma,
                                                 const std::vector<StaticPart>& b, const Mat34E* mb,
                                                 const Exact& bound2, const std::set<std::pair<int, int>>* only,
                                                 CheckStats& stats) {
  double reach;
  {
    RoundingGuard guard;
    reach = CGAL::sqrt(to_interval(bound2)).sup();
  }
  struct Placed {
    int part, index;
    Simplex s;
    std::array<double, 3> lo, hi;
  };
  auto place = [&](const std::vector<StaticPart>& parts, const Mat34E* m, bool first) {
    std::vector<char> use(parts.size(), only ? 0 : 1);
    if (only)
      for (const auto& [i, j] : *only) use[first ? i : j] = 1;
    std::vector<Placed> out;
    for (std::size_t i = 0; i < parts.size(); ++i) {
      if (!use[i]) continue;
      for (std::size_t n = 0; n < parts[i].simplices.size(); ++n) {
        Simplex s = parts[i].simplices[n];
        if (m)
          for (int k = 0; k < s.count; ++k) {
            Vec3E r;
            for (int c = 0; c < 3; ++c)
              r[c] = (*m)[4 * c] * s.p[k][0] + (*m)[4 * c + 1] * s.p[k][1] + (*m)[4 * c + 2] * s.p[k][2] + (*m)[4 * c + 3];
            s.p[k] = r;
          }
        Placed p{static_cast<int>(i), static_cast<int>(n), s, {}, {}};
        for (int c = 0; c < 3; ++c) {
          p.lo[c] = std::numeric_limits<double>::infinity();
          p.hi[c] = -p.lo[c];
          for (int k = 0; k < s.count; ++k) {
            const Interval x = to_interval(s.p[k][c]);
            p.lo[c] = std::min(p.lo[c], x.inf());
            p.hi[c] = std::max(p.hi[c], x.sup());
          }
        }
        out.push_back(std::move(p));
      }
    }
    return out;
  };
  const std::vector<Placed> xs = place(a, ma, true), ys = place(b, mb, false);
  std::optional<DistanceHit> best;
  for (const Placed& x : xs)
    for (const Placed& y : ys) {
      if (only && !only->count({x.part, y.part})) continue;
      // Boxes (enclosing the exact simplices) farther apart along an axis
      // than the reach (rounded up) hold no pair within it.
      bool far = false;
      for (int c = 0; c < 3 && !far; ++c) far = x.lo[c] - y.hi[c] > reach || y.lo[c] - x.hi[c] > reach;
      if (far) continue;
      ++stats.static_tests;
      ClosestPoints cp = closest_points(x.s, y.s);
      if (cp.d2 <= bound2 && (!best || cp.d2 < best->points.d2)) best = DistanceHit{x.part, y.part, std::move(cp), x.index, y.index};
    }
  return best;
}

std::optional<StaticHit> first_hit(const std::vector<StaticPart>& a, const std::vector<StaticPart>& b,
                                          const std::set<std::pair<int, int>>* only, CheckStats& stats) {
  return filtered_first_hit(
      a, nullptr, b, nullptr, only,
      [] { return std::optional<std::pair<std::optional<Mat34E>, std::optional<Mat34E>>>(std::in_place); }, stats);
}

}  // namespace tmcert::detail
