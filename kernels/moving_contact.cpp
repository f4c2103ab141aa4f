#include "kernels/moving_contact.h"

#include <algorithm>
#include <utility>

namespace tmcert {

namespace {

using V3 = std::array<PolyQ, 3>;

V3 diff(const MovingPoint& a, const MovingPoint& b) { return {sub(a.x[0], b.x[0]), sub(a.x[1], b.x[1]), sub(a.x[2], b.x[2])}; }

V3 cross(const V3& a, const V3& b) {
  return {sub(mul(a[1], b[2]), mul(a[2], b[1])), sub(mul(a[2], b[0]), mul(a[0], b[2])),
          sub(mul(a[0], b[1]), mul(a[1], b[0]))};
}

PolyQ dot(const V3& a, const V3& b) { return add(add(mul(a[0], b[0]), mul(a[1], b[1])), mul(a[2], b[2])); }

bool is_zero(const V3& a) { return a[0].empty() && a[1].empty() && a[2].empty(); }

CGAL::Sign sign(const PolyQ& p, RealRoot& r) { return p.empty() ? CGAL::ZERO : sign_at(primitive(p), r); }

bool zero_at(const V3& a, RealRoot& r) {
  for (const PolyQ& p : a)
    if (sign(p, r) != CGAL::ZERO) return false;
  return true;
}

// gcd of the nonzero components (their common roots); a is not zero.
PolyZ common(const V3& a) {
  PolyZ g;
  for (const PolyQ& p : a) {
    if (p.empty()) continue;
    g = g.empty() ? primitive(p) : gcd(g, primitive(p));
    if (degree(g) == 0) break;
  }
  return g;
}

// The area vector of a polygon: sum of (p_k - p_0) x (p_(k+1) - p_0);
// zero exactly when the (convex) polygon is collapsed to a segment or point.
V3 area_vector(const std::vector<MovingPoint>& poly) {
  V3 n;
  for (std::size_t k = 1; k + 1 < poly.size(); ++k) {
    const V3 c = cross(diff(poly[k], poly[0]), diff(poly[k + 1], poly[0]));
    for (int i = 0; i < 3; ++i) n[i] = add(n[i], c[i]);
  }
  return n;
}

// Where two coplanar segments meet at r, or nothing.
std::optional<ContactPoint> meet(const MovingPoint& a0, const MovingPoint& a1, const MovingPoint& b0,
                                 const MovingPoint& b1, RealRoot& r) {
  const V3 da = diff(a1, a0), db = diff(b1, b0);
  const V3 n = cross(da, db);
  if (zero_at(n, r)) {
    // Parallel (or a segment reduced to a point): they meet exactly when an
    // endpoint of one lies on the other.
    if (ContactSolver::on_segment(a0, b0, b1, r)) return ContactPoint{{a0}};
    if (ContactSolver::on_segment(a1, b0, b1, r)) return ContactPoint{{a1}};
    if (ContactSolver::on_segment(b0, a0, a1, r)) return ContactPoint{{b0}};
    if (ContactSolver::on_segment(b1, a0, a1, r)) return ContactPoint{{b1}};
    return std::nullopt;
  }
  // In their common plane (normal n != 0): each segment's ends on opposite
  // sides of (or on) the other's line.
  auto side = [&](const V3& d, const MovingPoint& p, const MovingPoint& o) { return sign(dot(cross(d, diff(p, o)), n), r); };
  auto opposite_or_on = [](CGAL::Sign x, CGAL::Sign y) { return static_cast<int>(x) * static_cast<int>(y) <= 0; };
  if (!opposite_or_on(side(db, a0, b0), side(db, a1, b0))) return std::nullopt;
  if (!opposite_or_on(side(da, b0, a0), side(da, b1, a0))) return std::nullopt;
  return ContactPoint{{a0, a1, b0, b1}};
}

// Exact rational intervals (for the point box).
struct Range {
  Exact lo, hi;
};

Range operator+(const Range& a, const Range& b) { return {a.lo + b.lo, a.hi + b.hi}; }
Range operator*(const Range& a, const Range& b) {
  const Exact p[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
  return {*std::min_element(p, p + 4), *std::max_element(p, p + 4)};
}
// b > 0 throughout.
Range operator/(const Range& a, const Range& b) {
  const Range inv{Exact(1) / b.hi, Exact(1) / b.lo};
  return a * inv;
}

Range evaluate(const PolyQ& p, const Range& t) {
  Range acc{Exact(0), Exact(0)};
  for (int i = static_cast<int>(p.size()) - 1; i >= 0; --i) acc = acc * t + Range{p[i], p[i]};
  return acc;
}

Range intersect(const Range& a, const Range& b) { return {std::max(a.lo, b.lo), std::min(a.hi, b.hi)}; }
Range hull(const Range& a, const Range& b) { return {std::min(a.lo, b.lo), std::max(a.hi, b.hi)}; }

}  // namespace

std::optional<Contact> earlier(std::optional<Contact> a, std::optional<Contact> b) {
  if (!a) return b;
  if (!b) return a;
  return compare(b->t, a->t) == CGAL::SMALLER ? b : a;
}

bool ContactSolver::on_segment(const MovingPoint& v, const MovingPoint& e0, const MovingPoint& e1, RealRoot& r) {
  const V3 d = diff(e1, e0), q = diff(v, e0);
  if (zero_at(d, r)) return zero_at(q, r);  // the segment is a point at r
  if (!zero_at(cross(q, d), r)) return false;
  return sign(dot(q, d), r) != CGAL::NEGATIVE && sign(dot(diff(v, e1), diff(e0, e1)), r) != CGAL::NEGATIVE;
}

bool ContactSolver::in_polygon(const MovingPoint& v, const std::vector<MovingPoint>& poly, RealRoot& r) {
  const V3 n = area_vector(poly);
  const std::size_t m = poly.size();
  if (zero_at(n, r)) {  // collapsed: the polygon is the union of its edges
    for (std::size_t k = 0; k < m; ++k)
      if (on_segment(v, poly[k], poly[(k + 1) % m], r)) return true;
    return false;
  }
  for (std::size_t k = 0; k < m; ++k) {
    const V3 e = diff(poly[(k + 1) % m], poly[k]);
    if (sign(dot(cross(e, diff(v, poly[k])), n), r) == CGAL::NEGATIVE) return false;
  }
  return true;
}

bool ContactSolver::segments_meet(const MovingPoint& a0, const MovingPoint& a1, const MovingPoint& b0,
                                  const MovingPoint& b1, RealRoot& r) {
  return meet(a0, a1, b0, b1, r).has_value();
}

bool ContactSolver::touch(const std::vector<MovingPoint>& a, const std::vector<MovingPoint>& b, RealRoot& r) {
  if (a.size() > 1 && b.size() == 1) return touch(b, a, r);
  if (a.size() == 1) {
    if (b.size() == 1) return on_segment(a[0], b[0], b[0], r);  // a segment reduced to the point b
    if (b.size() == 2) return on_segment(a[0], b[0], b[1], r);
    return sign(dot(area_vector(b), diff(a[0], b[0])), r) == CGAL::ZERO && in_polygon(a[0], b, r);
  }
  if (a.size() == 2 && b.size() == 2)
    return sign(dot(cross(diff(a[1], a[0]), diff(b[1], b[0])), diff(b[0], a[0])), r) == CGAL::ZERO &&
           segments_meet(a[0], a[1], b[0], b[1], r);
  return false;
}

std::optional<Contact> ContactSolver::vertex_vertex(const MovingPoint& a, const MovingPoint& b) const {
  const V3 d = diff(a, b);
  if (is_zero(d)) return Contact{rational_root(u0_), {{a}}};  // the same point throughout
  const PolyZ g = common(d);
  if (degree(g) <= 0) return std::nullopt;
  std::vector<RealRoot> roots = real_roots(square_free(g), u0_, u1_);
  if (roots.empty()) return std::nullopt;
  return Contact{roots.front(), {{a}}};
}

std::optional<Contact> ContactSolver::vertex_edge(const MovingPoint& v, const MovingPoint& e0,
                                                  const MovingPoint& e1) const {
  const V3 c = cross(diff(v, e0), diff(e1, e0));
  if (is_zero(c)) {
    // On the segment's line throughout (or the segment is a point): the
    // vertex first meets the segment at the start or at an endpoint.
    RealRoot start = rational_root(u0_);
    if (on_segment(v, e0, e1, start)) return Contact{start, {{v}}};
    return earlier(vertex_vertex(v, e0), vertex_vertex(v, e1));
  }
  const PolyZ g = common(c);
  if (degree(g) <= 0) return std::nullopt;
  for (RealRoot& r : real_roots(square_free(g), u0_, u1_))
    if (on_segment(v, e0, e1, r)) return Contact{r, {{v}}};
  return std::nullopt;
}

std::optional<Contact> ContactSolver::vertex_face(const MovingPoint& v, const std::vector<MovingPoint>& poly) const {
  const PolyQ d = dot(area_vector(poly), diff(v, poly[0]));
  if (d.empty()) {
    // In the polygon's plane throughout (or the polygon is collapsed): the
    // vertex first meets it at the start or on an edge.
    RealRoot start = rational_root(u0_);
    if (in_polygon(v, poly, start)) return Contact{start, {{v}}};
    std::optional<Contact> best;
    for (std::size_t k = 0; k < poly.size(); ++k)
      best = earlier(std::move(best), vertex_edge(v, poly[k], poly[(k + 1) % poly.size()]));
    return best;
  }
  for (RealRoot& r : real_roots(square_free(primitive(d)), u0_, u1_))
    if (in_polygon(v, poly, r)) return Contact{r, {{v}}};
  return std::nullopt;
}

std::optional<Contact> ContactSolver::edge_edge(const MovingPoint& a0, const MovingPoint& a1, const MovingPoint& b0,
                                                const MovingPoint& b1) const {
  const PolyQ d = dot(cross(diff(a1, a0), diff(b1, b0)), diff(b0, a0));
  if (d.empty()) {
    // In one plane throughout (parallel, coplanar or degenerate): the
    // segments first meet at the start or with an endpoint on the other.
    RealRoot start = rational_root(u0_);
    if (auto where = meet(a0, a1, b0, b1, start)) return Contact{start, std::move(*where)};
    std::optional<Contact> best = vertex_edge(a0, b0, b1);
    best = earlier(std::move(best), vertex_edge(a1, b0, b1));
    best = earlier(std::move(best), vertex_edge(b0, a0, a1));
    return earlier(std::move(best), vertex_edge(b1, a0, a1));
  }
  for (RealRoot& r : real_roots(square_free(primitive(d)), u0_, u1_))
    if (auto where = meet(a0, a1, b0, b1, r)) return Contact{r, std::move(*where)};
  return std::nullopt;
}

std::array<std::array<Exact, 2>, 3> point_box(Contact& c, const PolyQ& weight) {
  // Narrow the time, then enclose the point with exact interval arithmetic
  // over it; the bounds are rounded outward to doubles (short numbers).
  Integer two80(1);
  mpz_mul_2exp(two80.mpz(), two80.mpz(), 80);
  const Exact width = Exact(Integer(1), two80);
  refine_to(c.t, width);
  const Range t{c.t.lo, c.t.hi};
  const Range w = evaluate(weight, t);
  if (!(w.lo > 0)) throw ExactLimit("point_box: weight range not positive");
  auto place = [&](const MovingPoint& p) {
    std::array<Range, 3> out;
    for (int i = 0; i < 3; ++i) out[i] = evaluate(p.x[i], t) / w;
    return out;
  };
  std::array<Range, 3> box;
  const auto& pts = c.where.points;
  if (pts.size() == 1) {
    box = place(pts[0]);
  } else {
    // On both segments: inside both hulls; and a0 + s (a1 - a0) with s from
    // the lines' equations when their directions are far from parallel.
    const auto A0 = place(pts[0]), A1 = place(pts[1]), B0 = place(pts[2]), B1 = place(pts[3]);
    for (int i = 0; i < 3; ++i) box[i] = intersect(hull(A0[i], A1[i]), hull(B0[i], B1[i]));
    const V3 da = diff(pts[1], pts[0]), db = diff(pts[3], pts[2]);
    const V3 n = cross(da, db);
    const Range nn = evaluate(dot(n, n), t);
    if (nn.lo > 0) {
      const Range s = evaluate(dot(cross(diff(pts[2], pts[0]), db), n), t) / nn;
      for (int i = 0; i < 3; ++i) {
        const Range x = A0[i] + s * (evaluate(da[i], t) / w);
        box[i] = intersect(box[i], x);
      }
    }
  }
  std::array<std::array<Exact, 2>, 3> out;
  for (int i = 0; i < 3; ++i) {
    out[i][0] = Exact(to_interval(box[i].lo).inf());
    out[i][1] = Exact(to_interval(box[i].hi).sup());
  }
  return out;
}

}  // namespace tmcert
