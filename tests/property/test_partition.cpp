// Property test of the partition of a check's interval (SCENE_FORMAT.md,
// "Every interval claim holds"; proofs/partition.md): for random scenes of
// every motion kind - rational Bezier motions, keyframes (slerp, screw,
// nlerp, rpy or quaternion rotations), robot links moving in joint space,
// solids, clearances and tolerances, one or two moving bodies - every part
// the result leaves certified (before the witness, or up to the end, and
// in no undecided interval) is checked at random rational instants inside
// it by an oracle written independently of the search:
//
//   * rational motions: the exact pose (de Casteljau of tests/support), and
//     exact geometry written here: simplices meeting (edges against edges
//     and triangles), a vertex inside a solid by exact ray parity, exact
//     squared distances (point-triangle, segment-segment) for clearances
//     (distance <= d) and tolerances (distance <= r / sqrt(W): a translation
//     within the tolerance makes them touch);
//   * transcendental motions: the pose from an independent MPFR evaluation
//     at 256 bits (tests/support/mp_reference.h; robot chains from their
//     joint values here), read as exact rationals, and the same geometry
//     with a margin of 1e-30 that the MPFR error (below 1e-60) cannot
//     cross: a crossing of an edge through a triangle, or a vertex inside a
//     solid, with every sign away from zero by the margin; a distance below
//     the bound by the margin.
//
// A violation is a part the result claims free of contact (or of coming
// within the clearance) where the oracle proves a contact: a false
// interval claim.  The scenes make the search stop undecided (coarse
// epsilon, small depth and stop budgets, exact resolution off) and bodies
// enter solids and pass through faces, so that the parts after a stop are
// exercised: on the code before the partition fix (issue 21) the keyframe
// and robot solid cases fail within a few dozen scenes.
//
// Also checked: the undecided intervals are ordered, disjoint and inside the
// check's interval, and the result does not depend on the thread count.
//
// Run: `tmcert_property --run_test=partition`.  Replay a failure with
// RC_PARAMS="seed=N" (printed at the start) or the printed reproduce line;
// the scene is logged as tmcert-scene/1 JSON.

#include "tests/support/mp_reference.h"
#include "tests/support/scene_testing.h"

#include "src/io/parse.h"

#include <rapidcheck.h>
#include <rapidcheck/boost_test.h>

#include <boost/test/unit_test.hpp>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

using namespace tmcert;
using namespace tmcert::testing;

namespace {

// ------------------------------------------------------------------ exact geometry (the oracle)

using Simplex = std::vector<Vec3E>;  // 1, 2 or 3 points: a point, a segment, a triangle

Exact norm2(const Vec3E& a) { return dot(a, a); }
Vec3E along(const Vec3E& p, const Vec3E& q, const Exact& s) { return add(p, mul(s, sub(q, p))); }

// Do closed segments ab and cd share a point (exactly)?
bool segments_meet(const Vec3E& a, const Vec3E& b, const Vec3E& c, const Vec3E& d) {
  if (a == b) return on_segment(a, c, d);
  if (c == d) return on_segment(c, a, b);
  const Vec3E u = sub(b, a), v = sub(d, c), w = sub(c, a);
  const Vec3E n = cross(u, v);
  if (is_zero(n)) {  // parallel: collinear and overlapping
    if (!is_zero(cross(u, w))) return false;
    return on_segment(c, a, b) || on_segment(d, a, b) || on_segment(a, c, d) || on_segment(b, c, d);
  }
  if (dot(w, n) != 0) return false;  // skew lines
  const Exact nn = norm2(n);
  const Exact s = dot(cross(w, v), n) / nn, t = dot(cross(w, u), n) / nn;
  return s >= 0 && s <= 1 && t >= 0 && t <= 1;
}

// Does segment pq cross the plane of the (non-degenerate) triangle abc at a
// point of the triangle, not lying in its plane?  (Coplanar cases are the
// edge and vertex tests' business.)
bool edge_crosses_triangle(const Vec3E& p, const Vec3E& q, const Vec3E& a, const Vec3E& b, const Vec3E& c) {
  const Vec3E n = cross(sub(b, a), sub(c, a));
  if (is_zero(n)) return false;
  const Exact dp = dot(n, sub(p, a)), dq = dot(n, sub(q, a));
  if ((dp > 0 && dq > 0) || (dp < 0 && dq < 0) || (dp == 0 && dq == 0)) return false;
  return in_triangle(along(p, q, dp / (dp - dq)), a, b, c);
}

std::vector<std::pair<Vec3E, Vec3E>> edges_of(const Simplex& s) {
  if (s.size() == 1) return {{s[0], s[0]}};
  if (s.size() == 2) return {{s[0], s[1]}};
  return {{s[0], s[1]}, {s[1], s[2]}, {s[2], s[0]}};
}

bool point_in(const Vec3E& p, const Simplex& s) {
  if (s.size() == 1) return p == s[0];
  if (s.size() == 2) return on_segment(p, s[0], s[1]);
  return in_triangle(p, s[0], s[1], s[2]);
}

// Two closed simplices share a point: a vertex of one in the other, two
// edges meeting, or an edge through a triangle (for two convex sets in
// space a common point exists iff one of these does).
bool simplices_meet(const Simplex& x, const Simplex& y) {
  for (const Vec3E& p : x)
    if (point_in(p, y)) return true;
  for (const Vec3E& p : y)
    if (point_in(p, x)) return true;
  for (const auto& [a, b] : edges_of(x))
    for (const auto& [c, d] : edges_of(y))
      if (segments_meet(a, b, c, d)) return true;
  if (y.size() == 3)
    for (const auto& [a, b] : edges_of(x))
      if (edge_crosses_triangle(a, b, y[0], y[1], y[2])) return true;
  if (x.size() == 3)
    for (const auto& [a, b] : edges_of(y))
      if (edge_crosses_triangle(a, b, x[0], x[1], x[2])) return true;
  return false;
}

Exact point_segment_d2(const Vec3E& p, const Vec3E& a, const Vec3E& b) {
  const Vec3E ab = sub(b, a);
  const Exact l = norm2(ab);
  if (l == 0) return norm2(sub(p, a));
  Exact s = dot(sub(p, a), ab) / l;
  if (s < 0) s = 0;
  if (s > 1) s = 1;
  return norm2(sub(p, along(a, b, s)));
}

Exact point_simplex_d2(const Vec3E& p, const Simplex& s) {
  if (s.size() == 1) return norm2(sub(p, s[0]));
  if (s.size() == 2) return point_segment_d2(p, s[0], s[1]);
  const Vec3E n = cross(sub(s[1], s[0]), sub(s[2], s[0]));
  if (!is_zero(n)) {
    const Exact h = dot(n, sub(p, s[0]));
    const Vec3E foot = sub(p, mul(h / norm2(n), n));
    if (in_triangle(foot, s[0], s[1], s[2])) return h * h / norm2(n);
  }
  Exact best = point_segment_d2(p, s[0], s[1]);
  for (const Exact& d : {point_segment_d2(p, s[1], s[2]), point_segment_d2(p, s[2], s[0])}) best = std::min(best, d);
  return best;
}

// Closest distance squared of two segments: the interior critical point of
// the convex quadratic when the lines are not parallel, else the boundary
// (point to segment).
Exact segment_segment_d2(const Vec3E& a, const Vec3E& b, const Vec3E& c, const Vec3E& d) {
  Exact best = std::min(std::min(point_segment_d2(a, c, d), point_segment_d2(b, c, d)),
                        std::min(point_segment_d2(c, a, b), point_segment_d2(d, a, b)));
  const Vec3E u = sub(b, a), v = sub(d, c), w = sub(a, c);
  const Exact uu = dot(u, u), uv = dot(u, v), vv = dot(v, v), uw = dot(u, w), vw = dot(v, w);
  const Exact den = uu * vv - uv * uv;
  if (den > 0) {
    const Exact s = (uv * vw - vv * uw) / den, t = (uu * vw - uv * uw) / den;
    if (s > 0 && s < 1 && t > 0 && t < 1) best = std::min(best, norm2(sub(along(a, b, s), along(c, d, t))));
  }
  return best;
}

Exact simplex_d2(const Simplex& x, const Simplex& y) {
  if (simplices_meet(x, y)) return 0;
  Exact best = -1;
  auto take = [&](const Exact& d) {
    if (best < 0 || d < best) best = d;
  };
  for (const Vec3E& p : x) take(point_simplex_d2(p, y));
  for (const Vec3E& p : y) take(point_simplex_d2(p, x));
  for (const auto& [a, b] : edges_of(x))
    for (const auto& [c, d] : edges_of(y)) take(segment_segment_d2(a, b, c, d));
  return best;
}

// Where a point is against a closed triangulated surface, by exact ray
// parity: 1 inside, 0 outside, -1 on the surface.  Rays through an edge,
// a vertex or in a triangle's plane are replaced by the next direction.
int inside_surface(const Vec3E& p, const std::vector<Simplex>& triangles) {
  for (const Simplex& t : triangles)
    if (in_triangle(p, t[0], t[1], t[2])) return -1;
  static const int kDirections[][3] = {{7, 3, 2}, {-5, 11, 3}, {2, -7, 13}, {17, 5, -11}, {-3, -13, 7}, {1, 19, -23}};
  for (const auto& dir : kDirections) {
    const Vec3E d{Exact(dir[0]), Exact(dir[1]), Exact(dir[2])};
    int crossings = 0;
    bool degenerate = false;
    for (const Simplex& t : triangles) {
      const Vec3E n = cross(sub(t[1], t[0]), sub(t[2], t[0]));
      const Exact nd = dot(n, d);
      if (nd == 0) {
        if (dot(n, sub(p, t[0])) == 0) degenerate = true;  // the ray in the plane (conservatively)
        continue;
      }
      const Exact s = dot(n, sub(t[0], p)) / nd;
      if (s <= 0) continue;
      const Vec3E x = add(p, mul(s, d));
      if (!in_triangle(x, t[0], t[1], t[2])) continue;
      // Inside or on the boundary: strictly inside every edge?
      bool strict = true;
      for (int e = 0; e < 3; ++e)
        if (dot(cross(sub(t[(e + 1) % 3], t[e]), sub(x, t[e])), n) == 0) strict = false;
      if (!strict) degenerate = true;
      ++crossings;
    }
    if (!degenerate) return crossings % 2;
  }
  return -1;  // every ray degenerate: count it as touching (never happens on these scenes)
}

// The same with a margin (the MPFR case): inside, and farther than the
// margin from every triangle.
bool robustly_inside(const Vec3E& p, const std::vector<Simplex>& triangles, const Exact& margin2) {
  if (inside_surface(p, triangles) != 1) return false;
  for (const Simplex& t : triangles)
    if (!(point_simplex_d2(p, t) > margin2)) return false;
  return true;
}

// Segment pq crosses triangle abc with every sign away from zero by the
// margin: both ends farther than it from the plane on opposite sides, the
// crossing farther than it inside every edge.
bool robust_crossing(const Vec3E& p, const Vec3E& q, const Simplex& t, const Exact& margin2) {
  const Vec3E n = cross(sub(t[1], t[0]), sub(t[2], t[0]));
  const Exact nn = norm2(n);
  if (nn == 0) return false;
  const Exact dp = dot(n, sub(p, t[0])), dq = dot(n, sub(q, t[0]));
  if (!(dp * dq < 0) || !(dp * dp > margin2 * nn) || !(dq * dq > margin2 * nn)) return false;
  const Vec3E x = along(p, q, dp / (dp - dq));
  for (int e = 0; e < 3; ++e) {
    const Vec3E u = sub(t[(e + 1) % 3], t[e]);
    const Vec3E c = cross(u, sub(x, t[e]));
    if (!(dot(c, n) > 0) || !(norm2(c) > margin2 * norm2(u))) return false;
  }
  return true;
}

// A body placed: its simplices (polygons as fans), and when solid its
// surface triangles.
struct Placed {
  std::vector<Simplex> simplices;
  std::vector<Simplex> surface;  // solid only
  std::vector<Vec3E> vertices;
};

Placed place_body(const Body& b, const std::function<Vec3E(const Vec3E&)>& f) {
  Placed out;
  for (const auto& poly : b.polygons) {
    std::vector<Vec3E> w;
    for (const Vec3E& v : poly) w.push_back(f(v));
    out.vertices.insert(out.vertices.end(), w.begin(), w.end());
    for (std::size_t k = 1; k + 1 < w.size(); ++k) {
      out.simplices.push_back({w[0], w[k], w[k + 1]});
      if (b.solid) out.surface.push_back({w[0], w[k], w[k + 1]});
    }
  }
  for (const auto& s : b.segments) {
    out.simplices.push_back({f(s[0]), f(s[1])});
    out.vertices.push_back(out.simplices.back()[0]);
    out.vertices.push_back(out.simplices.back()[1]);
  }
  for (const Vec3E& p : b.points) {
    out.simplices.push_back({f(p)});
    out.vertices.push_back(out.simplices.back()[0]);
  }
  return out;
}

// What the oracle asks of one instant.
struct Claim {
  Exact clearance2 = 0;  // > 0: a distance at most its root violates
  Exact reach2 = 0;      // > 0: a distance at most its root (a translation within a tolerance) violates
  Exact margin2 = 0;     // 0: exact poses; > 0: MPFR poses, everything robust by this margin
};

// Empty when the claim "no contact (within the clearance or tolerance)" can
// hold at this configuration; else what proves it false.
std::string violation(const Placed& a, const Placed& b, const Claim& c) {
  const bool exact = c.margin2 == 0;
  // A vertex inside (or, exactly, on) the other body's solid.
  for (int side = 0; side < 2; ++side) {
    const Placed& solid = side == 0 ? b : a;
    const Placed& other = side == 0 ? a : b;
    if (solid.surface.empty()) continue;
    for (const Vec3E& v : other.vertices) {
      if (exact ? inside_surface(v, solid.surface) != 0 : robustly_inside(v, solid.surface, c.margin2))
        return "vertex " + str(v) + " inside a solid";
    }
  }
  const Exact bound = std::max(c.clearance2, c.reach2);
  for (const Simplex& x : a.simplices)
    for (const Simplex& y : b.simplices) {
      if (exact) {
        if (bound == 0 ? simplices_meet(x, y) : simplex_d2(x, y) <= bound)
          return bound == 0 ? "simplices meet" : "simplices within the clearance or tolerance";
        continue;
      }
      if (bound > 0) {
        // The MPFR error (below 1e-60 on coordinates of size about 1)
        // changes a squared distance by far less than the margin.
        if (simplex_d2(x, y) + c.margin2 < bound) return "simplices robustly within the bound";
        continue;
      }
      if (y.size() == 3)
        for (const auto& [p, q] : edges_of(x))
          if (p != q && robust_crossing(p, q, y, c.margin2)) return "an edge robustly through a triangle";
      if (x.size() == 3)
        for (const auto& [p, q] : edges_of(y))
          if (p != q && robust_crossing(p, q, x, c.margin2)) return "an edge robustly through a triangle";
    }
  return "";
}

// ------------------------------------------------------------------ poses

// An exact rational from an MPFR value (all its bits).
Exact exact_of(const Mp& x) {
  mpq_t q;
  mpq_init(q);
  mpfr_get_q(q, x.get());
  const Exact out(q);
  mpq_clear(q);
  return out;
}

// The pose of a body at scene time t: exact (rational motion or segment,
// or no motion), else from the MPFR reference.  `link` evaluates a robot
// link's chain.
struct PoseAt {
  std::optional<Mat34E> exact;
  std::optional<MpPose> mp;
};

using LinkPose = std::function<MpPose(const Exact& s)>;

PoseAt pose_of(const Body& b, const Exact& t, const LinkPose* link) {
  if (!b.motion && !b.trajectory) return {kIdentity, std::nullopt};
  if (b.motion) return {pose_at(b, t), std::nullopt};
  for (const MotionSegment& seg : b.trajectory->segments) {
    if (t < seg.t0 || t > seg.t1) continue;
    const Exact s = (t - seg.t0) / (seg.t1 - seg.t0);
    if (seg.rational) return {eval_motion(*seg.rational, t), std::nullopt};
    if (seg.link) return {std::nullopt, (*link)(s)};
    return {std::nullopt, reference_pose(seg.from, seg.to, seg.interpolation, Mp(s))};
  }
  throw std::logic_error("time outside the trajectory");
}

std::function<Vec3E(const Vec3E&)> placer(const PoseAt& p) {
  if (p.exact) {
    const Mat34E m = *p.exact;
    return [m](const Vec3E& x) { return place(m, x); };
  }
  const MpPose m = *p.mp;
  return [m](const Vec3E& x) {
    const std::array<Mp, 3> y = apply_pose(m, x);
    return Vec3E{exact_of(y[0]), exact_of(y[1]), exact_of(y[2])};
  };
}

// ------------------------------------------------------------------ the claims of a result

// The parts a check claims certified: [t0, end] minus the undecided
// intervals, `end` the witness's time (an algebraic one: the lower end of
// its interval) or t1.  Also checks the shape of the partition.
std::vector<std::pair<Exact, Exact>> certified_parts(const CheckResult& r) {
  const auto [t0, t1] = r.interval;
  RC_ASSERT(t0 < t1);
  Exact end = t1;
  if (r.witness) {
    end = r.witness->t;
    RC_ASSERT(t0 <= end);
    RC_ASSERT(end <= t1);
  }
  std::vector<std::pair<Exact, Exact>> out;
  Exact cursor = t0;
  for (const UndecidedInterval& u : r.undecided) {
    RC_ASSERT(u.t0 < u.t1);
    RC_ASSERT(cursor <= u.t0);  // ordered, disjoint (abutting allowed)
    RC_ASSERT(u.t1 <= t1);
    if (cursor < u.t0 && cursor < end) out.push_back({cursor, std::min(u.t0, end)});
    cursor = u.t1;
  }
  if (cursor < end) out.push_back({cursor, end});
  if (r.verdict == Verdict::Safe) RC_ASSERT(r.undecided.empty() && !r.witness);
  return out;
}

// Random instants inside (a, b): a few uniform ones, and some just after a
// (where a false claim after an undecided stop starts).
std::vector<Exact> samples(const Exact& a, const Exact& b, int count) {
  std::vector<Exact> out;
  for (const int den : {1000, 97}) out.push_back(a + (b - a) * Exact(1, den));
  for (int k = 0; k < count; ++k) {
    const int den = *rc::gen::element(7, 64, 1000, 65537);
    out.push_back(a + (b - a) * Exact(*rc::gen::inRange(1, den), den));
  }
  return out;
}

struct Oracle {
  const Scene& scene;
  Claim claim;
  std::map<int, LinkPose> links;  // robot links by body index
};

void check_claims(const Oracle& o, const CheckResult& r, const std::string& what) {
  const Body& a = o.scene.bodies[r.bodies[0]];
  const Body& b = o.scene.bodies[r.bodies[1]];
  const auto la = o.links.find(r.bodies[0]), lb = o.links.find(r.bodies[1]);
  const int per_part = r.undecided.size() > 40 ? 1 : 4;
  for (const auto& [lo, hi] : certified_parts(r))
    for (const Exact& t : samples(lo, hi, per_part)) {
      const PoseAt pa = pose_of(a, t, la == o.links.end() ? nullptr : &la->second);
      const PoseAt pb = pose_of(b, t, lb == o.links.end() ? nullptr : &lb->second);
      Claim c = o.claim;
      if (pa.exact && pb.exact) c.margin2 = 0;
      else if (c.margin2 == 0) c.margin2 = Exact(1, 1000000) * pow10(-54);  // (1e-30)^2
      const std::string v = violation(place_body(a, placer(pa)), place_body(b, placer(pb)), c);
      if (!v.empty()) {
        RC_LOG() << what << ": check " << a.name << " x " << b.name << " claims [" << str(lo) << ", " << str(hi)
                 << "] certified, but at t = " << str(t) << ": " << v << "\n  result: " << describe(r) << "\n";
        RC_FAIL("a part claimed certified is not");
      }
    }
}

// ------------------------------------------------------------------ scenes

std::string q(const Exact& x) { return "\"" + to_string(x) + "\""; }
std::string vec(const Vec3E& v) { return "[" + q(v[0]) + ", " + q(v[1]) + ", " + q(v[2]) + "]"; }

std::string box_polygons(const Vec3E& lo, const Vec3E& hi) {
  auto V = [&](int x, int y, int z) { return vec({x ? hi[0] : lo[0], y ? hi[1] : lo[1], z ? hi[2] : lo[2]}); };
  auto quad = [&](std::initializer_list<std::array<int, 3>> c) {
    std::string s = "[";
    bool first = true;
    for (const auto& v : c) {
      s += (first ? "" : ", ") + V(v[0], v[1], v[2]);
      first = false;
    }
    return s + "]";
  };
  // Outward-oriented faces of the box.
  return "[" + quad({{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}}) + ", " + quad({{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}) +
         ", " + quad({{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}}) + ", " + quad({{1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 0, 1}}) +
         ", " + quad({{1, 1, 0}, {0, 1, 0}, {0, 1, 1}, {1, 1, 1}}) + ", " + quad({{0, 1, 0}, {0, 0, 0}, {0, 0, 1}, {0, 1, 1}}) +
         "]";
}

// A small mover in its own frame: a point, a segment, a triangle, or a
// closed tetrahedron (solid or not), of size about 1/4.
std::string mover_geometry(bool& solid) {
  const int kind = *rc::gen::inRange(0, 4);
  solid = false;
  switch (kind) {
    case 0: return "\"points\": [" + vec(pick_point(-0.125, 0.125)) + "]";
    case 1: return "\"segments\": [[" + vec(pick_point(-0.25, -0.0625)) + ", " + vec(pick_point(0.0625, 0.25)) + "]]";
    case 2: {
      const std::vector<Vec3E> t = *rc::gen::suchThat(rc::gen::exec([] { return pick_triangle(-0.25, 0.25); }), nondegenerate);
      return "\"polygons\": [[" + vec(t[0]) + ", " + vec(t[1]) + ", " + vec(t[2]) + "]]";
    }
    default: {
      solid = *rc::gen::arbitrary<bool>();
      const Exact s = pick(0.0625, 0.25);
      const Vec3E o{0, 0, 0}, x{s, 0, 0}, y{0, s, 0}, z{0, 0, s};
      // Outward faces of the tetrahedron o, x, y, z.
      return "\"polygons\": [[" + vec(o) + ", " + vec(y) + ", " + vec(x) + "], [" + vec(o) + ", " + vec(x) + ", " + vec(z) +
             "], [" + vec(o) + ", " + vec(z) + ", " + vec(y) + "], [" + vec(x) + ", " + vec(y) + ", " + vec(z) + "]]" +
             (solid ? ", \"solid\": true" : "");
    }
  }
}

// A rational rotation matrix from an integer quaternion (R(q) / |q|^2).
Mat34E rational_rotation(int w, int x, int y, int z, const Vec3E& t) {
  const Exact n = Exact(w * w + x * x + y * y + z * z);
  return {Exact(w * w + x * x - y * y - z * z) / n, Exact(2 * (x * y - w * z)) / n, Exact(2 * (x * z + w * y)) / n, t[0],
          Exact(2 * (x * y + w * z)) / n, Exact(w * w - x * x + y * y - z * z) / n, Exact(2 * (y * z - w * x)) / n, t[1],
          Exact(2 * (x * z - w * y)) / n, Exact(2 * (y * z + w * x)) / n, Exact(w * w - x * x - y * y + z * z) / n, t[2]};
}

std::string matrix_json(const Mat34E& m) {
  std::string s = "[";
  for (int r = 0; r < 3; ++r) {
    s += r ? ", [" : "[";
    for (int c = 0; c < 4; ++c) s += (c ? ", " : "") + q(m[4 * r + c]);
    s += "]";
  }
  return s + "]";
}

// A point on the way through the unit cube [0, 1]^3 (x from -1 to 2):
// translations that enter, pass, or stop inside.
Vec3E way_point(int step, int steps) {
  const Exact x = Exact(-1) + Exact(3 * step, steps) + pick(-0.25, 0.25);
  return {x, pick(0.125, 0.875), pick(0.125, 0.875)};
}

std::string rational_motion_json() {
  const int degree = *rc::gen::inRange(1, 4);
  const int steps = *rc::gen::element(degree, degree + 1, 2 * degree);
  const bool turn = *rc::gen::arbitrary<bool>();
  std::string s = "{\"type\": \"rational_bezier\", \"control_points\": [";
  std::string w = "[";
  for (int k = 0; k <= degree; ++k) {
    const Vec3E t = way_point(k, steps);
    const Mat34E m = turn ? rational_rotation(*rc::gen::inRange(1, 4), *rc::gen::inRange(-1, 2), *rc::gen::inRange(-1, 2),
                                              *rc::gen::inRange(-1, 2), t)
                          : translation(t[0], t[1], t[2]);
    s += (k ? ", " : "") + matrix_json(m);
    w += (k ? ", " : "") + q(Exact(*rc::gen::inRange(1, 4), *rc::gen::inRange(1, 3)));
  }
  return s + "], \"weights\": " + w + "]}";
}

std::string rotation_json(bool rpy) {
  if (rpy) return "{\"rpy\": " + vec({pick(-1.5, 1.5), pick(-1.5, 1.5), pick(-1.5, 1.5)}) + "}";
  return "{\"quaternion\": [" + q(Exact(*rc::gen::inRange(1, 5))) + ", " + q(Exact(*rc::gen::inRange(-2, 3))) + ", " +
         q(Exact(*rc::gen::inRange(-2, 3))) + ", " + q(Exact(*rc::gen::inRange(-2, 3))) + "]}";
}

std::string keyframe_motion_json() {
  const int n = *rc::gen::inRange(2, 4);
  const std::string how = *rc::gen::element<std::string>("slerp", "screw", "nlerp");
  std::string s = "{\"type\": \"keyframes\", \"interpolation\": \"" + how + "\", \"poses\": [";
  for (int k = 0; k < n; ++k) {
    const bool rpy = *rc::gen::inRange(0, 4) != 0;
    s += std::string(k ? ", " : "") + "{\"translation\": " + vec(way_point(k, n - 1 + *rc::gen::inRange(0, 2))) +
         ", \"rotation\": " + rotation_json(rpy) + "}";
  }
  return s + "]}";
}

struct Options {
  VerifyOptions verify;
  std::string label;
};

// Search options that make it stop: a coarse epsilon, sometimes a small
// depth or stop budget, exact resolution sometimes off; the hierarchy, the
// kernel and the thread count random.
Options pick_options() {
  Options o;
  o.verify.epsilon = Exact(1, *rc::gen::element(4, 16, 64, 256));
  o.verify.max_depth = *rc::gen::element(6, 10, 30);
  o.verify.max_stops = *rc::gen::element<std::uint64_t>(2, 16, 256);
  o.verify.max_nodes = 20000;
  o.verify.exact_resolution = *rc::gen::arbitrary<bool>();
  o.verify.hierarchy = *rc::gen::arbitrary<bool>();
  o.verify.kernel = *rc::gen::inRange(0, 4) == 0 ? KernelKind::Exact : KernelKind::Filtered;
  o.verify.threads = *rc::gen::element(1, 3);
  o.label = "epsilon " + to_string(*o.verify.epsilon) + ", max_depth " + std::to_string(o.verify.max_depth) +
            ", max_stops " + std::to_string(o.verify.max_stops) + (o.verify.exact_resolution ? "" : ", no exact resolution") +
            (o.verify.hierarchy ? "" : ", all pairs") + ", kernel " + to_string(o.verify.kernel) + ", threads " +
            std::to_string(o.verify.threads);
  return o;
}

Exact mass_sum(const Body& b) {
  Exact w = 0;
  for (const Exact& x : b.mass.weights) w += x;
  return w;
}

// Verifies the scene (after reading it back: the scene printed in the log
// is what ran) and checks every check's claims.
void verify_and_check(const std::string& json, const Options& o, std::map<int, LinkPose> links = {},
                      const std::string& base = ".") {
  RC_LOG() << json << "\n" << o.label << "\n";
  std::vector<SceneRobot> robots;
  Scene scene;
  try {
    scene = parse_scene_text(json, "partition", base, robots);
  } catch (const InputError& e) {
    RC_DISCARD(std::string("refused (a valid refusal, e.g. keyframes 180 degrees apart): ") + e.what());
  }
  const SceneResult result = verify_scene(scene, o.verify);
  Oracle oracle{scene, {}, std::move(links)};
  RC_TAG(to_string(result.verdict));
  for (std::size_t k = 0; k < result.checks.size(); ++k) {
    const CheckResult& r = result.checks[k];
    Claim c;
    c.clearance2 = r.clearance * r.clearance;
    // A tolerance r of a body: a translation by v with |v|^2 W <= r^2 is admissible.
    for (const int i : r.bodies) {
      const Body& b = scene.bodies[i];
      if (b.tolerance > 0) c.reach2 = std::max(c.reach2, b.tolerance * b.tolerance / mass_sum(b));
    }
    oracle.claim = c;
    for (const UndecidedInterval& u : r.undecided)
      if (u.reason == StopReason::AfterUndecided) RC_TAG("after_undecided");
    check_claims(oracle, r, o.label);
  }
  // The thread count does not change the result.
  if (o.verify.threads > 1 && o.verify.time_limit == 0) {
    VerifyOptions one = o.verify;
    one.threads = 1;
    const SceneResult single = verify_scene(scene, one);
    for (std::size_t k = 0; k < result.checks.size(); ++k) {
      const CheckResult &x = result.checks[k], &y = single.checks[k];
      RC_ASSERT(x.verdict == y.verdict);
      RC_ASSERT(x.undecided.size() == y.undecided.size());
      for (std::size_t i = 0; i < x.undecided.size(); ++i) {
        RC_ASSERT(x.undecided[i].t0 == y.undecided[i].t0);
        RC_ASSERT(x.undecided[i].t1 == y.undecided[i].t1);
        RC_ASSERT(x.undecided[i].reason == y.undecided[i].reason);
      }
      RC_ASSERT(x.witness.has_value() == y.witness.has_value());
      if (x.witness) RC_ASSERT(x.witness->t == y.witness->t);
    }
  }
}

// The fixed cube [0, 1]^3, solid or not, and extras: a clearance or a
// tolerance of the mover, sometimes.
struct Extras {
  std::string scene_fields, mover_fields;
};

Extras pick_extras() {
  Extras e;
  const int k = *rc::gen::inRange(0, 6);
  if (k == 0) e.scene_fields = "\"clearance\": " + q(pick(0.0625, 0.25)) + ", ";
  if (k == 1) e.mover_fields = ", \"tolerance\": " + q(pick(0.0625, 0.25));
  return e;
}

std::string cube_json(bool solid) {
  return "{\"name\": \"cube\", \"polygons\": " + box_polygons({0, 0, 0}, {1, 1, 1}) + (solid ? ", \"solid\": true" : "") + "}";
}

// ------------------------------------------------------------------ robots

// A chain of 1-3 revolute joints about integer axes, box links (no origin
// offset: the body frame is the link frame), moving between two random
// joint vectors, based beside a solid box it reaches into.
struct Chain {
  std::vector<std::array<int, 3>> xyz, axis, box;  // hundredths; axis integers
  std::vector<std::array<int, 2>> q;               // hundredths, at t = 0 and 1
};

std::string triple(const std::array<int, 3>& v, bool hundredths) {
  std::ostringstream s;
  for (int i = 0; i < 3; ++i) s << (i ? " " : "") << (hundredths ? v[i] / 100.0 : v[i]);
  return s.str();
}

std::string urdf_of(const Chain& c) {
  std::ostringstream u;
  u << "<robot name=\"chain\">\n<link name=\"l0\"/>\n";
  for (std::size_t j = 0; j < c.xyz.size(); ++j) {
    u << "<link name=\"l" << j + 1 << "\"><collision><geometry><box size=\"" << triple(c.box[j], true)
      << "\"/></geometry></collision></link>\n";
    u << "<joint name=\"j" << j + 1 << "\" type=\"revolute\"><parent link=\"l" << j << "\"/><child link=\"l" << j + 1
      << "\"/><origin xyz=\"" << triple(c.xyz[j], true) << "\"/><axis xyz=\"" << triple(c.axis[j], false)
      << "\"/><limit lower=\"-3\" upper=\"3\" effort=\"1\" velocity=\"1\"/></joint>\n";
  }
  u << "</robot>\n";
  return u.str();
}

MpPose mp_chain(const Chain& c, const Vec3E& base, std::size_t link, const Exact& s) {
  MpPose m;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) m[4 * i + j] = Mp(i == j ? 1 : 0);
    m[4 * i + 3] = Mp(base[i]);
  }
  auto compose = [](const MpPose& a, const MpPose& b) {
    MpPose out;
    for (int r = 0; r < 3; ++r)
      for (int col = 0; col < 4; ++col) {
        Mp v = a[4 * r] * b[col] + a[4 * r + 1] * b[4 + col] + a[4 * r + 2] * b[8 + col];
        if (col == 3) v = v + a[4 * r + 3];
        out[4 * r + col] = v;
      }
    return out;
  };
  for (std::size_t j = 0; j < link; ++j) {
    MpPose origin;
    for (int i = 0; i < 3; ++i) {
      for (int k = 0; k < 3; ++k) origin[4 * i + k] = Mp(i == k ? 1 : 0);
      origin[4 * i + 3] = Mp(Exact(c.xyz[j][i], 100));
    }
    const Exact qv = Exact(c.q[j][0], 100) + (Exact(c.q[j][1], 100) - Exact(c.q[j][0], 100)) * s;
    const Mp n = sqrt(Mp(c.axis[j][0] * c.axis[j][0] + c.axis[j][1] * c.axis[j][1] + c.axis[j][2] * c.axis[j][2]));
    const Mp half = Mp(qv) / Mp(2);
    const MpMat3 r = quat_matrix_unit({cos(half), sin(half) * Mp(c.axis[j][0]) / n, sin(half) * Mp(c.axis[j][1]) / n,
                                       sin(half) * Mp(c.axis[j][2]) / n});
    MpPose joint;
    for (int i = 0; i < 3; ++i) {
      for (int k = 0; k < 3; ++k) joint[4 * i + k] = r[3 * i + k];
      joint[4 * i + 3] = Mp(0);
    }
    m = compose(compose(m, origin), joint);
  }
  return m;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(partition)

// One body moving by a rational Bezier motion (degree 1-3, random weights,
// translations or rational rotations) through the fixed unit cube.
BOOST_AUTO_TEST_CASE(rational_motions_claim_only_what_holds) {
  check_cases(
      [] {
        bool mover_solid = false;
        const std::string geometry = mover_geometry(mover_solid);
        const Extras e = pick_extras();
        const bool solid = *rc::gen::inRange(0, 4) != 0;
        const std::string json = "{\"format\": \"tmcert-scene/1\", " + e.scene_fields + "\"bodies\": [" + cube_json(solid) +
                                 ", {\"name\": \"mover\", " + geometry + e.mover_fields + ", \"motion\": " +
                                 rational_motion_json() + "}], \"checks\": [[\"mover\", \"cube\"]]}";
        verify_and_check(json, pick_options());
      },
      60);
}

// Keyframes (slerp, screw, nlerp; rpy rotations mostly): enclosed poses.
BOOST_AUTO_TEST_CASE(keyframe_motions_claim_only_what_holds) {
  check_cases(
      [] {
        bool mover_solid = false;
        const std::string geometry = mover_geometry(mover_solid);
        const Extras e = pick_extras();
        const bool solid = *rc::gen::inRange(0, 4) != 0;
        const std::string json = "{\"format\": \"tmcert-scene/1\", " + e.scene_fields + "\"bodies\": [" + cube_json(solid) +
                                 ", {\"name\": \"mover\", " + geometry + e.mover_fields + ", \"motion\": " +
                                 keyframe_motion_json() + "}], \"checks\": [[\"mover\", \"cube\"]]}";
        Options o = pick_options();
        o.verify.exact_resolution = true;  // rational parts only; keyframes are enclosed
        verify_and_check(json, o);
      },
      100);
}

// Both bodies move: the solid cube too (keyframes or rational), the check
// named either way round.
BOOST_AUTO_TEST_CASE(two_moving_bodies_claim_only_what_holds) {
  check_cases(
      [] {
        bool mover_solid = false;
        const std::string geometry = mover_geometry(mover_solid);
        const bool rational = *rc::gen::arbitrary<bool>();
        const bool solid = *rc::gen::inRange(0, 4) != 0;
        std::string cube_motion;
        if (rational) {
          cube_motion = "{\"type\": \"rational_bezier\", \"control_points\": [" +
                        matrix_json(translation(pick(-0.25, 0.25), 0, 0)) + ", " +
                        matrix_json(translation(pick(-0.5, 0.5), pick(-0.25, 0.25), 0)) + "]}";
        } else {
          cube_motion = "{\"type\": \"keyframes\", \"interpolation\": \"slerp\", \"poses\": [{\"translation\": " +
                        vec({pick(-0.25, 0.25), 0, 0}) + ", \"rotation\": " + rotation_json(true) + "}, {\"translation\": " +
                        vec({pick(-0.5, 0.5), 0, 0}) + ", \"rotation\": " + rotation_json(true) + "}]}";
        }
        const std::string motion = rational ? rational_motion_json() : keyframe_motion_json();
        const bool swap = *rc::gen::arbitrary<bool>();
        const std::string json = "{\"format\": \"tmcert-scene/1\", \"bodies\": [{\"name\": \"cube\", \"polygons\": " +
                                 box_polygons({0, 0, 0}, {1, 1, 1}) + (solid ? ", \"solid\": true" : "") +
                                 ", \"motion\": " + cube_motion + "}, {\"name\": \"mover\", " + geometry +
                                 ", \"motion\": " + motion + "}], \"checks\": [" +
                                 (swap ? "[\"cube\", \"mover\"]" : "[\"mover\", \"cube\"]") + "]}";
        Options o = pick_options();
        verify_and_check(json, o);
      },
      60);
}

// Robot links turning in joint space (enclosed poses) into a solid box.
BOOST_AUTO_TEST_CASE(robot_links_claim_only_what_holds) {
  check_cases(
      [] {
        Chain c;
        const int joints = *rc::gen::inRange(1, 4);
        for (int j = 0; j < joints; ++j) {
          c.xyz.push_back({j == 0 ? 0 : *rc::gen::inRange(20, 50), 0, *rc::gen::inRange(-10, 11)});
          c.axis.push_back(*rc::gen::element(std::array<int, 3>{0, 0, 1}, std::array<int, 3>{0, 1, 0},
                                             std::array<int, 3>{1, 1, 0}, std::array<int, 3>{0, 1, 2}));
          c.box.push_back({*rc::gen::inRange(20, 60), *rc::gen::inRange(5, 20), *rc::gen::inRange(5, 20)});
          c.q.push_back({*rc::gen::inRange(-150, 151), *rc::gen::inRange(-150, 151)});
        }
        const std::string urdf = urdf_of(c);
        RC_LOG() << urdf;
        const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                          ("tmcert-partition-" + std::to_string(::getpid()));
        std::filesystem::create_directories(dir);
        {
          std::ofstream out(dir / "chain.urdf");
          out << urdf;
        }
        const Vec3E base{pick(-0.5, 0.5), pick(-0.5, 0.5), 0};
        const bool solid = *rc::gen::inRange(0, 4) != 0;
        std::string joint_names, q0, q1;
        for (int j = 0; j < joints; ++j) {
          joint_names += std::string(j ? ", " : "") + "\"j" + std::to_string(j + 1) + "\"";
          q0 += std::string(j ? ", " : "") + q(Exact(c.q[j][0], 100));
          q1 += std::string(j ? ", " : "") + q(Exact(c.q[j][1], 100));
        }
        const Extras e = pick_extras();
        const std::string json =
            "{\"format\": \"tmcert-scene/1\", " + e.scene_fields + "\"robots\": [{\"name\": \"r\", \"urdf\": \"chain.urdf\", " +
            "\"base\": {\"translation\": " + vec(base) + "}, \"joints\": [" + joint_names +
            "], \"path\": {\"times\": [0, 1], \"positions\": [[" + q0 + "], [" + q1 + "]]}}], \"bodies\": [{\"name\": \"block\", " +
            "\"polygons\": " +
            box_polygons({pick(0.125, 0.5), pick(-0.5, -0.0625), pick(-0.25, -0.0625)}, {1, pick(0.0625, 0.5), pick(0.0625, 0.25)}) +
            (solid ? ", \"solid\": true" : "") + "}]}";
        std::map<int, LinkPose> links;
        std::vector<SceneRobot> robots;
        Scene scene;
        try {
          scene = parse_scene_text(json, "partition", dir.string(), robots);
        } catch (const InputError& e) {
          RC_DISCARD(std::string("refused: ") + e.what());
        }
        for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
          const std::string& name = scene.bodies[i].name;
          if (name.rfind("r/l", 0) != 0) continue;
          const std::size_t link = std::stoul(name.substr(3));
          links[static_cast<int>(i)] = [c, base, link](const Exact& s) { return mp_chain(c, base, link, s); };
        }
        Options o = pick_options();
        o.verify.max_nodes = 4000;  // robot links are costly pieces: a smaller budget (its limit is a stop too)
        verify_and_check(json, o, std::move(links), dir.string());
      },
      30);
}

// The oracle itself on hand cases (it must be able to see a violation).
BOOST_AUTO_TEST_CASE(oracle_sees_contact_inside_and_distance) {
  const Scene scene = parse_scene_text(
      "{\"format\": \"tmcert-scene/1\", \"bodies\": [" + cube_json(true) +
          ", {\"name\": \"p\", \"points\": [[0, 0, 0]]}, {\"name\": \"s\", \"segments\": [[[\"1/2\", \"1/2\", -1], "
          "[\"1/2\", \"1/2\", \"1/2\"]]]}], \"checks\": [[\"p\", \"cube\"]]}",
      "oracle");
  const Body &cube = scene.bodies[0], &p = scene.bodies[1], &s = scene.bodies[2];
  auto at = [](const Vec3E& d) { return [d](const Vec3E& x) { return add(x, d); }; };
  const Placed c = place_body(cube, at({0, 0, 0}));
  Claim exact;
  BOOST_TEST(violation(place_body(p, at({Exact(1, 2), Exact(1, 2), Exact(1, 2)})), c, exact) != "");  // inside
  BOOST_TEST(violation(place_body(p, at({1, Exact(1, 2), Exact(1, 2)})), c, exact) != "");            // on a face
  BOOST_TEST(violation(place_body(p, at({2, 2, 2})), c, exact) == "");
  Claim near;
  near.clearance2 = Exact(1, 4);
  BOOST_TEST(violation(place_body(p, at({Exact(3, 2), Exact(1, 2), Exact(1, 2)})), c, near) != "");  // 1/2 away
  BOOST_TEST(violation(place_body(p, at({Exact(8, 5), Exact(1, 2), Exact(1, 2)})), c, near) == "");
  // A segment through the cube's bottom face, robustly (the MPFR case).
  Claim robust;
  robust.margin2 = Exact(1, 1000000);
  const Placed hollow = place_body(scene.bodies[0], at({0, 0, 0}));
  BOOST_TEST(violation(place_body(s, at({0, 0, 0})), hollow, robust) != "");
  BOOST_TEST(violation(place_body(s, at({0, 0, Exact(-3, 2)})), hollow, robust) == "");
}

BOOST_AUTO_TEST_SUITE_END()
