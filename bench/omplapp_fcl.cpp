// OMPL.app's own geometry and collision checking, for the OMPL.app benchmark
// problems (issue 23 item 8, issue 26 item 5): bench/omplapp_paths.py and
// scripts/omplapp_to_scene.py run this program; it knows nothing of tmcert.
//
// What OMPL.app (github.com/ompl/omplapp, src/omplapp/geometry/) does, done
// here with the same libraries (Debian libassimp-dev, libfcl-dev,
// libompl-dev) and the same operations in the same order:
//
//  - RigidBodyGeometry::addRobotMesh / addEnvironmentMesh: assimp reads the
//    COLLADA file with aiProcess_GenNormals | aiProcess_Triangulate |
//    aiProcess_JoinIdenticalVertices | aiProcess_SortByPType |
//    aiProcess_OptimizeGraph.
//  - detail/assimpUtil.cpp, extractTriangles: walks the node tree from the
//    root with `transform *= node->mTransformation` (aiMatrix4x4, single
//    precision) and keeps every face of 3 indices as `transform * vertex`;
//    extractVertices does the same for every vertex of every mesh, and
//    sceneCenter is their mean (a single-precision sum divided by the count).
//  - FCLMethodWrapper::configure: the robot's triangles minus the robot's
//    centre (getRobotCenter = sceneCenter; single precision), the
//    environment's triangles as they are (no shift), each triangle its own
//    three vertices, into FCL OBBRSS BVH models (double).
//  - FCLStateValidityChecker::isValid: satisfiesBounds(state) and no
//    fcl::collide of the robot at Translation3d(x, y, z) * Quaterniond(w, x,
//    y, z) with the environment at the identity.
//  - The state space: ompl::base::SE3StateSpace with the .cfg's volume as
//    translation bounds, extended to hold the .cfg's start and goal
//    (apps/detail/appUtil.cpp InferProblemDefinitionBounds, factor 1, add
//    0); SpaceInformation with OMPL's default DiscreteMotionValidator and
//    default resolution (longest valid segment 0.01 of the maximum extent,
//    per component: CompoundStateSpace::validSegmentCount is the largest of
//    R^3's ceil(|dt| / (0.01 x bounds diagonal)) and SO(3)'s
//    ceil(acos|q1.q2| / (0.01 x pi/2))).
//  - A path as PathGeometric::check: isValid(first state), then
//    checkMotion(s_k, s_k+1) edge by edge until the first invalid one.
//
// One difference, on purpose: the stored paths' quaternions are normalised
// (in double) when read.  Some are written with 6 digits (Twistycooler) and
// SO3StateSpace::satisfiesBounds rejects a quaternion whose norm is 1e-9 or
// more away from 1, which would make every such state invalid; tmcert
// rotates by q/|q| too (docs/scene-format.md, "Rigid poses").
//
// Usage:
//   tmcert_omplapp_fcl mesh FILE.dae [--robot]
//       prints the triangles OMPL.app gives FCL, one per line as nine C99
//       hexadecimal floats (exact), after a line `center cx cy cz vertices N
//       triangles M` (the robot's centre in hexadecimal floats; with
//       --robot the triangles are shifted by it, as OMPL.app does).
//   tmcert_omplapp_fcl check PROBLEM.cfg PATH.path [--reps N] [--queries]
//       checks the path as OMPL.app's SE3 setup does and prints one JSON
//       object per line: {"kind":"path", ...} (PathGeometric::check, the
//       median of N runs' wall time; first_invalid_edge: the edge k (from
//       state k) where it stopped, -2 when the first state is invalid, -1
//       when the path is valid), {"kind":"edges", ...} (every edge
//       checked, none stopping the others), and with --queries one line per
//       shortcut query (waypoint k to k+2 and k to k+4: checkMotion, once
//       each, wall time).
//   tmcert_omplapp_fcl sample PROBLEM.cfg PATH.path FROM TO N
//       FCL on N + 1 evenly spaced states of the straight edge from state
//       FROM to state TO of the path (OMPL's interpolation): a line
//       {"kind":"sample", "invalid": count, "first": s, "last": s}.
// Exit status 0; 3 on bad usage or unreadable input (a message on stderr).
#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/narrowphase/collision.h>
#include <ompl/base/DiscreteMotionValidator.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/StateValidityChecker.h>
#include <ompl/base/spaces/SE3StateSpace.h>
#include <ompl/config.h>
#include <ompl/util/Console.h>
#include <fcl/config.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace ob = ompl::base;

namespace {

[[noreturn]] void fail(const std::string& message) {
  std::fprintf(stderr, "tmcert_omplapp_fcl: %s\n", message.c_str());
  std::exit(3);
}

using Clock = std::chrono::steady_clock;
double since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// This thread's CPU time (the machine may be shared: wall time then counts
// other processes' time slices).
double cpu_now() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// ------------------------------------------------------------------ OMPL.app's geometry

constexpr unsigned kImportFlags = aiProcess_GenNormals | aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                                  aiProcess_SortByPType | aiProcess_OptimizeGraph;

void extract_vertices(const aiScene* scene, const aiNode* node, aiMatrix4x4 transform,
                      std::vector<aiVector3D>& vertices) {
  transform *= node->mTransformation;
  for (unsigned i = 0; i < node->mNumMeshes; ++i) {
    const aiMesh* a = scene->mMeshes[node->mMeshes[i]];
    for (unsigned j = 0; j < a->mNumVertices; ++j) vertices.push_back(transform * a->mVertices[j]);
  }
  for (unsigned n = 0; n < node->mNumChildren; ++n) extract_vertices(scene, node->mChildren[n], transform, vertices);
}

void extract_triangles(const aiScene* scene, const aiNode* node, aiMatrix4x4 transform,
                       std::vector<aiVector3D>& triangles) {
  transform *= node->mTransformation;
  for (unsigned i = 0; i < node->mNumMeshes; ++i) {
    const aiMesh* a = scene->mMeshes[node->mMeshes[i]];
    for (unsigned j = 0; j < a->mNumFaces; ++j)
      if (a->mFaces[j].mNumIndices == 3)
        for (int k = 0; k < 3; ++k) triangles.push_back(transform * a->mVertices[a->mFaces[j].mIndices[k]]);
  }
  for (unsigned n = 0; n < node->mNumChildren; ++n)
    extract_triangles(scene, node->mChildren[n], transform, triangles);
}

struct Geometry {
  std::vector<aiVector3D> triangles;  // 3 per triangle, shifted by `center` for the robot
  aiVector3D center{0, 0, 0};
  std::size_t vertices = 0;
};

Geometry load_mesh(const std::string& path, bool robot) {
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(path.c_str(), kImportFlags);
  if (scene == nullptr || !scene->HasMeshes())
    fail(path + ": assimp cannot read a mesh from it (" + importer.GetErrorString() + ")");
  Geometry g;
  std::vector<aiVector3D> vertices;
  extract_vertices(scene, scene->mRootNode, aiMatrix4x4(), vertices);
  g.vertices = vertices.size();
  if (robot) {  // sceneCenter
    for (const auto& v : vertices) g.center += v;
    g.center /= static_cast<float>(vertices.size());
  }
  extract_triangles(scene, scene->mRootNode, aiMatrix4x4(), g.triangles);
  if (robot)
    for (auto& p : g.triangles) p -= g.center;
  return g;
}

// ------------------------------------------------------------------ the .cfg and .path

std::map<std::string, std::string> read_cfg(const std::string& path) {
  std::ifstream in(path);
  if (!in) fail("cannot read " + path);
  std::map<std::string, std::string> out;
  std::string line, section;
  while (std::getline(in, line)) {
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    if (line[first] == '[') {
      section = line.substr(first + 1, line.find(']') - first - 1);
      continue;
    }
    const auto eq = line.find('=');
    if (eq == std::string::npos || section != "problem") continue;
    auto trim = [](std::string s) {
      const auto a = s.find_first_not_of(" \t\r"), b = s.find_last_not_of(" \t\r");
      return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
    };
    out[trim(line.substr(0, eq))] = trim(line.substr(eq + 1));
  }
  return out;
}

double cfg_number(const std::map<std::string, std::string>& cfg, const std::string& key, const std::string& file) {
  const auto it = cfg.find(key);
  if (it == cfg.end()) fail(file + ": [problem] has no " + key);
  char* end = nullptr;
  const double v = std::strtod(it->second.c_str(), &end);
  if (end == it->second.c_str() || *end != '\0' || !std::isfinite(v)) fail(file + ": " + key + " is not a number");
  return v;
}

struct State {
  double x, y, z, qx, qy, qz, qw;
};

std::vector<State> read_path(const std::string& path) {
  std::ifstream in(path);
  if (!in) fail("cannot read " + path);
  std::vector<State> out;
  std::string line;
  int lineno = 0;
  while (std::getline(in, line)) {
    ++lineno;
    std::istringstream ls(line);
    std::vector<double> v;
    std::string tok;
    while (ls >> tok) {
      char* end = nullptr;
      const double d = std::strtod(tok.c_str(), &end);
      if (*end != '\0' || !std::isfinite(d)) fail(path + ": line " + std::to_string(lineno) + ": not a number");
      v.push_back(d);
    }
    if (v.empty()) continue;
    if (v.size() != 7) fail(path + ": line " + std::to_string(lineno) + ": not 7 numbers (x y z qx qy qz qw)");
    const double n = std::sqrt(v[3] * v[3] + v[4] * v[4] + v[5] * v[5] + v[6] * v[6]);
    if (!(n > 0)) fail(path + ": line " + std::to_string(lineno) + ": zero quaternion");
    out.push_back({v[0], v[1], v[2], v[3] / n, v[4] / n, v[5] / n, v[6] / n});
  }
  if (out.size() < 2) fail(path + ": fewer than 2 states");
  return out;
}

// ------------------------------------------------------------------ OMPL + FCL

using Model = fcl::BVHModel<fcl::OBBRSSd>;

std::shared_ptr<Model> build_model(const Geometry& g) {
  std::vector<fcl::Vector3d> pts;
  std::vector<fcl::Triangle> tris;
  for (const auto& p : g.triangles) pts.emplace_back(p[0], p[1], p[2]);
  for (std::size_t i = 0; i < pts.size(); i += 3) tris.emplace_back(i, i + 1, i + 2);
  auto model = std::make_shared<Model>();
  model->beginModel();
  model->addSubModel(pts, tris);
  model->endModel();
  model->computeLocalAABB();
  return model;
}

class FclChecker : public ob::StateValidityChecker {
 public:
  FclChecker(const ob::SpaceInformationPtr& si, std::shared_ptr<Model> robot, std::shared_ptr<Model> env)
      : ob::StateValidityChecker(si), robot_(std::move(robot)), env_(std::move(env)) {}
  bool isValid(const ob::State* state) const override {
    ++calls;
    if (!si_->satisfiesBounds(state)) return false;
    const auto* s = state->as<ob::SE3StateSpace::StateType>();
    const auto& q = s->rotation();
    const fcl::Transform3d tf = fcl::Translation3d(s->getX(), s->getY(), s->getZ()) * fcl::Quaterniond(q.w, q.x, q.y, q.z);
    static const fcl::Transform3d identity(fcl::Transform3d::Identity());
    fcl::CollisionRequestd request;
    fcl::CollisionResultd result;
    return fcl::collide(robot_.get(), tf, env_.get(), identity, request, result) == 0;
  }
  mutable std::atomic<long> calls{0};

 private:
  std::shared_ptr<Model> robot_, env_;
};

std::string dir_of(const std::string& path) {
  const auto slash = path.rfind('/');
  return slash == std::string::npos ? std::string(".") : path.substr(0, slash);
}

struct Problem {
  Geometry robot, env;
  double load_s = 0, build_s = 0;
  std::shared_ptr<ob::SE3StateSpace> space;
  ob::SpaceInformationPtr si;
  std::shared_ptr<FclChecker> checker;
  std::vector<ob::State*> states;
  int out_of_bounds = 0;
  ~Problem() {
    for (auto* s : states) si->freeState(s);
  }
};

// OMPL.app's SE3 setup of the problem, and the path's states.
void setup(Problem& p, const std::string& cfg_path, const std::string& path_path) {
  const auto cfg = read_cfg(cfg_path);
  for (const char* key : {"robot", "world"})
    if (!cfg.count(key)) fail(cfg_path + ": [problem] has no " + key);
  const std::string dir = dir_of(cfg_path);
  auto t0 = Clock::now();
  p.robot = load_mesh(dir + "/" + cfg.at("robot"), true);
  p.env = load_mesh(dir + "/" + cfg.at("world"), false);
  p.load_s = since(t0);
  t0 = Clock::now();
  auto robot_model = build_model(p.robot), env_model = build_model(p.env);
  p.build_s = since(t0);

  p.space = std::make_shared<ob::SE3StateSpace>();
  ob::RealVectorBounds bounds(3);
  const char* axes[3] = {"x", "y", "z"};
  for (int k = 0; k < 3; ++k) {
    bounds.setLow(k, cfg_number(cfg, std::string("volume.min.") + axes[k], cfg_path));
    bounds.setHigh(k, cfg_number(cfg, std::string("volume.max.") + axes[k], cfg_path));
  }
  for (const char* end : {"start", "goal"})  // InferProblemDefinitionBounds, factor 1, add 0
    for (int k = 0; k < 3; ++k) {
      const double v = cfg_number(cfg, std::string(end) + "." + axes[k], cfg_path);
      if (bounds.low[k] > v) bounds.low[k] = v;
      if (bounds.high[k] < v) bounds.high[k] = v;
    }
  p.space->setBounds(bounds);
  p.si = std::make_shared<ob::SpaceInformation>(p.space);
  p.checker = std::make_shared<FclChecker>(p.si, robot_model, env_model);
  p.si->setStateValidityChecker(p.checker);
  p.si->setup();  // DiscreteMotionValidator at the default resolution

  for (const State& st : read_path(path_path)) {
    ob::State* s = p.si->allocState();
    auto* se3 = s->as<ob::SE3StateSpace::StateType>();
    se3->setXYZ(st.x, st.y, st.z);
    se3->rotation().x = st.qx, se3->rotation().y = st.qy, se3->rotation().z = st.qz, se3->rotation().w = st.qw;
    if (!p.si->satisfiesBounds(s)) ++p.out_of_bounds;
    p.states.push_back(s);
  }
}

// FCL on n + 1 evenly spaced states of the edge from state `from` to state
// `to` (OMPL's interpolation): how many collide, and where.
int run_sample(const std::string& cfg_path, const std::string& path_path, int from, int to, int n) {
  Problem p;
  setup(p, cfg_path, path_path);
  const int m = static_cast<int>(p.states.size());
  if (from < 0 || to < 0 || from >= m || to >= m || n < 1) fail("sample: FROM and TO must be states of the path, N >= 1");
  ob::State* test = p.si->allocState();
  int hits = 0;
  double first = -1, last = -1;
  for (int j = 0; j <= n; ++j) {
    const double s = static_cast<double>(j) / n;
    p.space->interpolate(p.states[from], p.states[to], s, test);
    if (!p.checker->isValid(test)) {
      ++hits;
      if (first < 0) first = s;
      last = s;
    }
  }
  p.si->freeState(test);
  std::printf("{\"kind\":\"sample\",\"from\":%d,\"to\":%d,\"states\":%d,\"invalid\":%d,\"first\":%.17g,"
              "\"last\":%.17g}\n",
              from, to, n + 1, hits, first, last);
  return 0;
}

int run_check(const std::string& cfg_path, const std::string& path_path, int reps, bool queries) {
  Problem p;
  setup(p, cfg_path, path_path);
  const Geometry& robot = p.robot;
  const Geometry& env = p.env;
  const double load_s = p.load_s, build_s = p.build_s;
  const auto& space = p.space;
  const auto& si = p.si;
  const auto& checker = p.checker;
  const std::vector<ob::State*>& states = p.states;
  const int out_of_bounds = p.out_of_bounds;

  const auto mv = si->getMotionValidator();
  const std::size_t n = states.size();

  // PathGeometric::check, timed
  std::vector<double> times, cpu_times;
  bool valid = false;
  long calls = 0;
  int first_invalid = -1;
  for (int r = 0; r < std::max(reps, 1); ++r) {
    checker->calls = 0;
    const auto c0 = Clock::now();
    const double u0 = cpu_now();
    bool ok = si->isValid(states[0]);
    int bad = ok ? -1 : -2;  // -2: the first state is invalid
    for (std::size_t j = 0; ok && j + 1 < n; ++j)
      if (!mv->checkMotion(states[j], states[j + 1])) ok = false, bad = static_cast<int>(j);
    times.push_back(since(c0));
    cpu_times.push_back(cpu_now() - u0);
    valid = ok, calls = checker->calls, first_invalid = bad;
  }
  std::printf("{\"kind\":\"path\",\"states\":%zu,\"robot_triangles\":%zu,\"env_triangles\":%zu,"
              "\"robot_vertices\":%zu,\"out_of_bounds\":%d,\"extent\":%.17g,\"longest_valid_segment\":%.17g,"
              "\"valid\":%s,\"first_invalid_edge\":%d,\"state_checks\":%ld,\"seconds\":%.9g,\"cpu_seconds\":%.9g,"
              "\"reps\":%d,\"load_seconds\":%.9g,\"build_seconds\":%.9g,\"fcl\":\"%s\",\"ompl\":\"%d.%d.%d\"}\n",
              n, robot.triangles.size() / 3, env.triangles.size() / 3, robot.vertices, out_of_bounds,
              space->getMaximumExtent(), space->getLongestValidSegmentLength(), valid ? "true" : "false",
              first_invalid, calls, median(times), median(cpu_times), std::max(reps, 1), load_s, build_s, FCL_VERSION,
              OMPL_MAJOR_VERSION, OMPL_MINOR_VERSION, OMPL_PATCH_VERSION);

  // every edge (none stops the others), and the states alone
  {
    int invalid_states = 0, invalid_edges = 0;
    long edge_calls = 0;
    std::string bad_edges;
    for (std::size_t j = 0; j < n; ++j)
      if (!si->isValid(states[j])) ++invalid_states;
    checker->calls = 0;
    const auto c0 = Clock::now();
    for (std::size_t j = 0; j + 1 < n; ++j)
      if (!mv->checkMotion(states[j], states[j + 1])) {
        ++invalid_edges;
        bad_edges += (bad_edges.empty() ? "" : ",") + std::to_string(j);
      }
    const double s = since(c0);
    edge_calls = checker->calls;
    std::printf("{\"kind\":\"edges\",\"invalid_states\":%d,\"invalid_edges\":%d,\"invalid_edge_starts\":[%s],"
                "\"state_checks\":%ld,\"seconds\":%.9g}\n",
                invalid_states, invalid_edges, bad_edges.c_str(), edge_calls, s);
  }

  if (queries)
    for (int step : {2, 4})
      for (std::size_t k = 0; k + step < n; ++k) {
        checker->calls = 0;
        const auto c0 = Clock::now();
        const double u0 = cpu_now();
        const bool ok = mv->checkMotion(states[k], states[k + step]);
        const double u = cpu_now() - u0, s = since(c0);
        std::printf("{\"kind\":\"query\",\"from\":%zu,\"to\":%zu,\"valid\":%s,\"state_checks\":%ld,"
                    "\"seconds\":%.9g,\"cpu_seconds\":%.9g}\n",
                    k, k + step, ok ? "true" : "false", static_cast<long>(checker->calls), s, u);
      }
  return 0;
}

int run_mesh(const std::string& path, bool robot) {
  const Geometry g = load_mesh(path, robot);
  std::printf("center %a %a %a vertices %zu triangles %zu\n", static_cast<double>(g.center.x),
              static_cast<double>(g.center.y), static_cast<double>(g.center.z), g.vertices, g.triangles.size() / 3);
  for (std::size_t i = 0; i < g.triangles.size(); i += 3)
    std::printf("%a %a %a %a %a %a %a %a %a\n", static_cast<double>(g.triangles[i].x),
                static_cast<double>(g.triangles[i].y), static_cast<double>(g.triangles[i].z),
                static_cast<double>(g.triangles[i + 1].x), static_cast<double>(g.triangles[i + 1].y),
                static_cast<double>(g.triangles[i + 1].z), static_cast<double>(g.triangles[i + 2].x),
                static_cast<double>(g.triangles[i + 2].y), static_cast<double>(g.triangles[i + 2].z));
  return std::fflush(stdout) == 0 ? 0 : 4;
}

void usage() {
  std::fprintf(stderr,
               "usage: tmcert_omplapp_fcl mesh FILE.dae [--robot]\n"
               "       tmcert_omplapp_fcl check PROBLEM.cfg PATH.path [--reps N] [--queries]\n"
               "       tmcert_omplapp_fcl sample PROBLEM.cfg PATH.path FROM TO N\n");
  std::exit(3);
}

}  // namespace

int main(int argc, char** argv) {
  ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
  if (argc < 3) usage();
  const std::string mode = argv[1];
  if (mode == "mesh") {
    bool robot = false;
    for (int i = 3; i < argc; ++i) {
      if (std::string(argv[i]) == "--robot") robot = true;
      else usage();
    }
    return run_mesh(argv[2], robot);
  }
  if (mode == "check" && argc >= 4) {
    int reps = 3;
    bool queries = false;
    for (int i = 4; i < argc; ++i) {
      const std::string a = argv[i];
      if (a == "--reps" && i + 1 < argc) reps = std::atoi(argv[++i]);
      else if (a == "--queries") queries = true;
      else usage();
    }
    return run_check(argv[2], argv[3], reps, queries);
  }
  if (mode == "sample" && argc == 7) return run_sample(argv[2], argv[3], std::atoi(argv[4]), std::atoi(argv[5]), std::atoi(argv[6]));
  usage();
}
