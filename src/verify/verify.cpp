#include "src/verify/verify.h"

#include "kernels/containment.h"
#include "src/io/parse.h"

#include "src/motion/enclosure.h"
#include "src/motion/segment.h"
#include "src/motion/segment_kinds.h"
#include "src/verify/prepared.h"
#include "src/verify/prepared_pair.h"
#include "src/verify/refine.h"
#include "src/verify/search.h"
#include "src/verify/solid_contact.h"
#include "src/verify/true_shape.h"
#include "src/io/primitives.h"

#include <CGAL/number_utils.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <thread>

namespace tmcert {

const char* to_string(Verdict v) {
  switch (v) {
    case Verdict::Safe: return "safe";
    case Verdict::Collision: return "collision";
    case Verdict::Undecided: return "undecided";
  }
  return "undecided";
}

const char* to_string(KernelKind k) {
  switch (k) {
    case KernelKind::Filtered: return "filtered";
    case KernelKind::Exact: return "exact";
    case KernelKind::Fast: return "fast";
  }
  return "filtered";
}

const char* to_string(StopReason r) {
  switch (r) {
    case StopReason::Epsilon: return "epsilon";
    case StopReason::Depth: return "depth";
    case StopReason::Limit: return "limit";
    case StopReason::AfterUndecided: return "after_undecided";
    case StopReason::EnlargedModel: return "enlarged_model";
  }
  return "limit";
}

std::pair<Exact, Exact> parameter_interval(const Body& a, const Body& b) {
  if (a.moves()) return *a.interval();
  if (b.moves()) return *b.interval();
  if (a.interval()) return *a.interval();
  if (b.interval()) return *b.interval();
  return {Exact(0), Exact(1)};
}

namespace {

using detail::Check;
using detail::first_hit;

}  // namespace

namespace {

// An axis-aligned box, outward-rounded: its lower and upper corners.
using ReachBox = std::array<std::array<double, 3>, 2>;

PoseInterval interval_map(const Mat34E& m) {
  PoseInterval out;
  for (int e = 0; e < 12; ++e) out[e] = to_interval(m[e]);
  return out;
}

// The poses of a rational curve for its box: its control points (with
// positive weights the curve lies in their convex hull), except for an
// nlerp keyframe segment, whose control points carry the scale of the
// quaternions as written (a unit bar under a quaternion of 1e9 would get a
// box of 1e9): there its exact poses at its two ends, the keyframes (a
// tolerance, not a bound).
void add_curve_maps(const Motion& m, std::vector<PoseInterval>& maps) {
  if (!m.nlerp) {
    for (const Mat34E& c : m.control_points) maps.push_back(interval_map(c));
    return;
  }
  for (const Exact& t : {m.t0, m.t1}) maps.push_back(interval_map(motion_pose(m, t)));
}

// The box of a body's local bounding box (of its vertices, outward-rounded)
// placed by every pose of its motion, in interval arithmetic: the control
// points of a rational motion, the keyframe poses of keyframe segments
// (never their rational control points), a link's poses at its waypoints
// (enclosed).  It holds every vertex under every one of these poses; the
// poses bound what the body sweeps only for a rational curve (a tolerance,
// not a bound).  nullopt for a body without vertices or an enclosure that
// is not finite.  Cost: one pass over the vertices, then a constant per
// pose (docs/scene-format.md, "Default epsilon").
std::optional<ReachBox> reach_box(const Body& b) {
  std::array<double, 3> lo, hi;
  lo.fill(std::numeric_limits<double>::infinity());
  hi.fill(-std::numeric_limits<double>::infinity());
  bool any = false;
  auto add = [&](const Vec3E& v) {
    any = true;
    for (int i = 0; i < 3; ++i) {
      const Interval x = to_interval(v[i]);
      lo[i] = std::min(lo[i], x.inf());
      hi[i] = std::max(hi[i], x.sup());
    }
  };
  for (const auto& poly : b.polygons) for (const Vec3E& v : poly) add(v);
  for (const auto& s : b.segments) for (const Vec3E& v : s) add(v);
  for (const Vec3E& v : b.points) add(v);
  if (!any) return std::nullopt;

  std::vector<PoseInterval> maps;
  if (b.motion) add_curve_maps(*b.motion, maps);
  else if (!b.trajectory) maps.push_back(interval_map({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0}));
  if (b.trajectory)
    for (const MotionSegment& seg : b.trajectory->segments) {
      const VerifiedSegmentKind& kind = verified_kind_of(seg);
      if (const Motion* rational = kind.rational(seg)) {
        add_curve_maps(*rational, maps);
        continue;
      }
      for (const bool last : {false, true}) maps.push_back(kind.enclosed_end(seg, last));
    }
  RoundingGuard guard;
  const Interval local[3] = {Interval(lo[0], hi[0]), Interval(lo[1], hi[1]), Interval(lo[2], hi[2])};
  std::optional<ReachBox> box;
  for (const PoseInterval& m : maps)
    for (int i = 0; i < 3; ++i) {
      const Interval c = m[4 * i] * local[0] + m[4 * i + 1] * local[1] + m[4 * i + 2] * local[2] + m[4 * i + 3];
      if (!std::isfinite(c.inf()) || !std::isfinite(c.sup())) return std::nullopt;
      if (!box) {
        box.emplace();
        (*box)[0].fill(std::numeric_limits<double>::infinity());
        (*box)[1].fill(-std::numeric_limits<double>::infinity());
      }
      (*box)[0][i] = std::min((*box)[0][i], c.inf());
      (*box)[1][i] = std::max((*box)[1][i], c.sup());
    }
  return box;
}

// 1/1000 of the box's diagonal (its upper bound), as a decimal with six
// significant digits.
Exact thousandth_of_diagonal(const std::optional<ReachBox>& box) {
  if (!box) return Exact(1, 1000);
  double d;
  {
    RoundingGuard guard;
    Interval d2(0);
    for (int i = 0; i < 3; ++i) d2 += CGAL::square(Interval((*box)[1][i]) - Interval((*box)[0][i]));
    d = CGAL::sqrt(d2).sup();
  }
  const double eps = d / 1000;
  if (!(eps > 0) || !std::isfinite(eps)) return Exact(1, 1000);
  char text[64];
  std::snprintf(text, sizeof text, "%.6g", eps);
  Exact out;
  if (!parse_exact(text, out) || !(out > 0)) return Exact(1, 1000);
  return out;
}

std::optional<ReachBox> merged(std::optional<ReachBox> a, const std::optional<ReachBox>& b) {
  if (!a) return b;
  if (b)
    for (int i = 0; i < 3; ++i) {
      if ((*b)[0][i] < (*a)[0][i]) (*a)[0][i] = (*b)[0][i];
      if ((*b)[1][i] > (*a)[1][i]) (*a)[1][i] = (*b)[1][i];
    }
  return a;
}

}  // namespace

Exact default_epsilon(const Scene& scene) {
  std::optional<ReachBox> box;
  for (const Body& b : scene.bodies) box = merged(box, reach_box(b));
  return thousandth_of_diagonal(box);
}

Exact default_epsilon(const Body& a, const Body& b) {
  return thousandth_of_diagonal(merged(reach_box(a), reach_box(b)));
}

void require_supported(const Scene& scene) {
  // The parser checks this; a scene built in code must hold it too, since
  // containment needs a closed surface.
  for (const Body& b : scene.bodies)
    if (b.solid) {
      std::string problem = solid_problem(b);
      if (problem.empty()) problem = shell_intersection_problem(b);
      if (!problem.empty()) throw InputError(scene.source + ": body \"" + b.name + "\": solid: " + problem);
    }
  // Nothing to check would be reported "safe" vacuously: a user who forgot
  // the motion or the checks must hear about it instead.
  if (scene.checks.empty())
    throw InputError(scene.source + ": checks: nothing to check (no body has a motion and no checks are given, "
                     "or the list is empty)");
  for (const auto& [a, b] : scene.checks) {
    const Body& x = scene.bodies[a];
    const Body& y = scene.bodies[b];
    if (x.moves() && y.moves() && *x.interval() != *y.interval())
      throw InputError(scene.source + ": checks: [\"" + x.name + "\", \"" + y.name +
                       "\"]: two moving bodies must share their motion interval");
  }
}

namespace {

CheckResult run_check(int a, int b, const PreparedBody& pa, const PreparedBody& pb,
                      const VerifyOptions& options) {
  const auto started = std::chrono::steady_clock::now();
  CheckResult result;
  result.bodies = {a, b};
  const bool swapped = !pa.moving && pb.moving;
  const PreparedBody& moving = swapped ? pb : pa;
  const PreparedBody& other = swapped ? pa : pb;

  auto finish = [&] {
    for (const FilterCounters& c : result.stats.by_kind) result.stats.contact += c;
    result.stats.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return result;
  };

  if (!moving.moving) {
    // Two motionless bodies: one exact static test decides.
    if (auto hit = first_hit(moving.parts, other.parts, nullptr, result.stats)) {
      const std::string x = moving.body->name + " " + moving.parts[hit->part_moving].name;
      const std::string y = other.body->name + " " + other.parts[hit->part_other].name;
      const Exact t0 = moving.body->motion ? moving.body->motion->t0 : Exact(0);
      result.verdict = Verdict::Collision;
      result.witness = Witness{t0, swapped ? std::array{y, x} : std::array{x, y}, hit->point};
      result.first_contact = std::pair{t0, t0};
    } else {
      result.verdict = Verdict::Safe;
    }
    return finish();
  }

  const Motion& motion = *moving.body->motion;
  const double eps = CGAL::to_double(*options.epsilon);
  if (!other.moving) {
    Check<1> check{moving, other, swapped, moving.curve, enclose(moving.curve), motion, eps * eps, moving.max_rho2, options, result};
    check.run();
  } else {
    const HomogeneousCurve<Exact, 2> joint = joint_curve(motion, *other.body->motion);
    Check<2> check{moving, other, false, joint, enclose(joint), motion, eps * eps, moving.max_rho2 + other.max_rho2, options, result};
    check.run();
  }
  if (result.verdict != Verdict::Collision)
    result.verdict = result.undecided.empty() ? Verdict::Safe : Verdict::Undecided;
  if (result.verdict == Verdict::Safe) result.first_contact.reset();
  return finish();
}

}  // namespace

Verifier::Verifier(const Scene& scene, const VerifyOptions& options)
    : scene_(scene), options_(options), once_(new std::once_flag[scene.bodies.size()]),
      prepared_(scene.bodies.size()), surface_once_(new std::once_flag[scene.bodies.size()]),
      surfaces_(scene.bodies.size()) {
  boxes_.reserve(scene.bodies.size());
  interval_.reserve(scene.bodies.size());
  std::map<std::pair<Exact, Exact>, int> intervals;
  for (const Body& b : scene.bodies) {
    boxes_.push_back(swept_box(b));
    if (!options.epsilon) reach_.push_back(reach_box(b));
    if (b.moves())
      interval_.push_back(intervals.emplace(*b.interval(), static_cast<int>(intervals.size())).first->second);
    else
      interval_.push_back(-1);
  }
}

Verifier::~Verifier() = default;

const PreparedBody& Verifier::prepared(int body) const {
  std::call_once(once_[body], [&] {
    const Body& b = scene_.bodies[body];
    if (options_.run)
      options_.run->set_step("preparing body " + b.name + " (" + std::to_string(b.polygons.size()) + " polygons, " +
                             std::to_string(b.segments.size() + b.points.size()) + " segments and points: features, " +
                             "metric, bounding-volume hierarchy)");
    prepared_[body] = std::make_unique<PreparedBody>(b);
    if (options_.run) options_.run->set_step("");
  });
  return *prepared_[body];
}

namespace {

// The pose at the start of the motion, exactly; nullopt when it is only
// enclosed (a keyframe with an rpy rotation).
std::optional<Mat34E> start_pose(const Body& b) {
  if (b.motion) return b.motion->control_points[0];  // the curve's value at its start
  if (b.trajectory) {
    const MotionSegment& first = b.trajectory->segments.front();
    return kind_of(first).exact_end(first, false);
  }
  return Mat34E{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
}

// The start pose enclosed (exact poses as point intervals).
PoseInterval start_pose_enclosed(const Body& b) {
  if (const auto m = start_pose(b)) {
    PoseInterval out;
    for (int e = 0; e < 12; ++e) out[e] = to_interval((*m)[e]);
    return out;
  }
  const MotionSegment& first = b.trajectory->segments.front();
  return verified_kind_of(first).enclosed_end(first, false);
}

// The boxes of the two bodies at their start poses (enclosures of every
// vertex image) are disjoint: neither body holds a point of the other there.
bool start_boxes_disjoint(const Body& x, const Body& y) {
  std::array<std::array<double, 3>, 2> lo, hi;
  int k = 0;
  for (const Body* b : {&x, &y}) {
    const PoseInterval m = start_pose_enclosed(*b);
    lo[k].fill(std::numeric_limits<double>::infinity());
    hi[k].fill(-std::numeric_limits<double>::infinity());
    RoundingGuard guard;
    auto add = [&](const Vec3E& v) {
      const Interval p[3] = {to_interval(v[0]), to_interval(v[1]), to_interval(v[2])};
      for (int i = 0; i < 3; ++i) {
        const Interval c = m[4 * i] * p[0] + m[4 * i + 1] * p[1] + m[4 * i + 2] * p[2] + m[4 * i + 3];
        lo[k][i] = std::min(lo[k][i], c.inf());
        hi[k][i] = std::max(hi[k][i], c.sup());
      }
    };
    for (const auto& poly : b->polygons) for (const Vec3E& v : poly) add(v);
    for (const auto& seg : b->segments) for (const Vec3E& v : seg) add(v);
    for (const Vec3E& v : b->points) add(v);
    ++k;
  }
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(lo[0][i]) || !std::isfinite(hi[0][i]) || !std::isfinite(lo[1][i]) || !std::isfinite(hi[1][i]))
      return false;
    if (hi[0][i] < lo[1][i] || hi[1][i] < lo[0][i]) return true;
  }
  return false;
}

// The box of the given points placed by an enclosed pose; false when not finite.
bool placed_box(const std::vector<Vec3E>& points, const PoseInterval& m, std::array<double, 3>& lo,
                std::array<double, 3>& hi) {
  lo.fill(std::numeric_limits<double>::infinity());
  hi.fill(-std::numeric_limits<double>::infinity());
  RoundingGuard guard;
  for (const Vec3E& v : points) {
    const Interval p[3] = {to_interval(v[0]), to_interval(v[1]), to_interval(v[2])};
    for (int i = 0; i < 3; ++i) {
      const Interval c = m[4 * i] * p[0] + m[4 * i + 1] * p[1] + m[4 * i + 2] * p[2] + m[4 * i + 3];
      lo[i] = std::min(lo[i], c.inf());
      hi[i] = std::max(hi[i], c.sup());
    }
  }
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(lo[i]) || !std::isfinite(hi[i])) return false;
  return true;
}

// A URDF cylinder's or sphere's polyhedron (Body::primitive, convex, about
// the z axis of its frame: every vertex within `radial` of the axis, or of
// the centre for a sphere, a cylinder's caps at z = +-length/2) placed by
// the enclosed rigid pose m holds no point of the box of p placed by pm:
// in the primitive's frame, R^T (box - c) (the true R, c of a rigid pose lie
// in m) is farther from the axis (centre) than every vertex, or beyond a
// cap.  Interval arithmetic, outward rounded.
bool outside_primitive_polyhedron(const Body& primitive, const PoseInterval& m, const Vec3E& p, const PoseInterval& pm) {
  const Body::Primitive& prim = *primitive.primitive;
  const bool sphere = prim.kind == Body::Primitive::Kind::Sphere;
  Exact reach2 = 0;  // the largest squared distance of a vertex from the axis (centre)
  for (const auto& poly : primitive.polygons)
    for (const Vec3E& v : poly) reach2 = std::max(reach2, v[0] * v[0] + v[1] * v[1] + (sphere ? v[2] * v[2] : Exact(0)));
  RoundingGuard guard;
  const Interval q[3] = {to_interval(p[0]), to_interval(p[1]), to_interval(p[2])};
  std::array<Interval, 3> w, x;
  for (int i = 0; i < 3; ++i) w[i] = pm[4 * i] * q[0] + pm[4 * i + 1] * q[1] + pm[4 * i + 2] * q[2] + pm[4 * i + 3];
  for (int j = 0; j < 3; ++j) x[j] = m[j] * (w[0] - m[3]) + m[4 + j] * (w[1] - m[7]) + m[8 + j] * (w[2] - m[11]);
  const Interval d2 = CGAL::square(x[0]) + CGAL::square(x[1]) + (sphere ? CGAL::square(x[2]) : Interval(0));
  if (!std::isfinite(d2.inf())) return false;
  if (d2.inf() > to_interval(reach2).sup()) return true;
  if (sphere) return false;
  const Interval h = to_interval(prim.length) / Interval(2);
  return x[2].inf() > h.sup() || x[2].sup() < -h.sup();
}

// With an enclosed start pose: every solid body of the pair provably holds
// no connected component of the other at the start, because one vertex of
// each component lies outside the solid's box there (a component with one
// vertex outside and a point inside would cross the surface at the start,
// which the start check of the surfaces sees: proofs/containment.md).
// Finer than start_boxes_disjoint: a robot link's box may overlap a table
// while its one component's vertex is far from the table's box.
// `primitive_in_doubt` (when given) is set when it is a URDF cylinder's or
// sphere's polyhedron that may hold a component (a finer one may not).
bool start_components_outside(const Body& x, const Body& y, bool* primitive_in_doubt = nullptr) {
  const Body* pair[2] = {&x, &y};
  for (int s = 0; s < 2; ++s) {
    const Body& solid = *pair[s];
    const Body& other = *pair[1 - s];
    if (!solid.solid) continue;
    std::vector<Vec3E> vertices;
    for (const auto& poly : solid.polygons) vertices.insert(vertices.end(), poly.begin(), poly.end());
    std::array<double, 3> lo, hi;
    if (!placed_box(vertices, start_pose_enclosed(solid), lo, hi)) return false;
    const Mat34E identity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
    const PoseInterval po = start_pose_enclosed(other);
    for (const auto& rep : component_representatives(other, identity)) {
      std::array<double, 3> rlo, rhi;
      if (!placed_box({rep.second}, po, rlo, rhi)) return false;
      bool apart = false;
      for (int i = 0; i < 3; ++i) apart = apart || rhi[i] < lo[i] || hi[i] < rlo[i];
      if (!apart && solid.primitive) apart = outside_primitive_polyhedron(solid, start_pose_enclosed(solid), rep.second, po);
      if (!apart) {
        if (primitive_in_doubt) *primitive_in_doubt = solid.primitive.has_value();
        return false;
      }
    }
  }
  return true;
}

}  // namespace

CheckResult Verifier::check(int a, int b) const { return check(a, b, Exact(0)); }

CheckResult Verifier::check(int a, int b, const Exact& clearance) const {
  // The joint curve pairs the motions by curve parameter: that is the same
  // instant only when the scene intervals agree.
  if (interval_[a] >= 0 && interval_[b] >= 0 && interval_[a] != interval_[b])
    throw InputError(scene_.source + ": checks: [\"" + scene_.bodies[a].name + "\", \"" + scene_.bodies[b].name +
                     "\"]: two moving bodies must share their motion interval");
  // The time limit counts from here, per check.
  VerifyOptions options = options_;
  // The check's share of the run's progress (src/verify/progress.h).
  std::optional<RunProgress::Slot> slot;
  if (options.run && options.run->checks_are_items()) {
    slot.emplace(*options.run);
    options.slot = &*slot;
    options.slot_span = RunProgress::kUnit;
    options.run->set_activity("checking " + scene_.bodies[a].name + " x " + scene_.bodies[b].name);
  }
  // With refinement and no time limit given, 30 s (check_time_limit): the
  // first search and the refinement share it.
  options.deadline = detail::check_deadline(options, std::chrono::steady_clock::now());
  // Without a given epsilon, the check's own: from the box of its two
  // bodies (default_epsilon(a, b)), not of the whole scene.
  if (!options.epsilon) options.epsilon = thousandth_of_diagonal(merged(reach_[a], reach_[b]));
  CheckResult result = check_with(a, b, clearance, options);
  const Body& x = scene_.bodies[a];
  const Body& y = scene_.bodies[b];
  if (enlarged_pair(x, y)) {
    // A URDF cylinder or sphere: a collision only with a contact proven on
    // the true shapes; parts left undecided because the polyhedra touch are
    // searched again with finer polyhedra (src/io/primitives.h), up to
    // the finest, on the same deadline (a certificate records the levels,
    // CheckResult::levels).  proofs/robot-links.md section 6.
    const Exact t_end = x.moves() ? x.interval()->second : y.moves() ? y.interval()->second
                        : x.interval() ? x.interval()->second : y.interval() ? y.interval()->second : Exact(0);
    settle_enlarged(result, prepared(a), prepared(b), t_end);
    auto enlarged_parts = [](const CheckResult& r) {
      return std::any_of(r.undecided.begin(), r.undecided.end(),
                         [](const UndecidedInterval& u) { return u.reason == StopReason::EnlargedModel; });
    };
    Scene finer;
    finer.source = scene_.source;
    finer.bodies = {x, y};
    finer.checks = {{0, 1}};
    CheckStats spent = result.stats;
    while (result.verdict != Verdict::Collision && enlarged_parts(result) &&
           !past_deadline(options)) {
      const bool ra = refine_primitive(finer.bodies[0]), rb = refine_primitive(finer.bodies[1]);
      if (!ra && !rb) break;
      const Verifier again(finer, options);
      CheckResult r = again.check_with(0, 1, clearance, options);
      settle_enlarged(r, again.prepared(0), again.prepared(1), t_end);
      r.bodies = {a, b};
      for (int k = 0; k < 2; ++k)
        r.levels[k] = finer.bodies[k].primitive ? finer.bodies[k].primitive->level : 0;
      r.stats.nodes += spent.nodes;
      r.stats.stops += spent.stops;
      r.stats.static_tests += spent.static_tests;
      r.stats.seconds += spent.seconds;
      spent = r.stats;
      result = std::move(r);
    }
  }
  if (!result.refined) result.epsilon = *options.epsilon;
  result.interval = parameter_interval(scene_.bodies[a], scene_.bodies[b]);
  return result;
}

CheckResult Verifier::check_with(int a, int b, const Exact& clearance, const VerifyOptions& options) const {
  const Body& x = scene_.bodies[a];
  const Body& y = scene_.bodies[b];
  const bool general = x.trajectory || y.trajectory || x.tolerance > 0 || y.tolerance > 0 || clearance > 0;
  // The boxes hold everything the bodies sweep (keyframe motions included);
  // tolerances have none, and a clearance needs more than disjointness.
  if (clearance == 0 && disjoint(boxes_[a], boxes_[b])) {
    // Certified prefilter: the boxes hold everything the bodies sweep.
    CheckResult result;
    result.bodies = {a, b};
    result.verdict = Verdict::Safe;
    result.stats.prefiltered = true;
    result.clearance = clearance;
    return result;
  }
  const bool mx = interval_[a] >= 0, my = interval_[b] >= 0;
  // A solid's inside counts as contact: at the start parameter, a vertex of
  // each connected component of one body inside the other (solid) body is a
  // collision there.  Later contacts go through the surfaces
  // (proofs/containment.md).
  for (const Body* body : {&x, &y})
    if (body->solid)
      if (const std::string problem = solid_problem(*body); !problem.empty())
        throw InputError(scene_.source + ": body \"" + body->name + "\": solid: " + problem);
  if (x.solid || y.solid) {
    const Exact t0 = mx ? x.interval()->first : my ? y.interval()->first : x.motion ? x.motion->t0 : y.motion ? y.motion->t0 : Exact(0);
    // The start containment needs both start poses exactly; with an
    // enclosed (rpy) start pose it is settled only when the bodies' boxes
    // at the start are disjoint (then neither holds a point of the other),
    // else it is left open, and with it the whole check.
    const bool exact_start = start_pose(x) && start_pose(y);
    bool primitive_in_doubt = false;
    if (!exact_start && !start_boxes_disjoint(x, y) && !start_components_outside(x, y, &primitive_in_doubt)) {
      CheckResult result;
      result.bodies = {a, b};
      result.clearance = clearance;
      if (enlarged_pair(x, y)) {  // a contact of the true shapes at the start decides it
        const std::optional<TrueContact> c =
            true_contact(side_at(prepared(a), t0), side_at(prepared(b), t0), result.stats);
        if (c) {
          result.verdict = Verdict::Collision;
          result.witness = witness_of(t0, *c);
          result.first_contact = std::pair{t0, t0};
          return result;
        }
      }
      result.verdict = Verdict::Undecided;
      const auto range = mx ? *x.interval() : my ? *y.interval() : std::pair{t0, t0};
      // A component maybe inside a primitive's polyhedron: finer
      // polyhedra may settle it (Verifier::check).
      result.undecided.push_back(
          {range.first, range.second, primitive_in_doubt ? StopReason::EnlargedModel : StopReason::Epsilon});
      result.first_contact = range;
      return result;
    }
    for (int side = 0; side < 2 && exact_start; ++side) {
      const int solid = side == 0 ? a : b, other = side == 0 ? b : a;
      if (!scene_.bodies[solid].solid) continue;
      const ClosedSurface* surface = start_surface(solid);
      if (!surface) continue;  // singular pose: the solid is its surface there
      for (const auto& [part, point] : start_representatives(scene_.bodies[other])) {
        if (!surface->contains(point)) continue;
        CheckResult result;
        result.bodies = {a, b};
        result.verdict = Verdict::Collision;
        const std::string inside = scene_.bodies[solid].name + " interior";
        const std::string at = scene_.bodies[other].name + " " + part;
        result.witness = Witness{t0, side == 0 ? std::array{inside, at} : std::array{at, inside}, point};
        result.first_contact = std::pair{t0, t0};
        result.clearance = clearance;
        return result;
      }
    }
  }
  const auto started = std::chrono::steady_clock::now();
  CheckResult result = general ? check_general(a, b, clearance, options)
                               : run_check(a, b, prepared(a), prepared(b), options);
  // Refinement (src/verify/refine.h): the undecided parts searched again,
  // each as a part of the check's interval (after the start containment
  // above, which the whole check shares).
  if (options.refine && result.verdict == Verdict::Undecided && (mx || my)) {
    const Body& mover = mx ? x : y;
    const auto interval = *mover.interval();
    detail::refine_check(result, interval.first, interval.second, !general, options, started,
                         [&](const Exact& t0, const Exact& t1, bool start_free, const VerifyOptions& o) {
                           return detail::check_prepared_pair(prepared(a), prepared(b), {a, b}, clearance, o,
                                                              start_free, std::pair{t0, t1});
                         });
  }
  return result;
}


const ClosedSurface* Verifier::start_surface(int body) const {
  std::call_once(surface_once_[body], [&] { surfaces_[body] = placed_surface(scene_.bodies[body], *start_pose(scene_.bodies[body])); });
  return surfaces_[body].get();
}

std::vector<std::pair<std::string, Vec3E>> Verifier::start_representatives(const Body& b) const {
  return component_representatives(b, *start_pose(b));
}

CheckResult verify_check(const Scene& scene, int body_a, int body_b, const VerifyOptions& options) {
  return Verifier(scene, options).check(body_a, body_b);
}

SceneResult verify_scene(const Scene& scene, const VerifyOptions& options, int threads) {
  require_supported(scene);
  SceneResult out;
  out.kernel = options.kernel;
  out.certified = options.kernel != KernelKind::Fast;
  out.epsilon_per_check = !options.epsilon;
  out.max_depth = options.max_depth;
  out.max_nodes = options.max_nodes;
  out.max_stops = options.max_stops;
  out.time_limit = detail::check_time_limit(options);

  // Threads go to the checks first; when there are fewer checks than
  // threads, each check spreads its pieces over the rest.  Progress: a lone
  // check reports its pieces, several checks report as each finishes.
  const std::size_t checks = scene.checks.size();
  VerifyOptions per_check = options;
  per_check.threads = std::max(options.threads, static_cast<int>(threads / std::max<std::size_t>(1, checks)));
  if (options.run) {
    options.run->set_checks(checks);
    options.run->set_activity("bounding what the bodies sweep");
  }
  const Verifier verifier(scene, per_check);
  out.checks.resize(scene.checks.size());
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  auto worker = [&] {
    try {
      for (std::size_t k = next++; k < scene.checks.size(); k = next++) {
        if (options.run && options.run->cancelled()) break;  // no result: see below
        const auto [a, b] = scene.checks[k];
        out.checks[k] = verifier.check(a, b, scene.clearance_of(k));
      }
    } catch (...) {  // reported by the caller; never a verdict
      std::lock_guard<std::mutex> lock(failure_mutex);
      if (!failure) failure = std::current_exception();
      next = scene.checks.size();
    }
  };
  const int n = std::max(1, std::min<int>(threads, static_cast<int>(scene.checks.size())));
  std::vector<std::thread> pool;
  for (int i = 1; i < n; ++i) pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
  // A cancelled run has checks cut short or not run: no result at all.
  if (options.run && options.run->cancelled()) throw Cancelled();

  // The scene's epsilon: the given one, or (per check, or refined) the
  // largest of the checks' own.
  out.refine = options.refine;
  if (options.epsilon && !options.refine) out.epsilon = *options.epsilon;
  else
    for (const CheckResult& c : out.checks)
      if (c.epsilon > out.epsilon) out.epsilon = c.epsilon;
  out.verdict = Verdict::Safe;
  for (const CheckResult& c : out.checks) {
    if (c.verdict == Verdict::Collision) out.verdict = Verdict::Collision;
    else if (c.verdict == Verdict::Undecided && out.verdict == Verdict::Safe) out.verdict = Verdict::Undecided;
  }
  return out;
}

}  // namespace tmcert