#include "src/verify/verify.h"

#include "kernels/containment.h"
#include "src/scene/parse.h"

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

Exact default_epsilon(const Scene& scene) {
  std::optional<Vec3E> lo, hi;
  for (const Body& b : scene.bodies) {
    std::vector<Mat34E> maps;
    if (b.motion) maps = b.motion->control_points;
    else maps.push_back({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0});
    for (const Vec3E& v : body_vertices(b))
      for (const Mat34E& m : maps) {
        const Vec3E w = apply_map(m, v);
        if (!lo) { lo = w; hi = w; continue; }
        for (int i = 0; i < 3; ++i) {
          if (w[i] < (*lo)[i]) (*lo)[i] = w[i];
          if (w[i] > (*hi)[i]) (*hi)[i] = w[i];
        }
      }
  }
  if (!lo) return Exact(1, 1000);
  Exact d2 = 0;
  for (int i = 0; i < 3; ++i) d2 += ((*hi)[i] - (*lo)[i]) * ((*hi)[i] - (*lo)[i]);
  const double eps = std::sqrt(CGAL::to_double(d2)) / 1000;
  if (!(eps > 0) || !std::isfinite(eps)) return Exact(1, 1000);
  char text[64];
  std::snprintf(text, sizeof text, "%.6g", eps);
  Exact out;
  if (!parse_exact(text, out) || !(out > 0)) return Exact(1, 1000);
  return out;
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
    const bool mx = x.motion && x.motion->degree() >= 1, my = y.motion && y.motion->degree() >= 1;
    if (mx && my && (x.motion->t0 != y.motion->t0 || x.motion->t1 != y.motion->t1))
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
  const double eps = CGAL::to_double(options.epsilon);
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
    if (b.motion && b.motion->degree() >= 1)
      interval_.push_back(intervals.emplace(std::pair{b.motion->t0, b.motion->t1}, static_cast<int>(intervals.size())).first->second);
    else
      interval_.push_back(-1);
  }
}

Verifier::~Verifier() = default;

const PreparedBody& Verifier::prepared(int body) const {
  std::call_once(once_[body], [&] { prepared_[body] = std::make_unique<PreparedBody>(scene_.bodies[body]); });
  return *prepared_[body];
}

CheckResult Verifier::check(int a, int b) const {
  // The joint curve pairs the motions by curve parameter: that is the same
  // instant only when the scene intervals agree.
  if (interval_[a] >= 0 && interval_[b] >= 0 && interval_[a] != interval_[b])
    throw InputError(scene_.source + ": checks: [\"" + scene_.bodies[a].name + "\", \"" + scene_.bodies[b].name +
                     "\"]: two moving bodies must share their motion interval");
  if (disjoint(boxes_[a], boxes_[b])) {
    // Certified prefilter: the boxes hold everything the bodies sweep.
    CheckResult result;
    result.bodies = {a, b};
    result.verdict = Verdict::Safe;
    result.stats.prefiltered = true;
    return result;
  }
  const Body& x = scene_.bodies[a];
  const Body& y = scene_.bodies[b];
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
    const Exact t0 = mx ? x.motion->t0 : my ? y.motion->t0 : x.motion ? x.motion->t0 : y.motion ? y.motion->t0 : Exact(0);
    for (int side = 0; side < 2; ++side) {
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
        return result;
      }
    }
  }
  return run_check(a, b, prepared(a), prepared(b), options_);
}

namespace {

Mat34E start_pose(const Body& b) {
  if (b.motion) return b.motion->control_points[0];  // the curve's value at its start
  return {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
}

}  // namespace

const ClosedSurface* Verifier::start_surface(int body) const {
  std::call_once(surface_once_[body], [&] { surfaces_[body] = placed_surface(scene_.bodies[body], start_pose(scene_.bodies[body])); });
  return surfaces_[body].get();
}

std::vector<std::pair<std::string, Vec3E>> Verifier::start_representatives(const Body& b) const {
  return component_representatives(b, start_pose(b));
}

CheckResult verify_check(const Scene& scene, int body_a, int body_b, const VerifyOptions& options) {
  return Verifier(scene, options).check(body_a, body_b);
}

SceneResult verify_scene(const Scene& scene, const VerifyOptions& options, int threads) {
  require_supported(scene);
  SceneResult out;
  out.kernel = options.kernel;
  out.certified = options.kernel != KernelKind::Fast;
  out.epsilon = options.epsilon;

  // Threads go to the checks first; when there are fewer checks than
  // threads, each check spreads its pieces over the rest.  Progress: a lone
  // check reports its pieces, several checks report as each finishes.
  const std::size_t checks = scene.checks.size();
  VerifyOptions per_check = options;
  per_check.threads = std::max(options.threads, static_cast<int>(threads / std::max<std::size_t>(1, checks)));
  if (checks != 1) per_check.progress = nullptr;
  std::atomic<std::size_t> finished{0};
  std::mutex progress_mutex;
  const Verifier verifier(scene, per_check);
  out.checks.resize(scene.checks.size());
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  auto worker = [&] {
    try {
      for (std::size_t k = next++; k < scene.checks.size(); k = next++) {
        const auto [a, b] = scene.checks[k];
        out.checks[k] = verifier.check(a, b);
        const std::size_t f = ++finished;
        if (options.progress && checks > 1) {
          std::lock_guard<std::mutex> lock(progress_mutex);
          options.progress(static_cast<double>(f) / checks);
        }
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

  out.verdict = Verdict::Safe;
  for (const CheckResult& c : out.checks) {
    if (c.verdict == Verdict::Collision) out.verdict = Verdict::Collision;
    else if (c.verdict == Verdict::Undecided && out.verdict == Verdict::Safe) out.verdict = Verdict::Undecided;
  }
  return out;
}

}  // namespace tmcert