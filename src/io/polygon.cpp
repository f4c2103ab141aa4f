// The scene reader's polygon checks (src/io/polygon.h).
#include "src/io/polygon.h"

#include "kernels/vec3.h"
#include "src/io/parse.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_triangulation_face_base_2.h>
#include <CGAL/Filtered_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

namespace tmcert::reader {

namespace {

using Vec2E = std::array<Exact, 2>;

int sign(const Exact& x) { return x > 0 ? 1 : (x < 0 ? -1 : 0); }

using vec3::cross;
using vec3::dot;
using vec3::is_zero;
using vec3::sub;

// Twice the signed area of triangle abc: > 0 for a left turn.
Exact orient(const Vec2E& a, const Vec2E& b, const Vec2E& c) {
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

// A cheap enclosure of a rational: mpq_get_d truncates toward zero, so the
// value lies between that double and its neighbour away from zero.  False
// when the double is not finite (then only exact arithmetic decides).
bool cheap_interval(const Exact& q, Interval& out) {
  const double d = mpq_get_d(q.mpq());
  if (!std::isfinite(d)) return false;
  const int s = mpq_sgn(q.mpq());
  const double away = std::nextafter(d, s >= 0 ? std::numeric_limits<double>::infinity()
                                               : -std::numeric_limits<double>::infinity());
  if (!std::isfinite(away)) return false;
  out = s == 0 ? Interval(0) : Interval(std::min(d, away), std::max(d, away));
  return true;
}

// The sign of orient(a, b, c): an interval filter first, exact when the
// filter cannot decide (the filtered-predicate pattern of DESIGN.md).
int orient_sign(const Vec2E& a, const Vec2E& b, const Vec2E& c) {
  Interval x[6];
  const Exact* q[6] = {&a[0], &a[1], &b[0], &b[1], &c[0], &c[1]};
  bool ok = true;
  for (int i = 0; i < 6 && ok; ++i) ok = cheap_interval(*q[i], x[i]);
  if (ok) {
    RoundingGuard guard;
    const Interval det = (x[2] - x[0]) * (x[5] - x[1]) - (x[3] - x[1]) * (x[4] - x[0]);
    if (det.inf() > 0) return 1;
    if (det.sup() < 0) return -1;
  }
  return sign(orient(a, b, c));
}

// Given that p is collinear with a and b: is it on the closed segment ab?
bool within_box(const Vec2E& a, const Vec2E& b, const Vec2E& p) {
  return std::min(a[0], b[0]) <= p[0] && p[0] <= std::max(a[0], b[0]) &&
         std::min(a[1], b[1]) <= p[1] && p[1] <= std::max(a[1], b[1]);
}

// Do the closed segments ab and cd share a point?
bool segments_meet(const Vec2E& a, const Vec2E& b, const Vec2E& c, const Vec2E& d) {
  const int o1 = orient_sign(a, b, c), o2 = orient_sign(a, b, d);
  const int o3 = orient_sign(c, d, a), o4 = orient_sign(c, d, b);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return (o1 == 0 && within_box(a, b, c)) || (o2 == 0 && within_box(a, b, d)) ||
         (o3 == 0 && within_box(c, d, a)) || (o4 == 0 && within_box(c, d, b));
}

// Position of a direction in counterclockwise order starting at +x.
bool angle_less(const Vec2E& a, const Vec2E& b) {
  auto half = [](const Vec2E& d) { return (d[1] < 0 || (d[1] == 0 && d[0] < 0)) ? 1 : 0; };
  if (half(a) != half(b)) return half(a) < half(b);
  return a[0] * b[1] - a[1] * b[0] > 0;
}

// A polygon after validation, in original 3D coordinates and in the
// injective 2D projection, with each vertex's index in the input.
struct CleanPolygon {
  std::vector<Vec3E> points;
  std::vector<Vec2E> flat;
  std::vector<std::size_t> original;
};

std::string vertex_name(std::size_t i) { return "vertex " + std::to_string(i); }

// Throws InputError (message without location; the caller adds the path)
// unless the polygon is planar, has no repeated vertex and not all vertices
// are collinear.  Projects it onto the coordinate plane that drops the
// largest component of its normal, which is injective on its plane.
CleanPolygon project_polygon(const std::vector<Vec3E>& v) {
  const std::size_t n = v.size();
  // Repeated vertices, in O(n log n): sort, then compare neighbours.
  std::vector<std::size_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return v[a] < v[b] || (v[a] == v[b] && a < b);
  });
  for (std::size_t k = 1; k < n; ++k)
    if (v[order[k]] == v[order[k - 1]])
      throw InputError(vertex_name(order[k - 1]) + " and " + vertex_name(order[k]) +
                       " are equal (a polygon must be simple)");

  // A non-collinear triple 0, 1, j gives the plane.
  const Vec3E e1 = sub(v[1], v[0]);
  Vec3E normal{0, 0, 0};
  std::size_t j = 2;
  for (; j < n; ++j) {
    normal = cross(e1, sub(v[j], v[0]));
    if (!is_zero(normal)) break;
  }
  if (j == n) throw InputError("polygon vertices are collinear");
  for (std::size_t i = 2; i < n; ++i)
    if (dot(normal, sub(v[i], v[0])) != 0)
      throw InputError("polygon is not planar: " + vertex_name(i) + " is off the plane of vertices 0, 1 and " +
                       std::to_string(j));

  int drop = 0;
  for (int a = 1; a < 3; ++a)
    if (CGAL::abs(normal[a]) > CGAL::abs(normal[drop])) drop = a;
  const int u = drop == 0 ? 1 : 0, w = drop == 2 ? 1 : 2;
  CleanPolygon p;
  p.points = v;
  p.original.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    p.flat.push_back({v[i][u], v[i][w]});
    p.original[i] = i;
  }
  return p;
}

// Removes, repeatedly, every vertex that lies strictly between its two
// neighbours on their line: the boundary stays the same point set.  A vertex
// collinear with its neighbours but not between them is a spike where the
// two edges overlap: the polygon is not simple.
CleanPolygon remove_collinear(const CleanPolygon& in) {
  const std::size_t n = in.flat.size();
  std::vector<std::size_t> prev(n), next(n);
  std::vector<bool> alive(n, true);
  for (std::size_t i = 0; i < n; ++i) {
    prev[i] = (i + n - 1) % n;
    next[i] = (i + 1) % n;
  }
  std::vector<std::size_t> work(n);
  for (std::size_t i = 0; i < n; ++i) work[i] = n - 1 - i;
  std::size_t count = n;
  while (!work.empty()) {
    const std::size_t i = work.back();
    work.pop_back();
    if (!alive[i]) continue;
    const Vec2E &a = in.flat[prev[i]], &b = in.flat[i], &c = in.flat[next[i]];
    if (orient_sign(a, b, c) != 0) continue;
    const Exact along = (a[0] - b[0]) * (c[0] - b[0]) + (a[1] - b[1]) * (c[1] - b[1]);
    if (along > 0)
      throw InputError("adjacent edges overlap at " + vertex_name(in.original[i]) + " (a polygon must be simple)");
    // Only a fully collinear polygon could shrink below 3; that was rejected before.
    if (count <= 3) throw InputError("polygon vertices are collinear");
    alive[i] = false;
    --count;
    next[prev[i]] = next[i];
    prev[next[i]] = prev[i];
    work.push_back(prev[i]);
    work.push_back(next[i]);
  }
  CleanPolygon out;
  for (std::size_t i = 0; i < n; ++i)
    if (alive[i]) {
      out.points.push_back(in.points[i]);
      out.flat.push_back(in.flat[i]);
      out.original.push_back(in.original[i]);
    }
  return out;
}

// True iff the cleaned polygon (no zero turns) turns the same way at every
// vertex and winds around exactly once, i.e. is convex and simple.  The
// winding is counted as how often the edge direction passes the +x direction.
bool is_convex(const CleanPolygon& p) {
  const std::size_t n = p.flat.size();
  int turn = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const int s = orient_sign(p.flat[(i + n - 1) % n], p.flat[i], p.flat[(i + 1) % n]);
    if (turn == 0) turn = s;
    if (s != turn) return false;
  }
  std::vector<Vec2E> dir(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2E &a = p.flat[i], &b = p.flat[(i + 1) % n];
    dir[i] = {b[0] - a[0], b[1] - a[1]};
  }
  int wraps = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2E &d = dir[i], &e = dir[(i + 1) % n];
    if (turn > 0 ? angle_less(e, d) : angle_less(d, e)) ++wraps;
  }
  return wraps == 1;
}

// Throws unless no two non-adjacent edges share a point (adjacent edges
// meet only at their common vertex once zero turns are gone).  Edges are
// swept in order of their smallest x so only overlapping ones are compared.
void require_simple(const CleanPolygon& p) {
  const std::size_t n = p.flat.size();
  std::vector<Exact> lo(n), hi(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2E &a = p.flat[i], &b = p.flat[(i + 1) % n];
    lo[i] = std::min(a[0], b[0]);
    hi[i] = std::max(a[0], b[0]);
  }
  std::vector<std::size_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return lo[a] < lo[b]; });
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = order[k];
    for (std::size_t m = k + 1; m < n && lo[order[m]] <= hi[i]; ++m) {
      const std::size_t j = order[m];
      if ((i + 1) % n == j || (j + 1) % n == i) continue;  // adjacent
      if (segments_meet(p.flat[i], p.flat[(i + 1) % n], p.flat[j], p.flat[(j + 1) % n])) {
        auto edge = [&](std::size_t e) {
          return "edge " + std::to_string(p.original[e]) + "-" + std::to_string(p.original[(e + 1) % n]);
        };
        const std::size_t first = std::min(i, j), second = std::max(i, j);
        throw InputError("polygon is self-intersecting: " + edge(first) + " and " + edge(second) + " meet");
      }
    }
  }
}

// Triangulation of a polygon (no repeated vertex, no zero turn) by CGAL's
// constrained Delaunay triangulation of its exact 2D projection, on a
// filtered exact kernel: O(n log n) expected, where ear clipping and the
// pairwise simplicity test were quadratic or worse (52 s for 10 000
// vertices).  The polygon's edges are the constraints.  The polygon is
// simple iff no two constraints cross or overlap (CGAL throws) and every
// edge is an edge of the triangulation (else a vertex lies on it); then no
// point is added, every triangle has three polygon vertices, and the
// triangles inside are those reached from the outside across an odd number
// of constraints.  Each is returned in the polygon's orientation.  Nothing
// when the polygon is not simple (require_simple then says why).
std::optional<std::vector<std::array<std::size_t, 3>>> triangulate(const CleanPolygon& p) {
  using K = CGAL::Filtered_kernel<CGAL::Simple_cartesian<Exact>>;
  using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::size_t, K>;
  using Fbi = CGAL::Triangulation_face_base_with_info_2<int, K>;  // constraints crossed from outside
  using Fb = CGAL::Constrained_triangulation_face_base_2<K, Fbi>;
  using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
  using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::No_constraint_intersection_tag>;
  const std::size_t n = p.flat.size();
  Exact twice_area = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2E &a = p.flat[i], &b = p.flat[(i + 1) % n];
    twice_area += a[0] * b[1] - a[1] * b[0];
  }
  const int orientation = sign(twice_area);  // nonzero for a simple polygon
  std::vector<std::pair<K::Point_2, std::size_t>> points;
  points.reserve(n);
  for (std::size_t i = 0; i < n; ++i) points.emplace_back(K::Point_2(p.flat[i][0], p.flat[i][1]), i);
  Cdt cdt;
  cdt.insert(points.begin(), points.end());  // spatially sorted
  if (cdt.number_of_vertices() != n) return std::nullopt;
  std::vector<Cdt::Vertex_handle> handle(n);
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) handle[v->info()] = v;
  try {
    for (std::size_t i = 0; i < n; ++i) cdt.insert_constraint(handle[i], handle[(i + 1) % n]);
  } catch (const Cdt::Intersection_of_constraints_exception&) {
    return std::nullopt;
  }
  if (cdt.number_of_vertices() != n) return std::nullopt;
  for (std::size_t i = 0; i < n; ++i)
    if (!cdt.is_edge(handle[i], handle[(i + 1) % n])) return std::nullopt;
  // Each face's count of constraints crossed from the infinite face: flood
  // fill across unconstrained edges, one more across a constrained one.
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info() = -1;
  std::vector<Cdt::Edge> border;
  auto fill = [&](Cdt::Face_handle start, int level) {
    if (start->info() != -1) return;
    start->info() = level;
    std::vector<Cdt::Face_handle> queue{start};
    while (!queue.empty()) {
      const Cdt::Face_handle f = queue.back();
      queue.pop_back();
      for (int e = 0; e < 3; ++e) {
        const Cdt::Face_handle g = f->neighbor(e);
        if (g->info() != -1) continue;
        if (cdt.is_constrained(Cdt::Edge(f, e))) {
          border.push_back(Cdt::Edge(f, e));
        } else {
          g->info() = level;
          queue.push_back(g);
        }
      }
    }
  };
  fill(cdt.infinite_face(), 0);
  for (std::size_t k = 0; k < border.size(); ++k) {  // border grows while filling: breadth first
    const Cdt::Edge e = border[k];
    fill(e.first->neighbor(e.second), e.first->info() + 1);
  }
  std::vector<std::array<std::size_t, 3>> triangles;
  triangles.reserve(n - 2);
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (f->info() % 2 == 0) continue;
    // CGAL's faces are counterclockwise in the projection.
    std::array<std::size_t, 3> t{f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()};
    if (orientation < 0) std::swap(t[1], t[2]);
    triangles.push_back(t);
  }
  if (triangles.size() != n - 2) return std::nullopt;
  return triangles;
}

constexpr std::size_t kFacesNamed = 5;

static std::string count_text(std::size_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}
static std::string faces_text(const std::vector<std::size_t>& faces, std::size_t total) {
  std::string out = total == 1 ? "face " : "faces ";
  for (std::size_t k = 0; k < faces.size(); ++k) out += (k ? ", " : "") + std::to_string(faces[k]);
  if (total > faces.size()) out += ", ...";
  return out;
}

// A face of a mesh file (docs/scene-format.md, "Data from real

// Collinear points: the segment between the two extreme ones along their
// line (their convex hull, exactly), or the point when all are equal.
void add_degenerate(Body& b, const std::vector<Vec3E>& v) {
  std::size_t i = 1;
  while (i < v.size() && v[i] == v[0]) ++i;
  if (i == v.size()) {
    b.points.push_back(v[0]);
    return;
  }
  const Vec3E d = sub(v[i], v[0]);
  std::size_t lo = 0, hi = 0;
  Exact s_lo = 0, s_hi = 0;
  for (std::size_t k = 1; k < v.size(); ++k) {
    const Exact s = dot(d, sub(v[k], v[0]));
    if (s < s_lo) s_lo = s, lo = k;
    if (s > s_hi) s_hi = s, hi = k;
  }
  b.segments.push_back({v[lo], v[hi]});
}

}  // namespace

// Validates one input polygon and returns its cleaned vertices plus its
// convex pieces (tagged with `index`).  Errors carry no location.
std::pair<std::vector<Vec3E>, std::vector<ConvexPiece>> split_polygon(const std::vector<Vec3E>& vertices,
                                                                      int index) {
  // A triangle with distinct, non-collinear vertices is its own convex
  // piece (anything else goes through the general checks and their messages).
  if (vertices.size() == 3 && vertices[0] != vertices[1] && vertices[1] != vertices[2] && vertices[0] != vertices[2] &&
      !is_zero(cross(sub(vertices[1], vertices[0]), sub(vertices[2], vertices[0]))))
    return {vertices, {ConvexPiece{index, vertices}}};
  const CleanPolygon clean = remove_collinear(project_polygon(vertices));
  std::vector<ConvexPiece> pieces;
  if (is_convex(clean)) {
    pieces.push_back(ConvexPiece{index, clean.points});
  } else {
    const auto triangles = triangulate(clean);
    if (!triangles) {
      require_simple(clean);  // says why (quadratic, but only for a bad polygon)
      throw InputError("polygon could not be triangulated (is it simple?)");
    }
    for (const auto& t : *triangles)
      pieces.push_back(ConvexPiece{index, {clean.points[t[0]], clean.points[t[1]], clean.points[t[2]]}});
  }
  return {clean.points, std::move(pieces)};
}

void add_mesh_face(Body& b, const std::vector<Vec3E>& v, std::size_t face, MeshFaceCounts& counts) {
  const std::size_t n = v.size();
  std::size_t i = 1;
  while (i < n && v[i] == v[0]) ++i;
  Vec3E normal{0, 0, 0};
  if (i < n) {
    const Vec3E d = sub(v[i], v[0]);
    for (std::size_t j = i + 1; j < n && is_zero(normal); ++j) normal = cross(d, sub(v[j], v[0]));
  }
  if (is_zero(normal)) {  // collinear (or a single point)
    add_degenerate(b, v);
    if (counts.degenerate++ < kFacesNamed) counts.degenerate_faces.push_back(face);
    return;
  }
  bool planar = true;
  for (std::size_t k = 1; k < n && planar; ++k) planar = dot(normal, sub(v[k], v[0])) == 0;
  if (planar) {
    auto [clean, pieces] = split_polygon(v, static_cast<int>(b.polygons.size()));
    b.polygons.push_back(std::move(clean));
    for (ConvexPiece& piece : pieces) b.pieces.push_back(std::move(piece));
    return;
  }
  if (counts.fans++ < kFacesNamed) counts.fan_faces.push_back(face);
  for (std::size_t k = 1; k + 1 < n; ++k) {
    const std::vector<Vec3E> triangle = {v[0], v[k], v[k + 1]};
    ++counts.fan_triangles;
    if (is_zero(cross(sub(v[k], v[0]), sub(v[k + 1], v[0])))) {
      add_degenerate(b, triangle);
      ++counts.fan_degenerate;
      continue;
    }
    auto [clean, pieces] = split_polygon(triangle, static_cast<int>(b.polygons.size()));
    b.polygons.push_back(std::move(clean));
    for (ConvexPiece& piece : pieces) b.pieces.push_back(std::move(piece));
  }
}

std::vector<std::string> mesh_face_notes(const std::string& where, const MeshFaceCounts& counts) {
  std::vector<std::string> notes;
  if (counts.fans > 0)
    notes.push_back(where + count_text(counts.fans, "face is", "faces are") + " not exactly planar (" +
                    faces_text(counts.fan_faces, counts.fans) + "): each is split into the triangles of a fan from its " +
                    "first vertex, " + count_text(counts.fan_triangles, "triangle", "triangles") + " in all" +
                    (counts.fan_degenerate > 0 ? " (" + std::to_string(counts.fan_degenerate) + " of zero area, read as segments)" : "") +
                    "; the body is these triangles");
  if (counts.degenerate > 0)
    notes.push_back(where + count_text(counts.degenerate, "face has", "faces have") + " zero area (" +
                    faces_text(counts.degenerate_faces, counts.degenerate) + "): " +
                    (counts.degenerate == 1 ? "it is" : "each is") + " read as the segment (or point) it covers");
  return notes;
}

}  // namespace tmcert::reader

namespace tmcert {

std::pair<std::vector<Vec3E>, std::vector<ConvexPiece>> split_scene_polygon(const std::vector<Vec3E>& vertices,
                                                                            int index) {
  return reader::split_polygon(vertices, index);
}

}  // namespace tmcert
