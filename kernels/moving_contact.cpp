#include "kernels/moving_contact.h"

#include <algorithm>
#include <utility>

namespace tmcert {

namespace {

// Internally every point of one call is scaled by one positive integer to
// integer coefficients (the predicates are homogeneous in the points, so
// their signs do not change): GMP integers instead of rationals.
struct ZPoint {
  std::array<PolyZ, 3> x;
};
using V3 = std::array<PolyZ, 3>;
using Points = std::vector<ZPoint>;

// The integer images of points under one common scale, and that scale.
struct Scaled {
  Points points;
  Integer scale;
};

Scaled scaled(std::initializer_list<const std::vector<MovingPoint>*> groups) {
  Integer den(1);
  for (const auto* g : groups)
    for (const MovingPoint& m : *g)
      for (const PolyQ& p : m.x)
        for (const Exact& c : p) mpz_lcm(den.mpz(), den.mpz(), c.denominator().mpz());
  Scaled out{{}, den};
  for (const auto* g : groups)
    for (const MovingPoint& m : *g) {
      ZPoint z;
      for (int i = 0; i < 3; ++i)
        for (const Exact& c : m.x[i]) {
          Integer q;
          mpz_divexact(q.mpz(), den.mpz(), c.denominator().mpz());
          z.x[i].push_back(q * c.numerator());
        }
      out.points.push_back(std::move(z));
    }
  return out;
}

V3 diff(const ZPoint& a, const ZPoint& b) { return {sub(a.x[0], b.x[0]), sub(a.x[1], b.x[1]), sub(a.x[2], b.x[2])}; }

V3 cross(const V3& a, const V3& b) {
  return {sub(mul(a[1], b[2]), mul(a[2], b[1])), sub(mul(a[2], b[0]), mul(a[0], b[2])),
          sub(mul(a[0], b[1]), mul(a[1], b[0]))};
}

PolyZ dot(const V3& a, const V3& b) { return add(add(mul(a[0], b[0]), mul(a[1], b[1])), mul(a[2], b[2])); }

bool is_zero(const V3& a) { return a[0].empty() && a[1].empty() && a[2].empty(); }

// p / w when w (degree >= 1) divides p exactly, else nothing.  Integer
// long division: w is primitive, so by Gauss's lemma w | p in Q[u] only
// with an integer quotient; a leading coefficient not divisible by lc(w)
// means w does not divide p.
std::optional<PolyZ> divided(const PolyZ& p, const PolyZ& w) {
  const int dw = degree(w);
  if (dw < 1 || degree(p) < dw) return std::nullopt;
  PolyZ rem = p, q(p.size() - w.size() + 1);
  for (int k = degree(p) - dw; k >= 0; --k) {
    const Integer& top = rem[k + dw];
    if (top == 0) continue;
    if (!mpz_divisible_p(top.mpz(), w.back().mpz())) return std::nullopt;
    Integer c;
    mpz_divexact(c.mpz(), top.mpz(), w.back().mpz());
    for (int i = 0; i <= dw; ++i) {
      Integer t;  // fresh: Gmpz copies share their value
      mpz_mul(t.mpz(), c.mpz(), w[i].mpz());
      rem[k + i] = rem[k + i] - t;
    }
    q[k] = c;
  }
  for (int i = 0; i < dw; ++i)
    if (rem[i] != 0) return std::nullopt;
  trim(q);
  return q;
}

const PolyZ kNoFactor;

// p without the factors of w (a primitive polynomial positive on the
// piece, or empty: none): p = w^k q with w > 0 gives q the same roots and
// signs there.
PolyZ reduced(PolyZ p, const PolyZ& w) {
  if (w.empty() || p.empty()) return p;
  while (std::optional<PolyZ> q = divided(p, w)) p = std::move(*q);
  return p;
}

// a / w^k for the largest k with w^k dividing every component (w positive
// on the piece or empty): the same direction at every u of the piece, so
// every sign and zero of a product with it is that of a (§3). A fixed
// polygon's points are w y: its edges lose a factor w, its area vector w².
V3 reduced_all(V3 a, const PolyZ& w) {
  if (w.empty() || is_zero(a)) return a;
  for (;;) {
    V3 q;
    for (int i = 0; i < 3; ++i) {
      if (a[i].empty()) continue;
      std::optional<PolyZ> d = divided(a[i], w);
      if (!d) return a;
      q[i] = std::move(*d);
    }
    a = std::move(q);
  }
}

CGAL::Sign sign(const PolyZ& p, RealRoot& r, const PolyZ& w = kNoFactor) {
  if (p.empty()) return CGAL::ZERO;
  if (w.empty() || r.is_rational()) return sign_at(p, r);
  // The cheap enclosure first; the division by w only when it is needed.
  if (const CGAL::Sign s = enclosure_sign(p, r.lo, r.hi); s != CGAL::ZERO) return s;
  return sign_at(reduced(p, w), r);
}

bool zero_at(const V3& a, RealRoot& r, const PolyZ& w = kNoFactor) {
  for (const PolyZ& p : a)
    if (sign(p, r, w) != CGAL::ZERO) return false;
  return true;
}

// gcd of the nonzero components (their common roots); a is not zero.
PolyZ common(const V3& a) {
  PolyZ g;
  for (const PolyZ& p : a) {
    if (p.empty()) continue;
    g = g.empty() ? primitive(p) : gcd(g, p);
    if (degree(g) == 0) break;
  }
  return g;
}

// The area vector of a polygon: sum of (p_k - p_0) x (p_(k+1) - p_0);
// zero exactly when the (convex) polygon is collapsed to a segment or point.
V3 area_vector(const Points& poly) {
  V3 n;
  for (std::size_t k = 1; k + 1 < poly.size(); ++k) {
    const V3 c = cross(diff(poly[k], poly[0]), diff(poly[k + 1], poly[0]));
    for (int i = 0; i < 3; ++i) n[i] = add(n[i], c[i]);
  }
  return n;
}

// A contact found on the integer points: its time and the indices of the
// points that locate it (one, or the four of two edges).
struct Found {
  RealRoot t;
  std::vector<int> where;
};

std::optional<Found> first(std::optional<Found> a, std::optional<Found> b) {
  if (!a) return b;
  if (!b) return a;
  return compare(b->t, a->t) == CGAL::SMALLER ? b : a;
}

// on_line: the caller knows (v - e0) x (e1 - e0) = 0 at r (r is a root of
// the gcd of its components), so that test is skipped.
bool on_segment(const ZPoint& v, const ZPoint& e0, const ZPoint& e1, RealRoot& r, const PolyZ& w = kNoFactor,
                bool on_line = false) {
  const V3 d = diff(e1, e0), q = diff(v, e0);
  if (zero_at(d, r, w)) return zero_at(q, r, w);  // the segment is a point at r
  if (!on_line && !zero_at(cross(q, d), r, w)) return false;
  return sign(dot(q, d), r, w) != CGAL::NEGATIVE && sign(dot(diff(v, e1), diff(e0, e1)), r, w) != CGAL::NEGATIVE;
}

// Vertex v (coplanar with the polygon at r) in the closed convex polygon.
// n: the polygon's area vector (area_vector(poly)), computed once by callers
// that test several roots.
bool in_polygon(const ZPoint& v, const Points& poly, const V3& n, RealRoot& r, const PolyZ& w = kNoFactor) {
  const std::size_t m = poly.size();
  if (zero_at(n, r, w)) {  // collapsed: the polygon is the union of its edges
    for (std::size_t k = 0; k < m; ++k)
      if (on_segment(v, poly[k], poly[(k + 1) % m], r, w)) return true;
    return false;
  }
  for (std::size_t k = 0; k < m; ++k) {
    const V3 e = reduced_all(diff(poly[(k + 1) % m], poly[k]), w);
    if (sign(dot(cross(e, diff(v, poly[k])), n), r, w) == CGAL::NEGATIVE) return false;
  }
  return true;
}

// Where two coplanar segments (points 0 1 and 2 3 of p) meet at r: the
// indices of the points that locate it, or nothing.
std::optional<std::vector<int>> meet(const Points& p, RealRoot& r, const PolyZ& w = kNoFactor) {
  const V3 da = reduced_all(diff(p[1], p[0]), w), db = reduced_all(diff(p[3], p[2]), w);
  const V3 n = cross(da, db);
  if (zero_at(n, r, w)) {
    // Parallel (or a segment reduced to a point): they meet exactly when an
    // endpoint of one lies on the other.
    if (on_segment(p[0], p[2], p[3], r, w)) return std::vector<int>{0};
    if (on_segment(p[1], p[2], p[3], r, w)) return std::vector<int>{1};
    if (on_segment(p[2], p[0], p[1], r, w)) return std::vector<int>{2};
    if (on_segment(p[3], p[0], p[1], r, w)) return std::vector<int>{3};
    return std::nullopt;
  }
  // In their common plane (normal n != 0): each segment's ends on opposite
  // sides of (or on) the other's line.
  auto side = [&](const V3& d, const ZPoint& x, const ZPoint& o) { return sign(dot(cross(d, diff(x, o)), n), r, w); };
  auto opposite_or_on = [](CGAL::Sign x, CGAL::Sign y) { return static_cast<int>(x) * static_cast<int>(y) <= 0; };
  if (!opposite_or_on(side(db, p[0], p[2]), side(db, p[1], p[2]))) return std::nullopt;
  if (!opposite_or_on(side(da, p[2], p[0]), side(da, p[3], p[0]))) return std::nullopt;
  return std::vector<int>{0, 1, 2, 3};
}

class Solver {
 public:
  Solver(const Exact& u0, const Exact& u1, const PolyZ& positive, std::map<PolyZ, std::vector<RealRoot>>& cache,
         std::optional<RealRoot>& bound)
      : u0_(u0), u1_(u1), positive_(positive), cache_(cache), bound_(bound) {}

  // r (a root, in increasing order) is after the caller's bound: it and
  // the later roots need no containment test.
  bool past_bound(RealRoot& r) const { return bound_ && compare(r, *bound_) == CGAL::LARGER; }

  // The roots of p (nonzero) in [u0, u1], isolated once per polynomial (the
  // cache keeps them refined as far as they were).
  std::vector<RealRoot>& roots(const PolyZ& p) const {
    const PolyZ key = primitive(p);
    auto it = cache_.find(key);
    if (it == cache_.end()) it = cache_.emplace(key, real_roots(square_free(key), u0_, u1_)).first;
    return it->second;
  }

  // p without the factors of the positive polynomial (same roots and signs
  // on the piece: p = w^k q with w > 0 there).
  PolyZ reduced(PolyZ p) const { return ::tmcert::reduced(std::move(p), positive_); }

  std::optional<Found> vertex_vertex(const Points& p, int a, int b) const {
    const V3 d = diff(p[a], p[b]);
    if (is_zero(d)) return Found{rational_root(u0_), {a}};  // the same point throughout
    const PolyZ g = common(d);
    if (degree(g) <= 0) return std::nullopt;
    const std::vector<RealRoot>& found = roots(g);
    if (found.empty()) return std::nullopt;
    return Found{found.front(), {a}};
  }

  std::optional<Found> vertex_edge(const Points& p, int v, int e0, int e1) const {
    const V3 c = cross(diff(p[v], p[e0]), diff(p[e1], p[e0]));
    if (is_zero(c)) {
      // On the segment's line throughout (or the segment is a point): the
      // vertex first meets the segment at the start or at an endpoint.
      RealRoot start = rational_root(u0_);
      if (on_segment(p[v], p[e0], p[e1], start, positive_)) return Found{start, {v}};
      return first(vertex_vertex(p, v, e0), vertex_vertex(p, v, e1));
    }
    const PolyZ g = reduced(common(c));
    if (degree(g) <= 0) return std::nullopt;
    for (RealRoot& r : roots(g)) {
      if (past_bound(r)) break;
      // r is a root of g, which divides every component of c: on the line.
      if (on_segment(p[v], p[e0], p[e1], r, positive_, true)) return Found{r, {v}};
    }
    return std::nullopt;
  }

  // Vertex p[0] and the polygon p[1..].
  std::optional<Found> vertex_face(const Points& p) const {
    const Points poly(p.begin() + 1, p.end());
    const V3 n = reduced_all(area_vector(poly), positive_);
    const PolyZ d = reduced(dot(n, diff(p[0], poly[0])));
    if (d.empty()) {
      // In the polygon's plane throughout (or the polygon is collapsed): the
      // vertex first meets it at the start or on an edge.
      RealRoot start = rational_root(u0_);
      if (in_polygon(p[0], poly, n, start, positive_)) return Found{start, {0}};
      std::optional<Found> best;
      const int m = static_cast<int>(poly.size());
      for (int k = 0; k < m; ++k) best = first(std::move(best), vertex_edge(p, 0, 1 + k, 1 + (k + 1) % m));
      return best;
    }
    for (RealRoot& r : roots(d)) {
      if (past_bound(r)) break;
      if (in_polygon(p[0], poly, n, r, positive_)) return Found{r, {0}};
    }
    return std::nullopt;
  }

  // Edges p[0] p[1] and p[2] p[3].
  std::optional<Found> edge_edge(const Points& p) const {
    const V3 da = reduced_all(diff(p[1], p[0]), positive_), db = reduced_all(diff(p[3], p[2]), positive_);
    const PolyZ d = reduced(dot(cross(da, db), diff(p[2], p[0])));
    if (d.empty()) {
      // In one plane throughout (parallel, coplanar or degenerate): the
      // segments first meet at the start or with an endpoint on the other.
      RealRoot start = rational_root(u0_);
      if (auto where = meet(p, start, positive_)) return Found{start, std::move(*where)};
      std::optional<Found> best = vertex_edge(p, 0, 2, 3);
      best = first(std::move(best), vertex_edge(p, 1, 2, 3));
      best = first(std::move(best), vertex_edge(p, 2, 0, 1));
      return first(std::move(best), vertex_edge(p, 3, 0, 1));
    }
    for (RealRoot& r : roots(d)) {
      if (past_bound(r)) break;
      if (auto where = meet(p, r, positive_)) return Found{r, std::move(*where)};
    }
    return std::nullopt;
  }

 private:
  Exact u0_, u1_;
  const PolyZ& positive_;
  std::map<PolyZ, std::vector<RealRoot>>& cache_;
  std::optional<RealRoot>& bound_;
};

// The contact with the caller's points (not the scaled ones) locating it.
std::optional<Contact> contact_of(std::optional<Found> f, std::initializer_list<const std::vector<MovingPoint>*> groups) {
  if (!f) return std::nullopt;
  std::vector<const MovingPoint*> all;
  for (const auto* g : groups)
    for (const MovingPoint& m : *g) all.push_back(&m);
  Contact c{std::move(f->t), {}};
  for (int i : f->where) c.where.points.push_back(*all[i]);
  return c;
}

// Rational polynomial vectors (for the point box).
using VQ = std::array<PolyQ, 3>;
VQ diff_q(const MovingPoint& a, const MovingPoint& b) { return {sub(a.x[0], b.x[0]), sub(a.x[1], b.x[1]), sub(a.x[2], b.x[2])}; }
VQ cross_q(const VQ& a, const VQ& b) {
  return {sub(mul(a[1], b[2]), mul(a[2], b[1])), sub(mul(a[2], b[0]), mul(a[0], b[2])),
          sub(mul(a[0], b[1]), mul(a[1], b[0]))};
}
PolyQ dot_q(const VQ& a, const VQ& b) { return add(add(mul(a[0], b[0]), mul(a[1], b[1])), mul(a[2], b[2])); }

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
  const std::vector<MovingPoint> all{v, e0, e1};
  const Scaled s = scaled({&all});
  return ::tmcert::on_segment(s.points[0], s.points[1], s.points[2], r);
}

bool ContactSolver::in_polygon(const MovingPoint& v, const std::vector<MovingPoint>& poly, RealRoot& r) {
  const std::vector<MovingPoint> vertex{v};
  Scaled s = scaled({&vertex, &poly});
  const Points p(s.points.begin() + 1, s.points.end());
  return ::tmcert::in_polygon(s.points[0], p, area_vector(p), r);
}

bool ContactSolver::segments_meet(const MovingPoint& a0, const MovingPoint& a1, const MovingPoint& b0,
                                  const MovingPoint& b1, RealRoot& r) {
  const std::vector<MovingPoint> all{a0, a1, b0, b1};
  return meet(scaled({&all}).points, r).has_value();
}

bool ContactSolver::touch(const std::vector<MovingPoint>& a, const std::vector<MovingPoint>& b, RealRoot& r) {
  if (a.size() > 1 && b.size() == 1) return touch(b, a, r);
  const Scaled s = scaled({&a, &b});
  const Points& p = s.points;
  if (a.size() == 1) {
    if (b.size() == 1) return ::tmcert::on_segment(p[0], p[1], p[1], r);  // a segment reduced to the point b
    if (b.size() == 2) return ::tmcert::on_segment(p[0], p[1], p[2], r);
    const Points poly(p.begin() + 1, p.end());
    const V3 n = area_vector(poly);
    return sign(dot(n, diff(p[0], poly[0])), r) == CGAL::ZERO && ::tmcert::in_polygon(p[0], poly, n, r);
  }
  if (a.size() == 2 && b.size() == 2)
    return sign(dot(cross(diff(p[1], p[0]), diff(p[3], p[2])), diff(p[2], p[0])), r) == CGAL::ZERO && meet(p, r);
  return false;
}

std::optional<Contact> ContactSolver::vertex_vertex(const MovingPoint& a, const MovingPoint& b) const {
  const std::vector<MovingPoint> all{a, b};
  const Scaled s = scaled({&all});
  return contact_of(Solver(u0_, u1_, positive_, roots_, bound_).vertex_vertex(s.points, 0, 1), {&all});
}

std::optional<Contact> ContactSolver::vertex_edge(const MovingPoint& v, const MovingPoint& e0,
                                                  const MovingPoint& e1) const {
  const std::vector<MovingPoint> all{v, e0, e1};
  const Scaled s = scaled({&all});
  return contact_of(Solver(u0_, u1_, positive_, roots_, bound_).vertex_edge(s.points, 0, 1, 2), {&all});
}

std::optional<Contact> ContactSolver::vertex_face(const MovingPoint& v, const std::vector<MovingPoint>& poly) const {
  const std::vector<MovingPoint> vertex{v};
  const Scaled s = scaled({&vertex, &poly});
  return contact_of(Solver(u0_, u1_, positive_, roots_, bound_).vertex_face(s.points), {&vertex, &poly});
}

std::optional<Contact> ContactSolver::edge_edge(const MovingPoint& a0, const MovingPoint& a1, const MovingPoint& b0,
                                                const MovingPoint& b1) const {
  const std::vector<MovingPoint> all{a0, a1, b0, b1};
  const Scaled s = scaled({&all});
  return contact_of(Solver(u0_, u1_, positive_, roots_, bound_).edge_edge(s.points), {&all});
}

namespace {

// The point's box over the time interval t in double intervals (call under
// RoundingGuard); nothing when a bound is not finite.
std::optional<std::array<Interval, 3>> box_in_doubles(const Contact& c, const PolyQ& weight, const Interval& t) {
  auto eval = [&](const PolyQ& p) {
    Interval acc(0);
    for (std::size_t i = p.size(); i-- > 0;) acc = acc * t + to_interval(p[i]);
    return acc;
  };
  const Interval w = eval(weight);
  if (!(w.inf() > 0)) return std::nullopt;
  auto place = [&](const MovingPoint& p) {
    std::array<Interval, 3> out;
    for (int i = 0; i < 3; ++i) out[i] = eval(p.x[i]) / w;
    return out;
  };
  auto meet = [](const Interval& a, const Interval& b) { return Interval(std::max(a.inf(), b.inf()), std::min(a.sup(), b.sup())); };
  auto join = [](const Interval& a, const Interval& b) { return Interval(std::min(a.inf(), b.inf()), std::max(a.sup(), b.sup())); };
  std::array<Interval, 3> box;
  const auto& pts = c.where.points;
  if (pts.size() == 1) {
    box = place(pts[0]);
  } else {
    const auto A0 = place(pts[0]), A1 = place(pts[1]), B0 = place(pts[2]), B1 = place(pts[3]);
    for (int i = 0; i < 3; ++i) {
      const Interval a = join(A0[i], A1[i]), b = join(B0[i], B1[i]);
      if (!(std::max(a.inf(), b.inf()) <= std::min(a.sup(), b.sup()))) return std::nullopt;
      box[i] = meet(a, b);
    }
    // And a0 + s (a1 - a0), s from the lines' equations, when the
    // directions are not nearly parallel (intervals over the same time).
    using I3 = std::array<Interval, 3>;
    auto minus = [](const I3& x, const I3& y) { return I3{x[0] - y[0], x[1] - y[1], x[2] - y[2]}; };
    auto cross3 = [](const I3& x, const I3& y) {
      return I3{x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]};
    };
    auto dot3 = [](const I3& x, const I3& y) { return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]; };
    const I3 da = minus(A1, A0), db = minus(B1, B0), n = cross3(da, db);
    const Interval nn = dot3(n, n);
    if (nn.inf() > 0) {
      const Interval sa = dot3(cross3(minus(B0, A0), db), n) / nn;
      for (int i = 0; i < 3; ++i) {
        const Interval x = A0[i] + sa * da[i];
        if (std::max(x.inf(), box[i].inf()) <= std::min(x.sup(), box[i].sup())) box[i] = meet(box[i], x);
      }
    }
  }
  for (const Interval& x : box)
    if (!std::isfinite(x.inf()) || !std::isfinite(x.sup()) || !(x.inf() <= x.sup())) return std::nullopt;
  return box;
}

}  // namespace

std::array<std::array<Exact, 2>, 3> point_box(Contact& c, const PolyQ& weight) {
  // Narrow the time to about double precision, then enclose the point over
  // it: in double intervals (their bounds are the box), or if those
  // overflow, in exact rational intervals rounded outward to doubles.
  refine_to(c.t, Exact(Integer(1), Integer(1) << 56));
  std::array<std::array<Exact, 2>, 3> out;
  {
    RoundingGuard guard;
    const Interval t(to_interval(c.t.lo).inf(), to_interval(c.t.hi).sup());
    if (const auto box = box_in_doubles(c, weight, t)) {
      for (int i = 0; i < 3; ++i) out[i] = {Exact((*box)[i].inf()), Exact((*box)[i].sup())};
      return out;
    }
  }
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
    const VQ da = diff_q(pts[1], pts[0]), db = diff_q(pts[3], pts[2]);
    const VQ n = cross_q(da, db);
    const Range nn = evaluate(dot_q(n, n), t);
    if (nn.lo > 0) {
      const Range s = evaluate(dot_q(cross_q(diff_q(pts[2], pts[0]), db), n), t) / nn;
      for (int i = 0; i < 3; ++i) {
        const Range x = A0[i] + s * (evaluate(da[i], t) / w);
        box[i] = intersect(box[i], x);
      }
    }
  }
  for (int i = 0; i < 3; ++i) {
    out[i][0] = Exact(to_interval(box[i].lo).inf());
    out[i][1] = Exact(to_interval(box[i].hi).sup());
  }
  return out;
}

}  // namespace tmcert
