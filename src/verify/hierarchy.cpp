#include "src/verify/hierarchy.h"

#include <algorithm>
#include <limits>
#include <numeric>

namespace tmcert {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct Builder {
  const std::vector<std::vector<Vec3<Interval>>>& features;  // the items' points
  const std::array<Interval, 16>* gi;
  BvTree tree;
  std::vector<std::uint32_t> order;  // leaf indices, permuted by the splits

  // Upper bound of |x - c| over the box x, c exact.
  static Interval distance(const Vec3<Interval>& x, const std::array<double, 3>& c) {
    Interval s(0);
    for (int i = 0; i < 3; ++i) s += CGAL::square(x[i] - Interval(c[i]));
    return CGAL::sqrt(s);
  }

  // rho over an item: the largest rho at its points.  rho is convex (a norm
  // of (x, 1)) and the item lies in the convex hull of its points, so this
  // bounds rho over the item (not over its sphere).
  double rho_points(const std::vector<Vec3<Interval>>& pts) const {
    if (!gi) return 0;
    double p = 0;
    for (const auto& x : pts) {
      const Interval h[4] = {x[0], x[1], x[2], Interval(1)};
      Interval q(0);
      for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) q += h[r] * (*gi)[4 * r + c] * h[c];
      if (!(q.sup() >= 0)) return kInf;
      const double s = CGAL::sqrt(Interval(0, q.sup())).sup();
      if (!std::isfinite(s)) return kInf;
      p = std::max(p, s);
    }
    return p;
  }

  BvNode leaf(std::uint32_t k) {
    BvNode n;
    const auto& pts = features[k];
    std::array<double, 3> lo{kInf, kInf, kInf}, hi{-kInf, -kInf, -kInf};
    for (const auto& x : pts)
      for (int i = 0; i < 3; ++i) {
        lo[i] = std::min(lo[i], x[i].inf());
        hi[i] = std::max(hi[i], x[i].sup());
      }
    for (int i = 0; i < 3; ++i) n.c[i] = std::isfinite(lo[i]) && std::isfinite(hi[i]) ? lo[i] / 2 + hi[i] / 2 : 0;
    double r = 0;
    for (const auto& x : pts) r = std::max(r, distance(x, n.c).sup());
    n.r = std::isnan(r) ? kInf : r;
    n.p = rho_points(pts);
    // A flat item (three or more points): the slab along its normal.
    if (pts.size() >= 3) {
      auto mid = [](const Vec3<Interval>& x) {
        return std::array<double, 3>{CGAL::to_double(x[0]), CGAL::to_double(x[1]), CGAL::to_double(x[2])};
      };
      const auto p0 = mid(pts[0]);
      std::array<double, 3> best{};
      double best2 = 0;
      for (std::size_t i = 1; i < pts.size(); ++i)
        for (std::size_t j = i + 1; j < pts.size() && j < i + 3; ++j) {
          const auto pi = mid(pts[i]), pj = mid(pts[j]);
          const std::array<double, 3> u{pi[0] - p0[0], pi[1] - p0[1], pi[2] - p0[2]};
          const std::array<double, 3> v{pj[0] - p0[0], pj[1] - p0[1], pj[2] - p0[2]};
          const std::array<double, 3> c{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
          const double c2 = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
          if (c2 > best2) { best2 = c2; best = c; }
        }
      if (best2 > 0 && std::isfinite(best2)) {
        const double len = std::sqrt(best2);
        for (int i = 0; i < 3; ++i) n.slab_n[i] = best[i] / len;
        set_slab(n, pts);
      }
    }
    return n;
  }

  // The slab of node n along n.slab_n over the points, rounded outward (any
  // direction gives a sound slab; a flat set gives a thin one).
  static void set_slab(BvNode& n, const std::vector<Vec3<Interval>>& pts) {
    double lo = kInf, hi = -kInf;
    for (const auto& x : pts) {
      const Interval d = Interval(n.slab_n[0]) * x[0] + Interval(n.slab_n[1]) * x[1] + Interval(n.slab_n[2]) * x[2];
      lo = std::min(lo, d.inf());
      hi = std::max(hi, d.sup());
    }
    n.slab = std::isfinite(lo) && std::isfinite(hi) && lo <= hi;
    n.slab_lo = lo;
    n.slab_hi = hi;
  }

  // The points of the items order[first, last).
  std::vector<Vec3<Interval>> points_under(std::size_t first, std::size_t last) const {
    std::vector<Vec3<Interval>> pts;
    for (std::size_t k = first; k < last; ++k)
      pts.insert(pts.end(), features[order[k]].begin(), features[order[k]].end());
    return pts;
  }

  // A curved node (items with different normals): a slab along the
  // thinnest of the normals of up to kThickCandidates of its flat leaves,
  // spread over its items, when that slab is thinner than the node's
  // sphere (proofs/hierarchy.md §1b: any direction gives a sound slab).
  // The candidates are compared by the widths of their slabs in double
  // (a choice only); the chosen slab is measured over every point of every
  // item under the node, rounded outward (set_slab).
  static constexpr std::size_t kThickCandidates = 8;
  void thick_slab(BvNode& n, std::size_t first, std::size_t last) const {
    const std::size_t count = last - first;
    const std::size_t step = std::max<std::size_t>(1, count / kThickCandidates);
    double best_width = kInf;
    std::array<double, 3> best{};
    for (std::size_t k = first; k < last; k += step) {
      const BvNode& l = tree.nodes[order[k]];
      if (!l.slab) continue;
      double lo = kInf, hi = -kInf;
      for (std::size_t q = first; q < last; ++q)
        for (const auto& x : features[order[q]]) {
          const double d = l.slab_n[0] * CGAL::to_double(x[0]) + l.slab_n[1] * CGAL::to_double(x[1]) +
                           l.slab_n[2] * CGAL::to_double(x[2]);
          lo = std::min(lo, d);
          hi = std::max(hi, d);
        }
      if (hi - lo < best_width) {
        best_width = hi - lo;
        best = l.slab_n;
      }
    }
    if (!(best_width < n.r)) return;  // no candidate, or no thinner than the sphere
    n.slab_n = best;
    set_slab(n, points_under(first, last));
    n.slab = n.slab && n.slab_hi - n.slab_lo < n.r;
    n.slab_thick = n.slab;
  }

  // Builds the subtree over order[first, last) and returns its node index.
  std::uint32_t build(std::size_t first, std::size_t last) {
    if (last - first == 1) return order[first];
    std::array<double, 3> lo{kInf, kInf, kInf}, hi{-kInf, -kInf, -kInf};
    std::array<double, 3> clo = lo, chi = hi;  // of the leaf centers
    for (std::size_t k = first; k < last; ++k) {
      const BvNode& l = tree.nodes[order[k]];
      for (int i = 0; i < 3; ++i) {
        lo[i] = std::min(lo[i], l.c[i] - l.r);
        hi[i] = std::max(hi[i], l.c[i] + l.r);
        clo[i] = std::min(clo[i], l.c[i]);
        chi[i] = std::max(chi[i], l.c[i]);
      }
    }
    int axis = 0;
    for (int i = 1; i < 3; ++i)
      if (chi[i] - clo[i] > chi[axis] - clo[axis]) axis = i;
    const std::size_t mid = first + (last - first) / 2;
    std::nth_element(order.begin() + first, order.begin() + mid, order.begin() + last,
                     [&](std::uint32_t x, std::uint32_t y) {
                       const double a = tree.nodes[x].c[axis], b = tree.nodes[y].c[axis];
                       return a < b || (a == b && x < y);
                     });
    const std::uint32_t left = build(first, mid), right = build(mid, last);
    BvNode n;
    for (int i = 0; i < 3; ++i) n.c[i] = std::isfinite(lo[i]) && std::isfinite(hi[i]) ? lo[i] / 2 + hi[i] / 2 : 0;
    // Radius over the leaf spheres (tighter than over the two children).
    double r = 0, p = 0;
    for (std::size_t k = first; k < last; ++k) {
      const BvNode& l = tree.nodes[order[k]];
      const Interval d = distance({Interval(l.c[0]), Interval(l.c[1]), Interval(l.c[2])}, n.c) + Interval(l.r);
      r = std::max(r, d.sup());
      p = std::max(p, l.p);
    }
    n.r = std::isnan(r) || !std::isfinite(r) ? kInf : r;
    n.p = p;
    // Flat when every leaf is flat with (nearly) the first leaf's normal, up
    // to sign; the slab is then measured over all their points.
    const BvNode& first_leaf = tree.nodes[order[first]];
    bool flat = first_leaf.slab;
    for (std::size_t k = first; flat && k < last; ++k) {
      const BvNode& l = tree.nodes[order[k]];
      double dot = 0;
      for (int i = 0; i < 3; ++i) dot += l.slab_n[i] * first_leaf.slab_n[i];
      flat = l.slab && std::fabs(std::fabs(dot) - 1) < 1e-9;
    }
    if (flat) {
      n.slab_n = first_leaf.slab_n;
      set_slab(n, points_under(first, last));
    } else {
      thick_slab(n, first, last);
    }
    n.left = left;
    n.right = right;
    n.leaves = static_cast<std::uint32_t>(last - first);
    tree.nodes.push_back(n);
    return static_cast<std::uint32_t>(tree.nodes.size() - 1);
  }
};

}  // namespace

namespace {

Builder make_builder(const std::vector<std::vector<Vec3<Interval>>>& items, const std::array<Interval, 16>* gi) {
  return Builder{items, gi, {}, {}};
}

}  // namespace

BvTree build_tree(const std::vector<std::vector<Vec3<Interval>>>& items, const std::array<Interval, 16>* gi) {
  RoundingGuard guard;
  Builder b = make_builder(items, gi);
  const std::size_t n = items.size();
  b.tree.leaves = static_cast<std::uint32_t>(n);
  if (n == 0) return b.tree;
  b.tree.nodes.reserve(2 * n - 1);
  for (std::size_t k = 0; k < n; ++k) b.tree.nodes.push_back(b.leaf(static_cast<std::uint32_t>(k)));
  b.order.resize(n);
  std::iota(b.order.begin(), b.order.end(), 0u);
  if (n > 1) b.build(0, n);
  return std::move(b.tree);
}

std::vector<BvNode> item_spheres(const std::vector<std::vector<Vec3<Interval>>>& items,
                                 const std::array<Interval, 16>* gi) {
  RoundingGuard guard;
  Builder b = make_builder(items, gi);
  std::vector<BvNode> out;
  out.reserve(items.size());
  for (std::size_t k = 0; k < items.size(); ++k) out.push_back(b.leaf(static_cast<std::uint32_t>(k)));
  return out;
}

void build_cell_tree(CellTree& cells, const std::vector<std::vector<Vec3<Interval>>>& cell_points,
                     const std::array<Interval, 16>* gi) {
  cells.tree = build_tree(cell_points, gi);
  cells.below.assign(cells.tree.nodes.size(), {0, 0, 0});
  for (std::size_t k = 0; k < cells.cells(); ++k)
    cells.below[k] = {cells.vertex_begin[k + 1] - cells.vertex_begin[k], cells.edge_begin[k + 1] - cells.edge_begin[k],
                      cells.face[k] >= 0 ? 1u : 0u};
  // Children have smaller indices than their parent.
  for (std::size_t i = cells.tree.leaves; i < cells.tree.nodes.size(); ++i) {
    const BvNode& n = cells.tree.nodes[i];
    for (int c = 0; c < 3; ++c) cells.below[i][c] = cells.below[n.left][c] + cells.below[n.right][c];
  }
}

}  // namespace tmcert
