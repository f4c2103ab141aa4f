// Property tests of the guarantee (DESIGN.md sections 4-6, SCENE_FORMAT.md
// "verdict"): never a false `safe`, never a false `collision`, every
// collision carries an exact witness inside its first-contact bracket, a
// clearance m is certified for epsilon <= m/4 (and m/2, DESIGN.md 6), an
// interpenetrating start is caught at t0, and verdicts do not depend on where
// the scene sits or on its unit of length.
//
// Every scene is built directly in C++ from exact rationals (small integers
// over small denominators), so the facts the properties rely on (a contact at
// a known time t*, a clearance m, a gap of exactly 10^-17) hold exactly.  The
// oracle used to check witnesses (rational Bezier evaluation, point in
// triangle / on segment) is written here independently of the library.
//
// Replay a failure with RC_PARAMS="seed=N" (the seed is printed at the start
// of the run) or with the RC_PARAMS="reproduce=..." line printed on failure;
// the failing scene is printed in the log as tmcert-scene/1 JSON.
// RC_PARAMS="max_success=N" changes the number of cases (the exact-kernel
// properties run half of them).

#include <rapidcheck/boost_test.h>

#include "kernels/number_types.h"
#include "src/metric/metric.h"
#include "src/scene/model.h"
#include "src/verify/verify.h"

#include <boost/test/unit_test.hpp>
#include <rapidcheck.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

using namespace tmcert;

namespace {

// ------------------------------------------------------------------ exact geometry (the oracle)

Vec3E sub(const Vec3E& a, const Vec3E& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Exact dot(const Vec3E& a, const Vec3E& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3E cross(const Vec3E& a, const Vec3E& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
bool is_zero(const Vec3E& a) { return a[0] == 0 && a[1] == 0 && a[2] == 0; }

Vec3E place(const Mat34E& m, const Vec3E& x) {
  Vec3E r;
  for (int i = 0; i < 3; ++i) r[i] = m[4 * i] * x[0] + m[4 * i + 1] * x[1] + m[4 * i + 2] * x[2] + m[4 * i + 3];
  return r;
}

const Mat34E kIdentity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};

Mat34E translation(const Exact& x, const Exact& y, const Exact& z) { return {1, 0, 0, x, 0, 1, 0, y, 0, 0, 1, z}; }

// The rational Bezier motion at scene parameter t, exactly: de Casteljau on
// the homogeneous points (w_k P_k, w_k).
Mat34E eval_motion(const Motion& m, const Exact& t) {
  const Exact u = (t - m.t0) / (m.t1 - m.t0);
  const std::size_t n = m.control_points.size();
  std::vector<std::array<Exact, 13>> h(n);
  for (std::size_t k = 0; k < n; ++k) {
    for (int e = 0; e < 12; ++e) h[k][e] = m.weights[k] * m.control_points[k][e];
    h[k][12] = m.weights[k];
  }
  for (std::size_t level = 1; level < n; ++level)
    for (std::size_t k = 0; k + level < n; ++k)
      for (int e = 0; e < 13; ++e) h[k][e] = (1 - u) * h[k][e] + u * h[k + 1][e];
  Mat34E out;
  for (int e = 0; e < 12; ++e) out[e] = h[0][e] / h[0][12];
  return out;
}

bool on_segment(const Vec3E& p, const Vec3E& a, const Vec3E& b) {
  if (a == b) return p == a;
  const Vec3E ab = sub(b, a), ap = sub(p, a);
  return is_zero(cross(ab, ap)) && dot(ap, ab) >= 0 && dot(sub(p, b), sub(a, b)) >= 0;
}

// p in the closed triangle abc, which may be degenerate (a singular affine
// map flattens it to a segment or a point).
bool in_triangle(const Vec3E& p, const Vec3E& a, const Vec3E& b, const Vec3E& c) {
  const Vec3E n = cross(sub(b, a), sub(c, a));
  if (is_zero(n)) return on_segment(p, a, b) || on_segment(p, b, c) || on_segment(p, a, c);
  if (dot(n, sub(p, a)) != 0) return false;
  return dot(cross(sub(b, a), sub(p, a)), n) >= 0 && dot(cross(sub(c, b), sub(p, b)), n) >= 0 &&
         dot(cross(sub(a, c), sub(p, c)), n) >= 0;
}

bool nondegenerate(const std::vector<Vec3E>& tri) { return !is_zero(cross(sub(tri[1], tri[0]), sub(tri[2], tri[0]))); }

// ------------------------------------------------------------------ scenes

std::vector<Vec3E> body_vertices(const Body& b) {
  std::vector<Vec3E> v;
  for (const auto& poly : b.polygons) v.insert(v.end(), poly.begin(), poly.end());
  for (const auto& seg : b.segments) v.insert(v.end(), seg.begin(), seg.end());
  v.insert(v.end(), b.points.begin(), b.points.end());
  return v;
}

// A body made of convex polygons (each given with no three consecutive
// vertices collinear), with the default mass distribution.
Body make_body(const std::string& name, const std::vector<std::vector<Vec3E>>& polygons,
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

Scene make_scene(Body moving, Body fixed, const Exact& epsilon) {
  Scene s;
  s.source = "property";
  s.bodies = {std::move(moving), std::move(fixed)};
  s.epsilon = epsilon;
  s.max_depth = 30;
  s.checks = {{0, 1}};
  return s;
}

std::vector<Vec3E> square_z0(const Exact& h) { return {{-h, -h, 0}, {h, -h, 0}, {h, h, 0}, {-h, h, 0}}; }

std::string str(const Exact& q) { return to_string(q); }
std::string str(const Vec3E& v) {
  return "[\"" + str(v[0]) + "\", \"" + str(v[1]) + "\", \"" + str(v[2]) + "\"]";
}

// The scene as a tmcert-scene/1 document (for failure logs: save it and run
// `tmcert verify` on it).
std::string describe(const Scene& s) {
  std::ostringstream o;
  o << "{ \"format\": \"tmcert-scene/1\", \"epsilon\": \"" << (s.epsilon ? str(*s.epsilon) : "?")
    << "\", \"max_depth\": " << s.max_depth << ", \"bodies\": [\n";
  for (std::size_t i = 0; i < s.bodies.size(); ++i) {
    const Body& b = s.bodies[i];
    o << "  { \"name\": \"" << b.name << "\", \"polygons\": [";
    for (std::size_t p = 0; p < b.polygons.size(); ++p) {
      o << (p ? ", " : "") << "[";
      for (std::size_t k = 0; k < b.polygons[p].size(); ++k) o << (k ? ", " : "") << str(b.polygons[p][k]);
      o << "]";
    }
    o << "]";
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

std::string describe(const CheckResult& r) {
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
  o << ", nodes " << r.stats.nodes << ", depth " << r.stats.max_depth << ", " << r.stats.seconds << " s";
  return o.str();
}

// A coarse label of the work a check took, for rapidcheck's distribution
// output (shows that the cases exercise subdivision, not just the root).
std::string work_label(const CheckResult& r) {
  const std::uint64_t n = r.stats.nodes;
  return n <= 1 ? "nodes 0-1" : n <= 16 ? "nodes 2-16" : n <= 256 ? "nodes 17-256" : n <= 4096 ? "nodes 257-4096" : "nodes > 4096";
}

std::string stop_label(const CheckResult& r) {
  if (r.verdict == Verdict::Collision && r.stats.nodes == 0) return "collision (start check)";
  if (r.verdict != Verdict::Undecided || r.undecided.empty()) return to_string(r.verdict);
  return std::string("undecided (") + to_string(r.undecided.front().reason) + ")";
}

// ------------------------------------------------------------------ the witness oracle

// The pose of a body at scene parameter t (identity when fixed; a one-point
// motion is a constant pose).
Mat34E pose_at(const Body& b, const Exact& t) {
  if (!b.motion) return kIdentity;
  return b.motion->control_points.size() == 1 ? b.motion->control_points[0] : eval_motion(*b.motion, t);
}

bool is_moving(const Body& b) { return b.motion && b.motion->control_points.size() >= 2; }

// Does the body (placed at scene parameter t) contain p?
bool body_contains(const Body& b, const Exact& t, const Vec3E& p) {
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

// Empty when the result is consistent with the guarantee as far as can be
// checked without knowing the truth: a collision has a genuine witness inside
// its first-contact bracket, a non-safe verdict has a bracket, and so on.
std::string consistency_problem(const Scene& s, int a, int b, const CheckResult& r) {
  const Motion& m = *(is_moving(s.bodies[a]) ? s.bodies[a].motion : s.bodies[b].motion);
  if (r.bodies[0] != a || r.bodies[1] != b) return "result names the wrong bodies";
  if (r.verdict == Verdict::Safe) {
    if (r.first_contact) return "safe with a first_contact bracket";
    if (r.witness) return "safe with a witness";
    if (!r.undecided.empty()) return "safe with undecided intervals";
    return "";
  }
  if (!r.first_contact) return "non-safe verdict without first_contact";
  const auto& [lo, hi] = *r.first_contact;
  if (lo < m.t0 || hi > m.t1 || lo > hi) return "first_contact outside the motion interval";
  for (const UndecidedInterval& u : r.undecided)
    if (u.t0 < m.t0 || u.t1 > m.t1 || u.t0 >= u.t1) return "undecided interval malformed or outside the motion";
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
Exact pick(double lo, double hi) {
  const int den = *rc::gen::element(1, 2, 4, 8, 16, 3, 5);
  const long n_lo = static_cast<long>(std::ceil(lo * den)), n_hi = static_cast<long>(std::floor(hi * den));
  if (n_lo > n_hi) return Exact(lo);
  return Exact(static_cast<int>(uniform(n_lo, n_hi)), den);
}

Vec3E pick_point(double lo, double hi) { return {pick(lo, hi), pick(lo, hi), pick(lo, hi)}; }

std::vector<Vec3E> pick_triangle(double lo, double hi) {
  std::vector<Vec3E> t = {pick_point(lo, hi), pick_point(lo, hi), pick_point(lo, hi)};
  RC_PRE(nondegenerate(t));
  return t;
}

// Positive weights in [1/4, 4].
std::vector<Exact> pick_weights(int count) {
  std::vector<Exact> w;
  for (int k = 0; k < count; ++k) w.push_back(pick(0.25, 4));
  return w;
}

// A motion interval [t0, t1] with t0 in [-1, 1] and length in [1/4, 2].
std::pair<Exact, Exact> pick_interval() {
  const Exact t0 = pick(-1, 1);
  return {t0, t0 + pick(0.25, 2)};
}

// A random affine (not necessarily rigid or regular) control point.
Mat34E pick_affine(double a_range, double t_range) {
  Mat34E m;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) m[4 * r + c] = pick(-a_range, a_range);
    m[4 * r + 3] = pick(-t_range, t_range);
  }
  return m;
}

Motion pick_translation_motion(int count, double xy, double z) {
  Motion m;
  std::tie(m.t0, m.t1) = pick_interval();
  for (int k = 0; k < count; ++k) m.control_points.push_back(translation(pick(-xy, xy), pick(-xy, xy), pick(-z, z)));
  m.weights = pick_weights(count);
  return m;
}

VerifyOptions options_for(const Exact& epsilon, KernelKind kernel, std::uint64_t max_nodes = 20000) {
  VerifyOptions o;
  o.kernel = kernel;
  o.epsilon = epsilon;
  o.max_depth = 30;
  o.max_nodes = max_nodes;
  return o;
}

// ------------------------------------------------------------------ scene kinds

// (b) A moving triangle whose every vertex, under every affine control point,
// has z >= m (with equality at the first or last control point), over the
// fixed square [-4,4]^2 x {0}.  The convex hull property gives clearance m.
Scene clearance_scene(Exact& m_out, int eps_divisor = 0) {
  const int count = uniform(2, 4);  // degree 1..3
  const Exact m = pick(0.25, 2) / *rc::gen::element(1, 1, 4, 8);  // 1/32 .. 2
  const std::vector<Vec3E> tri = pick_triangle(-1, 1);
  Motion motion;
  std::tie(motion.t0, motion.t1) = pick_interval();
  const int tight = *rc::gen::element(0, count - 1);
  for (int k = 0; k < count; ++k) {
    Mat34E p = pick_affine(2, 3);
    std::optional<Exact> zmin;
    for (const Vec3E& v : tri) {
      const Exact z = p[8] * v[0] + p[9] * v[1] + p[10] * v[2];
      if (!zmin || z < *zmin) zmin = z;
    }
    const Exact extra = k == tight ? Exact(0) : pick(0, 1);
    p[11] = m - *zmin + extra;
    motion.control_points.push_back(p);
  }
  motion.weights = pick_weights(count);
  m_out = m;
  const Exact epsilon = m / (eps_divisor > 0 ? eps_divisor : *rc::gen::element(4, 4, 8));
  return make_scene(make_body("mover", {tri}, motion), make_body("table", {square_z0(4)}), epsilon);
}

// (c) A triangle with one vertex below z = 0 and two above (or the reverse),
// its footprint in [-1,1]^2, so an edge pierces the interior of the square
// [-2,2]^2 x {0}; the motion only slides it by at most 1/2 in x, y and 1/4 in
// z, so the crossing stays strictly inside the square and no vertex comes
// near z = 0: no contact event ever happens, the bodies interpenetrate
// throughout.
Scene interpenetration_scene() {
  const int lone = uniform(0, 2);
  const int sign = *rc::gen::element(1, -1);
  std::vector<Vec3E> tri(3);
  for (int i = 0; i < 3; ++i) {
    const Exact h = pick(0.5, 2);
    tri[i] = {pick(-1, 1), pick(-1, 1), i == lone ? -sign * h : sign * h};
  }
  RC_PRE(nondegenerate(tri));
  const int count = uniform(2, 4);
  Motion motion = pick_translation_motion(count, 0.5, 0.25);
  return make_scene(make_body("blade", {tri}, motion), make_body("table", {square_z0(2)}), Exact(1, 100));
}

// A tilted triangle (vertex heights 0, in [1/4,1] and in [1,2] above its
// lowest vertex, footprint in [-1,1]^2) carried by a translation whose z goes
// from +3 at the start to -3 at the end (intermediate control points anywhere
// in [-3,3]) and whose x, y stay in [-1/2,1/2], through the square
// [-2,2]^2 x {0}: it passes clean through the square in the middle of the
// motion.
Scene sweep_scene() {
  std::vector<Vec3E> tri = {{pick(-1, 1), pick(-1, 1), 0}, {pick(-1, 1), pick(-1, 1), pick(0.25, 1)},
                            {pick(-1, 1), pick(-1, 1), pick(1, 2)}};
  RC_PRE(nondegenerate(tri));
  const int count = uniform(2, 4);
  Motion motion = pick_translation_motion(count, 0.5, 3);
  motion.control_points.front()[11] = 3;
  motion.control_points.back()[11] = -3;
  return make_scene(make_body("blade", {tri}, motion), make_body("table", {square_z0(2)}), Exact(1, 100));
}

// ------------------------------------------------------------------ transformations

Scene translated(const Scene& s, const Vec3E& d) {
  Scene out = s;
  for (Body& b : out.bodies) {
    if (b.motion) {
      for (Mat34E& p : b.motion->control_points)
        for (int r = 0; r < 3; ++r) p[4 * r + 3] += d[r];
      continue;
    }
    for (auto& poly : b.polygons)
      for (Vec3E& v : poly) v = {v[0] + d[0], v[1] + d[1], v[2] + d[2]};
    for (ConvexPiece& piece : b.pieces)
      for (Vec3E& v : piece.vertices) v = {v[0] + d[0], v[1] + d[1], v[2] + d[2]};
    for (auto& seg : b.segments)
      for (Vec3E& v : seg) v = {v[0] + d[0], v[1] + d[1], v[2] + d[2]};
    for (Vec3E& v : b.points) v = {v[0] + d[0], v[1] + d[1], v[2] + d[2]};
    b.mass = default_mass(body_vertices(b), Exact(1));
  }
  return out;
}

// Scales every length by f: coordinates of every body in its own frame,
// translation columns and epsilon (linear parts are unitless).
Scene scaled(const Scene& s, const Exact& f) {
  Scene out = s;
  for (Body& b : out.bodies) {
    for (auto& poly : b.polygons)
      for (Vec3E& v : poly) v = {v[0] * f, v[1] * f, v[2] * f};
    for (ConvexPiece& piece : b.pieces)
      for (Vec3E& v : piece.vertices) v = {v[0] * f, v[1] * f, v[2] * f};
    for (auto& seg : b.segments)
      for (Vec3E& v : seg) v = {v[0] * f, v[1] * f, v[2] * f};
    for (Vec3E& v : b.points) v = {v[0] * f, v[1] * f, v[2] * f};
    b.mass = default_mass(body_vertices(b), Exact(1));
    if (b.motion)
      for (Mat34E& p : b.motion->control_points)
        for (int r = 0; r < 3; ++r) p[4 * r + 3] *= f;
  }
  if (out.epsilon) *out.epsilon *= f;
  return out;
}

Exact pow10(int e) {
  Exact r = 1;
  for (int i = 0; i < (e < 0 ? -e : e); ++i) r *= 10;
  return e < 0 ? 1 / r : r;
}

// ------------------------------------------------------------------ property bodies

// A point of the convex hull of `v`: convex weights 0..4 (zeros allowed, so
// vertices and edge points too).
Vec3E barycentric_point(const std::vector<Vec3E>& v) {
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
std::pair<Body, std::vector<Vec3E>> pick_shape(const std::string& name, double lo, double hi, bool lower_dim) {
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

// (a) A contact built at a known rational time t* is never `safe`.
void contact_never_safe(KernelKind kernel, std::uint64_t max_nodes) {
  auto [fixed, fixed_hull] = pick_shape("fixed", -2, 2, false);
  if (*rc::gen::element(false, false, true)) {  // a fixed body under a constant (maybe singular) pose
    Motion pose;
    pose.control_points = {pick_affine(2, 1)};
    pose.weights = {1};
    for (Vec3E& v : fixed_hull) v = place(pose.control_points[0], v);
    fixed.motion = pose;
  }
  auto [mover, hull] = pick_shape("mover", -1, 1, true);
  const int count = uniform(2, 4);
  Motion motion;
  std::tie(motion.t0, motion.t1) = pick_interval();
  for (int k = 0; k < count; ++k) motion.control_points.push_back(pick_affine(2, 6));
  motion.weights = pick_weights(count);

  // Contact at t*: the point p of the moving body (a vertex in half the
  // cases, else any point: edge-edge, edge-face and face-vertex contacts
  // too) at the point q of the fixed body (vertices and edges included).
  const Exact s = pick(0, 1);
  const Exact t_star = motion.t0 + s * (motion.t1 - motion.t0);
  const bool at_vertex = *rc::gen::arbitrary<bool>();
  const Vec3E p = at_vertex ? hull[uniform(std::size_t(0), hull.size() - 1)] : barycentric_point(hull);
  const Vec3E q = barycentric_point(fixed_hull);
  const Vec3E x = place(eval_motion(motion, t_star), p);
  for (Mat34E& c : motion.control_points)
    for (int r = 0; r < 3; ++r) c[4 * r + 3] += q[r] - x[r];
  RC_ASSERT(place(eval_motion(motion, t_star), p) == q);  // the construction itself
  mover.motion = motion;

  const Exact epsilon = *rc::gen::element(Exact(1, 16), Exact(1, 100), Exact(1, 1000));
  Scene scene = make_scene(mover, fixed, epsilon);
  const bool swap = *rc::gen::arbitrary<bool>();
  const int a = swap ? 1 : 0, b = swap ? 0 : 1;
  scene.checks = {{a, b}};
  const CheckResult r = verify_check(scene, a, b, options_for(epsilon, kernel, max_nodes));
  RC_LOG() << describe(scene) << "\ncontact at t* = " << str(t_star) << " (body point " << str(p) << " at " << str(q)
           << ")\nkernel " << to_string(kernel) << ": " << describe(r) << "\n";
  RC_TAG(stop_label(r), work_label(r));
  RC_ASSERT(r.verdict != Verdict::Safe);
  const std::string problem = consistency_problem(scene, a, b, r);
  RC_ASSERT(problem == "");
  RC_ASSERT(r.first_contact->first <= t_star);  // everything before it is certified contact-free
}

// (a, touching) A body that touches the square [-1,1]^2 x {0} at exactly one
// instant t* and is strictly above it at every other time: a vertex, an
// edge or a whole face (flat bottom) comes down onto a point q of the closed
// square and goes back up.  The linear part is constant (identity, or a
// random possibly singular matrix); the translation is a polynomial
// parabola in z, (u - s)^2 k, with a linear drift in x and y, written at
// degree 2 or elevated to degree 3, with equal (not necessarily unit)
// weights.  Never safe; a collision can only be witnessed at t* itself.
void touching_never_safe(KernelKind kernel, std::uint64_t max_nodes) {
  const bool flat = *rc::gen::arbitrary<bool>();
  std::vector<Vec3E> tri;
  std::array<Exact, 9> lin = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  if (flat) {
    for (int i = 0; i < 3; ++i)
      tri.push_back({pick(-1, 1), pick(-1, 1), i == 0 ? Exact(0) : *rc::gen::element(Exact(0), pick(0.25, 1))});
    RC_PRE(nondegenerate(tri));
  } else {
    tri = pick_triangle(-1, 1);
    for (Exact& e : lin) e = pick(-2, 2);
  }
  // The lowest vertex under the linear part.
  std::vector<Vec3E> img;
  for (const Vec3E& v : tri)
    img.push_back({lin[0] * v[0] + lin[1] * v[1] + lin[2] * v[2], lin[3] * v[0] + lin[4] * v[1] + lin[5] * v[2],
                   lin[6] * v[0] + lin[7] * v[1] + lin[8] * v[2]});
  int low = 0;
  for (int i = 1; i < 3; ++i)
    if (img[i][2] < img[low][2]) low = i;
  const Vec3E q = {pick(-1, 1), pick(-1, 1), 0};
  const Exact s = pick(0, 1), k = pick(0.25, 4), vx = pick(-2, 2), vy = pick(-2, 2);
  // Translation a(u) = alpha + beta u + gamma u^2 per coordinate.
  const std::array<Exact, 3> alpha = {q[0] - img[low][0] - vx * s, q[1] - img[low][1] - vy * s, k * s * s - img[low][2]};
  const std::array<Exact, 3> beta = {vx, vy, -2 * k * s};
  const std::array<Exact, 3> gamma = {0, 0, k};
  std::vector<std::array<Exact, 3>> ctrl(3);
  for (int c = 0; c < 3; ++c) {
    ctrl[0][c] = alpha[c];
    ctrl[1][c] = alpha[c] + beta[c] / 2;
    ctrl[2][c] = alpha[c] + beta[c] + gamma[c];
  }
  if (*rc::gen::arbitrary<bool>()) {  // degree elevation to 3
    std::vector<std::array<Exact, 3>> e(4);
    for (int c = 0; c < 3; ++c) {
      e[0][c] = ctrl[0][c];
      e[1][c] = (ctrl[0][c] + 2 * ctrl[1][c]) / 3;
      e[2][c] = (2 * ctrl[1][c] + ctrl[2][c]) / 3;
      e[3][c] = ctrl[2][c];
    }
    ctrl = e;
  }
  Motion motion;
  std::tie(motion.t0, motion.t1) = pick_interval();
  const Exact w = pick(0.25, 4);
  for (const auto& a : ctrl) {
    motion.control_points.push_back({lin[0], lin[1], lin[2], a[0], lin[3], lin[4], lin[5], a[1], lin[6], lin[7], lin[8], a[2]});
    motion.weights.push_back(w);
  }
  const Exact t_star = motion.t0 + s * (motion.t1 - motion.t0);
  RC_ASSERT(place(eval_motion(motion, t_star), tri[low]) == q);  // the construction itself

  const Exact epsilon = *rc::gen::element(Exact(1, 16), Exact(1, 100), Exact(1, 1000));
  const Scene scene = make_scene(make_body("mover", {tri}, motion), make_body("table", {square_z0(1)}), epsilon);
  const CheckResult r = verify_check(scene, 0, 1, options_for(epsilon, kernel, max_nodes));
  RC_LOG() << describe(scene) << "\ntouching at t* = " << str(t_star) << " (vertex " << low << " at " << str(q)
           << ")\nkernel " << to_string(kernel) << ": " << describe(r) << "\n";
  RC_TAG(stop_label(r), work_label(r));
  RC_ASSERT(r.verdict != Verdict::Safe);
  RC_ASSERT(consistency_problem(scene, 0, 1, r) == "");
  RC_ASSERT(r.first_contact->first <= t_star);
  if (r.verdict == Verdict::Collision) RC_ASSERT(r.witness->t == t_star);  // the only contact instant
}

// Runs a property with at most `max_success` cases (the configured seed and
// reproduce settings still apply), reporting like RC_BOOST_PROP.
template <typename Testable>
void check_limited(Testable&& testable, int max_success) {
  using namespace rc::detail;
  const auto& tc = boost::unit_test::framework::current_test_case();
  TestMetadata metadata;
  metadata.id = tc.full_name();
  metadata.description = tc.p_name;
  TestParams params = configuration().testParams;
  params.maxSuccess = std::max(1, std::min(params.maxSuccess, max_success));
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

}  // namespace

BOOST_AUTO_TEST_SUITE(guarantee)

// ------------------------------------------------------------------ (a)

RC_BOOST_PROP(contact_at_known_time_is_never_safe_filtered, ()) { contact_never_safe(KernelKind::Filtered, 20000); }

BOOST_AUTO_TEST_CASE(contact_at_known_time_is_never_safe_exact) {
  check_limited([] { contact_never_safe(KernelKind::Exact, 20000); },
                std::max(1, rc::detail::configuration().testParams.maxSuccess / 2));
}

RC_BOOST_PROP(touching_at_known_time_is_never_safe_filtered, ()) { touching_never_safe(KernelKind::Filtered, 20000); }

BOOST_AUTO_TEST_CASE(touching_at_known_time_is_never_safe_exact) {
  check_limited([] { touching_never_safe(KernelKind::Exact, 20000); },
                std::max(1, rc::detail::configuration().testParams.maxSuccess / 2));
}

// ------------------------------------------------------------------ (b)

RC_BOOST_PROP(clearance_m_is_safe_for_epsilon_up_to_m_over_4, ()) {
  Exact m;
  const Scene scene = clearance_scene(m);
  const CheckResult r = verify_check(scene, 0, 1, options_for(*scene.epsilon, KernelKind::Filtered));
  RC_LOG() << describe(scene) << "\nclearance m = " << str(m) << "\n" << describe(r) << "\n";
  RC_TAG(stop_label(r), work_label(r));
  RC_ASSERT(r.verdict == Verdict::Safe);
  RC_ASSERT(consistency_problem(scene, 0, 1, r) == "");
}

// DESIGN.md section 6 claims more: safe for every epsilon <= m/2.  Checked
// at epsilon = m/2 exactly.
RC_BOOST_PROP(clearance_m_is_safe_for_epsilon_m_over_2, ()) {
  Exact m;
  const Scene scene = clearance_scene(m, 2);
  const CheckResult r = verify_check(scene, 0, 1, options_for(*scene.epsilon, KernelKind::Filtered));
  RC_LOG() << describe(scene) << "\nclearance m = " << str(m) << "\n" << describe(r) << "\n";
  RC_TAG(stop_label(r), work_label(r));
  RC_ASSERT(r.verdict == Verdict::Safe);
  RC_ASSERT(consistency_problem(scene, 0, 1, r) == "");
}

// ------------------------------------------------------------------ (c)

RC_BOOST_PROP(interpenetration_from_the_start_is_a_collision_at_t0, ()) {
  const Scene scene = interpenetration_scene();
  const Motion& m = *scene.bodies[0].motion;
  for (KernelKind kernel : {KernelKind::Filtered, KernelKind::Exact}) {
    const CheckResult r = verify_check(scene, 0, 1, options_for(*scene.epsilon, kernel));
    RC_LOG() << describe(scene) << "\nkernel " << to_string(kernel) << ": " << describe(r) << "\n";
    RC_ASSERT(r.verdict == Verdict::Collision);
    RC_ASSERT(consistency_problem(scene, 0, 1, r) == "");
    RC_ASSERT(r.witness->t == m.t0);
    RC_ASSERT(r.first_contact->first == m.t0);
    RC_ASSERT(r.first_contact->second == m.t0);
  }
}

// ------------------------------------------------------------------ (d)

// The lowest vertex of a triangle translated over the square [-1,1]^2 x {0}
// comes within exactly 10^-17 of it (above its interior, an edge or a corner)
// and never closer; the rest of the triangle stays higher.  Either a
// polynomial parabola whose minimum 10^-17 is reached at the middle of the
// motion (a dyadic parameter the search evaluates exactly), or a rational
// curve whose z control values are >= 10^-17 with equality at an end.
RC_BOOST_PROP(vertex_1e17_above_face_is_never_a_collision, ()) {
  const Exact delta = pow10(-17);
  std::vector<Vec3E> tri = {{0, 0, 0}, {pick(-1, 1), pick(-1, 1), pick(0.25, 1)}, {pick(-1, 1), pick(-1, 1), pick(0.25, 1)}};
  RC_PRE(nondegenerate(tri));
  Motion motion;
  std::tie(motion.t0, motion.t1) = pick_interval();
  const bool parabola = *rc::gen::arbitrary<bool>();
  if (parabola) {
    const Exact cx = pick(-1, 1), cy = pick(-1, 1), vx = pick(-2, 2), vy = pick(-2, 2), k = pick(0.25, 4);
    motion.control_points = {translation(cx - vx, cy - vy, delta + k / 4), translation(cx, cy, delta - k / 4),
                             translation(cx + vx, cy + vy, delta + k / 4)};
    motion.weights = {1, 1, 1};
  } else {
    const int count = uniform(2, 4);
    const int low = *rc::gen::element(0, count - 1);
    for (int k = 0; k < count; ++k)
      motion.control_points.push_back(translation(pick(-1, 1), pick(-1, 1), k == low ? delta : delta + pick(0, 2)));
    motion.weights = pick_weights(count);
  }
  const Exact epsilon(1, 1000);
  const Scene scene = make_scene(make_body("mover", {tri}, motion), make_body("table", {square_z0(1)}), epsilon);
  const CheckResult r = verify_check(scene, 0, 1, options_for(epsilon, KernelKind::Filtered));
  RC_LOG() << describe(scene) << "\n" << describe(r) << "\n";
  RC_TAG(stop_label(r), work_label(r));
  RC_ASSERT(r.verdict != Verdict::Collision);
  RC_ASSERT(consistency_problem(scene, 0, 1, r) == "");
}

// ------------------------------------------------------------------ (e)

RC_BOOST_PROP(verdicts_invariant_under_translation_by_1e6_and_scaling_by_1e_6, ()) {
  const int kind = uniform(0, 2);
  Exact m;
  const Scene scene = kind == 0 ? clearance_scene(m) : kind == 1 ? interpenetration_scene() : sweep_scene();
  const Verdict expected = kind == 0 ? Verdict::Safe : Verdict::Collision;
  const Exact big = pow10(6);
  const Vec3E d = {*rc::gen::element(1, -1) * big, *rc::gen::element(1, -1) * big, *rc::gen::element(1, -1) * big};
  const Scene variants[3] = {scene, translated(scene, d), scaled(scene, pow10(-6))};
  const char* names[3] = {"original", "translated by 10^6", "scaled by 10^-6"};
  std::optional<Verdict> first;
  for (int v = 0; v < 3; ++v) {
    const Scene& s = variants[v];
    const CheckResult r = verify_check(s, 0, 1, options_for(*s.epsilon, KernelKind::Filtered));
    RC_LOG() << names[v] << ": " << describe(s) << "\n" << describe(r) << "\n";
    RC_ASSERT(consistency_problem(s, 0, 1, r) == "");
    if (!first) first = r.verdict;
    RC_ASSERT(r.verdict == *first);
    RC_ASSERT(r.verdict == expected);
  }
}

// ------------------------------------------------------------------ deterministic cases

namespace {

// A tilted triangle, lowest vertex at its origin.
std::vector<Vec3E> tilted_triangle() { return {{0, 0, 0}, {1, 0, Exact(1, 2)}, {0, 1, 1}}; }

}  // namespace

BOOST_AUTO_TEST_CASE(sweep_through_the_middle_is_a_collision_after_t0) {
  // z translation 3 -> -3 over [0,1]: the lowest vertex reaches the square at
  // t* = 1/2 and nothing touches before.
  Motion motion;
  motion.t0 = 0;
  motion.t1 = 1;
  motion.control_points = {translation(0, 0, 3), translation(0, 0, -3)};
  motion.weights = {1, 1};
  const Exact t_star(1, 2);
  const Scene scene =
      make_scene(make_body("blade", {tilted_triangle()}, motion), make_body("table", {square_z0(2)}), Exact(1, 1000));
  for (KernelKind kernel : {KernelKind::Filtered, KernelKind::Exact}) {
    const CheckResult r = verify_check(scene, 0, 1, options_for(*scene.epsilon, kernel));
    BOOST_TEST_INFO(to_string(kernel) << ": " << describe(r));
    BOOST_TEST(consistency_problem(scene, 0, 1, r) == "");
    BOOST_REQUIRE((r.verdict == Verdict::Collision));
    BOOST_TEST(r.first_contact->first > motion.t0);
    BOOST_TEST(r.first_contact->first <= t_star);
    BOOST_TEST(r.witness->t >= t_star);
  }
}

BOOST_AUTO_TEST_CASE(rational_sweep_through_the_middle_is_a_collision_after_t0) {
  // Interval [2, 5], a rational cubic with unequal weights, z control values
  // 3, 1, -1, -3 (monotone: variation diminishing), x and y wandering.
  Motion motion;
  motion.t0 = 2;
  motion.t1 = 5;
  motion.control_points = {translation(0, 0, 3), translation(Exact(1, 2), -Exact(1, 3), 1),
                           translation(-Exact(1, 4), Exact(1, 2), -1), translation(0, 0, -3)};
  motion.weights = {1, 3, Exact(1, 2), 2};
  const Scene scene =
      make_scene(make_body("blade", {tilted_triangle()}, motion), make_body("table", {square_z0(2)}), Exact(1, 1000));
  const CheckResult r = verify_check(scene, 0, 1, options_for(*scene.epsilon, KernelKind::Filtered));
  BOOST_TEST_INFO(describe(r));
  BOOST_TEST(consistency_problem(scene, 0, 1, r) == "");
  BOOST_REQUIRE((r.verdict == Verdict::Collision));
  BOOST_TEST(r.first_contact->first > motion.t0);
  BOOST_TEST(r.first_contact->first < motion.t1);
}

BOOST_AUTO_TEST_CASE(pass_with_a_clear_margin_is_safe) {
  // Over the square at height 1 (lowest vertex), then beside it.
  Motion over;
  over.t0 = 0;
  over.t1 = 1;
  over.control_points = {translation(-6, 0, 1), translation(0, 1, 1), translation(6, 0, 1)};
  over.weights = {1, 2, 1};
  Motion beside;
  beside.t0 = -1;
  beside.t1 = 1;
  beside.control_points = {translation(3, -6, -1), translation(3, 6, 0)};
  beside.weights = {1, 1};
  for (const Motion& motion : {over, beside}) {
    const Scene scene =
        make_scene(make_body("blade", {tilted_triangle()}, motion), make_body("table", {square_z0(2)}), Exact(1, 1000));
    for (KernelKind kernel : {KernelKind::Filtered, KernelKind::Exact}) {
      const CheckResult r = verify_check(scene, 0, 1, options_for(*scene.epsilon, kernel));
      BOOST_TEST_INFO(to_string(kernel) << ": " << describe(r));
      BOOST_TEST((r.verdict == Verdict::Safe));
      BOOST_TEST(consistency_problem(scene, 0, 1, r) == "");
    }
  }
}

BOOST_AUTO_TEST_CASE(vertex_1e17_above_face_hovering_is_not_a_collision) {
  // The lowest vertex hovers at exactly 10^-17 above the square's interior
  // for the whole motion.
  const Exact delta = pow10(-17);
  Motion motion;
  motion.control_points = {translation(-Exact(1, 2), 0, delta), translation(Exact(1, 2), 0, delta)};
  motion.weights = {1, 1};
  const Scene scene =
      make_scene(make_body("blade", {tilted_triangle()}, motion), make_body("table", {square_z0(2)}), Exact(1, 1000));
  for (KernelKind kernel : {KernelKind::Filtered, KernelKind::Exact}) {
    const CheckResult r = verify_check(scene, 0, 1, options_for(*scene.epsilon, kernel, 2000));
    BOOST_TEST_INFO(to_string(kernel) << ": " << describe(r));
    BOOST_TEST((r.verdict != Verdict::Collision));
    BOOST_TEST(consistency_problem(scene, 0, 1, r) == "");
  }
}

BOOST_AUTO_TEST_CASE(the_oracle_itself) {
  // The independent evaluation and point-in-triangle test used as oracle.
  Motion m;
  m.t0 = 1;
  m.t1 = 3;
  m.control_points = {translation(0, 0, 0), translation(2, 0, 0), translation(4, 4, 0)};
  m.weights = {1, 2, 1};
  // u = 1/2: (0*1/4 + 2*2*1/2 + 4*1/4) / (1/4 + 1 + 1/4) = 3 / (3/2) = 2; y = 1 / (3/2) = 2/3.
  const Mat34E p = eval_motion(m, 2);
  BOOST_TEST(p[3] == Exact(2));
  BOOST_TEST(p[7] == Exact(2, 3));
  BOOST_TEST(in_triangle({Exact(1, 3), Exact(1, 3), 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}));
  BOOST_TEST(in_triangle({Exact(1, 2), Exact(1, 2), 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}));
  BOOST_TEST(!in_triangle({Exact(1, 2), Exact(1, 2), pow10(-17)}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}));
  BOOST_TEST(!in_triangle({Exact(1, 2) + pow10(-17), Exact(1, 2), 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}));
  BOOST_TEST(in_triangle({1, 1, 1}, {0, 0, 0}, {2, 2, 2}, {1, 1, 1}));  // degenerate
  BOOST_TEST(!in_triangle({3, 3, 3}, {0, 0, 0}, {2, 2, 2}, {1, 1, 1}));
}

BOOST_AUTO_TEST_SUITE_END()
