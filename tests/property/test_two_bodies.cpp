// Property tests of the guarantee for two moving bodies (DESIGN.md section 3:
// one joint curve in R^24 with the product metric), of the verdict's
// invariance under swapping the bodies of a check, a rational rotation of the
// world, a translation by 10^6 and a scaling by 10^-6, and of degenerate
// linear per-vertex motions (bench/ccd_queries.h's linear_body).
//
//  (a2)  both bodies move (random rational Bezier motions of degree 1-3,
//        random positive weights; triangle, parallelogram, segment or point
//        each); one motion is shifted so that a chosen point of one body is
//        at a chosen point of the other at a rational time t*: never `safe`
//        (filtered and exact kernels); first_contact starts at or before t*;
//        a collision's witness lies exactly on both bodies at its time.
//  (b2)  relative to a drift both bodies share, every control-point image of
//        every vertex of body 1 has n.x >= m/2, n = (2,3,6)/7, and body 2's
//        n.x <= -m/2: clearance m, so `safe` at epsilon = m/4 (and m/2).
//        The drift and a degree elevation / weight scaling of one motion
//        keep the certified prefilter from deciding alone (the search runs).
//  (swap) verify_check(s, a, b) and verify_check(s, b, a) agree: verdict,
//        first_contact's lower end, and each witness is at or after the
//        other order's certified-free prefix.
//  (rotation) a rational rotation (from an integer quaternion) of the world
//        keeps every verdict.
//  (degenerate) a triangle collapsing to a segment at t = 1, a segment
//        shrinking to a point, coplanar motions, parallel edges, zero motion
//        (p0 == p1) for one or both bodies: contact at a rational time =>
//        never safe; separated by a plane with margin m at both ends =>
//        safe at epsilon = m/4.
//  (scale) translation by 10^6 and scaling by 10^-6 (epsilon scaled) keep
//        the verdicts of (b2) scenes (safe) and of (a2) scenes in contact at
//        the start (collision at t0).
//
// Every scene is built in C++ from exact rationals; the oracle (rational
// Bezier evaluation, point in triangle / on segment) is written
// independently of the library, in tests/support/scene_testing.h (shared
// with test_guarantee.cpp).  Default masses are computed as the parser does
// (a single point's offsets use the scene's size), so the scene printed in a
// failure log (tmcert-scene/1 JSON) is the scene that was verified.
//
// Each property runs a multiple of rapidcheck's max_success (default 100):
// 400 % for the cheap filtered ones, 50 % for the exact kernel; about 6 s in
// Release.  Replay a failure with RC_PARAMS="seed=N" (printed at the start
// of the run) or with the RC_PARAMS="reproduce=..." line printed on failure:
//   RC_PARAMS="seed=N" tmcert_property --run_test=two_bodies/NAME

#include "tests/support/scene_testing.h"

#include "bench/ccd_queries.h"
#include "src/certificate/check.h"
#include "src/certificate/writer.h"

#include <nlohmann/json.hpp>

#include <array>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

using namespace tmcert;
using namespace tmcert::testing;

namespace {

// ------------------------------------------------------------------ geometry

// The separating plane of the clearance scenes: n.x = 0 with the rational
// unit normal n = (2,3,6)/7 (oblique: no coordinate box separates its sides
// in general), and two directions in that plane.
const Vec3E kNormal = {Exact(2, 7), Exact(3, 7), Exact(6, 7)};
const Vec3E kInPlane1 = {3, -2, 0};
const Vec3E kInPlane2 = {0, 2, -1};

// ------------------------------------------------------------------ generators (inside properties)

// A random motion of degree 1..3 (random affine control points, random
// positive weights) over the given interval.
Motion pick_motion(const std::pair<Exact, Exact>& interval, double a_range, double t_range) {
  Motion m;
  std::tie(m.t0, m.t1) = interval;
  const int count = uniform(2, 4);
  for (int k = 0; k < count; ++k) m.control_points.push_back(pick_affine(a_range, t_range));
  m.weights = pick_weights(count);
  return m;
}

// Shifts the translation of control point P along kNormal so that the
// images of `verts` lie on side `sign` of the plane n.x = 0 at distance
// >= level, with equality + extra for the closest one.
void push_to_side(Mat34E& P, const std::vector<Vec3E>& verts, int sign, const Exact& level, const Exact& extra) {
  std::optional<Exact> extreme;
  for (const Vec3E& v : verts) {
    const Exact h = dot(kNormal, place(P, v));
    if (!extreme || (sign > 0 ? h < *extreme : h > *extreme)) extreme = h;
  }
  const Exact shift = Exact(sign) * (level + extra) - *extreme;  // kNormal is a unit vector
  for (int r = 0; r < 3; ++r) P[4 * r + 3] += shift * kNormal[r];
}

// A point on side `sign` of the plane n.x = 0 at distance level + extra.
Vec3E point_on_side(int sign, const Exact& level, const Exact& extra, double range = 1) {
  const Vec3E x = pick_point(-range, range);
  return add(x, mul(Exact(sign) * (level + extra) - dot(kNormal, x), kNormal));
}

// ------------------------------------------------------------------ scene kinds

struct Case {
  Scene scene;
  std::string kind;
  std::optional<Exact> t_star;  // a contact time by construction (not necessarily the first)
  bool safe = false;            // clearance by construction
  std::string note;
};

// (a2) Both bodies move; body "one"'s chosen point p coincides with body
// "two"'s chosen point q at t* (t* = t0 when at_start).
Case contact2_case(bool at_start) {
  const auto interval = pick_interval();
  auto [one, hull1] = pick_shape("one", -1, 1, true);
  auto [two, hull2] = pick_shape("two", -1, 1, true);
  const double a_range = *rc::gen::element(1.0, 2.0);
  Motion m1 = pick_motion(interval, a_range, 6), m2 = pick_motion(interval, a_range, 6);
  const Exact s = at_start ? Exact(0) : pick(0, 1);
  const Exact t_star = interval.first + s * (interval.second - interval.first);
  const Vec3E p = *rc::gen::arbitrary<bool>() ? hull1[uniform(std::size_t(0), hull1.size() - 1)] : barycentric_point(hull1);
  const Vec3E q = *rc::gen::arbitrary<bool>() ? hull2[uniform(std::size_t(0), hull2.size() - 1)] : barycentric_point(hull2);
  const Vec3E x1 = place(eval_motion(m1, t_star), p), x2 = place(eval_motion(m2, t_star), q);
  // A constant translation added to every control point translates the
  // whole rational curve by it (the weights are normalised).
  for (Mat34E& c : m1.control_points)
    for (int r = 0; r < 3; ++r) c[4 * r + 3] += x2[r] - x1[r];
  RC_ASSERT(place(eval_motion(m1, t_star), p) == place(eval_motion(m2, t_star), q));  // the construction itself
  one.motion = m1;
  two.motion = m2;
  const Exact epsilon = *rc::gen::element(Exact(1, 16), Exact(1, 100), Exact(1, 1000));
  Case c{make_scene(one, two, epsilon), at_start ? "contact2 at start" : "contact2", t_star, false, ""};
  c.note = "contact at t* = " + str(t_star) + ": point " + str(p) + " of one at point " + str(q) + " of two, at " +
           str(place(eval_motion(m2, t_star), q));
  return c;
}

// Degree elevation of a rational Bezier motion (the same curve, one degree
// higher): homogeneous points H'_i = (i/(n+1)) H_{i-1} + (1 - i/(n+1)) H_i.
Motion elevated(const Motion& m) {
  const int n = m.degree();
  Motion out = m;
  out.control_points.assign(n + 2, Mat34E{});
  out.weights.assign(n + 2, Exact(0));
  for (int i = 0; i <= n + 1; ++i) {
    const Exact a = Exact(i, n + 1), b = 1 - a;
    Exact w = 0;
    std::array<Exact, 12> h;
    h.fill(Exact(0));
    if (i > 0) {
      w += a * m.weights[i - 1];
      for (int e = 0; e < 12; ++e) h[e] += a * m.weights[i - 1] * m.control_points[i - 1][e];
    }
    if (i <= n) {
      w += b * m.weights[i];
      for (int e = 0; e < 12; ++e) h[e] += b * m.weights[i] * m.control_points[i][e];
    }
    out.weights[i] = w;
    for (int e = 0; e < 12; ++e) out.control_points[i][e] = h[e] / w;
  }
  return out;
}

// (b2) Both bodies move.  Relative to a drift T(t) that both share, body
// one's vertex images under every control point have n.x >= m/2 and body
// two's n.x <= -m/2 (equality at one control point each): by the convex
// hull property, at every t body one - T(t) and body two - T(t) lie on
// opposite sides with margin, so the bodies keep distance >= m.
//
// With a drift ("drift"): both motions have the same degree and weights,
// control point k of each is its relative control point plus the drift's
// translation tau_k (large, across the plane too), so T(t) is the same
// rational curve for both.  Then one motion may be degree-elevated (up to
// degree 3) and its weights scaled by a constant (the same curves, written
// differently: degrees and weights of the two motions differ).  The hulls
// of the control-point images then overlap, so the certified prefilter
// (boxes and separating axes over control-point images) cannot decide and
// the joint-curve search must.  Without ("plain"): no drift, the relative
// motions as they are (often cleared by the prefilter alone).
//
// Relative translations lie along the plane before the push; both bodies
// follow one common line in it (control point k near A + (k/n) D), so they
// travel side by side.  Epsilon m/4, or m/eps_divisor when given.
Case clearance2_case(int eps_divisor = 4) {
  const Exact m = pick(0.25, 2) / *rc::gen::element(1, 1, 4, 8);  // 1/32 .. 2
  const auto interval = pick_interval();
  auto [one, hull1] = pick_shape("one", -1, 1, true);
  auto [two, hull2] = pick_shape("two", -1, 1, true);
  const bool drift = *rc::gen::element(true, true, true, true, false);
  auto in_plane = [](double range) { return add(mul(pick(-range, range), kInPlane1), mul(pick(-range, range), kInPlane2)); };
  const Vec3E A = in_plane(1), D = in_plane(1);
  Motion motions[2];
  motions[0] = pick_motion(interval, *rc::gen::element(1, 2), 0);
  const int n0 = motions[0].degree();
  std::vector<Vec3E> tau;
  for (int k = 0; k <= n0; ++k) tau.push_back(pick_point(-6, 6));
  for (int b = 0; b < 2; ++b) {
    if (b == 1) {
      motions[1] = pick_motion(interval, *rc::gen::element(1, 2), 0);
      if (drift) {  // the same degree and weights as body one's
        motions[1].control_points.resize(n0 + 1, motions[1].control_points[0]);
        for (int k = 0; k <= n0; ++k) motions[1].control_points[k] = pick_affine(1, 0);
        motions[1].weights = motions[0].weights;
      }
    }
    const int n = motions[b].degree();
    for (int k = 0; k <= n; ++k) {
      const Vec3E t = add(add(A, mul(Exact(k, n), D)), in_plane(0.25));
      for (int r = 0; r < 3; ++r) motions[b].control_points[k][4 * r + 3] = t[r];
    }
    const int tight = uniform(0, n);
    for (int k = 0; k <= n; ++k)
      push_to_side(motions[b].control_points[k], b == 0 ? hull1 : hull2, b == 0 ? 1 : -1, m / 2,
                   k == tight ? Exact(0) : pick(0, 1));
    if (drift)
      for (int k = 0; k <= n; ++k)
        for (int r = 0; r < 3; ++r) motions[b].control_points[k][4 * r + 3] += tau[k][r];
  }
  std::string note = "clearance m = " + str(m);
  if (drift) {
    const int b = uniform(0, 1);
    const int times = uniform(0, 3 - n0);
    for (int i = 0; i < times; ++i) motions[b] = elevated(motions[b]);
    const Exact scale = pick(0.25, 4);
    for (Exact& w : motions[b].weights) w *= scale;
    note += ", common drift; motion of body " + std::to_string(b + 1) + " elevated " + std::to_string(times) +
            " times, weights scaled by " + str(scale);
  }
  one.motion = motions[0];
  two.motion = motions[1];
  return Case{make_scene(one, two, m / eps_divisor), drift ? "clearance2 drift" : "clearance2 plain", std::nullopt, true,
              note};
}

// One moving body against a fixed one (plain, or under a constant possibly
// singular pose): a contact at t* or a clearance m.
Case fixed_case() {
  const bool contact = *rc::gen::arbitrary<bool>();
  const auto interval = pick_interval();
  auto [fixed, fixed_hull] = pick_shape("fixed", -2, 2, true);
  auto [mover, hull] = pick_shape("mover", -1, 1, true);
  const bool posed = *rc::gen::element(false, false, true);
  Mat34E pose = posed ? pick_affine(2, 1) : kIdentity;
  Motion motion = pick_motion(interval, 2, contact ? 6 : 3);
  const Exact m = pick(0.25, 2) / *rc::gen::element(1, 1, 4, 8);
  if (!contact) {
    const int tight = uniform(0, motion.degree());
    for (int k = 0; k <= motion.degree(); ++k)
      push_to_side(motion.control_points[k], hull, 1, m / 2, k == tight ? Exact(0) : pick(0, 1));
    push_to_side(pose, fixed_hull, -1, m / 2, Exact(0));
  }
  if (posed) {
    Motion p;
    p.t0 = interval.first;
    p.t1 = interval.second;
    p.control_points = {pose};
    p.weights = {1};
    fixed.motion = p;
  } else if (pose != kIdentity) {  // a translation only: move the coordinates
    const Vec3E d = {pose[3], pose[7], pose[11]};
    map_coordinates(fixed, [&](const Vec3E& v) { return add(v, d); });
  }
  for (Vec3E& v : fixed_hull) v = place(pose, v);  // world coordinates
  std::optional<Exact> t_star;
  std::string note = "clearance m = " + str(m);
  if (contact) {
    const Exact s = pick(0, 1);
    t_star = interval.first + s * (interval.second - interval.first);
    const Vec3E p = *rc::gen::arbitrary<bool>() ? hull[uniform(std::size_t(0), hull.size() - 1)] : barycentric_point(hull);
    const Vec3E q = barycentric_point(fixed_hull);
    const Vec3E x = place(eval_motion(motion, *t_star), p);
    for (Mat34E& c : motion.control_points)
      for (int r = 0; r < 3; ++r) c[4 * r + 3] += q[r] - x[r];
    RC_ASSERT(place(eval_motion(motion, *t_star), p) == q);
    note = "contact at t* = " + str(*t_star) + ": point " + str(p) + " of mover at " + str(q);
  }
  mover.motion = motion;
  const Exact epsilon = contact ? *rc::gen::element(Exact(1, 16), Exact(1, 100), Exact(1, 1000)) : m / 4;
  Scene scene = make_scene(mover, fixed, epsilon);
  if (*rc::gen::arbitrary<bool>()) {  // the fixed body first in the scene
    std::swap(scene.bodies[0], scene.bodies[1]);
  }
  return Case{scene, contact ? "fixed contact" : "fixed clearance", t_star, !contact, note};
}

// ------------------------------------------------------------------ transformations

// The rotation of the unit quaternion q / |q| (q = (a, b, c, d) integers):
// rational entries over n = a^2 + b^2 + c^2 + d^2.
Mat34E rotation(long a, long b, long c, long d) {
  const Exact n = Exact(a * a + b * b + c * c + d * d);
  auto e = [&](long v) { return Exact(v) / n; };
  return {e(a * a + b * b - c * c - d * d), e(2 * (b * c - a * d)), e(2 * (b * d + a * c)), 0,
          e(2 * (b * c + a * d)), e(a * a - b * b + c * c - d * d), e(2 * (c * d - a * b)), 0,
          e(2 * (b * d - a * c)), e(2 * (c * d + a * b)), e(a * a - b * b - c * c + d * d), 0};
}

bool is_rotation(const Mat34E& R) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      Exact s = 0;
      for (int k = 0; k < 3; ++k) s += R[4 * i + k] * R[4 * j + k];
      if (s != (i == j ? 1 : 0)) return false;
    }
  const Vec3E r0 = {R[0], R[1], R[2]}, r1 = {R[4], R[5], R[6]}, r2 = {R[8], R[9], R[10]};
  return dot(cross(r0, r1), r2) == 1 && R[3] == 0 && R[7] == 0 && R[11] == 0;
}

// ------------------------------------------------------------------ checking

// Runs check (a, b) and asserts consistency and the truth known by
// construction.
CheckResult run_and_check(const Case& c, int a, int b, KernelKind kernel, std::uint64_t max_nodes,
                          const std::string& label) {
  const Scene& s = c.scene;
  const CheckResult r = verify_check(s, a, b, options_for(*s.epsilon, kernel, max_nodes));
  RC_LOG() << label << " [" << c.kind << "] " << c.note << "\n" << describe(s) << "\ncheck (" << s.bodies[a].name
           << ", " << s.bodies[b].name << "), kernel " << to_string(kernel) << ": " << describe(r) << "\n";
  const std::string problem = consistency_problem(s, a, b, r);
  RC_LOG() << "consistency: " << (problem.empty() ? "ok" : problem) << "\n";
  RC_ASSERT(problem == "");
  if (c.safe) RC_ASSERT(r.verdict == Verdict::Safe);
  if (c.t_star) {
    RC_ASSERT(r.verdict != Verdict::Safe);
    RC_ASSERT(r.first_contact->first <= *c.t_star);  // everything before it is certified contact-free
  }
  return r;
}

// A case whose truth has room to spare: a clearance margin (safe for
// epsilon <= m/2) or a contact at the very start (the exact start check).
// Elsewhere - a contact at one instant, a clearance near epsilon - two runs
// that round differently (a swapped order, a rotated world) may end one
// with a proof and the other undecided; they can never contradict.
bool robust(const Case& c) {
  if (c.safe) return true;
  if (!c.t_star) return false;
  for (const Body& b : c.scene.bodies)
    if (b.motion && b.motion->degree() >= 1) return *c.t_star == b.motion->t0;
  return false;
}

// Two runs of the same geometry (swapped order, rotated world): certified
// answers never contradict, a collision's witness is a real contact so the
// other run's certified-free prefix ends at or before it, and robust cases
// get the same verdict.
void check_compatible(const Case& c, const CheckResult& x, const CheckResult& y) {
  RC_ASSERT(!(x.verdict == Verdict::Safe && y.verdict == Verdict::Collision));
  RC_ASSERT(!(y.verdict == Verdict::Safe && x.verdict == Verdict::Collision));
  if (x.verdict == Verdict::Collision) RC_ASSERT(witness_not_before(y.first_contact->first, *x.witness));
  if (y.verdict == Verdict::Collision) RC_ASSERT(witness_not_before(x.first_contact->first, *y.witness));
  if (robust(c)) RC_ASSERT(x.verdict == y.verdict);
}

// ------------------------------------------------------------------ degenerate linear motions

using bench::linear_body;

// Vertices at time t* (given) moving with velocities v: their positions at
// t = 0 and t = 1.
void around(const std::vector<Vec3E>& x, const std::vector<Vec3E>& v, const Exact& t_star, std::vector<Vec3E>& p0,
            std::vector<Vec3E>& p1) {
  p0.clear();
  p1.clear();
  for (std::size_t i = 0; i < x.size(); ++i) {
    p0.push_back(sub(x[i], mul(t_star, v[i])));
    p1.push_back(add(x[i], mul(1 - t_star, v[i])));
  }
}

std::vector<Vec3E> at_time(const std::vector<Vec3E>& p0, const std::vector<Vec3E>& p1, const Exact& t) {
  std::vector<Vec3E> out;
  for (std::size_t i = 0; i < p0.size(); ++i) out.push_back(lerp(p0[i], p1[i], t));
  return out;
}

Vec3E pick_velocity(bool planar) {
  Vec3E v = pick_point(-2, 2);
  if (planar) v[2] = 0;
  return v;
}

// A contact time: anywhere in [0, 1], often at an end (where a collapse
// happens).
Exact pick_contact_time() { return *rc::gen::element(pick(0, 1), pick(0, 1), Exact(1), Exact(0)); }

const char* kDegenerateKinds[] = {"collapsing triangle", "shrinking segment", "coplanar", "parallel edges",
                                  "zero motion", "both motionless"};

// Builds one degenerate case of the given kind (0..5), in contact at a
// rational time or separated by an oblique plane with margin m at both ends.
Case degenerate_case(int kind, bool contact) {
  std::vector<Vec3E> a0, a1, b0, b1;  // body one ("a") and body two ("b") vertices at t = 0 and 1
  const Exact m = pick(0.25, 2) / *rc::gen::element(1, 4, 8);
  std::optional<Exact> t_star;
  if (contact) t_star = pick_contact_time();
  std::optional<Vec3E> target;  // the common point at t* (contact cases)
  Vec3E separating = kNormal;   // the plane's normal (separated cases)
  std::string note;
  auto side = [&](int sign, bool tight = false) { return point_on_side(sign, m / 2, tight ? Exact(0) : pick(0, 1)); };
  switch (kind) {
    case 0: {  // a triangle whose third vertex moves onto the line of the other two at t = 1, a moving point
      const Exact alpha = contact ? pick(-1, 2) : pick(0, 1);
      if (contact) {
        b0 = pick_triangle(-1, 1);
        const Vec3E u = pick_point(-1, 1), w = pick_point(-1, 1);
        RC_PRE(u != w);
        b1 = {u, w, lerp(u, w, alpha)};
        target = barycentric_point(at_time(b0, b1, *t_star));
        around({*target}, {pick_velocity(false)}, *t_star, a0, a1);
      } else {
        b0 = {side(-1), side(-1), side(-1)};
        RC_PRE(nondegenerate(b0));
        const Vec3E u = side(-1, true), w = side(-1, *rc::gen::arbitrary<bool>());
        RC_PRE(u != w);
        b1 = {u, w, lerp(u, w, alpha)};
        // At t = 1 the point is right above the collapsed segment, at n.x = m/2;
        // at t = 0 anywhere on its side, or right above the triangle.
        const Vec3E mid = lerp(u, w, pick(0, 1)), over = barycentric_point(b0);
        a0 = {*rc::gen::arbitrary<bool>() ? side(1) : add(over, mul(m / 2 - dot(kNormal, over), kNormal))};
        a1 = {add(mid, mul(m / 2 - dot(kNormal, mid), kNormal))};
      }
      note = "third vertex onto the line at t = 1, alpha = " + str(alpha);
      break;
    }
    case 1: {  // a segment shrinking to a point at t = 1, against a moving point or segment
      const bool other_segment = *rc::gen::arbitrary<bool>();
      if (contact) {
        const Vec3E u = pick_point(-1, 1), w = pick_point(-1, 1);
        RC_PRE(u != w);
        const Vec3E z = pick_point(-1, 1);
        b0 = {u, w};
        b1 = {z, z};
        target = barycentric_point(at_time(b0, b1, *t_star));
        std::vector<Vec3E> x = {*target};
        if (other_segment) {
          const Vec3E dir = pick_point(-1, 1);
          RC_PRE(!is_zero(dir));
          const Exact s = pick(0, 1);
          x = {sub(*target, mul(s, dir)), add(*target, mul(1 - s, dir))};
        }
        std::vector<Vec3E> v;
        for (std::size_t i = 0; i < x.size(); ++i) v.push_back(pick_velocity(false));
        around(x, v, *t_star, a0, a1);
      } else {
        b0 = {side(-1), side(-1)};
        RC_PRE(b0[0] != b0[1]);
        const Vec3E z = side(-1, true);
        b1 = {z, z};
        // At t = 1 right above the shrunk point; at t = 0 anywhere on its
        // side, or right above the segment.
        const Vec3E over = barycentric_point(b0);
        a0 = {*rc::gen::arbitrary<bool>() ? side(1) : add(over, mul(m / 2 - dot(kNormal, over), kNormal))};
        a1 = {add(z, mul(m, kNormal))};
        if (other_segment) {
          a0.push_back(side(1));
          a1.push_back(side(1));
        }
      }
      note = "segment shrinks to a point at t = 1";
      break;
    }
    case 2: {  // everything in the plane z = 0: a triangle and a point, or two segments
      const bool edges = *rc::gen::arbitrary<bool>();
      auto flat = [](Vec3E v) { v[2] = 0; return v; };
      const Vec3E n2 = {Exact(3, 5), Exact(4, 5), 0};  // separating direction within the plane
      auto flat_side = [&](int sign, bool tight = false) {
        const Vec3E x = flat(pick_point(-1, 1));
        return add(x, mul(Exact(sign) * (m / 2 + (tight ? Exact(0) : pick(0, 1))) - dot(n2, x), n2));
      };
      const std::size_t nb = edges ? 2 : 3, na = edges ? 2 : 1;
      if (contact) {
        for (std::size_t i = 0; i < nb; ++i) {
          b0.push_back(flat(pick_point(-1, 1)));
          b1.push_back(flat(pick_point(-1, 1)));
        }
        target = barycentric_point(at_time(b0, b1, *t_star));
        std::vector<Vec3E> x = {*target};
        if (edges) {
          const Vec3E dir = flat(pick_point(-1, 1));
          RC_PRE(!is_zero(dir));
          const Exact s = pick(0, 1);
          x = {sub(*target, mul(s, dir)), add(*target, mul(1 - s, dir))};
        }
        std::vector<Vec3E> v;
        for (std::size_t i = 0; i < na; ++i) v.push_back(pick_velocity(true));
        around(x, v, *t_star, a0, a1);
        if (edges) RC_PRE(a0[0] != a0[1] || a1[0] != a1[1]);
      } else {
        separating = n2;
        const int tight = uniform(0, 1);
        for (std::size_t i = 0; i < nb; ++i) {
          b0.push_back(flat_side(-1, tight == 0 && i == 0));
          b1.push_back(flat_side(-1, tight == 1 && i == 0));
        }
        for (std::size_t i = 0; i < na; ++i) {
          a0.push_back(flat_side(1, tight == 0 && i == 0));
          a1.push_back(flat_side(1, tight == 1 && i == 0));
        }
      }
      if (!edges) RC_PRE(nondegenerate(b0) || nondegenerate(b1));
      note = edges ? "coplanar segments" : "coplanar triangle and point";
      break;
    }
    case 3: {  // two segments parallel to one direction throughout
      Vec3E d;
      if (contact) {
        d = pick_point(-1, 1);
        RC_PRE(!is_zero(d));
        // At t*: a = [c - s1 d, c + s2 d], b = [c - r1 d, c + r2 d] on one line, sharing c.
        const Vec3E c = pick_point(-1, 1);
        target = c;
        const Exact s1 = pick(0, 1), s2 = pick(0, 1), r1 = pick(0, 1), r2 = pick(0, 1);
        RC_PRE(s1 + s2 > 0 && r1 + r2 > 0);
        const std::vector<Vec3E> xa = {sub(c, mul(s1, d)), add(c, mul(s2, d))};
        const std::vector<Vec3E> xb = {sub(c, mul(r1, d)), add(c, mul(r2, d))};
        // Each segment translates, its ends also sliding along d (it stays parallel to d).
        const Vec3E va = pick_velocity(false), vb = pick_velocity(false);
        const Exact sa = pick(-1, 1), sb = pick(-1, 1);
        around(xa, {va, add(va, mul(sa, d))}, *t_star, a0, a1);
        around(xb, {vb, add(vb, mul(sb, d))}, *t_star, b0, b1);
        RC_PRE(a0[0] != a0[1] && b0[0] != b0[1]);
      } else {
        d = add(mul(pick(-1, 1), kInPlane1), mul(pick(-1, 1), kInPlane2));  // parallel to the separating plane
        RC_PRE(!is_zero(d));
        const Exact la0 = pick(0.25, 1), la1 = pick(0.25, 1), lb0 = pick(0.25, 1), lb1 = pick(0.25, 1);
        const Vec3E pa0 = side(1, true), pa1 = side(1), pb0 = side(-1, true), pb1 = side(-1);
        a0 = {pa0, add(pa0, mul(la0, d))};
        a1 = {pa1, add(pa1, mul(la1, d))};
        b0 = {pb0, add(pb0, mul(lb0, d))};
        b1 = {pb1, add(pb1, mul(lb1, d))};
      }
      note = "edges parallel to " + str(d);
      break;
    }
    case 4: {  // one body does not move (p0 == p1), the other does
      const bool triangle_still = *rc::gen::arbitrary<bool>();
      if (contact) {
        const std::vector<Vec3E> tri = pick_triangle(-1, 1);
        if (triangle_still) {
          b0 = b1 = tri;
          target = barycentric_point(tri);
          around({*target}, {pick_velocity(false)}, *t_star, a0, a1);
        } else {
          std::vector<Vec3E> v = {pick_velocity(false), pick_velocity(false), pick_velocity(false)};
          around(tri, v, *t_star, b0, b1);
          target = barycentric_point(tri);  // the point's fixed place, on the triangle at t*
          a0 = a1 = {*target};
        }
      } else {
        b0 = {side(-1, true), side(-1), side(-1)};
        RC_PRE(nondegenerate(b0));
        b1 = triangle_still ? b0 : std::vector<Vec3E>{side(-1), side(-1, true), side(-1)};
        a0 = {side(1, true)};
        a1 = triangle_still ? std::vector<Vec3E>{side(1)} : a0;
      }
      note = triangle_still ? "the triangle stands still" : "the point stands still";
      break;
    }
    default: {  // neither moves (p0 == p1 for both): touching or separated
      if (contact) {
        t_star = Exact(0);
        b0 = b1 = pick_triangle(-1, 1);
        target = barycentric_point(b0);
        if (*rc::gen::arbitrary<bool>()) {
          a0 = a1 = {*target};
        } else {  // a segment through a point of the triangle
          const Vec3E dir = pick_point(-1, 1);
          RC_PRE(!is_zero(dir));
          const Exact s = pick(0, 1);
          a0 = a1 = {sub(*target, mul(s, dir)), add(*target, mul(1 - s, dir))};
        }
      } else {
        b0 = b1 = {side(-1, true), side(-1), side(-1)};
        RC_PRE(nondegenerate(b0));
        a0 = a1 = {side(1, true), side(1)};
        RC_PRE(a0[0] != a0[1]);
      }
      note = "no motion at all";
      break;
    }
  }
  // The construction itself (separated): every vertex on its side with
  // margin at both ends, so at every time (the motion is linear).
  if (!contact) {
    for (const auto* v : {&a0, &a1})
      for (const Vec3E& p : *v) RC_ASSERT(dot(separating, p) >= m / 2);
    for (const auto* v : {&b0, &b1})
      for (const Vec3E& p : *v) RC_ASSERT(dot(separating, p) <= -m / 2);
    // A drift t * delta common to both bodies keeps the relative geometry
    // (so the clearance) but crosses the plane: the certified prefilter
    // (boxes and separating axes over the end positions) can no longer
    // decide alone.
    if (kind <= 3 && *rc::gen::element(true, true, false)) {
      // Across the plane (so that the sweeps overlap), and along it.
      Vec3E delta = add(mul(pick(-4, 4), separating), pick_point(-2, 2));
      if (kind == 2) delta[2] = 0;
      for (auto* v : {&a1, &b1})
        for (Vec3E& p : *v) p = add(p, delta);
      note += ", common drift " + str(delta);
    }
  }
  const Exact epsilon = contact ? *rc::gen::element(Exact(1, 16), Exact(1, 100), Exact(1, 1000)) : m / 4;
  Case c{make_scene(linear_body("a", a0, a1), linear_body("b", b0, b1), epsilon),
         std::string(kDegenerateKinds[kind]) + (contact ? " contact" : " separated"), t_star, !contact, note};
  if (contact) c.note += ", contact at t* = " + str(*t_star);
  else c.note += ", clearance m = " + str(m);
  // The construction itself (contact): a common point at t*.
  if (contact) {
    c.note += ", common point " + str(*target);
    RC_ASSERT(body_contains(c.scene.bodies[0], *t_star, *target));
    RC_ASSERT(body_contains(c.scene.bodies[1], *t_star, *target));
  }
  return c;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(two_bodies)

namespace {

// The certified kernels, the filtered one mostly; the exact one with a
// smaller node budget (it is slower per node).
KernelKind pick_kernel() { return *rc::gen::element(KernelKind::Filtered, KernelKind::Filtered, KernelKind::Filtered, KernelKind::Exact); }
std::uint64_t node_budget(KernelKind k) { return k == KernelKind::Exact ? 5000 : 20000; }

// (a2)
void contact2_never_safe(KernelKind kernel) {
  const Case c = contact2_case(false);
  const bool swap = *rc::gen::arbitrary<bool>();
  const CheckResult r = run_and_check(c, swap ? 1 : 0, swap ? 0 : 1, kernel, node_budget(kernel), "a2");
  RC_TAG(stop_label(r), work_label(r));
}

// (b2)
void clearance2_safe(KernelKind kernel, int eps_divisor) {
  const Case c = clearance2_case(eps_divisor);
  const CheckResult r = run_and_check(c, 0, 1, kernel, 20000, "b2");
  RC_TAG(c.kind, stop_label(r), work_label(r));
}

// Any of the scene kinds with a known truth: (a2), (b2), (a2) in contact at
// the start, one moving body against a fixed one.
Case any_case() {
  switch (uniform(0, 3)) {
    case 0: return contact2_case(false);
    case 1: return clearance2_case();
    case 2: return contact2_case(true);
    default: return fixed_case();
  }
}

// (degenerate)
void degenerate_known_truth(KernelKind kernel) {
  const int kind = uniform(0, 5);
  const bool contact = *rc::gen::arbitrary<bool>();
  const Case c = degenerate_case(kind, contact);
  const bool swap = *rc::gen::arbitrary<bool>();
  const CheckResult r = run_and_check(c, swap ? 1 : 0, swap ? 0 : 1, kernel, 20000, "degenerate");
  RC_TAG(c.kind, stop_label(r), r.stats.prefiltered ? "prefiltered" : "searched");
  if (kind == 5 && contact) {  // touching throughout: the start check
    RC_ASSERT(r.verdict == Verdict::Collision);
    RC_ASSERT(r.witness->t == 0);
  }
}

}  // namespace

// ------------------------------------------------------------------ (a2)

BOOST_AUTO_TEST_CASE(a2_contact_at_known_time_is_never_safe_filtered) {
  check_cases([] { contact2_never_safe(KernelKind::Filtered); }, 400);
}

BOOST_AUTO_TEST_CASE(a2_contact_at_known_time_is_never_safe_exact) {
  check_cases([] { contact2_never_safe(KernelKind::Exact); }, 50);
}

// ------------------------------------------------------------------ (b2)

BOOST_AUTO_TEST_CASE(b2_clearance_m_is_safe_for_epsilon_m_over_4_filtered) {
  check_cases([] { clearance2_safe(KernelKind::Filtered, 4); }, 400);
}

BOOST_AUTO_TEST_CASE(b2_clearance_m_is_safe_for_epsilon_m_over_4_exact) {
  check_cases([] { clearance2_safe(KernelKind::Exact, 4); }, 50);
}

// DESIGN.md section 6 claims safe for every epsilon <= m/2; for two moving
// bodies the same bound holds (the fattening R sqrt(rho1^2 + rho2^2) is what
// the stop test compares with epsilon, and the centers' images are then
// more than m - epsilon apart).  Checked at epsilon = m/2 exactly.
BOOST_AUTO_TEST_CASE(b2_clearance_m_is_safe_for_epsilon_m_over_2) {
  check_cases([] { clearance2_safe(KernelKind::Filtered, 2); }, 200);
}

// ------------------------------------------------------------------ (swap)

BOOST_AUTO_TEST_CASE(swapping_the_bodies_of_a_check_keeps_the_verdict) {
  check_cases(
      [] {
        const Case c = any_case();
        const KernelKind kernel = pick_kernel();
        const CheckResult ab = run_and_check(c, 0, 1, kernel, node_budget(kernel), "order (0, 1)");
        const CheckResult ba = run_and_check(c, 1, 0, kernel, node_budget(kernel), "order (1, 0)");
        RC_TAG(c.kind, stop_label(ab));
        RC_TAG(ab.verdict == ba.verdict ? "same verdict" : "proof in one order only");
        check_compatible(c, ab, ba);
      },
      300);
}

// ------------------------------------------------------------------ (rotation)

BOOST_AUTO_TEST_CASE(rational_rotation_of_the_world_keeps_every_verdict) {
  check_cases(
      [] {
        const Case c = any_case();
        long q[4];
        for (long& e : q) e = uniform(-3L, 3L);
        RC_PRE(q[0] != 0 || q[1] != 0 || q[2] != 0 || q[3] != 0);
        const Mat34E R = rotation(q[0], q[1], q[2], q[3]);
        RC_ASSERT(is_rotation(R));
        Case rotated = c;
        rotated.scene = world_mapped(c.scene, R);
        rotated.note += " (rotated by the quaternion (" + std::to_string(q[0]) + ", " + std::to_string(q[1]) + ", " +
                        std::to_string(q[2]) + ", " + std::to_string(q[3]) + "))";
        const KernelKind kernel = pick_kernel();
        const CheckResult r0 = run_and_check(c, 0, 1, kernel, node_budget(kernel), "original");
        const CheckResult r1 = run_and_check(rotated, 0, 1, kernel, node_budget(kernel), "rotated");
        RC_TAG(c.kind, stop_label(r0));
        RC_TAG(r0.verdict == r1.verdict ? "same verdict" : "proof in one frame only");
        check_compatible(c, r0, r1);
      },
      300);
}

// ------------------------------------------------------------------ (degenerate)

BOOST_AUTO_TEST_CASE(degenerate_linear_motions_have_their_known_truth_filtered) {
  check_cases([] { degenerate_known_truth(KernelKind::Filtered); }, 500);
}

BOOST_AUTO_TEST_CASE(degenerate_linear_motions_have_their_known_truth_exact) {
  check_cases([] { degenerate_known_truth(KernelKind::Exact); }, 200);
}

// ------------------------------------------------------------------ (scale)

BOOST_AUTO_TEST_CASE(translation_by_1e6_and_scaling_by_1e_6_keep_the_verdicts) {
  check_cases(
      [] {
        const bool clearance = *rc::gen::arbitrary<bool>();
        const Case c = clearance ? clearance2_case() : contact2_case(true);
        const Exact big = pow10(6);
        const Vec3E d = {*rc::gen::element(1, -1) * big, *rc::gen::element(1, -1) * big,
                         *rc::gen::element(1, -1) * big};
        Case variants[3] = {c, c, c};
        variants[1].scene = translated(c.scene, d);
        variants[1].note += " (translated by " + str(d) + ")";
        variants[2].scene = scaled(c.scene, pow10(-6));
        variants[2].note += " (lengths scaled by 10^-6)";
        const Exact t0 = c.scene.bodies[0].motion->t0;
        for (int v = 0; v < 3; ++v) {
          const CheckResult r =
              run_and_check(variants[v], 0, 1, KernelKind::Filtered, 20000, "variant " + std::to_string(v));
          if (v == 0) RC_TAG(c.kind, stop_label(r));
          RC_ASSERT(r.verdict == (clearance ? Verdict::Safe : Verdict::Collision));
          if (!clearance) {
            RC_ASSERT(r.witness->t == t0);
            RC_ASSERT(r.first_contact->first == t0);
            RC_ASSERT(r.first_contact->second == t0);
          }
        }
      },
      200);
}

// ------------------------------------------------------------------ deterministic cases

BOOST_AUTO_TEST_CASE(two_segments_crossing_head_on_and_passing_apart) {
  // Segment a (along z, |z| <= 1) moves in +x, segment b (along y, at height
  // dz) in -x; they pass x = 0 together at t = 1/2 only: they meet at
  // (0, 0, dz) when dz = 0, and keep clearance 1 when dz = 2.
  for (const Exact dz : {Exact(0), Exact(2)}) {
    Scene s = make_scene(linear_body("a", {{-2, 0, -1}, {-2, 0, 1}}, {{2, 0, -1}, {2, 0, 1}}),
                         linear_body("b", {{2, -1, dz}, {2, 1, dz}}, {{-2, -1, dz}, {-2, 1, dz}}), Exact(1, 1000));
    s.source = "deterministic";
    for (KernelKind kernel : {KernelKind::Filtered, KernelKind::Exact})
      for (const auto& [a, b] : {std::pair{0, 1}, std::pair{1, 0}}) {
        const CheckResult r = verify_check(s, a, b, options_for(*s.epsilon, kernel));
        BOOST_TEST_INFO("dz = " << str(dz) << ", " << to_string(kernel) << ", order (" << a << ", " << b
                                << "): " << describe(r));
        BOOST_TEST(consistency_problem(s, a, b, r) == "");
        if (dz == 0) {
          BOOST_REQUIRE((r.verdict == Verdict::Collision));
          BOOST_TEST(r.witness->t == Exact(1, 2));
          BOOST_TEST((r.witness->point == Vec3E{0, 0, 0}));
          BOOST_TEST(r.first_contact->first <= Exact(1, 2));
          BOOST_TEST(r.first_contact->first > 0);
        } else {
          BOOST_TEST((r.verdict == Verdict::Safe));
        }
      }
  }
}

// ------------------------------------------------------------------ (certificates)

// Every verdict of the random scenes above - both bodies moving with random
// degrees and weights, one fixed, degenerate linear motions, contacts at the
// start - gets a certificate that the independent exact checker accepts,
// and the same certificate with one separation direction negated (which can
// never separate) is rejected.
BOOST_AUTO_TEST_CASE(certificates_of_random_scenes_check_and_tampering_is_caught) {
  check_cases(
      [] {
        const bool degenerate = *rc::gen::arbitrary<bool>();
        const Case c = degenerate ? degenerate_case(uniform(0, 5), *rc::gen::arbitrary<bool>()) : any_case();
        const KernelKind kernel = pick_kernel();
        VerifyOptions options = options_for(*c.scene.epsilon, kernel, node_budget(kernel));
        options.record_cover = true;
        const SceneResult result = verify_scene(c.scene, options);
        RC_LOG() << "[" << c.kind << "] " << c.note << "\n" << describe(c.scene) << "\n" << describe(result.checks[0]) << "\n";
        nlohmann::json doc = nlohmann::json::parse(certificate::certificate_json(c.scene, result));
        const certificate::CheckOutcome outcome = certificate::check_certificate(c.scene, doc, "property");
        RC_LOG() << "checker: " << (outcome.ok ? "ok" : outcome.message) << "\n";
        RC_ASSERT(outcome.ok);
        nlohmann::json& pieces = doc["checks"][0]["pieces"];
        RC_TAG(to_string(result.checks[0].verdict), pieces.empty() ? "no pieces" : "pieces");
        if (pieces.empty()) return;
        // A random separation of a random piece's proof (shared nodes
        // followed: negating a shared one breaks every use, this one too).
        nlohmann::json& nodes = doc["checks"][0]["nodes"];
        nlohmann::json* proof = &pieces[uniform(std::size_t(0), pieces.size() - 1)]["proof"];
        while (proof->is_number_integer() || !proof->contains("sep")) {
          if (proof->is_number_integer()) {
            proof = &nodes[proof->get<std::size_t>()];
          } else if (proof->is_array()) {  // a split [s, P1, ..., Pm]
            proof = &(*proof)[uniform(std::size_t(1), proof->size() - 1)];
          } else {
            nlohmann::json& parts = (*proof)["parts"];
            proof = &parts[uniform(std::size_t(0), parts.size() - 1)];
          }
        }
        for (nlohmann::json& x : (*proof)["sep"]) {
          Exact q;
          const bool parsed = x.is_number_integer() ? (q = Exact(x.get<long>()), true) : parse_exact(x.get<std::string>(), q);
          RC_ASSERT(parsed);
          x = to_string(-q);
        }
        RC_ASSERT(!certificate::check_certificate(c.scene, doc, "property").ok);
      },
      200);
}

BOOST_AUTO_TEST_CASE(the_oracle_itself) {
  // Rotation matrices from integer quaternions are rotations.
  BOOST_TEST(is_rotation(rotation(1, 2, 2, 4)));
  BOOST_TEST(is_rotation(rotation(0, 0, 0, 3)));
  BOOST_TEST(is_rotation(rotation(-3, 1, 0, 2)));
  BOOST_TEST(!is_rotation(translation(1, 0, 0)));
  // The oblique normal is a unit vector, perpendicular to the in-plane directions.
  BOOST_TEST(dot(kNormal, kNormal) == Exact(1));
  BOOST_TEST(dot(kNormal, kInPlane1) == Exact(0));
  BOOST_TEST(dot(kNormal, kInPlane2) == Exact(0));
  // compose: (W o M)(x) = W(M(x)).
  const Mat34E W = {1, 2, 0, 1, 0, 1, 3, -1, 2, 0, 1, Exact(1, 2)};
  const Mat34E M = {0, 1, 0, 2, 1, 0, 1, 0, 0, 0, 2, -3};
  const Vec3E x = {Exact(1, 3), -2, 5};
  BOOST_TEST((place(compose(W, M), x) == place(W, place(M, x))));
  // linear_body: vertex i at p0[i] at t = 0 and p1[i] at t = 1, linearly.
  const Body b = linear_body("t", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{2, 0, 0}, {2, 2, 0}, {2, 0, 2}});
  BOOST_TEST((place(eval_motion(*b.motion, Exact(1, 2)), {1, 0, 0}) == Vec3E{Exact(3, 2), 1, 0}));
  BOOST_TEST(body_contains(b, 1, {2, 1, 1}));
  BOOST_TEST(!body_contains(b, 1, {2, 2, 2}));
}

BOOST_AUTO_TEST_SUITE_END()
