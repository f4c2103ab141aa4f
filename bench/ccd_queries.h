// Continuous-collision queries with linear per-vertex motion and ground
// truth known by construction (issue: two moving bodies).
//
// A point, segment or triangle whose vertices move linearly from their
// positions at t = 0 to those at t = 1 is an affine motion of degree 1: the
// canonical point (0,0,0), segment (0,0,0)-(1,0,0) or triangle
// (0,0,0),(1,0,0),(0,1,0) mapped by A(t) = [v1 - v0, v2 - v0, 0 | v0]
// (singular maps are allowed: nothing needs an inverse).
//
// Kinds of queries (vertex-face "vf" and edge-edge "ee"):
//   contact      contact built at a rational time t* (collision)
//   tunneling    the same with velocities 30x the size (collision)
//   start, end   contact at t = 0 or t = 1 exactly (collision)
//   grazing      a vertex touching an edge, or edge ends touching (collision)
//   coplanar     motion within the triangle's plane (vf) or a common plane
//                (ee), hitting or missing; truth from the exact swept test
//   parallel     edges parallel throughout, hitting or missing (ee)
//   miss         rigid relative translation plus a common drift; truth from
//                an exact test of the relative sweep (mostly safe)
//   separated    every vertex stays on its side of an oblique plane with a
//                margin at both ends, also while a triangle degenerates (safe)
//   static       no motion at all; truth from the exact static test
#pragma once

#include "kernels/static_intersection.h"
#include "src/metric/metric.h"
#include "src/model/model.h"

#include <random>
#include <string>
#include <vector>

namespace tmcert::bench {

struct Query {
  std::string kind;       // e.g. "vf contact"
  bool collides = false;  // ground truth
  std::optional<Exact> contact_time;  // a time of contact when known (not necessarily the first)
  int body_a = 0, body_b = 0;         // indices into the scene
};

struct QuerySet {
  Scene scene;
  std::vector<Query> queries;
};

// A body whose vertices (1, 2 or 3 of them) move linearly from p0[i] to p1[i].
inline Body linear_body(const std::string& name, const std::vector<Vec3E>& p0, const std::vector<Vec3E>& p1) {
  Body b;
  b.name = name;
  const std::size_t n = p0.size();
  const Vec3E o{0, 0, 0}, ex{1, 0, 0}, ey{0, 1, 0};
  if (n == 1) b.points = {o};
  else if (n == 2) b.segments = {{o, ex}};
  else {
    b.polygons = {{o, ex, ey}};
    b.pieces = {ConvexPiece{0, {o, ex, ey}}};
  }
  std::vector<Vec3E> verts = n == 1 ? std::vector<Vec3E>{o} : n == 2 ? std::vector<Vec3E>{o, ex} : std::vector<Vec3E>{o, ex, ey};
  b.mass = default_mass(verts, Exact(1));
  Motion m;
  for (const auto* p : {&p0, &p1}) {
    Mat34E a;
    for (int r = 0; r < 3; ++r) {
      a[4 * r + 0] = n >= 2 ? (*p)[1][r] - (*p)[0][r] : Exact(0);
      a[4 * r + 1] = n >= 3 ? (*p)[2][r] - (*p)[0][r] : Exact(0);
      a[4 * r + 2] = 0;
      a[4 * r + 3] = (*p)[0][r];
    }
    m.control_points.push_back(a);
    m.weights.push_back(Exact(1));
  }
  b.motion = m;
  return b;
}

class QueryGenerator {
 public:
  explicit QueryGenerator(unsigned seed) : rng_(seed) {}

  // `count` queries cycling through all kinds.
  QuerySet generate(int count) {
    QuerySet set;
    for (int i = 0; i < count; ++i) add(set, i);
    return set;
  }

 private:
  std::mt19937_64 rng_;

  Exact q(long lo, long hi, long den) { return Exact(std::uniform_int_distribution<long>(lo, hi)(rng_), den); }
  Vec3E point(long range = 1000, long den = 1000) { return {q(-range, range, den), q(-range, range, den), q(-range, range, den)}; }
  Exact time() { return q(1, 999, 1000); }
  static Vec3E add(const Vec3E& a, const Vec3E& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
  static Vec3E sub(const Vec3E& a, const Vec3E& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
  static Vec3E mul(const Exact& s, const Vec3E& a) { return {s * a[0], s * a[1], s * a[2]}; }
  static Exact dot(const Vec3E& a, const Vec3E& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
  static Vec3E cross(const Vec3E& a, const Vec3E& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  }
  static bool degenerate_triangle(const std::vector<Vec3E>& t) {
    const Vec3E n = cross(sub(t[1], t[0]), sub(t[2], t[0]));
    return n[0] == 0 && n[1] == 0 && n[2] == 0;
  }

  // Positions at 0 and 1 of vertices that are at x[i] at time ts with velocity v[i].
  static void around(const std::vector<Vec3E>& x, const std::vector<Vec3E>& v, const Exact& ts,
                     std::vector<Vec3E>& p0, std::vector<Vec3E>& p1) {
    p0.clear();
    p1.clear();
    for (std::size_t i = 0; i < x.size(); ++i) {
      p0.push_back(sub(x[i], mul(ts, v[i])));
      p1.push_back(add(x[i], mul(Exact(1) - ts, v[i])));
    }
  }

  void push(QuerySet& set, const std::string& kind, bool collides, std::optional<Exact> t,
            const std::vector<Vec3E>& a0, const std::vector<Vec3E>& a1, const std::vector<Vec3E>& b0,
            const std::vector<Vec3E>& b1) {
    const int ia = static_cast<int>(set.scene.bodies.size());
    const std::string id = std::to_string(set.queries.size());
    set.scene.bodies.push_back(linear_body("q" + id + "a", a0, a1));
    set.scene.bodies.push_back(linear_body("q" + id + "b", b0, b1));
    set.scene.checks.push_back({ia, ia + 1});
    set.queries.push_back(Query{kind, collides, t, ia, ia + 1});
  }

  std::vector<Vec3E> velocities(std::size_t n, long scale) {
    std::vector<Vec3E> v;
    for (std::size_t i = 0; i < n; ++i) v.push_back(point(1000 * scale, 1000));
    return v;
  }

  std::vector<Vec3E> triangle() {
    for (;;) {
      std::vector<Vec3E> t{point(), point(), point()};
      if (!degenerate_triangle(t)) return t;
    }
  }

  // Exact truth for a relative sweep: A static (point, segment or triangle),
  // B (a point or a segment) translating by d.
  static bool sweep_hits(const std::vector<Vec3E>& a, const std::vector<Vec3E>& b, const Vec3E& d) {
    auto simplex = [](const std::vector<Vec3E>& v) {
      Simplex s;
      s.count = static_cast<int>(v.size());
      for (std::size_t i = 0; i < v.size(); ++i) s.p[i] = v[i];
      for (std::size_t i = v.size(); i < 3; ++i) s.p[i] = v.back();
      return s;
    };
    const Simplex sa = simplex(a);
    // B is a point or a segment here, so its sweep (the hull of B and B + d)
    // is a segment or a parallelogram: planar, and covered by the triangles
    // of its vertex triples (degenerate ones reduce exactly).
    std::vector<Vec3E> all = b;
    for (const Vec3E& x : b) all.push_back(add(x, d));
    for (std::size_t i = 0; i < all.size(); ++i)
      for (std::size_t j = i; j < all.size(); ++j)
        for (std::size_t k = j; k < all.size(); ++k) {
          Simplex t{3, {all[i], all[j], all[k]}};
          if (common_point(sa, t)) return true;
        }
    return false;
  }

  void add(QuerySet& set, int i) {
    const bool vf = i % 2 == 0;
    const int kind = (i / 2) % 10;
    std::vector<Vec3E> a0, a1, b0, b1;
    const std::string prefix = vf ? "vf " : "ee ";
    switch (kind) {
      case 0: case 1: case 2: case 3: {  // contact, tunneling, start, end
        const Exact ts = kind == 2 ? Exact(0) : kind == 3 ? Exact(1) : time();
        const long speed = kind == 1 ? 30 : 1;
        std::vector<Vec3E> xa, xb;
        if (vf) {
          xb = triangle();
          Exact l1 = q(1, 998, 1000), l2 = q(1, 999, 1000);
          if (l1 + l2 >= 1) l2 = (Exact(1) - l1) / 2;
          xa = {add(xb[0], add(mul(l1, sub(xb[1], xb[0])), mul(l2, sub(xb[2], xb[0]))))};
        } else {
          xb = {point(), point()};
          const Vec3E c = add(xb[0], mul(q(1, 999, 1000), sub(xb[1], xb[0])));
          const Vec3E dir = point();
          const Exact s = q(1, 999, 1000);
          xa = {sub(c, mul(s, dir)), add(c, mul(Exact(1) - s, dir))};
        }
        around(xa, velocities(xa.size(), speed), ts, a0, a1);
        around(xb, velocities(xb.size(), speed), ts, b0, b1);
        const char* names[] = {"contact", "tunneling", "start", "end"};
        push(set, prefix + names[kind], true, ts, a0, a1, b0, b1);
        return;
      }
      case 4: {  // grazing: a vertex on an edge, or two edges meeting at an end
        const Exact ts = time();
        std::vector<Vec3E> xa, xb;
        if (vf) {
          xb = triangle();
          xa = {add(xb[0], mul(q(0, 1000, 1000), sub(xb[1], xb[0])))};
        } else {
          xb = {point(), point()};
          const Vec3E c = add(xb[0], mul(q(0, 1000, 1000), sub(xb[1], xb[0])));
          xa = {c, add(c, point())};
        }
        around(xa, velocities(xa.size(), 1), ts, a0, a1);
        around(xb, velocities(xb.size(), 1), ts, b0, b1);
        push(set, prefix + "grazing", true, ts, a0, a1, b0, b1);
        return;
      }
      case 5: case 6: case 7: {  // coplanar, parallel, miss: rigid relative translation
        std::vector<Vec3E> a = vf ? std::vector<Vec3E>{point()} : std::vector<Vec3E>{point(), point()};
        std::vector<Vec3E> b = vf ? triangle() : std::vector<Vec3E>{point(), point()};
        Vec3E d = point(2000, 1000);
        if (kind == 5) {  // everything in one plane: z = 0
          for (auto* v : {&a, &b})
            for (Vec3E& x : *v) x[2] = 0;
          d[2] = 0;
          if (!vf && a[0] == a[1]) a[1][0] += 1;
          if (vf && degenerate_triangle(b)) b = {Vec3E{0, 0, 0}, Vec3E{1, 0, 0}, Vec3E{0, 1, 0}};
        }
        if (kind == 6 && !vf) {  // parallel edges, offset
          const Vec3E dir = sub(b[1], b[0]);
          a[1] = add(a[0], mul(q(1, 2000, 1000), dir));
        }
        // Relative motion: b moves by d, a is static; then both drift by w.
        const bool hits = sweep_hits(b.size() == 3 ? b : a, b.size() == 3 ? a : b, b.size() == 3 ? mul(Exact(-1), d) : d);
        const Vec3E w = point();
        a0 = a;
        a1.clear();
        for (const Vec3E& x : a) a1.push_back(add(x, w));
        b0 = b;
        b1.clear();
        for (const Vec3E& x : b) b1.push_back(add(add(x, d), w));
        const char* names[] = {"coplanar", "parallel", "miss"};
        push(set, prefix + names[kind - 5], hits, std::nullopt, a0, a1, b0, b1);
        return;
      }
      case 8: {  // separated by the plane n.x = 0, n = (1,2,2)/3, margin m; b may degenerate
        const Vec3E n{Exact(1, 3), Exact(2, 3), Exact(2, 3)};
        const Exact m = q(1, 200, 1000);
        auto side = [&](int sign) {
          Vec3E x = point();
          const Exact h = dot(n, x);  // push to the side with margin
          const Exact want = sign * (m + q(0, 500, 1000));
          return add(x, mul(want - h, n));
        };
        const std::size_t na = vf ? 1 : 2, nb = vf ? 3 : 2;
        a0.clear(); a1.clear(); b0.clear(); b1.clear();
        for (std::size_t k = 0; k < na; ++k) { a0.push_back(side(1)); a1.push_back(side(1)); }
        for (std::size_t k = 0; k < nb; ++k) { b0.push_back(side(-1)); b1.push_back(side(-1)); }
        if (vf && i % 4 == 0) b1[2] = add(b1[0], mul(Exact(1, 2), sub(b1[1], b1[0])));  // collapses to a segment at t = 1
        if (!vf && i % 4 == 1) b1[1] = b1[0];  // shrinks to a point at t = 1
        if (vf && degenerate_triangle(b0)) b0 = {side(-1), side(-1), side(-1)};
        push(set, prefix + "separated", false, std::nullopt, a0, a1, b0, b1);
        return;
      }
      default: {  // static: no motion
        std::vector<Vec3E> a = vf ? std::vector<Vec3E>{point(300, 1000)} : std::vector<Vec3E>{point(), point()};
        std::vector<Vec3E> b = vf ? triangle() : std::vector<Vec3E>{point(), point()};
        const bool hits = sweep_hits(b.size() == 3 ? b : a, b.size() == 3 ? a : b, Vec3E{0, 0, 0});
        push(set, prefix + "static", hits, std::nullopt, a, a, b, b);
        return;
      }
    }
  }
};

}  // namespace tmcert::bench
