#include "src/verify/verify.h"

#include "kernels/containment.h"
#include "src/io/parse.h"

#include "src/motion/enclosure.h"
#include "src/motion/segment.h"
#include "src/verify/prepared.h"
#include "src/verify/search.h"
#include "src/verify/solid_contact.h"

#include <CGAL/number_utils.h>

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
  }
  return "limit";
}

namespace {

using detail::Check;
using detail::first_hit;

Vec3E apply_map(const Mat34E& m, const Vec3E& x) {
  Vec3E r;
  for (int i = 0; i < 3; ++i) r[i] = m[4 * i] * x[0] + m[4 * i + 1] * x[1] + m[4 * i + 2] * x[2] + m[4 * i + 3];
  return r;
}

std::vector<Vec3E> body_vertices(const Body& b) {
  std::vector<Vec3E> v;
  for (const auto& poly : b.polygons) v.insert(v.end(), poly.begin(), poly.end());
  for (const auto& s : b.segments) v.insert(v.end(), s.begin(), s.end());
  v.insert(v.end(), b.points.begin(), b.points.end());
  return v;
}

}  // namespace

namespace {

// An axis-aligned box of exact points: its lower and upper corners.
using ReachBox = std::array<Vec3E, 2>;

// The maps of a rational curve for its box: its control points (with
// positive weights the curve lies in their convex hull), except for an
// nlerp keyframe segment, whose control points carry the scale of the
// quaternions as written (a unit bar under a quaternion of 1e9 would get a
// box of 1e9): there its exact poses at s = k/8, poses along the motion (a
// tolerance, not a bound: the box of these poses lies inside the swept one).
void add_curve_maps(const Motion& m, std::vector<Mat34E>& maps) {
  if (!m.nlerp) {
    maps.insert(maps.end(), m.control_points.begin(), m.control_points.end());
    return;
  }
  for (int k = 0; k <= 8; ++k) maps.push_back(motion_pose(m, m.t0 + (m.t1 - m.t0) * Exact(k, 8)));
}

// The box of a body's vertices under every control point of its motion
// (nlerp keyframes: poses along them; keyframe and link poses at their
// ends, approximately for enclosed ones: a tolerance, not a bound);
// nullopt for a body without vertices.
std::optional<ReachBox> reach_box(const Body& b) {
  std::vector<Mat34E> maps;
  if (b.motion) add_curve_maps(*b.motion, maps);
  else if (!b.trajectory) maps.push_back({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0});
  if (b.trajectory)
    for (const MotionSegment& seg : b.trajectory->segments) {
      if (seg.rational) {
        add_curve_maps(*seg.rational, maps);
        continue;
      }
      // The keyframe poses (a tolerance, not a bound: the approximate
      // rotation of an rpy pose will do); a link's poses at its waypoints.
      if (seg.link) {
        const std::unique_ptr<SegmentModel> model = make_segment_model(seg);
        for (const Exact s : {Exact(0), Exact(1)}) {
          const PoseInterval m = enclose_pose(*model, s);
          Mat34E approx;
          for (int e = 0; e < 12; ++e) approx[e] = Exact(CGAL::to_double(m[e]));
          maps.push_back(approx);
        }
        continue;
      }
      for (const Pose* pose : {&seg.from, &seg.to}) {
        if (const auto m = exact_pose(*pose)) {
          maps.push_back(*m);
          continue;
        }
        RoundingGuard guard;
        const PoseInterval m = interval_pose(*pose);
        Mat34E approx;
        for (int e = 0; e < 12; ++e) approx[e] = Exact(CGAL::to_double(m[e]));
        maps.push_back(approx);
      }
    }
  std::optional<ReachBox> box;
  for (const Vec3E& v : body_vertices(b))
    for (const Mat34E& m : maps) {
      const Vec3E w = apply_map(m, v);
      if (!box) {
        box = ReachBox{w, w};
        continue;
      }
      for (int i = 0; i < 3; ++i) {
        if (w[i] < (*box)[0][i]) (*box)[0][i] = w[i];
        if (w[i] > (*box)[1][i]) (*box)[1][i] = w[i];
      }
    }
  return box;
}

// 1/1000 of the box's diagonal, as a decimal with six significant digits.
Exact thousandth_of_diagonal(const std::optional<ReachBox>& box) {
  if (!box) return Exact(1, 1000);
  Exact d2 = 0;
  for (int i = 0; i < 3; ++i) d2 += ((*box)[1][i] - (*box)[0][i]) * ((*box)[1][i] - (*box)[0][i]);
  const double eps = std::sqrt(CGAL::to_double(d2)) / 1000;
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
    if (first.rational) return first.rational->control_points[0];
    if (first.link) return make_segment_model(first)->exact_pose(Exact(0));
    return exact_pose(first.from);
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
  if (first.link) return enclose_pose(*make_segment_model(first), Exact(0));
  RoundingGuard guard;
  return interval_pose(first.from);
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

// With an enclosed start pose: every solid body of the pair provably holds
// no connected component of the other at the start, because one vertex of
// each component lies outside the solid's box there (a component with one
// vertex outside and a point inside would cross the surface at the start,
// which the start check of the surfaces sees: proofs/containment.md).
// Finer than start_boxes_disjoint: a robot link's box may overlap a table
// while its one component's vertex is far from the table's box.
bool start_components_outside(const Body& x, const Body& y) {
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
      if (!apart) return false;
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
  if (options.time_limit > 0)
    options.deadline = std::chrono::steady_clock::now() +
                       std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                           std::chrono::duration<double>(options.time_limit));
  // Without a given epsilon, the check's own: from the box of its two
  // bodies (default_epsilon(a, b)), not of the whole scene.
  if (!options.epsilon) options.epsilon = thousandth_of_diagonal(merged(reach_[a], reach_[b]));
  CheckResult result = check_with(a, b, clearance, options);
  result.epsilon = *options.epsilon;
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
    if (!exact_start && !start_boxes_disjoint(x, y) && !start_components_outside(x, y)) {
      CheckResult result;
      result.bodies = {a, b};
      result.clearance = clearance;
      result.verdict = Verdict::Undecided;
      const auto range = mx ? *x.interval() : my ? *y.interval() : std::pair{t0, t0};
      result.undecided.push_back({range.first, range.second, StopReason::Epsilon});
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
  if (general) return check_general(a, b, clearance, options);
  return run_check(a, b, prepared(a), prepared(b), options);
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
  out.time_limit = options.time_limit;

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

  // The scene's epsilon: the given one, or the largest of the checks' own.
  if (options.epsilon) out.epsilon = *options.epsilon;
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