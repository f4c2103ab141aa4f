#include "src/verify/prepared.h"

#include "src/model/segment_kind.h"
#include "src/motion/segment.h"
#include "kernels/vec3.h"

#include <CGAL/number_utils.h>

#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <unordered_map>
#include <unordered_set>

namespace tmcert {

namespace {

const Mat34E kIdentity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};

// ---------------------------------------------------------------- geometry
// Feature geometry written once over FT: exact with Exact, an enclosure with
// Interval (under RoundingGuard).  `gi` is G^-1 (row-major 4x4) or null for a
// body without metric (fixed, in world coordinates).

// rho^2 quadratic of x(s) = origin + s1 a0 + s2 a1: Q = M^T G^-1 M with
// M = [a0 a1 origin; 0 0 1] (4x3).
template <class FT>
void set_rho2(FeatureGeometry<FT>& f, const std::array<FT, 16>* gi) {
  for (auto& q : f.rho2) q = FT(0);
  if (!gi) return;
  FT m[4][3];
  for (int r = 0; r < 3; ++r) {
    m[r][0] = f.axis[0][r];
    m[r][1] = f.axis[1][r];
    m[r][2] = f.origin[r];
  }
  m[3][0] = FT(0);
  m[3][1] = FT(0);
  m[3][2] = FT(1);
  FT gm[4][3];  // G^-1 M
  for (int r = 0; r < 4; ++r)
    for (int j = 0; j < 3; ++j) {
      gm[r][j] = FT(0);
      for (int c = 0; c < 4; ++c) gm[r][j] += (*gi)[4 * r + c] * m[c][j];
    }
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j) {
      FT s(0);
      for (int r = 0; r < 4; ++r) s += m[r][i] * gm[r][j];
      f.rho2[3 * i + j] = s;
      f.rho2[3 * j + i] = s;
    }
}

template <class FT>
FeatureGeometry<FT> make_vertex(const Vec3<FT>& p, const std::array<FT, 16>* gi) {
  FeatureGeometry<FT> f;
  f.dim = 0;
  f.origin = p;
  f.axis = {Vec3<FT>{FT(0), FT(0), FT(0)}, Vec3<FT>{FT(0), FT(0), FT(0)}};
  set_rho2(f, gi);
  return f;
}

template <class FT>
FeatureGeometry<FT> make_edge(const Vec3<FT>& p, const Vec3<FT>& q, const std::array<FT, 16>* gi) {
  FeatureGeometry<FT> f;
  f.dim = 1;
  f.origin = p;
  f.axis = {vec3::sub(q, p), Vec3<FT>{FT(0), FT(0), FT(0)}};
  set_rho2(f, gi);
  return f;
}

// A convex polygon with v0, v1, v2 not collinear (checked exactly by the
// caller).  Parameter axes a0 = v1 - v0, a1 = v2 - v0, so the domain starts
// (0,0), (1,0), (0,1): counter-clockwise, and so is the whole convex polygon.
template <class FT>
FeatureGeometry<FT> make_face(const std::vector<Vec3<FT>>& v, const std::array<FT, 16>* gi) {
  FeatureGeometry<FT> f;
  f.dim = 2;
  f.origin = v[0];
  f.axis = {vec3::sub(v[1], v[0]), vec3::sub(v[2], v[0])};
  set_rho2(f, gi);
  f.orientation = 1;
  f.domain = {{FT(0), FT(0)}, {FT(1), FT(0)}, {FT(0), FT(1)}};
  if (v.size() > 3) {
    // Parameter coordinates of the other vertices: the 2x2 Gram system.
    const FT g00 = vec3::dot(f.axis[0], f.axis[0]), g01 = vec3::dot(f.axis[0], f.axis[1]), g11 = vec3::dot(f.axis[1], f.axis[1]);
    const FT det = g00 * g11 - g01 * g01;
    for (std::size_t i = 3; i < v.size(); ++i) {
      const Vec3<FT> d = vec3::sub(v[i], v[0]);
      const FT r0 = vec3::dot(f.axis[0], d), r1 = vec3::dot(f.axis[1], d);
      f.domain.push_back({(g11 * r0 - g01 * r1) / det, (g00 * r1 - g01 * r0) / det});
    }
  }
  return f;
}


Vec3<Interval> enclose3(const Vec3E& x) { return {to_interval(x[0]), to_interval(x[1]), to_interval(x[2])}; }

FeatureGeometry<double> midpoint(const FeatureGeometry<Interval>& e) {
  auto cv = [](const Interval& x) { return CGAL::to_double(x); };
  FeatureGeometry<double> f;
  f.dim = e.dim;
  f.orientation = e.orientation;
  for (int i = 0; i < 3; ++i) {
    f.origin[i] = cv(e.origin[i]);
    f.axis[0][i] = cv(e.axis[0][i]);
    f.axis[1][i] = cv(e.axis[1][i]);
  }
  for (int i = 0; i < 9; ++i) f.rho2[i] = cv(e.rho2[i]);
  for (const auto& d : e.domain) f.domain.push_back({cv(d[0]), cv(d[1])});
  return f;
}

// The feature list of a body, in a fixed order shared by the interval and
// exact tables: faces = convex pieces (skipping pieces degenerate under a
// singular pose), edges = piece edges (shared diagonals once), segments,
// points as degenerate edges; vertices = polygon vertices, segment ends,
// points.  See proofs/contact-tests.md for why this set is complete.
// Cells: one per convex piece, holding its face (if not degenerate), the
// edges it lists first and the polygon vertices of which it is the first
// piece to list them; a cell per segment (its edge and two end vertices)
// and per point (its degenerate edge and vertex); a polygon vertex no piece
// lists gets a cell of its own; cells owning nothing are dropped.  So every
// feature is in exactly one cell (proofs/hierarchy.md section 3).
struct CellList {
  int face = -1;
  std::vector<std::uint32_t> edges, vertices;
};

struct FeatureList {
  std::vector<std::pair<std::vector<Vec3E>, int>> faces;
  std::vector<std::pair<std::array<Vec3E, 2>, int>> edges;
  std::vector<std::pair<Vec3E, int>> vertices;
  std::vector<CellList> cells;
};

FeatureList feature_list(const Body& body, const std::function<Vec3E(const Vec3E&)>& place) {
  FeatureList out;
  const int first_segment = static_cast<int>(body.polygons.size());
  const int first_point = first_segment + static_cast<int>(body.segments.size());
  // Each distinct input vertex is placed once; placed points are numbered
  // (a singular pose may merge input vertices).
  PointIds inputs, placed;
  std::vector<std::uint32_t> placed_of;  // input id -> placed id
  auto placed_id = [&](const Vec3E& x) {
    const std::uint32_t i = inputs.id(x);
    if (i == placed_of.size()) placed_of.push_back(placed.id(place(x)));
    return placed_of[i];
  };
  std::unordered_set<std::uint64_t> seen;               // edges by their two placed ids
  std::vector<std::int64_t> vertex_cell;                // placed id -> first piece's cell listing it
  for (const ConvexPiece& piece : body.pieces) {
    CellList cell;
    std::vector<std::uint32_t> ids;
    for (const Vec3E& x : piece.vertices) ids.push_back(placed_id(x));
    std::vector<Vec3E> v;
    for (std::uint32_t id : ids) v.push_back(placed.point(id));
    // Degenerate only under a singular pose: its point set is then the union
    // of its edges, which stay features.
    if (!collinear(v[0], v[1], v[2])) {
      cell.face = static_cast<int>(out.faces.size());
      out.faces.push_back({v, piece.polygon});
    }
    for (std::size_t k = 0; k < v.size(); ++k) {
      const std::uint32_t a = ids[k], b = ids[(k + 1) % v.size()];
      const std::uint64_t key = (std::uint64_t(std::min(a, b)) << 32) | std::max(a, b);
      if (seen.insert(key).second) {
        cell.edges.push_back(static_cast<std::uint32_t>(out.edges.size()));
        out.edges.push_back({{v[k], v[(k + 1) % v.size()]}, piece.polygon});
      }
    }
    if (vertex_cell.size() < placed.size()) vertex_cell.resize(placed.size(), -1);
    for (std::uint32_t id : ids)
      if (vertex_cell[id] < 0) vertex_cell[id] = static_cast<std::int64_t>(out.cells.size());
    out.cells.push_back(std::move(cell));
  }
  // Vertices once each (a vertex shared by polygons is one feature; the
  // first polygon names it).
  std::vector<char> vertex_seen;
  for (std::size_t i = 0; i < body.polygons.size(); ++i)
    for (const Vec3E& x : body.polygons[i]) {
      const std::uint32_t id = placed_id(x);
      if (vertex_seen.size() < placed.size()) vertex_seen.resize(placed.size(), 0);
      if (vertex_seen[id]) continue;
      vertex_seen[id] = 1;
      const auto index = static_cast<std::uint32_t>(out.vertices.size());
      if (id < vertex_cell.size() && vertex_cell[id] >= 0) out.cells[vertex_cell[id]].vertices.push_back(index);
      else out.cells.push_back(CellList{-1, {}, {index}});
      out.vertices.push_back({placed.point(id), static_cast<int>(i)});
    }
  std::erase_if(out.cells, [](const CellList& c) { return c.face < 0 && c.edges.empty() && c.vertices.empty(); });
  for (std::size_t i = 0; i < body.segments.size(); ++i) {
    const int part = first_segment + static_cast<int>(i);
    const Vec3E p = place(body.segments[i][0]), q = place(body.segments[i][1]);
    const auto e = static_cast<std::uint32_t>(out.edges.size()), w = static_cast<std::uint32_t>(out.vertices.size());
    out.cells.push_back(CellList{-1, {e}, {w, w + 1}});
    out.edges.push_back({{p, q}, part});
    out.vertices.push_back({p, part});
    out.vertices.push_back({q, part});
  }
  for (std::size_t i = 0; i < body.points.size(); ++i) {
    const int part = first_point + static_cast<int>(i);
    const Vec3E p = place(body.points[i]);
    out.cells.push_back(CellList{-1, {static_cast<std::uint32_t>(out.edges.size())},
                                 {static_cast<std::uint32_t>(out.vertices.size())}});
    out.edges.push_back({{p, p}, part});
    out.vertices.push_back({p, part});
  }
  return out;
}

// An enclosure of G^-1 by interval Gauss-Jordan (no pivoting: G is positive
// definite).  Nothing when a pivot is not certainly positive.
std::optional<std::array<Interval, 16>> interval_inverse(const std::array<Interval, 16>& g) {
  RoundingGuard guard;
  Interval m[4][8];
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) {
      m[r][c] = g[4 * r + c];
      m[r][c + 4] = Interval(r == c ? 1 : 0);
    }
  for (int k = 0; k < 4; ++k) {
    if (!(m[k][k].inf() > 0)) return std::nullopt;
    const Interval pivot = m[k][k];
    for (int c = 0; c < 8; ++c) m[k][c] /= pivot;
    for (int r = 0; r < 4; ++r) {
      if (r == k) continue;
      const Interval f = m[r][k];
      for (int c = 0; c < 8; ++c) m[r][c] -= f * m[k][c];
    }
  }
  std::array<Interval, 16> inv;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) inv[4 * r + c] = m[r][c + 4];
  for (const Interval& x : inv)
    if (!std::isfinite(x.inf()) || !std::isfinite(x.sup())) return std::nullopt;
  return inv;
}

}  // namespace

// A body with a tolerance is prepared as a moving one (body frame, metric)
// even when it stands still: the search moves it within its tolerance.
PreparedBody::PreparedBody(const Body& b) : body(&b), moving(b.moves() || b.tolerance > 0), pose_(kIdentity) {
  if (b.motion && !moving) pose_ = b.motion->control_points[0];
  const bool identity = pose_ == kIdentity;
  auto place = [&](const Vec3E& x) { return moving || identity ? x : vec3::apply(pose_, x); };

  // Static parts, exact.
  for (std::size_t i = 0; i < b.polygons.size(); ++i) parts.push_back({"polygon " + std::to_string(i), {}});
  for (const ConvexPiece& piece : b.pieces) {
    std::vector<Vec3E> v;
    for (const Vec3E& x : piece.vertices) v.push_back(place(x));
    for (std::size_t k = 1; k + 1 < v.size(); ++k) parts[piece.polygon].simplices.push_back(Simplex{3, {v[0], v[k], v[k + 1]}});
  }
  for (std::size_t i = 0; i < b.segments.size(); ++i) {
    const Vec3E p = place(b.segments[i][0]), q = place(b.segments[i][1]);
    parts.push_back({"segment " + std::to_string(i), {Simplex{2, {p, q, q}}}});
  }
  for (std::size_t i = 0; i < b.points.size(); ++i) {
    const Vec3E p = place(b.points[i]);
    parts.push_back({"point " + std::to_string(i), {Simplex{1, {p, p, p}}}});
  }

  // Metric, enclosed by intervals.
  std::optional<std::array<Interval, 16>> gi;
  if (moving) {
    if (b.motion) curve = homogeneous_curve(*b.motion);
    {
      RoundingGuard guard;
      metric_data.g_interval.fill(Interval(0));
      for (std::size_t i = 0; i < b.mass.points.size(); ++i) {
        const Vec3<Interval> p = enclose3(b.mass.points[i]);
        const Interval h[4] = {p[0], p[1], p[2], Interval(1)};
        const Interval w = to_interval(b.mass.weights[i]);
        for (int r = 0; r < 4; ++r)
          for (int c = 0; c < 4; ++c) metric_data.g_interval[4 * r + c] += w * h[r] * h[c];
      }
    }
    for (int i = 0; i < 16; ++i) metric_data.g_double[i] = CGAL::to_double(metric_data.g_interval[i]);
    metric_data.exact = [this]() -> const Metric& { return exact_metric(); };
    gi = interval_inverse(metric_data.g_interval);
    if (!gi) {  // ill-conditioned: enclose the exact inverse instead
      std::array<Interval, 16> e;
      for (int i = 0; i < 16; ++i) e[i] = to_interval(exact_metric().inverse()[i]);
      gi = e;
    }
  }

  // Features, enclosed by intervals (computed from enclosures of the exact
  // coordinates under the rounding guard).
  const FeatureList list = feature_list(b, place);
  const std::array<Interval, 16>* g = gi ? &*gi : nullptr;
  // Enclosures of the features' exact points, each computed once.
  std::vector<std::vector<Vec3<Interval>>> face_points, edge_points, vertex_points;
  for (const auto& [v, part] : list.faces) {
    face_points.emplace_back();
    for (const Vec3E& x : v) face_points.back().push_back(enclose3(x));
  }
  for (const auto& [e, part] : list.edges) edge_points.push_back({enclose3(e[0]), enclose3(e[1])});
  for (const auto& [v, part] : list.vertices) vertex_points.push_back({enclose3(v)});
  RoundingGuard guard;
  for (std::size_t i = 0; i < list.faces.size(); ++i) {
    faces.interval.push_back(make_face<Interval>(face_points[i], g));
    faces.part.push_back(list.faces[i].second);
  }
  for (std::size_t i = 0; i < list.edges.size(); ++i) {
    edges.interval.push_back(make_edge<Interval>(edge_points[i][0], edge_points[i][1], g));
    edges.part.push_back(list.edges[i].second);
  }
  double best = 0;
  for (std::size_t i = 0; i < list.vertices.size(); ++i) {
    vertices.interval.push_back(make_vertex<Interval>(vertex_points[i][0], g));
    vertices.part.push_back(list.vertices[i].second);
    best = std::max(best, vertices.interval.back().q(2, 2).sup());
  }
  max_rho2 = best;
  for (FeatureTable* t : {&vertices, &edges, &faces})
    for (auto& f : t->interval) {
      f.rho2_max = detail::max_rho2(f).sup();  // once here, not per contact test
      t->approx.push_back(midpoint(f));
      if (!moving) {  // world coordinates: the axis test's vertex images, once
        std::array<Vec3<Interval>, detail::kAxisMaxVertices> tmp;
        const std::size_t n = detail::vertex_images<Interval>(f, nullptr, tmp.data());
        t->image_first.push_back(static_cast<std::uint32_t>(t->images.size()));
        t->image_count.push_back(static_cast<std::uint8_t>(n));
        t->images.insert(t->images.end(), tmp.begin(), tmp.begin() + n);
      }
    }

  // A sphere per feature and the hierarchy over the cells (spheres around
  // the vertex enclosures; a cell's sphere around those of all its
  // features).
  faces.spheres = item_spheres(face_points, g);
  edges.spheres = item_spheres(edge_points, g);
  vertices.spheres = item_spheres(vertex_points, g);
  std::vector<std::vector<Vec3<Interval>>> cell_points;
  for (const CellList& c : list.cells) {
    cells.face.push_back(c.face);
    cell_points.emplace_back();
    std::vector<Vec3<Interval>>& pts = cell_points.back();
    if (c.face >= 0) pts = face_points[c.face];
    for (std::uint32_t e : c.edges) {
      cells.edges.push_back(e);
      pts.insert(pts.end(), edge_points[e].begin(), edge_points[e].end());
    }
    for (std::uint32_t w : c.vertices) {
      cells.vertices.push_back(w);
      pts.push_back(vertex_points[w][0]);
    }
    cells.edge_begin.push_back(static_cast<std::uint32_t>(cells.edges.size()));
    cells.vertex_begin.push_back(static_cast<std::uint32_t>(cells.vertices.size()));
  }
  build_cell_tree(cells, cell_points, g);
}

const Metric& PreparedBody::exact_metric() const {
  std::call_once(metric_once_, [this] { metric_ = std::make_unique<const Metric>(Metric::from_mass(body->mass)); });
  return *metric_;
}

std::vector<Vec3E> PreparedBody::placed(const std::vector<Vec3E>& points) const {
  std::vector<Vec3E> out;
  for (const Vec3E& x : points) out.push_back(moving || pose_ == kIdentity ? x : vec3::apply(pose_, x));
  return out;
}

const ExactFeatureVertices& PreparedBody::exact_vertices() const {
  std::call_once(vertices_once_, [this] {
    auto e = std::make_unique<ExactFeatureVertices>();
    const bool identity = pose_ == kIdentity;
    const FeatureList list =
        feature_list(*body, [&](const Vec3E& x) { return moving || identity ? x : vec3::apply(pose_, x); });
    for (const auto& [v, part] : list.faces) e->faces.push_back(v);
    for (const auto& [ed, part] : list.edges) e->edges.push_back({ed[0], ed[1]});
    for (const auto& [v, part] : list.vertices) e->vertices.push_back({v});
    vertices_ = std::move(e);
  });
  return *vertices_;
}

const ExactFeatures& PreparedBody::exact() const {
  std::call_once(exact_once_, [this] {
    auto e = std::make_unique<ExactFeatures>();
    const Mat44E* gi = moving ? &exact_metric().inverse() : nullptr;
    const bool identity = pose_ == kIdentity;
    const FeatureList list =
        feature_list(*body, [&](const Vec3E& x) { return moving || identity ? x : vec3::apply(pose_, x); });
    for (const auto& [v, part] : list.faces) e->faces.push_back(make_face<Exact>(v, gi));
    for (const auto& [ed, part] : list.edges) e->edges.push_back(make_edge<Exact>(ed[0], ed[1], gi));
    for (const auto& [v, part] : list.vertices) e->vertices.push_back(make_vertex<Exact>(v, gi));
    exact_ = std::move(e);
  });
  return *exact_;
}

SweptBox swept_box(const Body& body) {
  // A tolerance: no box (such a check is never cleared by the prefilter).
  if (body.tolerance > 0) return SweptBox{};
  std::vector<Mat34E> maps;
  if (body.motion) maps = body.motion->control_points;
  else if (!body.trajectory) maps.push_back(kIdentity);
  std::vector<std::array<Interval, 12>> imaps;
  for (const Mat34E& m : maps) {
    std::array<Interval, 12> im;
    for (int e = 0; e < 12; ++e) im[e] = to_interval(m[e]);
    imaps.push_back(im);
  }
  if (body.trajectory)
    for (const MotionSegment& seg : body.trajectory->segments) {
      if (const Motion* rational = kind_of(seg).rational(seg)) {  // the convex hull property, segment by segment
        for (const Mat34E& m : rational->control_points) {
          std::array<Interval, 12> im;
          for (int e = 0; e < 12; ++e) im[e] = to_interval(m[e]);
          imaps.push_back(im);
        }
        continue;
      }
      // An enclosed segment: interval maps holding every pose of each
      // eighth of it (every vertex image then lies in its interval box).
      const std::unique_ptr<SegmentModel> model = make_segment_model(seg);
      constexpr int kSlices = 8;
      RoundingGuard guard;
      for (int k = 0; k < kSlices; ++k) {
        imaps.push_back(model->pose_values(Interval(static_cast<double>(k) / kSlices, static_cast<double>(k + 1) / kSlices)));
      }
    }
  SweptBox box;
  bool nan = false;
  box.lo.fill(std::numeric_limits<double>::infinity());
  box.hi.fill(-std::numeric_limits<double>::infinity());
  std::vector<Vec3E> all;
  for (const auto& poly : body.polygons) all.insert(all.end(), poly.begin(), poly.end());
  for (const auto& s : body.segments) all.insert(all.end(), s.begin(), s.end());
  all.insert(all.end(), body.points.begin(), body.points.end());
  const bool keep = all.size() <= static_cast<std::size_t>(kSweptPointsMax);
  if (keep) {
    box.vertices = static_cast<int>(all.size());
    box.points.resize(all.size() * imaps.size());
  }
  int vertex = 0;
  auto add_point = [&](const Vec3E& x) {
    const Vec3<Interval> xi = enclose3(x);
    RoundingGuard guard;
    for (std::size_t k = 0; k < imaps.size(); ++k) {
      const auto& m = imaps[k];
      for (int i = 0; i < 3; ++i) {
        const Interval y = m[4 * i] * xi[0] + m[4 * i + 1] * xi[1] + m[4 * i + 2] * xi[2] + m[4 * i + 3];
        if (std::isnan(y.inf()) || std::isnan(y.sup())) nan = true;  // std::min would drop it
        box.lo[i] = std::min(box.lo[i], y.inf());
        box.hi[i] = std::max(box.hi[i], y.sup());
        if (keep) box.points[k * all.size() + vertex][i] = y;
      }
    }
    ++vertex;
  };
  for (const Vec3E& x : all) add_point(x);
  box.valid = !nan;
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(box.lo[i]) || !std::isfinite(box.hi[i]) || !(box.lo[i] <= box.hi[i])) box.valid = false;
  return box;
}

namespace {

using V3 = std::array<double, 3>;

V3 mid(const std::array<Interval, 3>& x) { return {CGAL::to_double(x[0]), CGAL::to_double(x[1]), CGAL::to_double(x[2])}; }

// Projection range of interval points on a fixed axis; false on NaN.
bool project(const std::vector<std::array<Interval, 3>>& pts, const V3& n, double& lo, double& hi) {
  lo = std::numeric_limits<double>::infinity();
  hi = -lo;
  for (const auto& p : pts) {
    const Interval d = p[0] * n[0] + p[1] * n[1] + p[2] * n[2];
    if (std::isnan(d.inf()) || std::isnan(d.sup())) return false;
    lo = std::min(lo, d.inf());
    hi = std::max(hi, d.sup());
  }
  return true;
}

// Candidate axes from approximate geometry (any fixed axis is sound): for
// each pose, the edges of each body, their cross products across bodies and
// each body's triangle normals; and the line between the hulls' centroids.
bool separated_hulls(const SweptBox& a, const SweptBox& b) {
  const std::size_t poses_a = a.points.size() / a.vertices, poses_b = b.points.size() / b.vertices;
  std::vector<V3> axes;
  auto edges = [](const SweptBox& s, std::size_t k) {
    std::vector<V3> e;
    for (int i = 0; i < s.vertices; ++i)
      for (int j = i + 1; j < s.vertices; ++j)
        e.push_back(vec3::sub(mid(s.points[k * s.vertices + j]), mid(s.points[k * s.vertices + i])));
    return e;
  };
  for (std::size_t k : {std::size_t(0), poses_a - 1})
    for (std::size_t l : {std::size_t(0), poses_b - 1}) {
      const std::vector<V3> ea = edges(a, k), eb = edges(b, l);
      for (const V3& x : ea)
        for (const V3& y : eb) axes.push_back(vec3::cross(x, y));
      if (ea.size() >= 3) axes.push_back(vec3::cross(ea[0], ea[1]));
      if (eb.size() >= 3) axes.push_back(vec3::cross(eb[0], eb[1]));
      // A moving vertex against the other body's edges: its path direction.
      if (a.vertices == 1 && poses_a > 1)
        for (const V3& y : eb) axes.push_back(vec3::cross(vec3::sub(mid(a.points.back()), mid(a.points.front())), y));
      if (b.vertices == 1 && poses_b > 1)
        for (const V3& x : ea) axes.push_back(vec3::cross(vec3::sub(mid(b.points.back()), mid(b.points.front())), x));
    }
  V3 ca{0, 0, 0}, cb{0, 0, 0};
  for (const auto& p : a.points) { const V3 m = mid(p); for (int i = 0; i < 3; ++i) ca[i] += m[i]; }
  for (const auto& p : b.points) { const V3 m = mid(p); for (int i = 0; i < 3; ++i) cb[i] += m[i]; }
  for (int i = 0; i < 3; ++i) { ca[i] /= a.points.size(); cb[i] /= b.points.size(); }
  axes.push_back(vec3::sub(cb, ca));
  RoundingGuard guard;
  for (const V3& n : axes) {
    if (!std::isfinite(n[0]) || !std::isfinite(n[1]) || !std::isfinite(n[2])) continue;
    if (n[0] == 0 && n[1] == 0 && n[2] == 0) continue;
    double alo, ahi, blo, bhi;
    if (!project(a.points, n, alo, ahi) || !project(b.points, n, blo, bhi)) continue;
    if (ahi < blo || bhi < alo) return true;
  }
  return false;
}

}  // namespace

bool disjoint(const SweptBox& a, const SweptBox& b) {
  if (!a.valid || !b.valid) return false;
  for (int i = 0; i < 3; ++i)
    if (a.hi[i] < b.lo[i] || b.hi[i] < a.lo[i]) return true;
  if (a.vertices > 0 && b.vertices > 0) return separated_hulls(a, b);
  return false;
}

std::vector<StaticPart> transformed_parts(const PreparedBody& body, const Mat34E& map) {
  std::vector<StaticPart> out = body.parts;
  for (StaticPart& part : out)
    for (Simplex& s : part.simplices)
      for (int k = 0; k < s.count; ++k) s.p[k] = vec3::apply(map, s.p[k]);
  return out;
}

}  // namespace tmcert
