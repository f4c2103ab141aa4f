// Helpers shared by the property tests (tests/property/*.cpp): an exact
// oracle written independently of the library (rational Bezier evaluation,
// point in triangle / on segment, body containment, the consistency of a
// check result with the guarantee), scene building with default masses as
// the parser computes them, world maps and changes of unit, failure-log
// descriptions (scenes as tmcert-scene/1 JSON), rapidcheck generators of
// small exact rationals and shapes, and a runner for properties with a
// chosen number of cases.
#pragma once

#include <rapidcheck/boost_test.h>

#include "kernels/number_types.h"
#include "src/metric/metric.h"
#include "src/model/model.h"
#include "src/certificate/algebraic_witness.h"
#include "tests/support/witness_time.h"
#include "src/verify/verify.h"
#include "tests/support/exact_oracle.h"

#include <boost/test/unit_test.hpp>
#include <rapidcheck.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace tmcert::testing {

// ------------------------------------------------------------------ exact geometry (the oracle)

inline Vec3E add(const Vec3E& a, const Vec3E& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline Vec3E mul(const Exact& s, const Vec3E& a) { return {s * a[0], s * a[1], s * a[2]}; }
inline Vec3E lerp(const Vec3E& a, const Vec3E& b, const Exact& t) { return add(mul(1 - t, a), mul(t, b)); }

inline Vec3E place(const Mat34E& m, const Vec3E& x) {
  Vec3E r;
  for (int i = 0; i < 3; ++i) r[i] = m[4 * i] * x[0] + m[4 * i + 1] * x[1] + m[4 * i + 2] * x[2] + m[4 * i + 3];
  return r;
}

// The composition w o m of affine maps (x -> w(m(x))).
inline Mat34E compose(const Mat34E& w, const Mat34E& m) {
  Mat34E out;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) {
      Exact s = c == 3 ? w[4 * r + 3] : Exact(0);
      for (int k = 0; k < 3; ++k) s += w[4 * r + k] * m[4 * k + c];
      out[4 * r + c] = s;
    }
  return out;
}

inline const Mat34E kIdentity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};

inline Mat34E translation(const Exact& x, const Exact& y, const Exact& z) {
  return {1, 0, 0, x, 0, 1, 0, y, 0, 0, 1, z};
}

inline bool nondegenerate(const std::vector<Vec3E>& tri) {
  return !is_zero(cross(sub(tri[1], tri[0]), sub(tri[2], tri[0])));
}

inline Exact pow10(int e) {
  Exact r = 1;
  for (int i = 0; i < (e < 0 ? -e : e); ++i) r *= 10;
  return e < 0 ? 1 / r : r;
}

// ------------------------------------------------------------------ scenes

inline std::vector<Vec3E> body_vertices(const Body& b) {
  std::vector<Vec3E> v;
  for (const auto& poly : b.polygons) v.insert(v.end(), poly.begin(), poly.end());
  for (const auto& seg : b.segments) v.insert(v.end(), seg.begin(), seg.end());
  v.insert(v.end(), b.points.begin(), b.points.end());
  return v;
}

// Default masses exactly as the parser computes them (src/io/parse.cpp):
// the fallback size of a single point is the extent of every body's
// vertices in its own frame.
inline void rebuild_masses(Scene& s) {
  const Exact size = default_mass_fallback_size(s.bodies);
  for (Body& b : s.bodies)
    if (b.mass_is_default) b.mass = default_mass(body_vertices(b), size);
}

// A body made of convex polygons (each given with no three consecutive
// vertices collinear), with the default mass distribution of its own
// vertices (make_scene recomputes it with the scene's size).
inline Body make_body(const std::string& name, const std::vector<std::vector<Vec3E>>& polygons,
                      std::optional<Motion> motion = std::nullopt) {
  Body b;
  b.name = name;
  b.polygons = polygons;
  for (std::size_t i = 0; i < polygons.size(); ++i) b.pieces.push_back(ConvexPiece{static_cast<int>(i), polygons[i]});
  b.mass = default_mass(body_vertices(b), Exact(1));
  b.mass_is_default = true;
  b.motion = std::move(motion);
  return b;
}

// The scene of the two bodies with the one check (0, 1), default masses as
// the parser computes them.
inline Scene make_scene(Body one, Body two, const Exact& epsilon) {
  Scene s;
  s.source = "property";
  s.bodies = {std::move(one), std::move(two)};
  s.epsilon = epsilon;
  s.max_depth = 30;
  s.checks = {{0, 1}};
  rebuild_masses(s);
  return s;
}

inline VerifyOptions options_for(const Exact& epsilon, KernelKind kernel, std::uint64_t max_nodes = 20000) {
  VerifyOptions o;
  o.kernel = kernel;
  o.epsilon = epsilon;
  o.max_depth = 30;
  o.max_nodes = max_nodes;
  return o;
}

// ------------------------------------------------------------------ transformations

// Applies the affine world map W to the scene: moving (and posed) bodies'
// control points [A | a] -> W o [A | a]; plain fixed bodies' coordinates
// x -> W x (W must keep polygons valid: a rotation or a translation here).
inline Scene world_mapped(const Scene& s, const Mat34E& W) {
  Scene out = s;
  for (Body& b : out.bodies) {
    if (b.motion) {
      for (Mat34E& p : b.motion->control_points) p = compose(W, p);
      continue;
    }
    map_coordinates(b, [&](const Vec3E& v) { return place(W, v); });
  }
  rebuild_masses(out);
  return out;
}

// The scene translated by d.
inline Scene translated(const Scene& s, const Vec3E& d) { return world_mapped(s, translation(d[0], d[1], d[2])); }

// A change of unit: every length times f (coordinates in every body's own
// frame, translation columns, epsilon); linear parts are unitless.
inline Scene scaled(const Scene& s, const Exact& f) {
  Scene out = s;
  for (Body& b : out.bodies) {
    map_coordinates(b, [&](const Vec3E& v) { return mul(f, v); });
    if (b.motion)
      for (Mat34E& p : b.motion->control_points)
        for (int r = 0; r < 3; ++r) p[4 * r + 3] *= f;
  }
  if (out.epsilon) *out.epsilon *= f;
  rebuild_masses(out);
  return out;
}

// ------------------------------------------------------------------ failure logs

inline std::string str(const Exact& q) { return to_string(q); }
inline std::string str(const Vec3E& v) {
  return "[\"" + str(v[0]) + "\", \"" + str(v[1]) + "\", \"" + str(v[2]) + "\"]";
}

// The scene as a tmcert-scene/1 document (for failure logs: save it and run
// `tmcert verify` on it).
inline std::string describe(const Scene& s) {
  std::ostringstream o;
  o << "{ \"format\": \"tmcert-scene/1\", \"epsilon\": \"" << (s.epsilon ? str(*s.epsilon) : "?")
    << "\", \"max_depth\": " << s.max_depth << ", \"bodies\": [\n";
  for (std::size_t i = 0; i < s.bodies.size(); ++i) {
    const Body& b = s.bodies[i];
    o << "  { \"name\": \"" << b.name << "\"";
    if (!b.polygons.empty()) {
      o << ", \"polygons\": [";
      for (std::size_t p = 0; p < b.polygons.size(); ++p) {
        o << (p ? ", " : "") << "[";
        for (std::size_t k = 0; k < b.polygons[p].size(); ++k) o << (k ? ", " : "") << str(b.polygons[p][k]);
        o << "]";
      }
      o << "]";
    }
    if (!b.segments.empty()) {
      o << ", \"segments\": [";
      for (std::size_t k = 0; k < b.segments.size(); ++k)
        o << (k ? ", " : "") << "[" << str(b.segments[k][0]) << ", " << str(b.segments[k][1]) << "]";
      o << "]";
    }
    if (!b.points.empty()) {
      o << ", \"points\": [";
      for (std::size_t k = 0; k < b.points.size(); ++k) o << (k ? ", " : "") << str(b.points[k]);
      o << "]";
    }
    if (b.motion) {
      const Motion& m = *b.motion;
      o << ",\n    \"motion\": { \"type\": \"rational_bezier\", \"interval\": [\"" << str(m.t0) << "\", \"" << str(m.t1)
        << "\"],\n      \"control_points\": [";
      for (std::size_t k = 0; k < m.control_points.size(); ++k) {
        o << (k ? ",\n        " : "") << "[";
        for (int r = 0; r < 3; ++r) {
          o << (r ? ", " : "") << "[";
          for (int c = 0; c < 4; ++c) o << (c ? ", " : "") << "\"" << str(m.control_points[k][4 * r + c]) << "\"";
          o << "]";
        }
        o << "]";
      }
      o << "],\n      \"weights\": [";
      for (std::size_t k = 0; k < m.weights.size(); ++k) o << (k ? ", " : "") << "\"" << str(m.weights[k]) << "\"";
      o << "] }";
    }
    o << " }" << (i + 1 < s.bodies.size() ? "," : "") << "\n";
  }
  o << "], \"checks\": [";
  for (std::size_t c = 0; c < s.checks.size(); ++c)
    o << (c ? ", " : "") << "[\"" << s.bodies[s.checks[c].first].name << "\", \"" << s.bodies[s.checks[c].second].name
      << "\"]";
  o << "] }";
  return o.str();
}

inline std::string describe(const CheckResult& r) {
  std::ostringstream o;
  o << "verdict " << to_string(r.verdict);
  if (r.first_contact) o << ", first_contact [" << str(r.first_contact->first) << ", " << str(r.first_contact->second) << "]";
  if (r.witness)
    o << ", witness t=" << str(r.witness->t) << " (" << r.witness->features[0] << " / " << r.witness->features[1]
      << ") point " << str(r.witness->point);
  o << ", undecided intervals " << r.undecided.size();
  if (!r.undecided.empty())
    o << " (first [" << str(r.undecided.front().t0) << ", " << str(r.undecided.front().t1) << "] "
      << to_string(r.undecided.front().reason) << ")";
  o << ", nodes " << r.stats.nodes << ", depth " << r.stats.max_depth << (r.stats.prefiltered ? ", prefiltered" : "")
    << ", " << r.stats.seconds << " s";
  return o.str();
}

// A coarse label of the work a check took, for rapidcheck's distribution
// output (shows that the cases exercise subdivision, not just the root).
inline std::string nodes_label(const CheckResult& r) {
  const std::uint64_t n = r.stats.nodes;
  return n <= 1 ? "nodes 0-1" : n <= 16 ? "nodes 2-16" : n <= 256 ? "nodes 17-256" : n <= 4096 ? "nodes 257-4096" : "nodes > 4096";
}

// The same, with the checks the certified prefilter decided alone apart.
inline std::string work_label(const CheckResult& r) { return r.stats.prefiltered ? "prefiltered" : nodes_label(r); }

inline std::string stop_label(const CheckResult& r) {
  if (r.verdict == Verdict::Collision && r.stats.nodes == 0) return "collision (start check)";
  if (r.verdict != Verdict::Undecided || r.undecided.empty()) return to_string(r.verdict);
  return std::string("undecided (") + to_string(r.undecided.front().reason) + ")";
}

// ------------------------------------------------------------------ the witness oracle

// The pose of a body at scene parameter t (identity when fixed; a one-point
// motion is a constant pose).
inline Mat34E pose_at(const Body& b, const Exact& t) {
  if (!b.motion) return kIdentity;
  return b.motion->control_points.size() == 1 ? b.motion->control_points[0] : eval_motion(*b.motion, t);
}

inline bool is_moving(const Body& b) { return b.motion && b.motion->control_points.size() >= 2; }

// Does the body (placed at scene parameter t) contain p?
inline bool body_contains(const Body& b, const Exact& t, const Vec3E& p) {
  const Mat34E pose = pose_at(b, t);
  for (const ConvexPiece& piece : b.pieces)
    for (std::size_t k = 1; k + 1 < piece.vertices.size(); ++k)
      if (in_triangle(p, place(pose, piece.vertices[0]), place(pose, piece.vertices[k]),
                      place(pose, piece.vertices[k + 1])))
        return true;
  for (const auto& seg : b.segments)
    if (on_segment(p, place(pose, seg[0]), place(pose, seg[1]))) return true;
  for (const Vec3E& x : b.points)
    if (place(pose, x) == p) return true;
  return false;
}

// A witness at an irrational time (exact resolution): its root claim holds
// (square-free, exactly one root in the open interval, inside the motion),
// the bracket ends at it (and is exact unless something before it was left
// undecided), the point box is a box, and some sub-features (a vertex, an
// edge, the whole element) of the two named parts provably meet at the
// root - checked as `tmcert check` checks certificates, from the scene
// alone, not by the search.
inline std::string algebraic_witness_problem(const Scene& s, int a, int b, const CheckResult& r) {
  const Witness& w = *r.witness;
  const AlgebraicTime& at = *w.root;
  const Body& mb = is_moving(s.bodies[a]) ? s.bodies[a] : s.bodies[b];
  const Exact t0 = mb.motion->t0, t1 = mb.motion->t1;
  const certificate::ClaimedRoot claim{at.root_of, at.lo, at.hi};
  if (const std::string e = certificate::root_claim_error(claim, t0, t1); !e.empty()) return "witness root: " + e;
  if (w.t != at.lo || r.first_contact->second != at.hi) return "the bracket does not end at the witness's root";
  if (r.first_contact_exact != r.undecided.empty()) return "first contact exact unless undecided pieces precede it";
  if (r.first_contact_exact && r.first_contact->first != at.lo) return "exact first contact not at the witness";
  if (!w.point_box) return "no point box at an algebraic time";
  for (const auto& range : *w.point_box)
    if (range[0] > range[1]) return "empty point box";
  RealRoot root = certificate::check_parameter_root(claim, t0, t1);
  const certificate::CheckMotions motions(s.bodies[a], s.bodies[b]);
  const Body* bodies[2] = {&s.bodies[a], &s.bodies[b]};
  std::vector<std::vector<Vec3E>> elems[2];
  for (int k = 0; k < 2; ++k) {
    const std::string part = w.features[k].substr(bodies[k]->name.size() + 1);
    std::istringstream in(part);
    std::string kind;
    int index = -1;
    in >> kind >> index;
    if (kind == "polygon") {
      for (const ConvexPiece& piece : bodies[k]->pieces)
        if (piece.polygon == index) elems[k].push_back(piece.vertices);
    } else if (kind == "segment" && index >= 0 && index < static_cast<int>(bodies[k]->segments.size())) {
      elems[k].push_back({bodies[k]->segments[index][0], bodies[k]->segments[index][1]});
    } else if (kind == "point" && index >= 0 && index < static_cast<int>(bodies[k]->points.size())) {
      elems[k].push_back({bodies[k]->points[index]});
    }
  }
  for (const auto& ea : elems[0])
    for (const auto& eb : elems[1])
      for (const auto& sa : certificate::sub_features(ea.size()))
        for (const auto& sb : certificate::sub_features(eb.size())) {
          std::vector<MovingPoint> pa, pb;
          for (int i : sa) pa.push_back(motions.place(0, ea[i]));
          for (int j : sb) pb.push_back(motions.place(1, eb[j]));
          if (ContactSolver::touch(pa, pb, root)) return "";
        }
  return "no sub-features of the witness's parts meet at its root";
}

// Empty when the result is consistent with the guarantee as far as can be
// checked without knowing the truth: a collision has a genuine witness inside
// its first-contact bracket, a non-safe verdict has a bracket, and so on.
// Both bodies may move (then over the same interval).
inline std::string consistency_problem(const Scene& s, int a, int b, const CheckResult& r) {
  if (r.bodies[0] != a || r.bodies[1] != b) return "result names the wrong bodies";
  if (r.verdict == Verdict::Safe) {
    if (r.first_contact) return "safe with a first_contact bracket";
    if (r.witness) return "safe with a witness";
    if (!r.undecided.empty()) return "safe with undecided intervals";
    return "";
  }
  const Body& mb = is_moving(s.bodies[a]) ? s.bodies[a] : s.bodies[b];
  const Exact t0 = mb.motion ? mb.motion->t0 : Exact(0), t1 = mb.motion ? mb.motion->t1 : Exact(1);
  if (!r.first_contact) return "non-safe verdict without first_contact";
  const auto& [lo, hi] = *r.first_contact;
  if (lo < t0 || hi > t1 || lo > hi) return "first_contact outside the motion interval";
  for (const UndecidedInterval& u : r.undecided)
    if (u.t0 < t0 || u.t1 > t1 || u.t0 >= u.t1) return "undecided interval malformed or outside the motion";
  if (r.verdict == Verdict::Undecided) {
    if (r.witness) return "undecided with a witness";
    if (r.undecided.empty()) return "undecided without undecided intervals";
    if (r.undecided.front().t0 != lo) return "first_contact lower end is not the first undecided interval's";
    return "";
  }
  // Collision.
  if (!r.witness) return "collision without witness";
  const Witness& w = *r.witness;
  if (w.t < lo || w.t > hi) return "witness time outside first_contact";
  if (w.features[0].rfind(s.bodies[a].name + " ", 0) != 0 || w.features[1].rfind(s.bodies[b].name + " ", 0) != 0)
    return "witness features do not name the check's bodies in order";
  if (w.root) return algebraic_witness_problem(s, a, b, r);
  if (!body_contains(s.bodies[a], w.t, w.point)) return "witness point not on body " + s.bodies[a].name;
  if (!body_contains(s.bodies[b], w.t, w.point)) return "witness point not on body " + s.bodies[b].name;
  return "";
}

// ------------------------------------------------------------------ generators (inside properties)

// An integer in [lo, hi], uniform whatever rapidcheck's current size
// (gen::inRange alone draws near `lo` while the size is small); shrinks
// towards lo.
template <class T>
T uniform(T lo, T hi) {
  return *rc::gen::resize(100, rc::gen::inRange(lo, static_cast<T>(hi + 1)));
}

// A rational in [lo, hi] (lo, hi exact doubles such as 0.25) with a small
// denominator: 1, 2, 3, 4, 5, 8 or 16.
inline Exact pick(double lo, double hi) {
  const int den = *rc::gen::element(1, 2, 4, 8, 16, 3, 5);
  const long n_lo = static_cast<long>(std::ceil(lo * den)), n_hi = static_cast<long>(std::floor(hi * den));
  if (n_lo > n_hi) return Exact(lo);
  return Exact(static_cast<int>(uniform(n_lo, n_hi)), den);
}

inline Vec3E pick_point(double lo, double hi) { return {pick(lo, hi), pick(lo, hi), pick(lo, hi)}; }

inline std::vector<Vec3E> pick_triangle(double lo, double hi) {
  std::vector<Vec3E> t = {pick_point(lo, hi), pick_point(lo, hi), pick_point(lo, hi)};
  RC_PRE(nondegenerate(t));
  return t;
}

// Positive weights in [1/4, 4].
inline std::vector<Exact> pick_weights(int count) {
  std::vector<Exact> w;
  for (int k = 0; k < count; ++k) w.push_back(pick(0.25, 4));
  return w;
}

// A motion interval [t0, t1] with t0 in [-1, 1] and length in [1/4, 2].
inline std::pair<Exact, Exact> pick_interval() {
  const Exact t0 = pick(-1, 1);
  return {t0, t0 + pick(0.25, 2)};
}

// A random affine (not necessarily rigid or regular) control point.
inline Mat34E pick_affine(double a_range, double t_range) {
  Mat34E m;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) m[4 * r + c] = pick(-a_range, a_range);
    m[4 * r + 3] = pick(-t_range, t_range);
  }
  return m;
}

// A point of the convex hull of `v`: convex weights 0..4 (zeros allowed, so
// vertices and edge points too).
inline Vec3E barycentric_point(const std::vector<Vec3E>& v) {
  std::vector<int> w;
  int total = 0;
  for (std::size_t j = 0; j < v.size(); ++j) total += w.emplace_back(uniform(0, 4));
  if (total == 0) total = w[0] = 1;
  Vec3E q = {0, 0, 0};
  for (std::size_t j = 0; j < v.size(); ++j)
    for (int c = 0; c < 3; ++c) q[c] += Exact(w[j]) * v[j][c];
  for (int c = 0; c < 3; ++c) q[c] /= Exact(total);
  return q;
}

// A random feature set in [lo, hi]^3 (a parallelogram reaches a bit beyond):
// a triangle, a parallelogram (a convex quadrilateral face), or, when
// `lower_dim`, a segment or a single point.  Returns the body (no motion) and
// the vertices whose convex hull is its point set.
inline std::pair<Body, std::vector<Vec3E>> pick_shape(const std::string& name, double lo, double hi, bool lower_dim) {
  const int kind = uniform(0, lower_dim ? 3 : 1);
  Body b;
  std::vector<Vec3E> v;
  if (kind == 0) {
    v = pick_triangle(lo, hi);
    b = make_body(name, {v});
  } else if (kind == 1) {
    v = pick_triangle(lo, hi);
    // v0, v1, v2, v0 + v2 - v1: a parallelogram, vertices in order.
    v.push_back({v[0][0] + v[2][0] - v[1][0], v[0][1] + v[2][1] - v[1][1], v[0][2] + v[2][2] - v[1][2]});
    b = make_body(name, {v});
  } else if (kind == 2) {
    v = {pick_point(lo, hi), pick_point(lo, hi)};
    RC_PRE(v[0] != v[1]);
    b = make_body(name, {});
    b.segments.push_back({v[0], v[1]});
  } else {
    v = {pick_point(lo, hi)};
    b = make_body(name, {});
    b.points.push_back(v[0]);
  }
  b.mass = default_mass(body_vertices(b), Exact(1));
  return {b, v};
}

// ------------------------------------------------------------------ running properties

// Runs a property as the current Boost test case with `percent` % of the
// configured number of cases (RC_PARAMS="max_success=N", default 100; at
// least one case), under the configured seed and reproduce settings,
// reporting like RC_BOOST_PROP.
template <typename Testable>
void check_cases(Testable&& testable, int percent) {
  using namespace rc::detail;
  const auto& tc = boost::unit_test::framework::current_test_case();
  TestMetadata metadata;
  metadata.id = tc.full_name();
  metadata.description = tc.p_name;
  TestParams params = configuration().testParams;
  params.maxSuccess = std::max(1, static_cast<int>(static_cast<long>(params.maxSuccess) * percent / 100));
  const auto result = checkTestable(std::forward<Testable>(testable), metadata, params);
  BOOST_CHECK(true);
  if (result.template is<SuccessResult>()) {
    if (!result.template get<SuccessResult>().distribution.empty()) {
      std::cout << "- " << metadata.description << std::endl;
      printResultMessage(result, std::cout);
      std::cout << std::endl;
    }
  } else {
    std::ostringstream ss;
    ss << "\n";
    printResultMessage(result, ss);
    BOOST_FAIL(ss.str());
  }
}

}  // namespace tmcert::testing
