// Property tests of keyframe motions (issue 12, proofs/enclosures.md
// "Checked by"): random keyframe scenes (a bar or a triangle moving through
// 2-4 keyframes by slerp, screw or nlerp, rotations as random exact
// quaternions or rpy angles, against a fixed triangle), verified with the
// library from their JSON text (parse_scene_text + verify_scene), then
// checked against an independent high-precision evaluation of the motion
// (tests/support/mp_reference.h: MPFR at 256 bits, slerp by acos, screw by
// the SE(3) log/exp, nlerp as written, rpy from elementary matrices; it
// shares no formula with src/motion/segment.cpp):
//
//  (safe)      a `safe` verdict: at 200 sample times per keyframe segment
//              the configuration (placed in MPFR, error < 2^-240) shows no
//              certain crossing of an edge through a triangle (every sign
//              larger than 1e-40 in magnitude).  A false safe whose bodies
//              interpenetrate for longer than 1/200 of a segment fails here.
//  (collision) a `collision` verdict: the witness is re-checked at its time
//              t from the independent pose: a `point` must lie on both
//              named features as placed (distance <= 1e-30), a `point_box`
//              must hold a common point of both placed features (the
//              crossing of the named edge with the named triangle, found in
//              MPFR, inside the box up to 1e-30); t lies in first_contact.
//  (undecided) has a bracket, undecided intervals, no witness.
//  (bracket)   for `collision` and `undecided`, no sample time before
//              first_contact's lower end shows a certain crossing (that
//              prefix is certified contact-free).
//  (two bodies) the same with the triangle moving too, by its own 2-3
//              keyframes whose interior time differs from the bar's (the
//              check is cut at both bodies' breaks).
//  (clearance, tolerance) the same scenes with a scene clearance d or a
//              tolerance r of the mover: `safe` (and the prefix before
//              first_contact) must show no sample at a distance below d, or
//              below r / sqrt(W) (a translation by v, |v| sqrt(W) <= r, is
//              admissible; W the mover's mass sum); a clearance witness's
//              two points lie on the named features at t, at most d apart
//              (exactly); a toleranced witness's displacement has
//              |v|^2 W <= r^2 (exactly) and its point lies on the displaced
//              mover and on the obstacle.
//  (translation) keyframes whose rotations are all equal (pure
//              translation): slerp, screw and nlerp give the same verdict.
//
// Run: `tmcert_property --run_test=planner_motions` (about 20-40 s with the
// default 100 cases: the MPFR sampling dominates).  Larger run:
//   RC_PARAMS="max_success=500 seed=N" tmcert_property --run_test=planner_motions  (2250 cases, ~280 s)
// The seed is printed at the start of the run; a failure prints the scene
// as tmcert-scene/1 JSON (run `tmcert verify` on it) and the reproduce line.

#include "tests/support/mp_reference.h"
#include "tests/support/scene_testing.h"

#include "src/io/parse.h"

#include <rapidcheck.h>

#include <algorithm>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

using namespace tmcert;
using namespace tmcert::testing;

namespace {

// ------------------------------------------------------------------ scenes

struct KeyScene {
  std::string how;                       // "slerp", "screw", "nlerp"
  std::vector<Pose> poses;
  std::vector<Exact> times;
  std::vector<Vec3E> moving;             // 2 points: a bar; 3: a triangle (body frame)
  std::array<Vec3E, 3> obstacle;         // triangle (its own frame; the world when fixed)
  // The obstacle's own keyframes (empty: fixed), over the same interval
  // with other interior times, so the two bodies' pieces break at
  // different parameters.
  std::string obstacle_how;
  std::vector<Pose> obstacle_poses;
  std::vector<Exact> obstacle_times;
  // Scene clearance and the mover's tolerance (0: none); W = the sum of the
  // mover's default mass weights, read back from the parsed scene.
  Exact clearance = 0, tolerance = 0, weight_sum = 1;
  std::string json;
};

std::string q(const Exact& x) { return "\"" + to_string(x) + "\""; }
std::string vec(const Vec3E& v) { return "[" + q(v[0]) + ", " + q(v[1]) + ", " + q(v[2]) + "]"; }

std::string pose_json(const Pose& p) {
  std::string s = "{\"translation\": " + vec(p.translation);
  if (p.rotation.kind == Rotation::Kind::Quaternion)
    s += ", \"rotation\": {\"quaternion\": [" + q(p.rotation.quaternion[0]) + ", " + q(p.rotation.quaternion[1]) + ", " +
         q(p.rotation.quaternion[2]) + ", " + q(p.rotation.quaternion[3]) + "]}";
  else if (p.rotation.kind == Rotation::Kind::Rpy)
    s += ", \"rotation\": {\"rpy\": " + vec({p.rotation.rpy[0], p.rotation.rpy[1], p.rotation.rpy[2]}) + "}";
  return s + "}";
}

std::string keyframes_json(const std::string& how, const std::vector<Exact>& times, const std::vector<Pose>& poses) {
  std::ostringstream o;
  o << "{\"type\": \"keyframes\", \"interpolation\": \"" << how << "\", \"times\": [";
  for (std::size_t i = 0; i < times.size(); ++i) o << (i ? ", " : "") << q(times[i]);
  o << "],\n     \"poses\": [";
  for (std::size_t i = 0; i < poses.size(); ++i) o << (i ? ",\n       " : "") << pose_json(poses[i]);
  o << "]}";
  return o.str();
}

void build_json(KeyScene& k) {
  std::ostringstream o;
  o << "{\"format\": \"tmcert-scene/1\", \"epsilon\": \"1/200\", ";
  if (k.clearance > 0) o << "\"clearance\": " << q(k.clearance) << ", ";
  o << "\"bodies\": [\n"
    << "  {\"name\": \"tri\", \"polygons\": [[" << vec(k.obstacle[0]) << ", " << vec(k.obstacle[1]) << ", "
    << vec(k.obstacle[2]) << "]]";
  if (!k.obstacle_poses.empty()) o << ",\n   \"motion\": " << keyframes_json(k.obstacle_how, k.obstacle_times, k.obstacle_poses);
  o << "},\n  {\"name\": \"mover\", ";
  if (k.moving.size() == 2) o << "\"segments\": [[" << vec(k.moving[0]) << ", " << vec(k.moving[1]) << "]]";
  else o << "\"polygons\": [[" << vec(k.moving[0]) << ", " << vec(k.moving[1]) << ", " << vec(k.moving[2]) << "]]";
  if (k.tolerance > 0) o << ", \"tolerance\": " << q(k.tolerance);
  o << ",\n   \"motion\": " << keyframes_json(k.how, k.times, k.poses) << "}]}";
  k.json = o.str();
}

Rotation pick_rotation(bool rpy) {
  Rotation r;
  if (rpy) {
    r.kind = Rotation::Kind::Rpy;
    for (Exact& a : r.rpy) a = pick(-1.5, 1.5);
  } else {
    r.kind = Rotation::Kind::Quaternion;
    for (Exact& x : r.quaternion) x = Exact(uniform(-4, 4), uniform(1, 2));
    if (r.quaternion[0] == 0 && r.quaternion[1] == 0 && r.quaternion[2] == 0 && r.quaternion[3] == 0) r.quaternion[0] = 1;
  }
  return r;
}

KeyScene pick_scene(const std::string& how, bool pure_translation, bool moving_obstacle = false) {
  KeyScene k;
  k.how = how;
  const int n = uniform(2, 4);
  const bool rpy = !pure_translation && uniform(0, 2) == 0;
  const Rotation fixed = pick_rotation(false);
  for (int i = 0; i < n; ++i) {
    Pose p;
    p.translation = pick_point(-1.25, 1.25);
    p.rotation = pure_translation ? fixed : pick_rotation(rpy);
    k.poses.push_back(p);
  }
  Exact t = pick(-1, 1);
  for (int i = 0; i < n; ++i) {
    k.times.push_back(t);
    t += pick(0.25, 1);
  }
  if (uniform(0, 1) == 0) {
    k.moving = {pick_point(-0.75, 0.75), pick_point(-0.75, 0.75)};
    RC_PRE(k.moving[0] != k.moving[1]);
  } else {
    k.moving = {pick_point(-0.75, 0.75), pick_point(-0.75, 0.75), pick_point(-0.75, 0.75)};
    RC_PRE(nondegenerate(k.moving));
  }
  const std::vector<Vec3E> obstacle = pick_triangle(-1, 1);
  k.obstacle = {obstacle[0], obstacle[1], obstacle[2]};
  if (moving_obstacle) {
    // 2-3 keyframes over [first, last] of the mover's times, interior time
    // strictly between and different from the mover's.
    k.obstacle_how = *rc::gen::element<std::string>("slerp", "screw", "nlerp");
    k.obstacle_times = {k.times.front()};
    if (uniform(0, 1) == 0) {
      const Exact mid = k.times.front() + (k.times.back() - k.times.front()) * pick(0.1, 0.9);
      RC_PRE(std::find(k.times.begin(), k.times.end(), mid) == k.times.end());
      k.obstacle_times.push_back(mid);
    }
    k.obstacle_times.push_back(k.times.back());
    for (std::size_t i = 0; i < k.obstacle_times.size(); ++i) {
      Pose p;
      p.translation = pick_point(-0.5, 0.5);
      p.rotation = pick_rotation(uniform(0, 2) == 0);
      k.obstacle_poses.push_back(p);
    }
  }
  build_json(k);
  return k;
}

// ------------------------------------------------------------------ the independent configuration

using P3 = std::array<Mp, 3>;

P3 psub(const P3& a, const P3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Mp pdot(const P3& a, const P3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
P3 pcross(const P3& a, const P3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Mp det(const P3& a, const P3& b, const P3& c, const P3& d) { return pdot(psub(b, a), pcross(psub(c, a), psub(d, a))); }
P3 pw(const Vec3E& v) { return {Mp(v[0]), Mp(v[1]), Mp(v[2])}; }

// The pose at scene parameter t, independently (MPFR), or nullopt outside
// the motion.  Screw between equal rotations is the translation (slerp's
// formula then reduces to it too).
std::optional<MpPose> pose_at(const std::string& name, const std::vector<Pose>& poses, const std::vector<Exact>& times,
                              const Exact& t) {
  for (std::size_t i = 0; i + 1 < poses.size(); ++i) {
    if (t < times[i] || t > times[i + 1]) continue;
    const Exact s = (t - times[i]) / (times[i + 1] - times[i]);
    const Pose &a = poses[i], &b = poses[i + 1];
    Interpolation how = name == "slerp" ? Interpolation::Slerp : name == "screw" ? Interpolation::Screw : Interpolation::Nlerp;
    // The relative rotation's angle: a screw with (almost) no rotation is a translation.
    if (how == Interpolation::Screw) {
      const MpMat3 rd = mat_mul(transpose(rotation_matrix(a.rotation)), rotation_matrix(b.rotation));
      if (Mp(3) - (rd[0] + rd[4] + rd[8]) < Mp(1e-60)) how = Interpolation::Slerp;
    }
    return reference_pose(a, b, how, Mp(s));
  }
  return std::nullopt;
}

std::optional<MpPose> pose_at(const KeyScene& k, const Exact& t) { return pose_at(k.how, k.poses, k.times, t); }

std::vector<P3> placed_moving(const KeyScene& k, const MpPose& pose) {
  std::vector<P3> out;
  for (const Vec3E& v : k.moving) out.push_back(apply_pose(pose, v));
  return out;
}

// The obstacle at t (fixed: as written).
std::array<P3, 3> placed_obstacle(const KeyScene& k, const Exact& t) {
  if (k.obstacle_poses.empty()) return {pw(k.obstacle[0]), pw(k.obstacle[1]), pw(k.obstacle[2])};
  const auto pose = pose_at(k.obstacle_how, k.obstacle_poses, k.obstacle_times, t);
  RC_ASSERT(pose.has_value());
  return {apply_pose(*pose, k.obstacle[0]), apply_pose(*pose, k.obstacle[1]), apply_pose(*pose, k.obstacle[2])};
}

const Mp kSign(1e-40);

// A certain crossing of segment pq through the interior of triangle abc:
// every sign larger than kSign in magnitude.
bool certain_cross(const P3& p, const P3& q, const P3& a, const P3& b, const P3& c) {
  auto sgn = [](const Mp& x) { return kSign < x ? 1 : x < -kSign ? -1 : 0; };
  const int sp = sgn(det(a, b, c, p)), sq = sgn(det(a, b, c, q));
  if (sp == 0 || sq == 0 || sp == sq) return false;
  const int s0 = sgn(det(p, q, a, b)), s1 = sgn(det(p, q, b, c)), s2 = sgn(det(p, q, c, a));
  return s0 != 0 && s0 == s1 && s1 == s2;
}

// Does the configuration show a certain crossing (an edge of one body
// through the other's triangle)?
bool certainly_colliding(const std::vector<P3>& m, const std::array<P3, 3>& o) {
  const std::size_t edges = m.size() == 2 ? 1 : 3;
  for (std::size_t e = 0; e < edges; ++e)
    if (certain_cross(m[e], m[(e + 1) % m.size()], o[0], o[1], o[2])) return true;
  if (m.size() == 3)
    for (int e = 0; e < 3; ++e)
      if (certain_cross(o[e], o[(e + 1) % 3], m[0], m[1], m[2])) return true;
  return false;
}

// Distance from x to the closed segment ab or triangle abc (MPFR; brute
// force over the projection and the edges).  Every distance computed here is
// between two actual points of the features, so it is an upper bound of the
// true distance (up to MPFR's 2^-240).
Mp dist_segment(const P3& x, const P3& a, const P3& b) {
  const P3 d = psub(b, a);
  Mp t = pdot(psub(x, a), d) / pdot(d, d);
  if (t < Mp(0)) t = Mp(0);
  if (Mp(1) < t) t = Mp(1);
  const P3 y = {a[0] + t * d[0], a[1] + t * d[1], a[2] + t * d[2]};
  const P3 e = psub(x, y);
  return sqrt(pdot(e, e));
}
Mp dist_feature(const P3& x, const std::vector<P3>& f) {
  if (f.size() == 2) return dist_segment(x, f[0], f[1]);
  const P3 n = pcross(psub(f[1], f[0]), psub(f[2], f[0]));
  const Mp h = pdot(psub(x, f[0]), n) / sqrt(pdot(n, n));
  const P3 y = {x[0] - h * n[0] / sqrt(pdot(n, n)), x[1] - h * n[1] / sqrt(pdot(n, n)), x[2] - h * n[2] / sqrt(pdot(n, n))};
  const Mp u = pdot(pcross(psub(f[1], f[0]), psub(y, f[0])), n), v = pdot(pcross(psub(f[2], f[1]), psub(y, f[1])), n),
           w = pdot(pcross(psub(f[0], f[2]), psub(y, f[2])), n);
  if (!(u < Mp(0)) && !(v < Mp(0)) && !(w < Mp(0))) return abs(h);
  Mp best = dist_segment(x, f[0], f[1]);
  for (const Mp& d : {dist_segment(x, f[1], f[2]), dist_segment(x, f[2], f[0])})
    if (d < best) best = d;
  return best;
}

// An upper bound of the distance between two segments: the clamped
// closest-point parameters of the lines, then each end against the other.
Mp dist_seg_seg(const P3& p0, const P3& p1, const P3& q0, const P3& q1) {
  Mp best = dist_segment(p0, q0, q1);
  for (const Mp& d : {dist_segment(p1, q0, q1), dist_segment(q0, p0, p1), dist_segment(q1, p0, p1)})
    if (d < best) best = d;
  const P3 d1 = psub(p1, p0), d2 = psub(q1, q0), r = psub(p0, q0);
  const Mp a = pdot(d1, d1), b = pdot(d1, d2), c = pdot(d2, d2), d = pdot(d1, r), e = pdot(d2, r);
  const Mp den = a * c - b * b;
  if (Mp(1e-40) < den) {
    const Mp s = (b * e - c * d) / den, t = (a * e - b * d) / den;
    if (!(s < Mp(0)) && !(Mp(1) < s) && !(t < Mp(0)) && !(Mp(1) < t)) {
      const P3 x = {p0[0] + s * d1[0], p0[1] + s * d1[1], p0[2] + s * d1[2]};
      const P3 y = {q0[0] + t * d2[0], q0[1] + t * d2[1], q0[2] + t * d2[2]};
      const P3 g = psub(x, y);
      const Mp dd = sqrt(pdot(g, g));
      if (dd < best) best = dd;
    }
  }
  return best;
}

// An upper bound of the distance between the placed mover and obstacle
// (0 when an edge certainly crosses the other's triangle; otherwise the
// least of the vertex-feature and edge-edge distances, where the minimum
// of two disjoint polytopes is attained).
Mp upper_distance(const std::vector<P3>& m, const std::array<P3, 3>& o) {
  if (certainly_colliding(m, o)) return Mp(0);
  const std::vector<P3> ov(o.begin(), o.end());
  Mp best = dist_feature(m[0], ov);
  for (const P3& x : m) {
    const Mp d = dist_feature(x, ov);
    if (d < best) best = d;
  }
  for (const P3& x : ov) {
    const Mp d = dist_feature(x, m);
    if (d < best) best = d;
  }
  const std::size_t me = m.size() == 2 ? 1 : 3;
  for (std::size_t i = 0; i < me; ++i)
    for (int j = 0; j < 3; ++j) {
      const Mp d = dist_seg_seg(m[i], m[(i + 1) % m.size()], ov[j], ov[(j + 1) % 3]);
      if (d < best) best = d;
    }
  return best;
}

const Mp kOn(1e-30);

// The crossing point of segment pq with the plane of triangle abc, when
// the segment reaches the plane and the point is in the triangle (up to kOn).
std::optional<P3> crossing_point(const P3& p, const P3& q, const std::vector<P3>& t) {
  const Mp vp = det(t[0], t[1], t[2], p), vq = det(t[0], t[1], t[2], q);
  if (!(kOn < abs(vp - vq))) return std::nullopt;  // parallel to the plane
  const Mp l = vp / (vp - vq);
  if (l < -kOn || Mp(1) + kOn < l) return std::nullopt;
  const P3 x = {p[0] + (q[0] - p[0]) * l, p[1] + (q[1] - p[1]) * l, p[2] + (q[2] - p[2]) * l};
  if (kOn < dist_feature(x, t)) return std::nullopt;
  return x;
}

// ------------------------------------------------------------------ the checks

std::string fail_text(const KeyScene& k, const CheckResult& r, const std::string& why) {
  return why + "\n  result: " + describe(r) + "\n  scene:\n" + k.json;
}

// The witness, re-checked at its time from the independent pose.
// A witness at an algebraic time (exact resolution of a rational part): the
// root of `root_of` in (lo, hi) is narrowed exactly by bisection to 2^-80,
// and there the independent reference must place both features within a
// small distance of the witness box.
std::string algebraic_witness_problem(const KeyScene& k, const CheckResult& r) {
  const Witness& w = *r.witness;
  const AlgebraicTime& at = *w.root;
  if (!w.point_box) return "algebraic witness without point_box";
  if (!r.first_contact || r.first_contact->second != at.hi) return "bracket does not end at the root's interval";
  auto value = [&](const Exact& t) {
    Exact v = 0;
    for (std::size_t i = at.root_of.size(); i-- > 0;) v = v * t + Exact(at.root_of[i]);
    return v;
  };
  Exact lo = at.lo, hi = at.hi;
  const int sign_lo = CGAL::sign(value(lo));
  if (sign_lo == 0 || CGAL::sign(value(hi)) == 0 || sign_lo == CGAL::sign(value(hi)))
    return "root interval does not isolate a simple sign change";
  for (int i = 0; i < 80; ++i) {
    const Exact mid = (lo + hi) / 2;
    const int sm = CGAL::sign(value(mid));
    if (sm == 0) {
      lo = hi = mid;
      break;
    }
    (sm == sign_lo ? lo : hi) = mid;
  }
  const auto pose = pose_at(k, lo);
  if (!pose) return "witness root outside the motion";
  const std::vector<P3> m = placed_moving(k, *pose);
  const std::array<P3, 3> oa = placed_obstacle(k, lo);
  const std::vector<P3> o(oa.begin(), oa.end());
  P3 center;
  Mp diameter(0);
  for (int c = 0; c < 3; ++c) {
    center[c] = (Mp((*w.point_box)[c][0]) + Mp((*w.point_box)[c][1])) / Mp(2);
    diameter = diameter + (Mp((*w.point_box)[c][1]) - Mp((*w.point_box)[c][0]));
  }
  const Mp slack = diameter + Mp(1e-12);  // the box, and 2^-80 of motion
  if (slack < dist_feature(center, m)) return "algebraic witness box not on the moving feature at its root";
  if (slack < dist_feature(center, o)) return "algebraic witness box not on the obstacle at its root";
  return "";
}

std::string witness_problem(const KeyScene& k, const CheckResult& r) {
  const Witness& w = *r.witness;
  if (w.root) return algebraic_witness_problem(k, r);
  if (!r.first_contact || w.t < r.first_contact->first || w.t > r.first_contact->second) return "witness time outside first_contact";
  const auto pose = pose_at(k, w.t);
  if (!pose) return "witness time outside the motion";
  // The check is (tri, mover) in the scene's default order; the features
  // are "tri polygon 0" and "mover segment 0" / "mover polygon 0".
  const int tri_side = w.features[0].rfind("tri ", 0) == 0 ? 0 : 1;
  if (w.features[tri_side] != "tri polygon 0") return "unexpected obstacle feature " + w.features[tri_side];
  const std::string want_mover = k.moving.size() == 2 ? "mover segment 0" : "mover polygon 0";
  if (w.features[1 - tri_side] != want_mover) return "unexpected moving feature " + w.features[1 - tri_side];
  std::vector<P3> m = placed_moving(k, *pose);
  const std::array<P3, 3> oa = placed_obstacle(k, w.t);
  const std::vector<P3> o(oa.begin(), oa.end());
  if (w.points_box) {
    // Clearance at an enclosed pose (proofs/clearance.md section 6): a box
    // per body, in the check's order, every two points of the boxes within
    // the clearance, each box at a point of its feature at t.
    if (k.clearance == 0) return "points_box without a clearance";
    Exact far2 = 0;
    for (int c = 0; c < 3; ++c) {
      const auto& a = (*w.points_box)[0][c];
      const auto& b = (*w.points_box)[1][c];
      const Exact x = std::max(CGAL::abs(a[1] - b[0]), CGAL::abs(b[1] - a[0]));
      far2 += x * x;
    }
    if (far2 > k.clearance * k.clearance) return "clearance boxes farther apart than the clearance";
    for (int s = 0; s < 2; ++s) {
      const std::vector<P3>& f = (s == tri_side) ? o : m;
      P3 center;
      Mp diameter(0);
      for (int c = 0; c < 3; ++c) {
        center[c] = (Mp((*w.points_box)[s][c][0]) + Mp((*w.points_box)[s][c][1])) / Mp(2);
        diameter = diameter + (Mp((*w.points_box)[s][c][1]) - Mp((*w.points_box)[s][c][0]));
      }
      if (diameter + kOn < dist_feature(center, f)) return "clearance box " + std::to_string(s) + " not on its feature";
    }
    return "";
  }
  if (w.points) {
    // Clearance: one exact point on each body, in the check's order, no
    // farther apart than the clearance.
    if (k.clearance == 0) return "points without a clearance";
    const Vec3E d = testing::sub((*w.points)[0], (*w.points)[1]);
    if (testing::dot(d, d) > k.clearance * k.clearance) return "clearance witness points farther apart than the clearance";
    const std::vector<P3>& f0 = tri_side == 0 ? o : m;
    const std::vector<P3>& f1 = tri_side == 0 ? m : o;
    if (kOn < dist_feature(pw((*w.points)[0]), f0)) return "clearance witness point 0 not on its feature";
    if (kOn < dist_feature(pw((*w.points)[1]), f1)) return "clearance witness point 1 not on its feature";
    return "";
  }
  if (w.displacement) {
    // Tolerance: the mover translated by the displacement (within its
    // tolerance: |v|^2 W <= r^2) touches the obstacle at `point`.
    if (k.tolerance == 0) return "displacement without a tolerance";
    const int mover_side = 1 - tri_side;
    if (w.displaced != mover_side) return "displaced body is not the mover (the only one with a tolerance)";
    const Vec3E& v = *w.displacement;
    if (testing::dot(v, v) * k.weight_sum > k.tolerance * k.tolerance) return "displacement beyond the tolerance";
    std::vector<P3> moved = m;
    for (P3& x : moved)
      for (int c = 0; c < 3; ++c) x[c] = x[c] + Mp(v[c]);
    if (!w.point_box) {
      const P3 x = pw(w.point);
      if (kOn < dist_feature(x, moved)) return "toleranced witness point not on the displaced mover";
      if (kOn < dist_feature(x, o)) return "toleranced witness point not on the obstacle";
      return "";
    }
    // At an enclosed pose (a transcendental motion between keyframes): a
    // crossing of the displaced mover and the obstacle inside the box
    // (proofs/enclosures.md section 6), checked below.
    m = moved;
  }
  if (!w.point_box) {
    const P3 x = pw(w.point);
    if (kOn < dist_feature(x, m)) return "witness point not on the moving feature at t (distance " + std::to_string(dist_feature(x, m).to_double()) + ")";
    if (kOn < dist_feature(x, o)) return "witness point not on the obstacle";
    return "";
  }
  // A box: some common point of the placed features inside it.  The common
  // points of a certain transversal crossing are edge-through-triangle
  // crossings: try every edge of each through the other.
  const auto& box = *w.point_box;
  for (int c = 0; c < 3; ++c)
    if (box[c][0] > box[c][1]) return "empty point_box";
  std::vector<P3> candidates;
  auto edges_through = [&](const std::vector<P3>& e, const std::vector<P3>& t) {
    if (t.size() != 3) return;
    const std::size_t n = e.size() == 2 ? 1 : 3;
    for (std::size_t i = 0; i < n; ++i)
      if (auto x = crossing_point(e[i], e[(i + 1) % e.size()], t)) candidates.push_back(*x);
  };
  edges_through(m, o);
  edges_through(o, m);
  for (const P3& x : candidates) {
    bool inside = true;
    for (int c = 0; c < 3; ++c)
      inside = inside && !(x[c] < Mp(box[c][0]) - kOn) && !(Mp(box[c][1]) + kOn < x[c]);
    if (inside) return "";
  }
  return "no common point of the placed features inside point_box (" + std::to_string(candidates.size()) + " crossings found)";
}

// The first sample time before `limit` (exclusive; none: the whole motion)
// at which the configuration shows a certain crossing (with a clearance or
// a tolerance: a distance certainly within reach of a contact).
std::optional<Exact> sampled_crossing(const KeyScene& k, int samples, const std::optional<Exact>& limit) {
  for (std::size_t i = 0; i + 1 < k.times.size(); ++i)
    for (int j = 0; j <= samples; ++j) {
      const Exact t = k.times[i] + (k.times[i + 1] - k.times[i]) * Exact(j, samples);
      if (limit && t >= *limit) return std::nullopt;
      const auto pose = pose_at(k, t);
      if (!pose) continue;
      const std::vector<P3> m = placed_moving(k, *pose);
      const std::array<P3, 3> o = placed_obstacle(k, t);
      if (k.clearance == 0 && k.tolerance == 0) {
        if (certainly_colliding(m, o)) return t;
        continue;
      }
      // Clearance d: a distance below d violates it.  Tolerance r: a
      // translation by v with |v| sqrt(W) <= r is admissible, so a distance
      // below r / sqrt(W) is reached by an admissible motion.
      const Mp threshold = k.clearance > 0 ? Mp(k.clearance) : Mp(k.tolerance) / sqrt(Mp(k.weight_sum));
      if (upper_distance(m, o) < threshold - Mp(1e-20)) return t;
    }
  return std::nullopt;
}

std::string result_problem(const KeyScene& k, const CheckResult& r, int samples) {
  if (r.verdict != Verdict::Safe) {
    // The bracket's lower end is a certified contact-free prefix.
    if (!r.first_contact) return "non-safe verdict without first_contact";
    if (const auto t = sampled_crossing(k, samples, r.first_contact->first))
      return "a certain contact (crossing, or distance within the clearance or reach) at t = " + to_string(*t) + " before first_contact";
  }
  if (r.verdict == Verdict::Collision) {
    if (!r.witness) return "collision without a witness";
    return witness_problem(k, r);
  }
  if (r.verdict == Verdict::Undecided) {
    if (r.witness) return "undecided with a witness";
    if (r.undecided.empty()) return "undecided without undecided intervals";
    return "";
  }
  if (r.witness || r.first_contact || !r.undecided.empty()) return "safe with a witness, bracket or undecided interval";
  if (const auto t = sampled_crossing(k, samples, std::nullopt)) return "false safe: a certain contact (crossing, or distance within the clearance or reach) at t = " + to_string(*t);
  return "";
}

VerifyOptions planner_options() {
  VerifyOptions o;
  o.kernel = KernelKind::Filtered;
  o.epsilon = Exact(1, 200);
  o.max_depth = 30;
  o.max_nodes = 20000;
  return o;
}

std::optional<Scene> parse_or_discard(const KeyScene& k) {
  try {
    return parse_scene_text(k.json, "property");
  } catch (const InputError& e) {
    // Only the 180-degree rule may refuse a generated scene.
    const std::string what = e.what();
    RC_ASSERT(what.find("180 degrees") != std::string::npos || what.find("which arc") != std::string::npos);
    return std::nullopt;
  }
}

}  // namespace

BOOST_AUTO_TEST_SUITE(planner_motions)

BOOST_AUTO_TEST_CASE(keyframe_verdicts_agree_with_independent_sampling) {
  check_cases(
      [] {
        const std::string how = *rc::gen::element<std::string>("slerp", "screw", "nlerp");
        const KeyScene k = pick_scene(how, false);
        const auto scene = parse_or_discard(k);
        RC_PRE(scene.has_value());
        const SceneResult result = verify_scene(*scene, planner_options());
        RC_ASSERT(result.checks.size() == 1u);
        const CheckResult& r = result.checks[0];
        const std::string problem = result_problem(k, r, 200);
        if (!problem.empty()) RC_FAIL(fail_text(k, r, problem));
        RC_TAG(how, stop_label(r));
      },
      200);
}

BOOST_AUTO_TEST_CASE(two_moving_bodies_with_different_breaks_agree_with_independent_sampling) {
  check_cases(
      [] {
        const std::string how = *rc::gen::element<std::string>("slerp", "screw", "nlerp");
        const KeyScene k = pick_scene(how, false, true);
        const auto scene = parse_or_discard(k);
        RC_PRE(scene.has_value());
        const SceneResult result = verify_scene(*scene, planner_options());
        RC_ASSERT(result.checks.size() == 1u);
        const CheckResult& r = result.checks[0];
        const std::string problem = result_problem(k, r, 200);
        if (!problem.empty()) RC_FAIL(fail_text(k, r, problem));
        RC_TAG(how + "/" + k.obstacle_how, stop_label(r));
      },
      100);
}

BOOST_AUTO_TEST_CASE(clearance_and_tolerance_agree_with_independent_sampling) {
  check_cases(
      [] {
        const std::string how = *rc::gen::element<std::string>("slerp", "screw", "nlerp");
        KeyScene k = pick_scene(how, false);
        const Exact amount = *rc::gen::element(Exact(1, 20), Exact(1, 10), Exact(1, 4));
        const bool clearance = uniform(0, 1) == 0;
        (clearance ? k.clearance : k.tolerance) = amount;
        build_json(k);
        const auto scene = parse_or_discard(k);
        RC_PRE(scene.has_value());
        k.weight_sum = 0;
        for (const Exact& w : scene->bodies[1].mass.weights) k.weight_sum += w;
        RC_ASSERT(scene->bodies[1].name == std::string("mover"));
        const SceneResult result = verify_scene(*scene, planner_options());
        const CheckResult& r = result.checks[0];
        const std::string problem = result_problem(k, r, 100);
        if (!problem.empty()) RC_FAIL(fail_text(k, r, problem));
        RC_TAG(clearance ? "clearance" : "tolerance", stop_label(r));
      },
      100);
}

BOOST_AUTO_TEST_CASE(pure_translations_give_the_same_verdict_for_every_interpolation) {
  check_cases(
      [] {
        KeyScene k = pick_scene("slerp", true);
        std::optional<Verdict> first;
        std::string first_json;
        for (const std::string how : {"slerp", "screw", "nlerp"}) {
          k.how = how;
          build_json(k);
          const Scene scene = parse_scene_text(k.json, "property");  // equal rotations: never refused
          const SceneResult result = verify_scene(scene, planner_options());
          const CheckResult& r = result.checks[0];
          const std::string problem = result_problem(k, r, 50);
          if (!problem.empty()) RC_FAIL(fail_text(k, r, problem));
          if (!first) {
            first = r.verdict;
          } else if (*first != r.verdict) {
            RC_FAIL("verdict " + std::string(to_string(r.verdict)) + " with " + how + ", " + to_string(*first) +
                    " with slerp\n" + k.json);
          }
        }
        RC_TAG(to_string(*first));
      },
      50);
}

BOOST_AUTO_TEST_SUITE_END()
