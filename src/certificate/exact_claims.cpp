#include "src/certificate/exact_claims.h"

#include "src/certificate/check_numbers.h"

#include <optional>

namespace tmcert::certificate {

namespace {

// The checker's vector vocabulary (check_numbers.h).
using check_internal::cross;
using check_internal::dot;
using check_internal::is_zero;
using check_internal::sub;

// p on the closed segment [a, b] (a point when a = b).
bool on_segment(const Vec3E& p, const Vec3E& a, const Vec3E& b) {
  const Vec3E d = sub(b, a), w = sub(p, a);
  if (is_zero(d)) return is_zero(w);
  if (!is_zero(cross(d, w))) return false;
  const Exact s = dot(w, d);
  return s >= 0 && s <= dot(d, d);
}

// The closed segments [a, b] and [c, d] share a point.
bool segments_meet(const Vec3E& a, const Vec3E& b, const Vec3E& c, const Vec3E& d) {
  if (a == b) return on_segment(a, c, d);
  if (c == d) return on_segment(c, a, b);
  const Vec3E u = sub(b, a), v = sub(d, c);
  const Vec3E m = cross(u, v);
  if (is_zero(m))  // parallel: they meet iff an end of one lies on the other
    return on_segment(a, c, d) || on_segment(b, c, d) || on_segment(c, a, b) || on_segment(d, a, b);
  if (dot(m, sub(c, a)) != 0) return false;  // not coplanar
  // Coplanar, not parallel: each one's ends on opposite sides of (or on)
  // the other's line, sides measured along m.
  const int s1 = CGAL::sign(dot(cross(u, sub(c, a)), m)), s2 = CGAL::sign(dot(cross(u, sub(d, a)), m));
  const int s3 = CGAL::sign(dot(cross(v, sub(a, c)), m)), s4 = CGAL::sign(dot(cross(v, sub(b, c)), m));
  return s1 * s2 <= 0 && s3 * s4 <= 0;
}

// The area vector of a convex polygon in order: zero exactly when it is
// collapsed onto a segment or a point (then it is the union of its edges).
Vec3E area_vector(const std::vector<Vec3E>& q) {
  Vec3E n{Exact(0), Exact(0), Exact(0)};
  for (std::size_t k = 1; k + 1 < q.size(); ++k) {
    const Vec3E c = cross(sub(q[k], q[0]), sub(q[k + 1], q[0]));
    for (int i = 0; i < 3; ++i) n[i] += c[i];
  }
  return n;
}

bool meets_an_edge(const Vec3E& a, const Vec3E& b, const std::vector<Vec3E>& q) {
  for (std::size_t k = 0; k < q.size(); ++k)
    if (segments_meet(a, b, q[k], q[(k + 1) % q.size()])) return true;
  return false;
}

// p in the closed convex polygon q (at least three vertices, in order).
bool in_polygon(const Vec3E& p, const std::vector<Vec3E>& q) {
  const Vec3E n = area_vector(q);
  if (is_zero(n)) return meets_an_edge(p, p, q);
  if (dot(n, sub(p, q[0])) != 0) return false;
  for (std::size_t k = 0; k < q.size(); ++k) {
    const Vec3E& e0 = q[k];
    const Vec3E& e1 = q[(k + 1) % q.size()];
    if (dot(cross(sub(e1, e0), sub(p, e0)), n) < 0) return false;
  }
  return true;
}

bool point_in(const Vec3E& p, const std::vector<Vec3E>& e) {
  if (e.size() == 1) return p == e[0];
  if (e.size() == 2) return on_segment(p, e[0], e[1]);
  return in_polygon(p, e);
}

// The closed segment [a, b] meets element e (a segment or a polygon).
bool segment_meets(const Vec3E& a, const Vec3E& b, const std::vector<Vec3E>& e) {
  if (e.size() == 1) return on_segment(e[0], a, b);
  if (e.size() == 2) return segments_meet(a, b, e[0], e[1]);
  const Vec3E n = area_vector(e);
  if (is_zero(n)) return meets_an_edge(a, b, e);
  const Exact da = dot(n, sub(a, e[0])), db = dot(n, sub(b, e[0]));
  if ((da > 0 && db > 0) || (da < 0 && db < 0)) return false;
  if (da == 0 && db == 0)  // in the polygon's plane: an end inside, or it crosses the boundary
    return in_polygon(a, e) || in_polygon(b, e) || meets_an_edge(a, b, e);
  // The one point of the segment in the plane.
  const Exact s = da / (da - db);
  const Vec3E p{a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1]), a[2] + s * (b[2] - a[2])};
  return in_polygon(p, e);
}

Exact value(const PolyQ& p, const Exact& x) {
  Exact acc(0);
  for (auto it = p.rbegin(); it != p.rend(); ++it) acc = acc * x + *it;
  return acc;
}

// The numerator of a moving point at x: the point times the common weight
// w(x) > 0 (one positive scale for every point: the same intersections).
Vec3E at(const MovingPoint& m, const Exact& x) { return {value(m.x[0], x), value(m.x[1], x), value(m.x[2], x)}; }

std::vector<std::pair<int, int>> edges_of(std::size_t n) {
  std::vector<std::pair<int, int>> out;
  if (n == 2) out.push_back({0, 1});
  if (n >= 3)
    for (std::size_t k = 0; k < n; ++k) out.push_back({static_cast<int>(k), static_cast<int>((k + 1) % n)});
  return out;
}

const char* kind(std::size_t n) { return n == 1 ? "point" : n == 2 ? "segment" : "polygon"; }

}  // namespace

bool elements_meet(const std::vector<Vec3E>& a, const std::vector<Vec3E>& b) {
  if (a.size() == 1) return point_in(a[0], b);
  if (b.size() == 1) return point_in(b[0], a);
  if (a.size() == 2) return segment_meets(a[0], a[1], b);
  if (b.size() == 2) return segment_meets(b[0], b[1], a);
  // Two convex polygons meet iff an edge of one meets the other
  // (proofs/exact-resolution.md §6).
  for (std::size_t k = 0; k < a.size(); ++k)
    if (segment_meets(a[k], a[(k + 1) % a.size()], b)) return true;
  for (std::size_t k = 0; k < b.size(); ++k)
    if (segment_meets(b[k], b[(k + 1) % b.size()], a)) return true;
  return false;
}

std::string no_contact_error(const CheckMotions& motions, const std::vector<Vec3E>& a, const std::vector<Vec3E>& b,
                             const Exact& u0, const Exact& u1, const RealRoot* before) {
  if (a.empty() || b.empty()) return "an element without vertices";
  if (u0 > u1) return "an empty piece";
  std::optional<RealRoot> end;
  if (before) {
    end = *before;
    RealRoot start = rational_root(u0);
    try {
      if (compare(start, *end) != CGAL::SMALLER) return "the piece does not start before the witness time";
    } catch (const ExactLimit& e) {
      throw ResourceLimit(std::string("exact claim: ") + e.what());
    }
    if (end->hi > u1) return "the piece ends before the witness time's interval";
  }
  std::vector<MovingPoint> pa, pb;
  for (const Vec3E& v : a) pa.push_back(motions.place(0, v));
  for (const Vec3E& v : b) pb.push_back(motions.place(1, v));
  // Apart at the start.
  {
    std::vector<Vec3E> sa, sb;
    for (const MovingPoint& m : pa) sa.push_back(at(m, u0));
    for (const MovingPoint& m : pb) sb.push_back(at(m, u0));
    if (elements_meet(sa, sb)) return "the elements meet at the start of the piece";
  }
  // No vertex-element or edge-edge contact in the piece (before the witness
  // time, with `before`).
  const ContactSolver solver(u0, u1, primitive(motions.weight()));
  auto feature = [](const std::vector<MovingPoint>& e, const MovingPoint& v, const ContactSolver& s) {
    if (e.size() == 1) return s.vertex_vertex(v, e[0]);
    if (e.size() == 2) return s.vertex_edge(v, e[0], e[1]);
    return s.vertex_face(v, e);
  };
  auto too_early = [&](std::optional<Contact>& c) {
    if (!c) return false;
    if (!end) return true;
    RealRoot w = *end;
    return compare(c->t, w) == CGAL::SMALLER;
  };
  try {
    for (int side = 0; side < 2; ++side) {
      const std::vector<MovingPoint>& vs = side == 0 ? pa : pb;
      const std::vector<MovingPoint>& other = side == 0 ? pb : pa;
      for (std::size_t i = 0; i < vs.size(); ++i) {
        std::optional<Contact> c = feature(other, vs[i], solver);
        if (too_early(c))
          return std::string("vertex ") + std::to_string(i) + " of the " + (side == 0 ? "a" : "b") + " element touches the " +
                 kind(other.size()) + " at u ~ " + approximate(c->t);
      }
    }
    for (const auto& [i0, i1] : edges_of(pa.size()))
      for (const auto& [j0, j1] : edges_of(pb.size())) {
        std::optional<Contact> c = solver.edge_edge(pa[i0], pa[i1], pb[j0], pb[j1]);
        if (too_early(c))
          return "edge " + std::to_string(i0) + "-" + std::to_string(i1) + " of the a element touches edge " +
                 std::to_string(j0) + "-" + std::to_string(j1) + " of the b element at u ~ " + approximate(c->t);
      }
  } catch (const ExactLimit& e) {
    throw ResourceLimit(std::string("exact claim: ") + e.what());
  }
  return {};
}

}  // namespace tmcert::certificate
