// A planner's path, certified (issue 12, item 8).
//
// The gripper example (examples/gripper/: 438 triangles) moved through its
// fixture (5294 triangles) along a 20-keyframe SE(3) path
// (examples/gripper/generate_path.py), in a safe and a colliding variant:
//
//  - tmcert certifies the path as slerp, screw and nlerp between the same
//    keyframes (parse once; each timed run builds a fresh Verifier, so it
//    includes preparing both bodies, and runs the one check; filtered
//    kernel, one thread, the scene's epsilon);
//  - against what planners do today: FCL (the checker MoveIt uses; OBBRSS
//    BVH models of both meshes, built once, outside the timing) testing the
//    discrete poses OMPL's DiscreteMotionValidator tests along the same
//    slerp path at OMPL's default resolution.  OMPL (ompl/base/src/
//    StateSpace.cpp, SO3StateSpace.cpp, DiscreteMotionValidator.cpp):
//      * SE3StateSpace = R^3 (weight 1) x SO(3) (weight 1); longest valid
//        segment of each component = 0.01 (longestValidSegmentFraction) x
//        its maximum extent: R^3: the diagonal of the translation bounds;
//        SO(3): pi/2 (its distance is acos|q1.q2|, half the rotation angle);
//      * CompoundStateSpace::validSegmentCount(s1, s2) = the largest of the
//        components' ceil(distance / longest valid segment) (count factor 1);
//      * checkMotion(s1, s2): s2 first, then the states j/n, j = 1..n-1, in
//        bisection order, each a discrete collision check; the start state
//        of the path is checked once.  Interpolation: translation linear,
//        rotation slerp on the shorter arc (what the slerp scene certifies).
//    The translation bounds are the box of the fixture and the keyframes'
//    translations (OMPL's states must lie inside its bounds; the path starts
//    outside the fixture's box).  A colliding path is checked until the
//    first pose in collision, as a planner does; the run also reports
//    whether any OMPL pose collides at all, and how a 100x finer sampling
//    (FCL again) fares.
//
// Timed runs alternate between the four methods (slerp, screw, nlerp,
// FCL-discrete); each time is the median of --reps runs (default 5).
//
// Usage: tmcert_planner_bench [--reps N] [--root DIR] [--only safe|collision]
//        [--distance]
// --root is the source tree (examples/gripper/); by default the one this
// program was built from.  --distance prints, per segment of each variant,
// FCL's smallest distance over 200 slerp samples (floating point, a design
// aid, not a proof).
// Exit status: 0 when every certified verdict is the expected one (safe
// variant safe, colliding variant collision), 1 otherwise, 3 on bad usage.
#include "src/io/parse.h"
#include "src/verify/verify.h"

#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/collision_object.h>
#include <fcl/narrowphase/distance.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <queue>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#ifndef TMCERT_SOURCE_DIR
#define TMCERT_SOURCE_DIR "."
#endif

using namespace tmcert;

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    std::fprintf(stderr, "cannot read %s\n", path.c_str());
    std::exit(3);
  }
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// ------------------------------------------------------------------ meshes for FCL

struct Mesh {
  std::vector<fcl::Vector3d> verts;
  std::vector<fcl::Triangle> tris;
};

// OFF with triangles only (the gripper example's files); decimal
// coordinates, converted by strtod (correctly rounded).
Mesh read_off(const std::string& path) {
  std::istringstream in(read_text(path));
  std::string magic;
  in >> magic;
  std::size_t nv = 0, nf = 0, ne = 0;
  in >> nv >> nf >> ne;
  if (magic != "OFF" || !in) {
    std::fprintf(stderr, "%s: not an OFF file\n", path.c_str());
    std::exit(3);
  }
  Mesh m;
  for (std::size_t i = 0; i < nv; ++i) {
    std::string x, y, z;
    in >> x >> y >> z;
    m.verts.emplace_back(std::strtod(x.c_str(), nullptr), std::strtod(y.c_str(), nullptr),
                         std::strtod(z.c_str(), nullptr));
  }
  for (std::size_t i = 0; i < nf; ++i) {
    std::size_t k = 0, a = 0, b = 0, c = 0;
    in >> k >> a >> b >> c;
    if (k != 3 || !in) {
      std::fprintf(stderr, "%s: face %zu is not a triangle\n", path.c_str(), i);
      std::exit(3);
    }
    m.tris.emplace_back(a, b, c);
  }
  return m;
}

using Model = fcl::BVHModel<fcl::OBBRSSd>;

std::shared_ptr<Model> build_model(const Mesh& m) {
  auto model = std::make_shared<Model>();
  model->beginModel(static_cast<int>(m.tris.size()), static_cast<int>(m.verts.size()));
  model->addSubModel(m.verts, m.tris);
  model->endModel();
  return model;
}

// ------------------------------------------------------------------ the path (double)

struct SE3Pose {
  fcl::Vector3d t;
  Eigen::Quaterniond q;  // unit
};

std::vector<SE3Pose> read_keyframes(const std::string& scene_path) {
  const nlohmann::json doc = nlohmann::json::parse(read_text(scene_path));
  std::vector<SE3Pose> out;
  for (const auto& body : doc.at("bodies")) {
    if (!body.contains("motion")) continue;
    for (const auto& p : body.at("motion").at("poses")) {
      SE3Pose pose;
      for (int k = 0; k < 3; ++k) pose.t[k] = p.at("translation").at(k).get<double>();
      const auto& q = p.at("rotation").at("quaternion");
      pose.q = Eigen::Quaterniond(q.at(0).get<double>(), q.at(1).get<double>(), q.at(2).get<double>(),
                                  q.at(3).get<double>());
      pose.q.normalize();
      out.push_back(pose);
    }
  }
  return out;
}

// OMPL's SO3StateSpace: distance acos|q1.q2| (0 within 1e-9 of 1) and slerp
// on the shorter arc.
constexpr double kMaxQuaternionNormError = 1e-9;

double so3_distance(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) {
  const double dq = std::fabs(a.dot(b));
  return dq > 1.0 - kMaxQuaternionNormError ? 0.0 : std::acos(dq);
}

SE3Pose ompl_interpolate(const SE3Pose& a, const SE3Pose& b, double s) {
  SE3Pose out;
  out.t = a.t + s * (b.t - a.t);
  const double theta = so3_distance(a.q, b.q);
  if (theta > std::numeric_limits<double>::epsilon()) {
    const double d = 1.0 / std::sin(theta);
    const double s0 = std::sin((1.0 - s) * theta);
    double s1 = std::sin(s * theta);
    if (a.q.dot(b.q) < 0) s1 = -s1;
    out.q = Eigen::Quaterniond(s0 * d * a.q.w() + s1 * d * b.q.w(), s0 * d * a.q.x() + s1 * d * b.q.x(),
                               s0 * d * a.q.y() + s1 * d * b.q.y(), s0 * d * a.q.z() + s1 * d * b.q.z());
  } else {
    out.q = a.q;
  }
  return out;
}

struct Discretisation {
  double r3_extent = 0, so3_extent = 0.5 * M_PI, fraction = 0.01;
  std::vector<int> counts;  // per edge: OMPL's validSegmentCount
  int compound_formula_poses = 0;  // sum of ceil(d / (0.01 (r3 + so3 extents))) + 1, for comparison
  int poses = 0;                   // 1 + sum of counts
};

// `fixture_only`: the fixture's box as the translation bounds (the path
// leaves it, which OMPL would not allow; for comparison only).
Discretisation discretise(const std::vector<SE3Pose>& path, const Mesh& fixture, bool fixture_only = false) {
  Discretisation d;
  fcl::Vector3d lo = fixture.verts[0], hi = fixture.verts[0];
  for (const auto& v : fixture.verts) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  if (!fixture_only)
    for (const auto& p : path) lo = lo.cwiseMin(p.t), hi = hi.cwiseMax(p.t);
  d.r3_extent = (hi - lo).norm();
  const double seg_r3 = d.fraction * d.r3_extent, seg_so3 = d.fraction * d.so3_extent;
  const double seg_se3 = d.fraction * (d.r3_extent + d.so3_extent);
  d.poses = 1;
  d.compound_formula_poses = 1;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    const double dt = (path[i + 1].t - path[i].t).norm();
    const double dr = so3_distance(path[i].q, path[i + 1].q);
    const int n = std::max(static_cast<int>(std::ceil(dt / seg_r3)), static_cast<int>(std::ceil(dr / seg_so3)));
    d.counts.push_back(n);
    d.poses += n;
    d.compound_formula_poses += static_cast<int>(std::ceil((dt + dr) / seg_se3));
  }
  return d;
}

struct FclRun {
  bool collision = false;
  int checked = 0;
  int edge = -1;      // the edge of the first pose in collision
  double s = 0;       // its parameter in the edge
};

struct FclScene {
  std::shared_ptr<Model> gripper, fixture;
  std::unique_ptr<fcl::CollisionObjectd> g, f;
  FclScene(const Mesh& gm, const Mesh& fm) : gripper(build_model(gm)), fixture(build_model(fm)) {
    g = std::make_unique<fcl::CollisionObjectd>(gripper, fcl::Transform3d::Identity());
    f = std::make_unique<fcl::CollisionObjectd>(fixture, fcl::Transform3d::Identity());
  }
  bool collides(const SE3Pose& p) {
    fcl::Transform3d tf = fcl::Transform3d::Identity();
    tf.linear() = p.q.toRotationMatrix();
    tf.translation() = p.t;
    g->setTransform(tf);
    g->computeAABB();
    fcl::CollisionRequestd request;  // one contact, no contact data: a yes/no query
    fcl::CollisionResultd result;
    fcl::collide(g.get(), f.get(), request, result);
    return result.isCollision();
  }
  double distance(const SE3Pose& p) {
    fcl::Transform3d tf = fcl::Transform3d::Identity();
    tf.linear() = p.q.toRotationMatrix();
    tf.translation() = p.t;
    g->setTransform(tf);
    g->computeAABB();
    fcl::DistanceRequestd request;
    fcl::DistanceResultd result;
    fcl::distance(g.get(), f.get(), request, result);
    return result.min_distance;
  }
};

// OMPL's DiscreteMotionValidator::checkMotion along the path, edge by edge;
// stops at the first pose in collision unless `all`.
FclRun fcl_discrete(FclScene& fcl, const std::vector<SE3Pose>& path, const Discretisation& d, bool all) {
  FclRun run;
  auto hit = [&](int edge, double s) {
    ++run.checked;
    const SE3Pose p = s == 0 ? path[edge] : s == 1 ? path[edge + 1] : ompl_interpolate(path[edge], path[edge + 1], s);
    if (!fcl.collides(p)) return false;
    if (!run.collision) run.edge = edge, run.s = s;
    run.collision = true;
    return !all;
  };
  if (hit(0, 0)) return run;  // the start state
  for (std::size_t e = 0; e + 1 < path.size(); ++e) {
    const int nd = d.counts[e];
    if (hit(static_cast<int>(e), 1)) return run;
    if (nd < 2) continue;
    std::queue<std::pair<int, int>> pos;
    pos.emplace(1, nd - 1);
    while (!pos.empty()) {
      const auto [a, b] = pos.front();
      pos.pop();
      const int mid = (a + b) / 2;
      if (hit(static_cast<int>(e), static_cast<double>(mid) / nd)) return run;
      if (a < mid) pos.emplace(a, mid - 1);
      if (b > mid) pos.emplace(mid + 1, b);
    }
  }
  return run;
}

// ------------------------------------------------------------------ tmcert

struct TmRun {
  Verdict verdict = Verdict::Undecided;
  std::uint64_t nodes = 0;
  int depth = 0;
  double seconds = 0;        // fresh Verifier: preparing both bodies and the check
  double warm_seconds = 0;   // the same check again, bodies prepared (cf. FCL's models built once)
  std::string detail;
};

TmRun certify(const Scene& scene, bool warm) {
  VerifyOptions options;
  options.kernel = KernelKind::Filtered;
  options.epsilon = scene.epsilon ? *scene.epsilon : default_epsilon(scene);
  options.max_depth = scene.max_depth;
  const auto start = Clock::now();
  const Verifier verifier(scene, options);
  const CheckResult r = verifier.check(scene.checks[0].first, scene.checks[0].second);
  TmRun out;
  out.seconds = since(start);
  if (warm) {
    const auto again = Clock::now();
    const CheckResult r2 = verifier.check(scene.checks[0].first, scene.checks[0].second);
    out.warm_seconds = since(again);
    if (r2.verdict != r.verdict) out.detail = "SECOND RUN DIFFERS; ";
  }
  out.verdict = r.verdict;
  out.nodes = r.stats.nodes;
  out.depth = r.stats.max_depth;
  if (r.witness) out.detail += "witness t = " + to_string(r.witness->t);
  if (r.first_contact)
    out.detail += (out.detail.empty() ? "" : ", ") + std::string("first contact in [") +
                  to_string(r.first_contact->first) + ", " + to_string(r.first_contact->second) + "]";
  return out;
}

struct Variant {
  std::string name;  // "safe" / "collision"
  Verdict expected;
  std::array<std::string, 3> files;
};

}  // namespace

int main(int argc, char** argv) {
  int reps = 5;
  std::string root = TMCERT_SOURCE_DIR, only, method;
  bool distances = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--reps" && i + 1 < argc) reps = std::atoi(argv[++i]);
    else if (a == "--root" && i + 1 < argc) root = argv[++i];
    else if (a == "--only" && i + 1 < argc) only = argv[++i];
    else if (a == "--distance") distances = true;
    else if (a == "--method" && i + 1 < argc) method = argv[++i];
    else {
      std::fprintf(stderr, "usage: tmcert_planner_bench [--reps N] [--root DIR] [--only safe|collision] [--distance]\n"
                   "       [--method slerp|screw|nlerp|fcl]   (one method only, no table: for profiling)\n");
      return 3;
    }
  }
  if (reps < 1) reps = 1;
  const std::string dir = root + "/examples/gripper/";
  const std::array<const char*, 3> interps = {"slerp", "screw", "nlerp"};
  std::vector<Variant> variants;
  for (const char* v : {"safe", "collision"}) {
    if (!only.empty() && only != v) continue;
    Variant var;
    var.name = v;
    var.expected = std::string(v) == "safe" ? Verdict::Safe : Verdict::Collision;
    for (int k = 0; k < 3; ++k)
      var.files[k] = dir + "gripper-path-" + (var.name == "safe" ? "" : "collision-") + interps[k] + ".json";
    variants.push_back(var);
  }

  auto t0 = Clock::now();
  const Mesh gripper = read_off(dir + "gripper.off"), fixture = read_off(dir + "fixture.off");
  FclScene fcl(gripper, fixture);
  const double fcl_build = since(t0);

  bool ok = true;
  std::printf("tmcert planner path: the gripper (%zu triangles) through its fixture (%zu triangles), 20 keyframes;\n"
              "tmcert: filtered kernel, one thread, a fresh Verifier per run (bodies prepared inside the timing);\n"
              "FCL %s: OBBRSS models built once (%.1f ms, not timed), discrete poses of the slerp path at OMPL's\n"
              "default resolution; times are medians of %d runs, alternating the four methods\n\n",
              gripper.tris.size(), fixture.tris.size(), FCL_VERSION, 1e3 * fcl_build, reps);

  for (const Variant& var : variants) {
    std::array<Scene, 3> scenes;
    std::array<double, 3> parse_s{};
    for (int k = 0; k < 3; ++k) {
      const auto p0 = Clock::now();
      scenes[k] = parse_scene_file(var.files[k]);
      parse_s[k] = since(p0);
    }
    const std::vector<SE3Pose> path = read_keyframes(var.files[0]);
    const Discretisation d = discretise(path, fixture);
    if (distances) {
      std::printf("%s variant: FCL distance, 200 slerp samples per segment (floating point)\n", var.name.c_str());
      for (std::size_t e = 0; e + 1 < path.size(); ++e) {
        double best = 1e9, at = 0;
        for (int j = 0; j <= 200; ++j) {
          const double s = j / 200.0;
          const double dist = fcl.distance(ompl_interpolate(path[e], path[e + 1], s));
          if (dist < best) best = dist, at = s;
        }
        std::printf("  segment %2zu-%2zu: min %.3f mm at s = %.3f; OMPL poses %d\n", e, e + 1, 1e3 * best, at,
                    d.counts[e]);
      }
    }

    if (!method.empty()) {  // profiling: one method, reps runs, no table
      for (int r = 0; r < reps; ++r) {
        if (method == "fcl") {
          const auto f0 = Clock::now();
          const FclRun run = fcl_discrete(fcl, path, d, false);
          std::printf("%s FCL (%d poses): %.2f ms\n", var.name.c_str(), run.checked, 1e3 * since(f0));
        }
        for (int k = 0; k < 3; ++k)
          if (method == interps[k]) {
            const TmRun t = certify(scenes[k], false);
            if (t.verdict != var.expected) ok = false;
            std::printf("%s %s: %s, %llu nodes, %.1f ms\n", var.name.c_str(), interps[k], to_string(t.verdict),
                        static_cast<unsigned long long>(t.nodes), 1e3 * t.seconds);
          }
      }
      continue;
    }
    std::array<std::vector<double>, 4> times, warm;
    std::array<TmRun, 3> tm;
    FclRun fr;
    for (int r = 0; r < reps; ++r) {
      for (int m = 0; m < 4; ++m) {
        const int k = (m + r) % 4;  // rotate the order from run to run
        if (k < 3) {
          tm[k] = certify(scenes[k], true);
          times[k].push_back(tm[k].seconds);
          warm[k].push_back(tm[k].warm_seconds);
        } else {
          const auto f0 = Clock::now();
          fr = fcl_discrete(fcl, path, d, false);
          times[3].push_back(since(f0));
        }
      }
    }
    const FclRun all = fcl_discrete(fcl, path, d, true);
    // 100x finer than OMPL's resolution, all poses
    int fine_hits = 0, fine_poses = 0;
    double first_fine = -1;
    for (std::size_t e = 0; e + 1 < path.size(); ++e) {
      const int n = 100 * d.counts[e];
      for (int j = 1; j <= n; ++j) {
        ++fine_poses;
        if (fcl.collides(ompl_interpolate(path[e], path[e + 1], static_cast<double>(j) / n))) {
          if (first_fine < 0) first_fine = e + static_cast<double>(j) / n;
          ++fine_hits;
        }
      }
    }

    const double nlerp_t = median(times[2]), fcl_t = median(times[3]);
    std::printf("%s variant (expected %s); OMPL discretisation: R3 extent %.4f m (step %.2f mm), SO3 extent pi/2 "
                "(step %.2f deg of rotation), %d poses\n\n",
                var.name.c_str(), to_string(var.expected), d.r3_extent, 1e3 * d.fraction * d.r3_extent,
                2 * d.fraction * d.so3_extent * 180 / M_PI, d.poses);
    const double nlerp_w = median(warm[2]);
    std::printf("| method | verdict | nodes / poses | time [ms] | / nlerp | / FCL | prepared [ms] | / nlerp | / FCL |\n");
    std::printf("|---|---|--:|--:|--:|--:|--:|--:|--:|\n");
    for (int k = 0; k < 3; ++k) {
      const double t = median(times[k]), w = median(warm[k]);
      std::printf("| tmcert %s | %s | %llu | %.1f | %.2f | %.1f | %.1f | %.2f | %.1f |\n", interps[k],
                  to_string(tm[k].verdict), static_cast<unsigned long long>(tm[k].nodes), 1e3 * t, t / nlerp_t,
                  t / fcl_t, 1e3 * w, w / nlerp_w, w / fcl_t);
      if (tm[k].verdict != var.expected) ok = false;
    }
    std::printf("| FCL-discrete (slerp, OMPL resolution) | %s | %d | %.1f | %.2f | 1.0 | %.1f | %.2f | 1.0 |\n\n",
                fr.collision ? "collision (pose)" : "no pose collides", fr.checked, 1e3 * fcl_t, fcl_t / nlerp_t,
                1e3 * fcl_t, fcl_t / nlerp_w);
    for (int k = 0; k < 3; ++k)
      std::printf("  tmcert %s: depth %d, parse %.0f ms (not timed)%s%s\n", interps[k], tm[k].depth,
                  1e3 * parse_s[k], tm[k].detail.empty() ? "" : "; ", tm[k].detail.c_str());
    std::printf("  FCL at OMPL's resolution: %d of %d poses checked, %s", fr.checked, d.poses,
                all.collision ? "a pose collides" : "no pose collides");
    if (all.collision) std::printf(" (first: edge %d, s = %.4f)", all.edge, all.s);
    std::printf("; (sum of ceil(d/(0.01 x SE3 extent)) would give %d poses)\n", d.compound_formula_poses);
    {
      const Discretisation dbox = discretise(path, fixture, true);
      const FclRun box = fcl_discrete(fcl, path, dbox, true);
      std::printf("  FCL with the fixture's box alone as bounds (R3 extent %.4f m, step %.2f mm): %d poses, %s\n",
                  dbox.r3_extent, 1e3 * dbox.fraction * dbox.r3_extent, dbox.poses,
                  box.collision ? "a pose collides" : "no pose collides");
    }
    std::printf("  FCL at 100x OMPL's resolution: %d of %d poses collide%s", fine_hits, fine_poses,
                fine_hits ? ", the first at path parameter " : "");
    if (fine_hits) std::printf("%.4f (edge.fraction)", first_fine);
    std::printf("\n\n");
  }
  std::printf("%s\n", ok ? "all certified verdicts as expected" : "UNEXPECTED certified verdict");
  return ok ? 0 : 1;
}
