// Solid validation (solid.h, proofs/containment.md §4).
#include "src/model/solid.h"

#include "kernels/static_intersection.h"

#include <CGAL/Bbox_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/box_intersection_d.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <utility>

namespace tmcert {

namespace {

// Exact vertex ids and the polygons using each undirected edge.
struct Edges {
  std::map<Vec3E, std::size_t> ids;
  std::vector<const Vec3E*> points_of;
  std::map<std::pair<std::size_t, std::size_t>, std::vector<int>> users;
  std::vector<std::pair<std::size_t, std::size_t>> order;  // first-seen order

  std::size_t id(const Vec3E& v) {
    const auto [it, fresh] = ids.emplace(v, ids.size());
    if (fresh) points_of.push_back(&it->first);
    return it->second;
  }

  explicit Edges(const Body& b) {
    for (std::size_t p = 0; p < b.polygons.size(); ++p) {
      const std::vector<Vec3E>& poly = b.polygons[p];
      for (std::size_t i = 0; i < poly.size(); ++i) {
        const std::size_t u = id(poly[i]), w = id(poly[(i + 1) % poly.size()]);
        const std::pair<std::size_t, std::size_t> key{std::min(u, w), std::max(u, w)};
        std::vector<int>& list = users[key];
        if (list.empty()) order.push_back(key);
        list.push_back(static_cast<int>(p));
      }
    }
  }
};

std::string text(const Vec3E& v) {
  return "(" + to_string(v[0]) + ", " + to_string(v[1]) + ", " + to_string(v[2]) + ")";
}

}  // namespace

namespace {

std::vector<int> shells_of(const Body& b, const Edges& edges) {
  std::vector<std::size_t> parent(b.polygons.size());
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  auto find = [&](std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (const auto& [key, users] : edges.users)
    for (int p : users) parent[find(static_cast<std::size_t>(p))] = find(static_cast<std::size_t>(users[0]));
  std::vector<int> shell(b.polygons.size(), -1), number(b.polygons.size(), -1);
  int next = 0;
  for (std::size_t p = 0; p < b.polygons.size(); ++p) {
    int& n = number[find(p)];
    if (n < 0) n = next++;
    shell[p] = n;
  }
  return shell;
}

}  // namespace

std::vector<int> polygon_shells(const Body& b) { return shells_of(b, Edges(b)); }

// Every edge in exactly two polygons: each shell (the polygons linked by
// their edges) is closed.  No segments or points, whose "inside" would mean
// nothing.
std::string solid_problem(const Body& b) {
  if (!b.segments.empty() || !b.points.empty())
    return "a solid body cannot have segments or points (only polygons or a mesh forming closed shells)";
  if (b.polygons.empty()) return "a solid body needs polygons forming closed shells";
  const Edges edges(b);
  for (const auto& key : edges.order) {
    const std::vector<int>& users = edges.users.at(key);
    if (users.size() == 2) continue;
    return "not a closed surface: the edge " + text(*edges.points_of[key.first]) + "-" +
           text(*edges.points_of[key.second]) + " (of polygon " + std::to_string(users[0]) + ") belongs to " +
           std::to_string(users.size()) + (users.size() == 1 ? " polygon" : " polygons") +
           " (every edge of a solid must belong to exactly 2)";
  }
  return {};
}

namespace {

using K = CGAL::Simple_cartesian<Exact>;

struct Triangle {
  std::array<Vec3E, 3> v;
  int polygon = 0;
};

SimplexI enclose(const Simplex& s) {
  SimplexI out;
  out.count = s.count;
  for (int i = 0; i < s.count; ++i)
    for (int k = 0; k < 3; ++k) out.p[i][k] = to_interval(s.p[i][k]);
  return out;
}

// In-plane separating axes for triangles in (nearly) one plane, where the
// axes of certainly_disjoint (normals, edge cross products) all point out
// of the plane: n x e for each edge e of each triangle (a fixed axis needs
// no rigour; the interval projections decide).  Call under RoundingGuard.
bool separated_in_plane(const SimplexI& a, const SimplexI& b) {
  using V = std::array<double, 3>;
  auto mid = [](const std::array<Interval, 3>& x) {
    return V{CGAL::to_double(x[0]), CGAL::to_double(x[1]), CGAL::to_double(x[2])};
  };
  auto cross = [](const V& x, const V& y) {
    return V{x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]};
  };
  auto diff = [](const V& x, const V& y) { return V{x[0] - y[0], x[1] - y[1], x[2] - y[2]}; };
  auto range = [](const SimplexI& s, const V& n, double& lo, double& hi) {
    lo = std::numeric_limits<double>::infinity();
    hi = -lo;
    for (int i = 0; i < s.count; ++i) {
      const Interval d = s.p[i][0] * n[0] + s.p[i][1] * n[1] + s.p[i][2] * n[2];
      if (std::isnan(d.inf()) || std::isnan(d.sup())) return false;
      lo = std::min(lo, d.inf());
      hi = std::max(hi, d.sup());
    }
    return true;
  };
  for (const SimplexI* t : {&a, &b}) {
    if (t->count != 3) continue;
    const V p[3] = {mid(t->p[0]), mid(t->p[1]), mid(t->p[2])};
    const V normal = cross(diff(p[1], p[0]), diff(p[2], p[0]));
    for (int k = 0; k < 3; ++k) {
      const V axis = cross(normal, diff(p[(k + 1) % 3], p[k]));
      if (!std::isfinite(axis[0]) || !std::isfinite(axis[1]) || !std::isfinite(axis[2])) continue;
      double alo, ahi, blo, bhi;
      if (!range(a, axis, alo, ahi) || !range(b, axis, blo, bhi)) continue;
      if (ahi < blo || bhi < alo) return true;
    }
  }
  return false;
}

// Do the closed simplices meet?  Exact; the interval filters only skip
// pairs they prove disjoint.
bool meet(const Simplex& a, const Simplex& b) {
  {
    RoundingGuard guard;
    const SimplexI ia = enclose(a), ib = enclose(b);
    if (certainly_disjoint(ia, ib) || separated_in_plane(ia, ib)) return false;
  }
  return common_point(a, b).has_value();
}

// The sign of det(b - a, c - a, d - a) (coplanarity of four points), or of
// the orientation of d relative to the edge ab seen against c in their
// common plane: an interval filter, exact when unsure.
int orientation3(const Vec3E& a, const Vec3E& b, const Vec3E& c, const Vec3E& d) {
  {
    RoundingGuard guard;
    std::array<Interval, 3> u, v, w;
    for (int k = 0; k < 3; ++k) {
      const Interval ak = to_interval(a[k]);
      u[k] = to_interval(b[k]) - ak, v[k] = to_interval(c[k]) - ak, w[k] = to_interval(d[k]) - ak;
    }
    const Interval det = u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
                         u[2] * (v[0] * w[1] - v[1] * w[0]);
    if (det.inf() > 0) return 1;
    if (det.sup() < 0) return -1;
    if (det.inf() == 0 && det.sup() == 0) return 0;
  }
  const K::Point_3 pa(a[0], a[1], a[2]), pb(b[0], b[1], b[2]), pc(c[0], c[1], c[2]), pd(d[0], d[1], d[2]);
  return static_cast<int>(CGAL::orientation(pa, pb, pc, pd));
}

// For coplanar a, e, c, d with c and d off the line ae: are c and d on the
// same side of it?  ((e - a) x (c - a)) . ((e - a) x (d - a)) > 0; an
// interval filter, CGAL's exact coplanar_orientation when unsure.
bool same_side(const Vec3E& a, const Vec3E& e, const Vec3E& c, const Vec3E& d) {
  {
    RoundingGuard guard;
    std::array<Interval, 3> u, v, w;
    for (int k = 0; k < 3; ++k) {
      const Interval ak = to_interval(a[k]);
      u[k] = to_interval(e[k]) - ak, v[k] = to_interval(c[k]) - ak, w[k] = to_interval(d[k]) - ak;
    }
    auto cross = [](const std::array<Interval, 3>& x, const std::array<Interval, 3>& y) {
      return std::array<Interval, 3>{x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]};
    };
    const std::array<Interval, 3> n1 = cross(u, v), n2 = cross(u, w);
    const Interval dot = n1[0] * n2[0] + n1[1] * n2[1] + n1[2] * n2[2];
    if (dot.inf() > 0) return true;
    if (dot.sup() < 0) return false;
  }
  const K::Point_3 pa(a[0], a[1], a[2]), pe(e[0], e[1], e[2]), pc(c[0], c[1], c[2]), pd(d[0], d[1], d[2]);
  return CGAL::coplanar_orientation(pa, pe, pc, pd) == CGAL::POSITIVE;
}

// Is ae an edge of polygon p?  By the edge table (exact vertex ids).
bool polygon_has_edge(const Edges& edges, const Vec3E& a, const Vec3E& e, int p) {
  const auto ia = edges.ids.find(a), ie = edges.ids.find(e);
  if (ia == edges.ids.end() || ie == edges.ids.end()) return false;
  const auto it = edges.users.find({std::min(ia->second, ie->second), std::max(ia->second, ie->second)});
  return it != edges.users.end() && std::find(it->second.begin(), it->second.end(), p) != it->second.end();
}

// Do triangles s and t, of different polygons P and Q of one shell, meet
// outside the edges and vertices that P and Q share?  Both are
// non-degenerate (fans of strictly convex pieces), and within a polygon's
// pieces a vertex of the polygon is only ever a triangle vertex, so an
// allowed common point is a vertex common to s and t, or lies on an edge
// common to s and t that is an edge of both P and Q (proofs/containment.md
// §4).
bool improper(const Edges& edges, const Triangle& s, const Triangle& t) {
  int in_t[3] = {-1, -1, -1};  // index in t of each vertex of s
  int shared = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (s.v[i] == t.v[j]) in_t[i] = j, ++shared;
  const Simplex ts{3, s.v}, tt{3, t.v};
  switch (shared) {
    case 0:
      return meet(ts, tt);
    case 1: {
      // They meet only at the common vertex v iff neither edge opposite v
      // meets the other triangle: T1 and T2 are the cones from v over
      // their opposite edges, so a common point x != v gives one on the
      // nearer of the two opposite edges along the ray from v through x.
      const int i = in_t[0] >= 0 ? 0 : in_t[1] >= 0 ? 1 : 2, j = in_t[i];
      const Simplex os{2, {s.v[(i + 1) % 3], s.v[(i + 2) % 3], s.v[(i + 2) % 3]}};
      const Simplex ot{2, {t.v[(j + 1) % 3], t.v[(j + 2) % 3], t.v[(j + 2) % 3]}};
      return meet(os, tt) || meet(ot, ts);
    }
    case 2: {
      const int c = in_t[0] < 0 ? 0 : in_t[1] < 0 ? 1 : 2;
      const Vec3E& a = s.v[(c + 1) % 3];
      const Vec3E& e = s.v[(c + 2) % 3];
      int d = 0;
      while (t.v[d] == a || t.v[d] == e) ++d;
      // The common edge must be an edge of both polygons (a diagonal's
      // inside is inside its polygon).
      if (!polygon_has_edge(edges, a, e, s.polygon) || !polygon_has_edge(edges, a, e, t.polygon)) return true;
      // In different planes they meet in the line ae, i.e. the edge; in one
      // plane, only when the far vertices lie on opposite sides of it.
      if (orientation3(a, e, s.v[c], t.v[d]) != 0) return false;
      return same_side(a, e, s.v[c], t.v[d]);
    }
    default:
      return true;  // the same triangle twice
  }
}

}  // namespace

std::string shell_intersection_problem(const Body& b) {
  const Edges edges(b);
  const std::vector<int> shell = shells_of(b, edges);
  std::vector<Triangle> triangles;
  for (const ConvexPiece& piece : b.pieces)
    for (std::size_t k = 1; k + 1 < piece.vertices.size(); ++k)
      triangles.push_back({{piece.vertices[0], piece.vertices[k], piece.vertices[k + 1]}, piece.polygon});
  using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, std::size_t>;
  std::vector<Box> boxes;
  boxes.reserve(triangles.size());
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    double lo[3], hi[3];
    for (int k = 0; k < 3; ++k) {
      const Interval x[3] = {to_interval(triangles[i].v[0][k]), to_interval(triangles[i].v[1][k]),
                             to_interval(triangles[i].v[2][k])};
      lo[k] = std::min({x[0].inf(), x[1].inf(), x[2].inf()});
      hi[k] = std::max({x[0].sup(), x[1].sup(), x[2].sup()});
    }
    boxes.emplace_back(CGAL::Bbox_3(lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]), i);
  }
  // The first offending pair in triangle order, whatever order the sweep
  // reports pairs in, so that the message does not depend on it.
  std::pair<std::size_t, std::size_t> worst{triangles.size(), triangles.size()};
  CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& x, const Box& y) {
    const std::pair<std::size_t, std::size_t> key{std::min(x.info(), y.info()), std::max(x.info(), y.info())};
    if (!(key < worst)) return;
    const Triangle& s = triangles[key.first];
    const Triangle& t = triangles[key.second];
    if (s.polygon == t.polygon || shell[s.polygon] != shell[t.polygon]) return;
    if (improper(edges, s, t)) worst = key;
  });
  if (worst.first == triangles.size()) return {};
  const int p = std::min(triangles[worst.first].polygon, triangles[worst.second].polygon);
  const int q = std::max(triangles[worst.first].polygon, triangles[worst.second].polygon);
  const std::set<Vec3E> vp(b.polygons[p].begin(), b.polygons[p].end()), vq(b.polygons[q].begin(), b.polygons[q].end());
  if (vp == vq)
    return "shell " + std::to_string(shell[p]) + " intersects itself: polygon " + std::to_string(q) +
           " repeats polygon " + std::to_string(p) + " (the same vertices)";
  return "shell " + std::to_string(shell[p]) + " intersects itself: polygons " + std::to_string(p) + " and " +
         std::to_string(q) +
         " meet outside their shared edges and vertices (a shell's polygons may meet only there)";
}

}  // namespace tmcert
