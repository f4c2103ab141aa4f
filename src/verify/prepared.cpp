#include "src/verify/prepared.h"

#include <CGAL/number_utils.h>

#include <cmath>
#include <limits>
#include <map>

namespace tmcert {

namespace {

Vec3E apply_map(const Mat34E& m, const Vec3E& x) {
  Vec3E r;
  for (int i = 0; i < 3; ++i) r[i] = m[4 * i] * x[0] + m[4 * i + 1] * x[1] + m[4 * i + 2] * x[2] + m[4 * i + 3];
  return r;
}

Vec3E sub(const Vec3E& a, const Vec3E& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Exact dot(const Vec3E& a, const Vec3E& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// rho^2 quadratic of x(s) = origin + s1 a0 + s2 a1: Q = M^T G^-1 M with
// M = [a0 a1 origin; 0 0 1] (4x3).  Zero when the body has no metric.
void set_rho2(FeatureGeometry<Exact>& f, const Metric* metric) {
  for (auto& q : f.rho2) q = 0;
  if (!metric) return;
  const Mat44E& gi = metric->inverse();
  Exact m[4][3];
  for (int r = 0; r < 3; ++r) {
    m[r][0] = f.axis[0][r];
    m[r][1] = f.axis[1][r];
    m[r][2] = f.origin[r];
  }
  m[3][0] = 0;
  m[3][1] = 0;
  m[3][2] = 1;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      Exact s = 0;
      for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) s += m[r][i] * gi[4 * r + c] * m[c][j];
      f.rho2[3 * i + j] = s;
    }
}

FeatureGeometry<Exact> make_vertex(const Vec3E& p, const Metric* metric) {
  FeatureGeometry<Exact> f;
  f.dim = 0;
  f.origin = p;
  f.axis = {Vec3E{0, 0, 0}, Vec3E{0, 0, 0}};
  set_rho2(f, metric);
  return f;
}

FeatureGeometry<Exact> make_edge(const Vec3E& p, const Vec3E& q, const Metric* metric) {
  FeatureGeometry<Exact> f;
  f.dim = 1;
  f.origin = p;
  f.axis = {sub(q, p), Vec3E{0, 0, 0}};
  set_rho2(f, metric);
  return f;
}

// A convex polygon (>= 3 vertices, consecutive ones not collinear).  Nothing
// when the polygon is degenerate (a fixed body under a singular pose): its
// point set is then the union of its edges, which are features of their own.
std::optional<FeatureGeometry<Exact>> make_face(const std::vector<Vec3E>& v, const Metric* metric) {
  FeatureGeometry<Exact> f;
  f.dim = 2;
  f.origin = v[0];
  f.axis = {sub(v[1], v[0]), sub(v[2], v[0])};
  set_rho2(f, metric);
  // Parameter coordinates of every vertex: solve the 2x2 Gram system.
  const Exact g00 = dot(f.axis[0], f.axis[0]), g01 = dot(f.axis[0], f.axis[1]), g11 = dot(f.axis[1], f.axis[1]);
  const Exact det = g00 * g11 - g01 * g01;  // > 0 iff the axes are independent
  if (det == 0) return std::nullopt;
  Exact area2 = 0;
  for (const Vec3E& p : v) {
    const Vec3E d = sub(p, v[0]);
    const Exact r0 = dot(f.axis[0], d), r1 = dot(f.axis[1], d);
    f.domain.push_back({(g11 * r0 - g01 * r1) / det, (g00 * r1 - g01 * r0) / det});
  }
  for (std::size_t i = 0; i < f.domain.size(); ++i) {
    const auto& a = f.domain[i];
    const auto& b = f.domain[(i + 1) % f.domain.size()];
    area2 += a[0] * b[1] - a[1] * b[0];
  }
  f.orientation = area2 > 0 ? 1 : -1;
  return f;
}

template <class FT, class Convert>
FeatureGeometry<FT> convert(const FeatureGeometry<Exact>& e, Convert cv) {
  FeatureGeometry<FT> f;
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

void add(FeatureTable& t, FeatureGeometry<Exact> f, int part) {
  t.interval.push_back(convert<Interval>(f, [](const Exact& x) { return to_interval(x); }));
  t.approx.push_back(convert<double>(f, [](const Exact& x) { return CGAL::to_double(x); }));
  t.exact.push_back(std::move(f));
  t.part.push_back(part);
}

}  // namespace

PreparedBody prepare_body(const Body& body) {
  PreparedBody pb;
  pb.body = &body;
  pb.moving = body.motion && body.motion->degree() >= 1;
  Mat34E pose = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
  if (body.motion && !pb.moving) pose = body.motion->control_points[0];
  auto place = [&](const Vec3E& x) { return pb.moving ? x : apply_map(pose, x); };

  if (pb.moving) {
    pb.metric = std::make_unique<const Metric>(Metric::from_mass(body.mass));
    pb.metric_data = std::make_unique<MetricData>(*pb.metric);
    pb.curve = homogeneous_curve(*body.motion);
  }
  const Metric* metric = pb.metric.get();

  // Static parts and vertices.
  const int first_segment = static_cast<int>(body.polygons.size());
  const int first_point = first_segment + static_cast<int>(body.segments.size());
  for (std::size_t i = 0; i < body.polygons.size(); ++i)
    pb.parts.push_back({"polygon " + std::to_string(i), {}});
  for (const ConvexPiece& piece : body.pieces) {
    std::vector<Vec3E> v;
    for (const Vec3E& x : piece.vertices) v.push_back(place(x));
    for (std::size_t k = 1; k + 1 < v.size(); ++k)
      pb.parts[piece.polygon].simplices.push_back(Simplex{3, {v[0], v[k], v[k + 1]}});
    if (auto face = make_face(v, metric)) add(pb.faces, std::move(*face), piece.polygon);
  }
  // Edges of the convex pieces (shared diagonals once), then segments and
  // points (a point is a degenerate edge, see proofs/contact-tests.md).
  std::map<std::pair<Vec3E, Vec3E>, bool> seen;
  for (const ConvexPiece& piece : body.pieces) {
    const std::size_t n = piece.vertices.size();
    for (std::size_t k = 0; k < n; ++k) {
      Vec3E p = place(piece.vertices[k]), q = place(piece.vertices[(k + 1) % n]);
      auto key = p < q ? std::pair{p, q} : std::pair{q, p};
      if (seen.emplace(key, true).second) add(pb.edges, make_edge(p, q, metric), piece.polygon);
    }
  }
  for (std::size_t i = 0; i < body.polygons.size(); ++i)
    for (const Vec3E& x : body.polygons[i]) add(pb.vertices, make_vertex(place(x), metric), static_cast<int>(i));
  for (std::size_t i = 0; i < body.segments.size(); ++i) {
    const int part = first_segment + static_cast<int>(i);
    const Vec3E p = place(body.segments[i][0]), q = place(body.segments[i][1]);
    pb.parts.push_back({"segment " + std::to_string(i), {Simplex{2, {p, q, q}}}});
    add(pb.edges, make_edge(p, q, metric), part);
    add(pb.vertices, make_vertex(p, metric), part);
    add(pb.vertices, make_vertex(q, metric), part);
  }
  for (std::size_t i = 0; i < body.points.size(); ++i) {
    const int part = first_point + static_cast<int>(i);
    const Vec3E p = place(body.points[i]);
    pb.parts.push_back({"point " + std::to_string(i), {Simplex{1, {p, p, p}}}});
    add(pb.edges, make_edge(p, p, metric), part);
    add(pb.vertices, make_vertex(p, metric), part);
  }
  if (metric) {
    Exact best = 0;
    for (const auto& v : pb.vertices.exact)
      if (v.q(2, 2) > best) best = v.q(2, 2);
    pb.max_rho2 = CGAL::to_double(best);
  }
  return pb;
}

SweptBox swept_box(const Body& body) {
  std::vector<Mat34E> maps;
  if (body.motion) maps = body.motion->control_points;
  else maps.push_back({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0});
  std::vector<std::array<Interval, 12>> imaps;
  for (const Mat34E& m : maps) {
    std::array<Interval, 12> im;
    for (int e = 0; e < 12; ++e) im[e] = to_interval(m[e]);
    imaps.push_back(im);
  }
  SweptBox box;
  box.lo.fill(std::numeric_limits<double>::infinity());
  box.hi.fill(-std::numeric_limits<double>::infinity());
  auto add_point = [&](const Vec3E& x) {
    const Interval xi[3] = {to_interval(x[0]), to_interval(x[1]), to_interval(x[2])};
    RoundingGuard guard;
    for (const auto& m : imaps)
      for (int i = 0; i < 3; ++i) {
        const Interval y = m[4 * i] * xi[0] + m[4 * i + 1] * xi[1] + m[4 * i + 2] * xi[2] + m[4 * i + 3];
        box.lo[i] = std::min(box.lo[i], y.inf());
        box.hi[i] = std::max(box.hi[i], y.sup());
      }
  };
  for (const auto& poly : body.polygons)
    for (const Vec3E& x : poly) add_point(x);
  for (const auto& s : body.segments) {
    add_point(s[0]);
    add_point(s[1]);
  }
  for (const Vec3E& x : body.points) add_point(x);
  box.valid = true;
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(box.lo[i]) || !std::isfinite(box.hi[i]) || !(box.lo[i] <= box.hi[i])) box.valid = false;
  return box;
}

bool disjoint(const SweptBox& a, const SweptBox& b) {
  if (!a.valid || !b.valid) return false;
  for (int i = 0; i < 3; ++i)
    if (a.hi[i] < b.lo[i] || b.hi[i] < a.lo[i]) return true;
  return false;
}

std::vector<StaticPart> transformed_parts(const PreparedBody& body, const Mat34E& map) {
  std::vector<StaticPart> out = body.parts;
  for (StaticPart& part : out)
    for (Simplex& s : part.simplices)
      for (int k = 0; k < s.count; ++k) s.p[k] = apply_map(map, s.p[k]);
  return out;
}

}  // namespace tmcert
