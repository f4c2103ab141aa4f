// Speed against error (issue 5, item 4).
//
// Part 1, speed: time and outcome of the three kernels (fast, filtered,
// exact) as epsilon goes from 1e-1 to 1e-9 of the scene size, for the
// paper's octagons, the paper's grid scenes (n = 4 and 10), the gripper and
// the CCD query set (bench/ccd_queries.h) as one scene; with the interval
// filter's statistics per predicate.
//
// Part 2, hard cases: the fast (double precision, uncertified) path against
// the certified one (filtered: verdicts of the exact kernel) and the ground
// truth, on the CCD query kinds, on near-degenerate constructions (contacts
// and misses at 1e-12, nearly parallel edges, shallow crossings), on
// degenerate random scenes (grid vertices, shared vertices, coplanar
// features, touching contacts), each also translated far from the origin.
//
// Usage: tmcert_speed_error [--quick] [--csv FILE] [--hard-csv FILE]
//          [--only speed|hard] [--root DIR] [--grid-dir DIR] [--ccd N]
//          [--ccd-exact N] [--seed S] [--reps R]
//          [--ccd-hard N] [--hard N] [--offsets LIST] [--hard-f LIST]
//          [--nodes N] [--sets SET/OFFSET] [--verbose]
//
// --root is the source tree (examples/, bench/paper_grid.py); by default the
// one this program was built from.  Without --grid-dir the grid scenes are
// written by `python3 ROOT/bench/paper_grid.py` into a temporary directory
// (removed after parsing).  Part 1: --ccd queries as one scene (fast and
// filtered), the first --ccd-exact of them with the exact kernel too, up to
// --reps timed runs.  Part 2: --ccd-hard CCD queries, --hard constructions
// per kind, at the comma-separated --offsets and --hard-f values, node
// budget --nodes per check; --sets runs one set (e.g. ccd/1e6) only;
// --verbose lists slow queries on stderr.  The plots and the README tables
// come from bench/plot_speed_error.py on the two CSV files.
// Exit status 0 when no certified verdict contradicts the ground truth (and
// the filtered and exact kernels never contradict each other), 1 otherwise,
// 3 on bad usage.
#include "bench/ccd_queries.h"
#include "kernels/static_intersection.h"
#include "src/metric/metric.h"
#include "src/io/parse.h"
#include "src/verify/verify.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

#include <unistd.h>

#ifndef TMCERT_SOURCE_DIR
#define TMCERT_SOURCE_DIR "."
#endif

using namespace tmcert;
using namespace tmcert::bench;
namespace fs = std::filesystem;

namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// ------------------------------------------------------------------ exact vector helpers

Vec3E add(const Vec3E& a, const Vec3E& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Vec3E sub(const Vec3E& a, const Vec3E& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3E mul(const Exact& s, const Vec3E& a) { return {s * a[0], s * a[1], s * a[2]}; }
Exact dot(const Vec3E& a, const Vec3E& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3E cross(const Vec3E& a, const Vec3E& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
bool is_zero(const Vec3E& a) { return a[0] == 0 && a[1] == 0 && a[2] == 0; }
double norm_d(const Vec3E& a) { return std::sqrt(CGAL::to_double(dot(a, a))); }
// The exact rational nearest to the double x (x itself: doubles are rationals).
Exact ex(double x) { return Exact(x); }

// A decimal with six significant digits (as default_epsilon does).
Exact decimal(double x) {
  char text[64];
  std::snprintf(text, sizeof text, "%.6g", x);
  Exact out;
  if (!parse_exact(text, out)) return Exact(x);
  return out;
}

// ------------------------------------------------------------------ scenes

// The diagonal of the box holding every body's vertices under every control
// point of its motion (the box of default_epsilon, whose default is 1/1000
// of this diagonal).
double scene_size(const Scene& scene) {
  double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  for (const Body& b : scene.bodies) {
    std::vector<Vec3E> verts;
    for (const auto& poly : b.polygons) verts.insert(verts.end(), poly.begin(), poly.end());
    for (const auto& s : b.segments) verts.insert(verts.end(), s.begin(), s.end());
    verts.insert(verts.end(), b.points.begin(), b.points.end());
    std::vector<Mat34E> maps;
    if (b.motion) maps = b.motion->control_points;
    else maps.push_back({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0});
    for (const Vec3E& v : verts)
      for (const Mat34E& m : maps)
        for (int i = 0; i < 3; ++i) {
          const double w = CGAL::to_double(m[4 * i] * v[0] + m[4 * i + 1] * v[1] + m[4 * i + 2] * v[2] + m[4 * i + 3]);
          lo[i] = std::min(lo[i], w);
          hi[i] = std::max(hi[i], w);
        }
  }
  double d2 = 0;
  for (int i = 0; i < 3; ++i)
    if (hi[i] >= lo[i]) d2 += (hi[i] - lo[i]) * (hi[i] - lo[i]);
  return std::sqrt(d2);
}

// Every body's motion followed by the translation o (an exact world
// translation: nothing about the motion's geometry changes).
void translate_scene(Scene& scene, const Vec3E& o) {
  for (Body& b : scene.bodies) {
    if (!b.motion) {
      b.motion = Motion{};
      b.motion->control_points.push_back({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0});
      b.motion->weights.push_back(Exact(1));
    }
    for (std::size_t k = 0; k < b.motion->control_points.size(); ++k)
      for (int r = 0; r < 3; ++r) b.motion->control_points[k][4 * r + 3] += o[r];
  }
}

// ------------------------------------------------------------------ optional statistics

// Counters that only some versions of the library have: contact tests the
// filtered kernel's double pre-test kept without certified arithmetic
// (FilterCounters::screened: they are not in `calls`), and feature pairs the
// hull test cleared (CheckStats::hull_clears).  Zero where absent.
template <class C>
std::uint64_t screened_of(const C& c) {
  if constexpr (requires { c.screened; }) return c.screened;
  else return 0;
}
template <class C>
constexpr bool kHasScreen = requires(const C& c) { c.screened; };
template <class S>
std::uint64_t hull_clears_of(const S& s) {
  if constexpr (requires { s.hull_clears; }) return s.hull_clears;
  else return 0;
}
template <class S>
std::uint64_t axis_clears_of(const S& s) {
  if constexpr (requires { s.axis_clears; }) return s.axis_clears;
  else return 0;
}

// ------------------------------------------------------------------ part 1: speed against epsilon

const KernelKind kKernels[3] = {KernelKind::Fast, KernelKind::Filtered, KernelKind::Exact};

struct SpeedCase {
  std::string name;
  std::string group;  // octagons, grid, gripper, ccd
  Scene scene;
  double size = 0;
  bool exact = false;  // run the exact kernel too
};

struct SpeedRow {
  std::string scene, group;
  double size = 0, f = 0, epsilon = 0;
  KernelKind kernel = KernelKind::Filtered;
  bool ran = false;
  std::string note;  // why not run
  std::string verdict;
  int checks = 0, safe = 0, collision = 0, undecided = 0, prefiltered = 0;
  std::uint64_t nodes = 0;
  int max_depth = 0;
  double seconds = 0;
  int reps = 0;
  double und_frac = 0;  // undecided parameter length / total, over checks ending undecided
  int und_eps = 0, und_depth = 0, und_limit = 0;  // undecided pieces by reason
  std::array<FilterCounters, 3> by_kind{};
  std::array<std::uint64_t, 3> screened{};  // kept by the double pre-test (not in by_kind calls)
  std::uint64_t hull_clears = 0;
  std::uint64_t axis_clears = 0;  // contact tests settled by the axis test (not in by_kind calls)
  std::uint64_t tests() const {
    std::uint64_t n = 0;
    for (int k = 0; k < 3; ++k) n += by_kind[k].calls + screened[k];
    return n;
  }
  std::uint64_t exact() const { return by_kind[0].exact_fallbacks + by_kind[1].exact_fallbacks + by_kind[2].exact_fallbacks; }
  std::uint64_t static_conf = 0, static_pairs = 0, static_exact = 0, static_tests = 0, sphere_tests = 0;
};

// The parameter interval of a check (of whichever body moves).
std::pair<double, double> check_interval(const Scene& scene, const CheckResult& c) {
  for (int k : c.bodies) {
    const Body& b = scene.bodies[k];
    if (b.motion && b.motion->degree() >= 1) return {CGAL::to_double(b.motion->t0), CGAL::to_double(b.motion->t1)};
  }
  return {0, 1};
}

void summarize(const Scene& scene, const SceneResult& r, SpeedRow& row) {
  row.verdict = to_string(r.verdict);
  row.checks = static_cast<int>(r.checks.size());
  row.safe = row.collision = row.undecided = row.prefiltered = 0;
  row.nodes = 0;
  row.max_depth = 0;
  row.und_eps = row.und_depth = row.und_limit = 0;
  row.by_kind = {};
  row.screened = {};
  row.hull_clears = 0;
  row.axis_clears = 0;
  row.static_conf = row.static_pairs = row.static_exact = row.static_tests = row.sphere_tests = 0;
  double total = 0, und = 0;
  for (const CheckResult& c : r.checks) {
    const auto [t0, t1] = check_interval(scene, c);
    total += t1 - t0;
    if (c.verdict == Verdict::Safe) ++row.safe;
    if (c.verdict == Verdict::Collision) ++row.collision;
    if (c.verdict == Verdict::Undecided) {
      ++row.undecided;
      for (const UndecidedInterval& u : c.undecided) und += CGAL::to_double(u.t1 - u.t0);
    }
    for (const UndecidedInterval& u : c.undecided) {
      if (u.reason == StopReason::Epsilon) ++row.und_eps;
      if (u.reason == StopReason::Depth) ++row.und_depth;
      if (u.reason == StopReason::Limit) ++row.und_limit;
    }
    const CheckStats& s = c.stats;
    if (s.prefiltered) ++row.prefiltered;
    row.nodes += s.nodes;
    row.max_depth = std::max(row.max_depth, s.max_depth);
    for (int k = 0; k < 3; ++k) {
      row.by_kind[k] += s.by_kind[k];
      row.screened[k] += screened_of(s.by_kind[k]);
    }
    row.hull_clears += hull_clears_of(s);
    row.axis_clears += axis_clears_of(s);
    row.static_conf += s.static_configurations;
    row.static_pairs += s.static_filter_pairs;
    row.static_exact += s.static_filter_exact;
    row.static_tests += s.static_tests;
    row.sphere_tests += s.sphere_tests;
  }
  row.und_frac = total > 0 ? und / total : 0;
}

// verify_scene, one thread, max_depth 62 (the cap: epsilon alone ends the
// subdivision); the best wall time of up to `reps` runs: at least three
// unless one takes over a second, more only while they have taken less than
// a second in all (best of two was too noisy a ratio on the gripper).
// The first `count` kernels' runs alternate (fast, filtered, fast, ...):
// their ratio is what item 2 of the issue measures, and alternating keeps
// this machine's drift in speed out of it.
std::vector<SpeedRow> run_speed_alternating(const SpeedCase& c, double f, const std::vector<KernelKind>& kernels,
                                            int reps) {
  std::vector<SpeedRow> rows(kernels.size());
  std::vector<VerifyOptions> options(kernels.size());
  std::vector<double> best(kernels.size(), INFINITY);
  for (std::size_t i = 0; i < kernels.size(); ++i) {
    SpeedRow& row = rows[i];
    row.scene = c.name;
    row.group = c.group;
    row.size = c.size;
    row.f = f;
    row.kernel = kernels[i];
    options[i].kernel = kernels[i];
    options[i].epsilon = decimal(f * c.size);
    options[i].max_depth = 62;
    row.epsilon = CGAL::to_double(*options[i].epsilon);
  }
  double spent = 0;
  for (int k = 0; k < reps; ++k) {
    double longest = 0;
    for (std::size_t i = 0; i < kernels.size(); ++i) {
      const auto start = Clock::now();
      const SceneResult r = verify_scene(c.scene, options[i], 1);
      const double s = since(start);
      best[i] = std::min(best[i], s);
      longest = std::max(longest, s);
      spent += s;
      ++rows[i].reps;
      if (k == 0) summarize(c.scene, r, rows[i]);
    }
    if (longest > 1.0 || (k >= 2 && spent > 1.0 * static_cast<double>(kernels.size()))) break;
  }
  for (std::size_t i = 0; i < kernels.size(); ++i) {
    rows[i].seconds = best[i];
    rows[i].ran = true;
  }
  return rows;
}

SpeedRow run_speed(const SpeedCase& c, double f, KernelKind kernel, int reps) {
  SpeedRow row;
  row.scene = c.name;
  row.group = c.group;
  row.size = c.size;
  row.f = f;
  row.kernel = kernel;
  VerifyOptions options;
  options.kernel = kernel;
  options.epsilon = decimal(f * c.size);
  row.epsilon = CGAL::to_double(*options.epsilon);
  options.max_depth = 62;
  double best = INFINITY, spent = 0;
  for (int k = 0; k < reps; ++k) {
    const auto start = Clock::now();
    const SceneResult r = verify_scene(c.scene, options, 1);
    const double s = since(start);
    best = std::min(best, s);
    spent += s;
    ++row.reps;
    if (k == 0) summarize(c.scene, r, row);
    if (s > 1.0 || (k >= 2 && spent > 1.0)) break;
  }
  row.seconds = best;
  row.ran = true;
  return row;
}

double rate(std::uint64_t part, std::uint64_t whole) { return whole ? 100.0 * part / whole : 0.0; }

std::string fmt_rate(std::uint64_t part, std::uint64_t whole) {
  if (!whole) return "–";
  char b[32];
  std::snprintf(b, sizeof b, "%.2f%%", rate(part, whole));
  return b;
}

std::string fmt_count(std::uint64_t n) {
  char b[32];
  if (n >= 10'000'000) std::snprintf(b, sizeof b, "%.1fM", n / 1e6);
  else if (n >= 100'000) std::snprintf(b, sizeof b, "%.0fk", n / 1e3);
  else std::snprintf(b, sizeof b, "%llu", static_cast<unsigned long long>(n));
  return b;
}

void write_speed_csv(const std::string& path, const std::vector<SpeedRow>& rows) {
  std::ofstream out(path);
  out << "scene,group,size,f,epsilon,kernel,ran,note,verdict,checks,safe,collision,undecided,prefiltered,nodes,"
         "max_depth,seconds,reps,und_frac,und_eps,und_depth,und_limit,vf_calls,vf_exact,ee_calls,ee_exact,"
         "fv_calls,fv_exact,static_conf,static_pairs,static_exact,static_tests,sphere_tests,vf_screened,ee_screened,"
         "fv_screened,hull_clears,axis_clears\n";
  char line[1024];
  for (const SpeedRow& r : rows) {
    std::snprintf(line, sizeof line,
                  "%s,%s,%.9g,%.0e,%.9g,%s,%d,%s,%s,%d,%d,%d,%d,%d,%llu,%d,%.9g,%d,%.9g,%d,%d,%d,%llu,%llu,%llu,%llu,"
                  "%llu,%llu,%llu,%llu,%llu,%llu,%llu,%llu,%llu,%llu,%llu,%llu\n",
                  r.scene.c_str(), r.group.c_str(), r.size, r.f, r.epsilon, to_string(r.kernel), r.ran ? 1 : 0,
                  r.note.c_str(), r.verdict.c_str(), r.checks, r.safe, r.collision, r.undecided, r.prefiltered,
                  static_cast<unsigned long long>(r.nodes), r.max_depth, r.seconds, r.reps, r.und_frac, r.und_eps,
                  r.und_depth, r.und_limit, static_cast<unsigned long long>(r.by_kind[0].calls),
                  static_cast<unsigned long long>(r.by_kind[0].exact_fallbacks),
                  static_cast<unsigned long long>(r.by_kind[1].calls),
                  static_cast<unsigned long long>(r.by_kind[1].exact_fallbacks),
                  static_cast<unsigned long long>(r.by_kind[2].calls),
                  static_cast<unsigned long long>(r.by_kind[2].exact_fallbacks),
                  static_cast<unsigned long long>(r.static_conf), static_cast<unsigned long long>(r.static_pairs),
                  static_cast<unsigned long long>(r.static_exact), static_cast<unsigned long long>(r.static_tests),
                  static_cast<unsigned long long>(r.sphere_tests), static_cast<unsigned long long>(r.screened[0]),
                  static_cast<unsigned long long>(r.screened[1]), static_cast<unsigned long long>(r.screened[2]),
                  static_cast<unsigned long long>(r.hull_clears), static_cast<unsigned long long>(r.axis_clears));
    out << line;
  }
}

// ------------------------------------------------------------------ part 2: hard cases

// Every simplex of a body in its own frame (points, segments, triangles).
using Simplices = std::vector<Simplex>;

Simplex simplex_of(const std::vector<Vec3E>& v) {
  Simplex s;
  s.count = static_cast<int>(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) s.p[i] = v[i];
  for (std::size_t i = v.size(); i < 3; ++i) s.p[i] = v.back();
  return s;
}

Simplex translated(Simplex s, const Vec3E& d) {
  for (int k = 0; k < s.count; ++k) s.p[k] = add(s.p[k], d);
  return s;
}

// The parallelogram swept by segment [p, q] under the translation d, as two
// triangles (degenerate ones reduce exactly in common_point).
std::array<Simplex, 2> swept_segment(const Vec3E& p, const Vec3E& q, const Vec3E& d) {
  return {Simplex{3, {p, q, add(q, d)}}, Simplex{3, {p, add(q, d), add(p, d)}}};
}

// Exact truth for a relative translation: do A (fixed) and B + t d share a
// point for some t in [0, 1]?  At the first contact time either they meet
// at t = 0, or a vertex of one lies on the other, or two edges meet; every
// such event is a point of A on the region an edge or vertex of B sweeps, or
// a vertex of A on the region B sweeps backwards.
bool translation_hits(const Simplices& A, const Simplices& B, const Vec3E& d) {
  for (const Simplex& a : A)
    for (const Simplex& b : B) {
      if (common_point(a, b)) return true;
      // B's vertices and edges swept by d, against a.
      if (b.count == 1) {
        if (common_point(a, Simplex{2, {b.p[0], add(b.p[0], d), add(b.p[0], d)}})) return true;
        continue;
      }
      for (int i = 0; i < b.count; ++i) {
        const int j = (i + 1) % b.count;
        if (b.count == 2 && i == 1) break;
        for (const Simplex& s : swept_segment(b.p[i], b.p[j], d))
          if (common_point(a, s)) return true;
      }
      // a's vertices swept by -d, against b (needed when b is a triangle).
      if (b.count == 3)
        for (int i = 0; i < a.count; ++i)
          if (common_point(b, Simplex{2, {a.p[i], sub(a.p[i], d), sub(a.p[i], d)}})) return true;
    }
  return false;
}

// A body made of simplices (in its own frame) translating from p0 to p1.
Body translating_body(const std::string& name, const Simplices& parts, const Vec3E& p0, const Vec3E& p1) {
  Body b;
  b.name = name;
  std::vector<Vec3E> verts;
  for (const Simplex& s : parts) {
    std::vector<Vec3E> v(s.p.begin(), s.p.begin() + s.count);
    verts.insert(verts.end(), v.begin(), v.end());
    if (s.count == 3) {
      b.pieces.push_back(ConvexPiece{static_cast<int>(b.polygons.size()), v});
      b.polygons.push_back(v);
    } else if (s.count == 2) {
      b.segments.push_back({v[0], v[1]});
    } else {
      b.points.push_back(v[0]);
    }
  }
  b.mass = default_mass(verts, Exact(1));
  Motion m;
  for (const Vec3E* p : {&p0, &p1}) {
    m.control_points.push_back({1, 0, 0, (*p)[0], 0, 1, 0, (*p)[1], 0, 0, 1, (*p)[2]});
    m.weights.push_back(Exact(1));
  }
  b.motion = m;
  return b;
}

class HardGenerator {
 public:
  explicit HardGenerator(unsigned seed) : rng_(seed) {}

  // Near-degenerate constructions with exact truth (relative translations,
  // truth from translation_hits), `per_kind` of each kind.
  QuerySet constructions(int per_kind) {
    QuerySet set;
    // Names say the geometry at the built contact time; the truth (a
    // translating edge may clip the other edge at a nearby time) comes from
    // the exact swept test.
    const char* kinds[] = {"vf edge in 1e-12", "vf edge on",        "vf edge out 1e-12",     "vf vertex on",
                           "vf vertex out 1e-12", "vf shallow 1e-2", "ee near-parallel cross", "ee near-parallel off 1e-12",
                           "ee end on",        "ee end off 1e-12"};
    for (int i = 0; i < per_kind; ++i)
      for (int k = 0; k < 10; ++k) construct(set, kinds[k], k);
    return set;
  }

  // Random bodies of 1-3 simplices with vertices on the grid {-1, -1/2, 0,
  // 1/2, 1}^3 (shared vertices, coplanar and collinear features, touching
  // contacts at rational times), B translating by a grid vector relative to
  // A, both drifting; configurations that meet at t = 0 are skipped.
  QuerySet degenerate(int count) {
    QuerySet set;
    while (static_cast<int>(set.queries.size()) < count) {
      const Simplices A = grid_body(), B = grid_body();
      const Vec3E d = {q(-4, 4, 2), q(-4, 4, 2), q(-4, 4, 2)};
      bool start = false;
      for (const Simplex& a : A)
        for (const Simplex& b : B) start = start || common_point(a, b).has_value();
      if (start) continue;
      const bool hits = translation_hits(A, B, d);
      const Vec3E w = {q(-2, 2, 2), q(-2, 2, 2), q(-2, 2, 2)};
      const std::string kind = std::string("grid ") + (A.size() + B.size() > 3 ? "multi" : "single");
      push(set, kind, hits, std::nullopt, A, B, d, w);
    }
    return set;
  }

 private:
  std::mt19937_64 rng_;

  Exact q(long lo, long hi, long den) { return Exact(std::uniform_int_distribution<long>(lo, hi)(rng_), den); }
  Vec3E point() { return {q(-1000, 1000, 1000), q(-1000, 1000, 1000), q(-1000, 1000, 1000)}; }
  Exact time() { return q(1, 999, 1000); }
  Vec3E grid() { return {q(-2, 2, 2), q(-2, 2, 2), q(-2, 2, 2)}; }

  std::array<Vec3E, 3> triangle() {
    for (;;) {
      std::array<Vec3E, 3> t{point(), point(), point()};
      if (!is_zero(cross(sub(t[1], t[0]), sub(t[2], t[0])))) return t;
    }
  }
  Vec3E nonzero_point() {
    for (;;) {
      Vec3E p = point();
      if (!is_zero(p)) return p;
    }
  }

  Simplices grid_body() {
    Simplices out;
    std::vector<Vec3E> used;
    const int n = std::uniform_int_distribution<int>(1, 3)(rng_);
    auto vertex = [&] {
      if (!used.empty() && std::uniform_int_distribution<int>(0, 1)(rng_)) {
        return used[std::uniform_int_distribution<std::size_t>(0, used.size() - 1)(rng_)];
      }
      Vec3E v = grid();
      used.push_back(v);
      return v;
    };
    while (static_cast<int>(out.size()) < n) {
      const int type = std::uniform_int_distribution<int>(0, 19)(rng_);
      const int count = type < 12 ? 3 : type < 17 ? 2 : 1;
      std::vector<Vec3E> v;
      for (int k = 0; k < count; ++k) v.push_back(vertex());
      if (count == 3 && is_zero(cross(sub(v[1], v[0]), sub(v[2], v[0])))) continue;
      if (count == 2 && v[0] == v[1]) continue;
      bool duplicate = false;
      for (const Simplex& s : out)
        if (s.count == count && std::equal(v.begin(), v.end(), s.p.begin())) duplicate = true;
      if (duplicate) continue;
      out.push_back(simplex_of(v));
    }
    return out;
  }

  // A fixed in its frame, B translating by d relative to A, both drifting by w.
  static void push(QuerySet& set, const std::string& kind, bool collides, std::optional<Exact> t, const Simplices& A,
                   const Simplices& B, const Vec3E& d, const Vec3E& w) {
    const int ia = static_cast<int>(set.scene.bodies.size());
    const std::string id = std::to_string(set.queries.size());
    const Vec3E zero{0, 0, 0};
    set.scene.bodies.push_back(translating_body("h" + id + "a", A, zero, w));
    set.scene.bodies.push_back(translating_body("h" + id + "b", B, zero, add(d, w)));
    set.scene.checks.push_back({ia, ia + 1});
    set.queries.push_back(Query{kind, collides, t, ia, ia + 1});
  }

  // A random velocity with a component along n.
  Vec3E transversal(const Vec3E& n) {
    for (;;) {
      Vec3E d = point();
      if (dot(d, n) != 0) return d;
    }
  }

  void construct(QuerySet& set, const std::string& kind, int k) {
    const Exact ts = time();
    const Vec3E w = point();
    const double c12 = 1e-12;
    if (k <= 5) {  // vertex against a triangle
      const std::array<Vec3E, 3> T = triangle();
      const Vec3E N = cross(sub(T[1], T[0]), sub(T[2], T[0]));
      const int e = std::uniform_int_distribution<int>(0, 2)(rng_);
      const Vec3E& P = T[e];
      const Vec3E& Q = T[(e + 1) % 3];
      const Vec3E& R = T[(e + 2) % 3];
      Vec3E hit;     // where the point crosses the triangle's plane, at ts
      Vec3E d;       // the point's velocity relative to the triangle
      if (k <= 2) {  // near an edge: inside, on, outside by ~1e-12
        const Vec3E m = add(P, mul(q(100, 900, 1000), sub(Q, P)));
        Vec3E out = cross(N, sub(Q, P));
        if (dot(out, sub(R, P)) > 0) out = mul(Exact(-1), out);
        const double c = k == 0 ? -c12 : k == 1 ? 0.0 : c12;
        hit = add(m, mul(ex(c / norm_d(out)), out));
        d = transversal(N);
      } else if (k <= 4) {  // at a vertex, or off it by ~1e-12 (outward, in the plane)
        Vec3E out = sub(mul(Exact(2), P), add(Q, R));  // away from the opposite edge's midpoint
        hit = k == 3 ? P : add(P, mul(ex(c12 / norm_d(out)), out));
        d = transversal(N);
      } else {  // through the interior at a shallow angle (normal speed 1e-2 of the tangential)
        const Exact l1 = q(200, 400, 1000), l2 = q(200, 400, 1000);
        hit = add(P, add(mul(l1, sub(Q, P)), mul(l2, sub(R, P))));
        Vec3E tangent;
        do tangent = cross(N, point());
        while (is_zero(tangent));
        d = add(tangent, mul(ex(1e-2 * norm_d(tangent) / norm_d(N)), N));
      }
      const Vec3E b0 = sub(hit, mul(ts, d));
      const Simplices A{simplex_of({T[0], T[1], T[2]})}, B{simplex_of({b0})};
      push(set, kind, translation_hits(A, B, d), ts, A, B, d, w);
      return;
    }
    // Edge against edge.
    const Vec3E a0 = point(), a1 = add(a0, nonzero_point());
    const Vec3E dir_a = sub(a1, a0);
    Vec3E perp;
    do perp = cross(dir_a, point());
    while (is_zero(perp));
    if (k <= 7) {  // nearly parallel (angle ~1e-10), crossing or passing ~1e-12 apart at ts
      const Vec3E dir_b = add(dir_a, mul(ex(1e-10 * norm_d(dir_a) / norm_d(perp)), perp));
      const Vec3E m = add(a0, mul(q(200, 800, 1000), dir_a));
      const Exact s = q(200, 800, 1000);
      Vec3E b0 = sub(m, mul(s, dir_b)), b1 = add(m, mul(Exact(1) - s, dir_b));
      const Vec3E n = cross(dir_a, dir_b);
      if (k == 7) {
        const Vec3E off = mul(ex(c12 / norm_d(n)), n);
        b0 = add(b0, off);
        b1 = add(b1, off);
      }
      const Vec3E d = transversal(n);
      const Simplices A{simplex_of({a0, a1})}, B{simplex_of({sub(b0, mul(ts, d)), sub(b1, mul(ts, d))})};
      push(set, kind, translation_hits(A, B, d), ts, A, B, d, w);
      return;
    }
    // An end of B on A at ts, or ~1e-12 off A along their common normal.
    const Vec3E m = add(a0, mul(q(100, 900, 1000), dir_a));
    Vec3E dir_b;
    do dir_b = point();
    while (is_zero(cross(dir_a, dir_b)));
    const Vec3E n = cross(dir_a, dir_b);
    const Vec3E e0 = k == 8 ? m : add(m, mul(ex(c12 / norm_d(n)), n));
    const Vec3E e1 = add(e0, dir_b);
    const Vec3E d = transversal(n);
    const Simplices A{simplex_of({a0, a1})}, B{simplex_of({sub(e0, mul(ts, d)), sub(e1, mul(ts, d))})};
    push(set, kind, translation_hits(A, B, d), ts, A, B, d, w);
  }
};

struct HardSet {
  std::string name;    // ccd, constructed, degenerate
  std::string offset;  // "0", "1e3", ...
  QuerySet set;
  double size = 0;
  double magnitude = 1;  // of the world coordinates
};

// The filtered kernel encloses the subdivided curve by interval de
// Casteljau, whose widths grow by about an ulp of the coordinates per level:
// far from the origin its balls stop shrinking before they reach a tiny
// epsilon, and the search runs into the node budget with an exact fallback
// at nearly every test (measured at offset 1e6, f = 1e-9: 100 000 nodes and
// 20-30 s per query; at f = 1e-8, about 300 ulps, it still works).  Below
// 200 ulps only the fast kernel is run, and compared with the truth.
double certified_floor(const HardSet& h) {
  const double m = std::max(h.magnitude, 2.0);
  return 200 * (std::nextafter(m, INFINITY) - m);
}

struct Tally {
  bool cert_run = true;  // false: the certified kernel was not run (fast against the truth only)
  int n = 0, truth_coll = 0;
  int cert_safe = 0, cert_coll = 0, cert_und = 0, cert_false_safe = 0, cert_false_coll = 0;
  int fast_safe = 0, fast_coll = 0, fast_und = 0;
  int false_safe = 0;        // fast safe, truth collision
  int false_coll = 0;        // fast collision, truth safe (impossible: witnesses are exact)
  int missed_witness = 0;    // certified collision, fast not
  int extra_witness = 0;     // fast collision, certified not
  int fast_undecided = 0;    // fast undecided, certified decided
  int fast_decided = 0;      // fast safe or collision, certified undecided
  int fast_safe_cert_und_truth_safe = 0;  // of those: fast safe, truth safe (right, uncertified)
  double fast_s = 0, cert_s = 0;
  int disagreements() const { return false_safe + false_coll + missed_witness + extra_witness + fast_undecided + fast_decided; }
};

struct HardRow {
  std::string set, offset, kind;
  double f = 0;
  Tally t;
};

// Runs every query of the set with both kernels (one Verifier per kernel,
// checks one by one, timed in total).
bool verbose = false;

std::map<std::string, Tally> run_hard(const HardSet& h, double f, KernelKind certified, std::uint64_t max_nodes,
                                      bool run_certified) {
  VerifyOptions options;
  options.epsilon = decimal(f * h.size);
  options.max_depth = 62;
  options.max_nodes = max_nodes;
  std::vector<Verdict> fast(h.set.queries.size()), cert(h.set.queries.size(), Verdict::Undecided);
  double fast_s = 0, cert_s = 0;
  std::vector<KernelKind> kernels{KernelKind::Fast};
  if (run_certified) kernels.push_back(certified);
  for (KernelKind k : kernels) {
    options.kernel = k;
    const Verifier verifier(h.set.scene, options);
    const auto start = Clock::now();
    for (std::size_t i = 0; i < h.set.queries.size(); ++i) {
      const Query& q = h.set.queries[i];
      const auto t0 = Clock::now();
      const CheckResult r = verifier.check(q.body_a, q.body_b);
      (k == KernelKind::Fast ? fast : cert)[i] = r.verdict;
      if (verbose && since(t0) > 0.05)
        std::fprintf(stderr, "  %s %s f=%.0e %s query %zu (%s): %s, %llu nodes, %llu tests, %llu exact, %.3f s\n",
                     h.name.c_str(), h.offset.c_str(), f, to_string(k), i, q.kind.c_str(), to_string(r.verdict),
                     static_cast<unsigned long long>(r.stats.nodes),
                     static_cast<unsigned long long>(r.stats.contact.calls),
                     static_cast<unsigned long long>(r.stats.contact.exact_fallbacks), since(t0));
    }
    (k == KernelKind::Fast ? fast_s : cert_s) = since(start);
  }
  std::map<std::string, Tally> out;
  for (std::size_t i = 0; i < h.set.queries.size(); ++i) {
    const Query& q = h.set.queries[i];
    for (const std::string& key : {q.kind, std::string("~all")}) {
      Tally& t = out[key];
      t.cert_run = run_certified;
      ++t.n;
      if (q.collides) ++t.truth_coll;
      const Verdict x = fast[i];
      t.fast_safe += x == Verdict::Safe;
      t.fast_coll += x == Verdict::Collision;
      t.fast_und += x == Verdict::Undecided;
      if (q.collides && x == Verdict::Safe) ++t.false_safe;
      if (!q.collides && x == Verdict::Collision) ++t.false_coll;
      if (!run_certified) continue;
      const Verdict c = cert[i];
      t.cert_safe += c == Verdict::Safe;
      t.cert_coll += c == Verdict::Collision;
      t.cert_und += c == Verdict::Undecided;
      if (q.collides && c == Verdict::Safe) ++t.cert_false_safe;
      if (!q.collides && c == Verdict::Collision) ++t.cert_false_coll;
      if (c == Verdict::Collision && x != Verdict::Collision) ++t.missed_witness;
      if (x == Verdict::Collision && c != Verdict::Collision) ++t.extra_witness;
      if (x == Verdict::Undecided && c != Verdict::Undecided) ++t.fast_undecided;
      if (x != Verdict::Undecided && c == Verdict::Undecided) {
        ++t.fast_decided;
        if (x == Verdict::Safe && !q.collides) ++t.fast_safe_cert_und_truth_safe;
      }
    }
  }
  out["~all"].fast_s = fast_s;
  out["~all"].cert_s = cert_s;
  return out;
}

void write_hard_csv(const std::string& path, const std::vector<HardRow>& rows) {
  std::ofstream out(path);
  out << "set,offset,f,kind,cert_run,n,truth_coll,cert_safe,cert_coll,cert_und,cert_false_safe,cert_false_coll,fast_safe,"
         "fast_coll,fast_und,false_safe,false_coll,missed_witness,extra_witness,fast_undecided,fast_decided,"
         "fast_safe_truth_safe,fast_s,cert_s\n";
  for (const HardRow& r : rows) {
    const Tally& t = r.t;
    char line[512];
    std::snprintf(line, sizeof line, "%s,%s,%.0e,%s,%d,%d,%d,%d,%d,%d,%d,%d,%d,%d,%d,%d,%d,%d,%d,%d,%d,%d,%.6g,%.6g\n",
                  r.set.c_str(), r.offset.c_str(), r.f, r.kind.c_str(), t.cert_run ? 1 : 0, t.n, t.truth_coll, t.cert_safe, t.cert_coll,
                  t.cert_und, t.cert_false_safe, t.cert_false_coll, t.fast_safe, t.fast_coll, t.fast_und,
                  t.false_safe, t.false_coll, t.missed_witness, t.extra_witness, t.fast_undecided, t.fast_decided,
                  t.fast_safe_cert_und_truth_safe, t.fast_s, t.cert_s);
    out << line;
  }
}

std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("model name", 0) == 0) {
      const auto colon = line.find(':');
      if (colon != std::string::npos) return line.substr(colon + 2);
    }
  return "unknown CPU";
}

[[noreturn]] void usage() {
  std::fprintf(stderr,
               "usage: tmcert_speed_error [--quick] [--csv FILE] [--hard-csv FILE] [--only speed|hard]\n"
               "                          [--root DIR] [--grid-dir DIR] [--ccd N] [--ccd-exact N] [--seed S]\n"
               "                          [--reps R] [--ccd-hard N] [--hard N] [--offsets LIST] [--hard-f LIST]\n"
               "                          [--nodes N] [--sets SET/OFFSET] [--verbose]\n");
  std::exit(3);
}

}  // namespace

int main(int argc, char** argv) {
  bool quick = false;
  std::string csv, hard_csv, only, grid_dir, root = TMCERT_SOURCE_DIR;
  int ccd = -1, ccd_exact = -1, hard = -1, reps = -1;
  std::string sets_filter;  // e.g. "ccd/1e6": only that set and offset in part 2
  std::uint64_t hard_nodes = 20'000;
  std::vector<double> hard_f;
  int ccd_hard = -1;
  std::string offset_list;
  unsigned seed = 1;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) usage();
      return argv[++i];
    };
    if (a == "--quick") quick = true;
    else if (a == "--csv") csv = value();
    else if (a == "--hard-csv") hard_csv = value();
    else if (a == "--only") only = value();
    else if (a == "--root") root = value();
    else if (a == "--grid-dir") grid_dir = value();
    else if (a == "--ccd") ccd = std::atoi(value().c_str());
    else if (a == "--ccd-exact") ccd_exact = std::atoi(value().c_str());
    else if (a == "--hard") hard = std::atoi(value().c_str());
    else if (a == "--seed") seed = static_cast<unsigned>(std::atoi(value().c_str()));
    else if (a == "--reps") reps = std::atoi(value().c_str());
    else if (a == "--verbose") verbose = true;
    else if (a == "--hard-f") {
      hard_f.clear();
      std::string list = value();
      for (std::size_t at = 0; at <= list.size();) {
        const std::size_t comma = std::min(list.find(',', at), list.size());
        hard_f.push_back(std::atof(list.substr(at, comma - at).c_str()));
        at = comma + 1;
      }
    }
    else if (a == "--ccd-hard") ccd_hard = std::atoi(value().c_str());
    else if (a == "--offsets") offset_list = value();
    else if (a == "--sets") sets_filter = value();
    else if (a == "--nodes") hard_nodes = std::strtoull(value().c_str(), nullptr, 10);
    else usage();
  }
  if (!only.empty() && only != "speed" && only != "hard") usage();
  if (ccd < 0) ccd = quick ? 300 : 1000;
  if (ccd_exact < 0) ccd_exact = quick ? 50 : 100;
  if (hard < 0) hard = quick ? 10 : 20;
  if (reps < 1) reps = quick ? 2 : 5;
  if (ccd_hard < 0) ccd_hard = quick ? 300 : 1000;
  const auto all_start = Clock::now();
  bool ok = true;

  std::printf("# tmcert speed against error\n\n%s, Release build, one thread; %s run (seed %u)\n\n", cpu_model().c_str(),
              quick ? "quick" : "full", seed);

  // ---------------------------------------------------------------- part 1
  if (only != "hard") {
    std::vector<SpeedCase> cases;
    auto load = [&](const std::string& path, const std::string& name, const std::string& group, bool exact) {
      try {
        SpeedCase c{name, group, parse_scene_file(path), 0, exact};
        c.size = scene_size(c.scene);
        cases.push_back(std::move(c));
      } catch (const std::exception& e) {
        std::fprintf(stderr, "tmcert_speed_error: %s: %s (skipped)\n", path.c_str(), e.what());
      }
    };
    for (const char* v : {"collision", "near", "clear"})
      load(root + "/examples/octagons-" + v + ".json", std::string("octagons-") + v, "octagons", true);
    bool own_grid_dir = false;
    if (grid_dir.empty()) {
      own_grid_dir = true;
      grid_dir = (fs::temp_directory_path() / ("tmcert_speed_error_grid_" + std::to_string(::getpid()))).string();
      const std::string cmd = "python3 '" + root + "/bench/paper_grid.py' '" + grid_dir + "' 4 10 > /dev/null";
      if (std::system(cmd.c_str()) != 0) std::fprintf(stderr, "tmcert_speed_error: %s failed\n", cmd.c_str());
    }
    for (int n : {4, 10})
      for (const char* v : {"collision", "near", "clear"}) {
        char name[64];
        std::snprintf(name, sizeof name, "n%02d-global-%s", n, v);
        load(grid_dir + "/" + name + ".json", std::string("grid-") + name, "grid", n == 4);
      }
    if (own_grid_dir) {
      std::error_code ec;
      fs::remove_all(grid_dir, ec);  // the scenes are parsed: the files are no longer needed
    }
    for (const char* v : {"safe", "collision"})
      load(root + "/examples/gripper/gripper-" + v + ".json", std::string("gripper-") + v, "gripper", false);
    {
      const double size = 2 * std::sqrt(3.0);  // the generation cube [-1, 1]^3 (tunneling queries reach far beyond)
      QueryGenerator generator(seed);
      cases.push_back(SpeedCase{"ccd-" + std::to_string(ccd), "ccd", generator.generate(ccd).scene, size, false});
      QueryGenerator sub(seed);  // the same first queries
      cases.push_back(SpeedCase{"ccd-" + std::to_string(ccd_exact), "ccd", sub.generate(ccd_exact).scene, size, true});
    }

    std::printf("## Speed against epsilon\n\n"
                "epsilon = f x scene size (size = diagonal of the box holding every vertex under every control\n"
                "point, as default_epsilon uses; CCD: the diagonal 2 sqrt 3 of the generation cube [-1,1]^3);\n"
                "max_depth 62 (the cap), one thread; seconds = best of up to %d runs of verify_scene (bodies\n"
                "prepared in each run; repeated only while the runs took < 0.5 s in all). s/c/u = safe/collision/undecided checks;\n"
                "und.len = undecided parameter length / total length over all checks (only checks ending\n"
                "undecided); tests = contact tests (a double pre-test, when the library has one: also those it\n"
                "kept); fb = of them decided by exact arithmetic (filtered: the interval filter failed; exact: all).\n"
                "The exact kernel runs on the octagons, the n = 4 grids and the\n"
                "first %d CCD queries, and stops going to smaller f once a run takes more than %g s.\n\n",
                reps, ccd_exact, quick ? 5.0 : 20.0);
    for (const SpeedCase& c : cases)
      std::printf("- %s: %zu bodies, %zu checks, size %.6g\n", c.name.c_str(), c.scene.bodies.size(),
                  c.scene.checks.size(), c.size);
    std::printf("\n| scene | f | epsilon | kernel | verdict | s/c/u | nodes | depth | seconds | und.len | tests | fb |\n"
                "|---|--:|--:|---|---|---|--:|--:|--:|--:|--:|--:|\n");
    std::fflush(stdout);
    const double exact_limit = quick ? 5.0 : 20.0;
    const std::vector<double> fs_all = quick ? std::vector<double>{1e-1, 1e-3, 1e-5, 1e-7, 1e-9}
                                             : std::vector<double>{1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9};
    std::vector<SpeedRow> rows;
    for (const SpeedCase& c : cases) {
      // Why a kernel is no longer run at smaller f (time grows as f shrinks).
      std::map<KernelKind, std::string> stopped;
      for (double f : fs_all) {
        // Fast and filtered alternately while both still run.
        std::map<KernelKind, SpeedRow> paired;
        if (!stopped.count(KernelKind::Fast) && !stopped.count(KernelKind::Filtered)) {
          const std::vector<SpeedRow> two =
              run_speed_alternating(c, f, {KernelKind::Fast, KernelKind::Filtered}, reps);
          paired[KernelKind::Fast] = two[0];
          paired[KernelKind::Filtered] = two[1];
        }
        for (KernelKind k : kKernels) {
          if (k == KernelKind::Exact && !c.exact) continue;
          SpeedRow row;
          if (stopped.count(k)) {
            row.scene = c.name;
            row.group = c.group;
            row.size = c.size;
            row.f = f;
            row.epsilon = f * c.size;
            row.kernel = k;
            row.note = stopped[k];
            rows.push_back(row);
            std::printf("| %s | %.0e | %.3g | %s | not run: %s | | | | | | | |\n", c.name.c_str(), f, row.epsilon,
                        to_string(k), row.note.c_str());
            continue;
          }
          row = paired.count(k) ? paired[k] : run_speed(c, f, k, reps);
          if (k == KernelKind::Exact && row.seconds > exact_limit) stopped[k] = "slower than the limit at a larger f";
          if (row.und_limit > 0) stopped[k] = "node budget used up at a larger f";
          const std::uint64_t calls = row.tests(), fb = row.exact();
          std::printf("| %s | %.0e | %.3g | %s | %s | %d/%d/%d | %s | %d | %.4g | %.3g | %s | %s |\n", c.name.c_str(), f,
                      row.epsilon, to_string(k), row.verdict.c_str(), row.safe, row.collision, row.undecided,
                      fmt_count(row.nodes).c_str(), row.max_depth, row.seconds, row.und_frac, fmt_count(calls).c_str(),
                      k == KernelKind::Fast ? "–" : fmt_count(fb).c_str());
          std::fflush(stdout);
          rows.push_back(row);
        }
      }
    }

    // Ratios and certified consistency (filtered vs exact: no safe against collision).
    std::printf("\n### Time ratios (same run): filtered / fast and exact / filtered\n\n"
                "| scene | f | fast [s] | filtered [s] | exact [s] | filtered/fast | exact/filtered |\n"
                "|---|--:|--:|--:|--:|--:|--:|\n");
    std::map<std::tuple<std::string, double, int>, const SpeedRow*> by;
    for (const SpeedRow& r : rows) by[{r.scene, r.f, static_cast<int>(r.kernel)}] = &r;
    for (const SpeedCase& c : cases)
      for (double f : fs_all) {
        const SpeedRow* x = by[{c.name, f, static_cast<int>(KernelKind::Fast)}];
        const SpeedRow* y = by[{c.name, f, static_cast<int>(KernelKind::Filtered)}];
        const SpeedRow* z = c.exact ? by[{c.name, f, static_cast<int>(KernelKind::Exact)}] : nullptr;
        if (!x || !y) continue;
        char zs[32] = "–", zr[32] = "–";
        if (z && z->ran) {
          std::snprintf(zs, sizeof zs, "%.4g", z->seconds);
          std::snprintf(zr, sizeof zr, "%.1f", z->seconds / std::max(y->seconds, 1e-9));
          if ((z->verdict == "safe" && y->verdict == "collision") || (z->verdict == "collision" && y->verdict == "safe")) {
            std::printf("CONTRADICTION: %s f = %.0e: filtered %s, exact %s\n", c.name.c_str(), f, y->verdict.c_str(),
                        z->verdict.c_str());
            ok = false;
          }
        }
        std::printf("| %s | %.0e | %.4g | %.4g | %s | %.2f | %s |\n", c.name.c_str(), f, x->seconds, y->seconds, zs,
                    y->seconds / std::max(x->seconds, 1e-9), zr);
      }

    std::printf("\n### Filter statistics per predicate (filtered kernel)\n\n"
                "Contact tests, per predicate (vertex-face vf, edge-edge ee, face-vertex fv): tests / kept by the\n"
                "double pre-test (not cleared in plain double precision: kept without certified arithmetic) /\n"
                "interval calls (the clearing is proven: intervals first) / exact (the interval answer was\n"
                "uncertain: exact arithmetic ran), and in brackets the interval filter's failure rate exact /\n"
                "interval calls.  hull = feature pairs cleared by the hull test before any contact test.  Static\n"
                "tests (start check, witness candidates): conf = configurations, pairs = simplex pairs whose\n"
                "interval boxes overlap along x, fail = pairs the interval boxes and separating axes could not\n"
                "separate (an exact test follows unless an earlier hit ended the configuration: exact = exact\n"
                "tests run).%s\n\n"
                "| scene | f | vf tests/kept/interval/exact | ee tests/kept/interval/exact | fv tests/kept/interval/exact "
                "| hull | static conf | static pairs | static fail | static exact |\n"
                "|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n",
                kHasScreen<FilterCounters> ? ""
                                                           : "  (This library version has no double pre-test: kept = 0.)");
    auto funnel = [](const SpeedRow& r, int k) {
      const FilterCounters& c = r.by_kind[k];
      const std::uint64_t tests = c.calls + r.screened[k];
      if (!tests) return std::string("–");
      return fmt_count(tests) + "/" + fmt_count(r.screened[k]) + "/" + fmt_count(c.calls) + "/" +
             fmt_count(c.exact_fallbacks) + " (" + fmt_rate(c.exact_fallbacks, c.calls) + ")";
    };
    for (const SpeedRow& r : rows) {
      if (r.kernel != KernelKind::Filtered || !r.ran) continue;
      std::printf("| %s | %.0e | %s | %s | %s | %s | %s | %s | %s | %s |\n", r.scene.c_str(), r.f, funnel(r, 0).c_str(),
                  funnel(r, 1).c_str(), funnel(r, 2).c_str(), fmt_count(r.hull_clears).c_str(),
                  fmt_count(r.static_conf).c_str(), fmt_count(r.static_pairs).c_str(),
                  fmt_rate(r.static_exact, r.static_pairs).c_str(), fmt_count(r.static_tests).c_str());
    }
    if (!csv.empty()) {
      write_speed_csv(csv, rows);
      std::printf("\n(CSV: %s)\n", csv.c_str());
    }
    std::printf("\npart 1: %.1f s\n\n", since(all_start));
    std::fflush(stdout);
  }

  // ---------------------------------------------------------------- part 2
  if (only != "speed") {
    const auto hard_start = Clock::now();
    std::vector<HardSet> sets;
    if (offset_list.empty()) offset_list = quick ? "0,1e6,1e12" : "0,1e6,1e9,1e12";
    std::vector<std::pair<std::string, double>> offsets;
    for (std::size_t at = 0; at <= offset_list.size();) {
      const std::size_t comma = std::min(offset_list.find(',', at), offset_list.size());
      const std::string label = offset_list.substr(at, comma - at);
      offsets.push_back({label, std::atof(label.c_str())});
      at = comma + 1;
    }
    for (const auto& [label, o] : offsets) {
      // An exact translation along (1, -6/10, 8/10) o: not a coordinate axis.
      const Vec3E shift{Exact(o), Exact(o) * Exact(-6, 10), Exact(o) * Exact(8, 10)};
      {
        QueryGenerator generator(seed);
        HardSet h{"ccd", label, generator.generate(ccd_hard), 2 * std::sqrt(3.0), o};
        translate_scene(h.set.scene, shift);
        sets.push_back(std::move(h));
      }
      {
        HardGenerator generator(seed);
        HardSet h{"constructed", label, generator.constructions(hard), 2 * std::sqrt(3.0), o};
        translate_scene(h.set.scene, shift);
        sets.push_back(std::move(h));
      }
      {
        HardGenerator generator(seed + 1000);
        HardSet h{"degenerate", label, generator.degenerate(quick ? 200 : 500), 2 * std::sqrt(3.0), o};
        translate_scene(h.set.scene, shift);
        sets.push_back(std::move(h));
      }
    }
    const std::vector<double> hard_fs = !hard_f.empty() ? hard_f
                                        : quick          ? std::vector<double>{1e-6, 1e-9}
                                                         : std::vector<double>{1e-3, 1e-6, 1e-8, 1e-9};
    std::printf("## Fast path against the certified path on hard cases\n\n"
                "Each query is one check (two bodies, linear motions); the fast kernel (double precision, not\n"
                "certified) and the filtered kernel (certified; the exact kernel's verdicts) run on every query.\n"
                "Sets: ccd = bench/ccd_queries.h (every kind); constructed = near-degenerate constructions with\n"
                "exact truth (vertex crossing a triangle 1e-12 inside / on / 1e-12 outside an edge, on or 1e-12 off\n"
                "a vertex, through the interior at a 1e-3 slope; nearly parallel edges (angle 1e-10) crossing or\n"
                "missing by 1e-12; an edge's end on another edge or missing it by 1e-12; contacts at rational\n"
                "times); degenerate = random bodies of 1-3 simplices on the grid {-1,-1/2,0,1/2,1}^3 (shared\n"
                "vertices, coplanar and collinear features, touching contacts), translating by grid vectors, truth\n"
                "from an exact swept test. offset = the whole set translated by (1, -0.6, 0.8) x offset (exact).\n"
                "epsilon = f x 2 sqrt 3; max_depth 62; node budget %llu per check (then undecided, \"limit\").\n"
                "cert = not run: epsilon below 200 ulps of the coordinates, where the filtered kernel's interval\n"
                "enclosures of the subdivided curve stop shrinking (see the offset 1e6 table below); the fast\n"
                "kernel is then compared with the truth only.\n\n"
                "FS = fast safe, truth collision (false safe); FC = fast collision, truth safe (impossible: every\n"
                "witness is exact); miss = certified found a witness, fast did not; extra = fast found a witness,\n"
                "certified did not; f.und = fast undecided, certified decided; f.dec = fast decided, certified\n"
                "undecided (in brackets: of them fast safe with truth safe, right but unproven); cert FS/FC = the\n"
                "certified kernel against the truth (must be 0/0).\n\n"
                "| set | offset | f | n | truth coll | cert s/c/u | fast s/c/u | FS | FC | miss | extra | f.und "
                "| f.dec | cert FS/FC | fast [s] | cert [s] |\n"
                "|---|--:|--:|--:|--:|---|---|--:|--:|--:|--:|--:|--:|---|--:|--:|\n",
                static_cast<unsigned long long>(hard_nodes));
    std::fflush(stdout);
    std::vector<HardRow> rows;
    for (const HardSet& h : sets)
      for (double f : hard_fs) {
        if (!sets_filter.empty() && sets_filter != h.name + "/" + h.offset) continue;
        const bool certified = decimal(f * h.size) >= Exact(certified_floor(h));
        const std::map<std::string, Tally> tallies = run_hard(h, f, KernelKind::Filtered, hard_nodes, certified);
        for (const auto& [kind, t] : tallies) rows.push_back(HardRow{h.name, h.offset, kind, f, t});
        const Tally& t = tallies.at("~all");
        if (t.cert_false_safe || t.cert_false_coll) ok = false;
        if (certified)
          std::printf("| %s | %s | %.0e | %d | %d | %d/%d/%d | %d/%d/%d | %d | %d | %d | %d | %d | %d (%d) | %d/%d | %.3g | %.3g |\n",
                      h.name.c_str(), h.offset.c_str(), f, t.n, t.truth_coll, t.cert_safe, t.cert_coll, t.cert_und,
                      t.fast_safe, t.fast_coll, t.fast_und, t.false_safe, t.false_coll, t.missed_witness,
                      t.extra_witness, t.fast_undecided, t.fast_decided, t.fast_safe_cert_und_truth_safe,
                      t.cert_false_safe, t.cert_false_coll, t.fast_s, t.cert_s);
        else
          std::printf("| %s | %s | %.0e | %d | %d | not run | %d/%d/%d | %d | %d | – | – | – | – | – | %.3g | – |\n",
                      h.name.c_str(), h.offset.c_str(), f, t.n, t.truth_coll, t.fast_safe, t.fast_coll, t.fast_und,
                      t.false_safe, t.false_coll, t.fast_s);
        std::fflush(stdout);
      }
    std::printf("\n### By kind: every kind with a false safe or a missed witness of the fast path\n\n"
                "| set | offset | f | kind | n | truth coll | cert s/c/u | fast s/c/u | FS | miss | f.und | f.dec |\n"
                "|---|--:|--:|---|--:|--:|---|---|--:|--:|--:|--:|\n");
    int shown = 0;
    for (const HardRow& r : rows) {
      if (r.kind == "~all" || (r.t.false_safe == 0 && r.t.missed_witness == 0)) continue;
      const Tally& t = r.t;
      char cert[64] = "not run";
      if (t.cert_run) std::snprintf(cert, sizeof cert, "%d/%d/%d", t.cert_safe, t.cert_coll, t.cert_und);
      std::printf("| %s | %s | %.0e | %s | %d | %d | %s | %d/%d/%d | %d | %d | %d | %d |\n", r.set.c_str(),
                  r.offset.c_str(), r.f, r.kind.c_str(), t.n, t.truth_coll, cert, t.fast_safe, t.fast_coll,
                  t.fast_und, t.false_safe, t.missed_witness, t.fast_undecided, t.fast_decided);
      ++shown;
    }
    if (!shown) std::printf("| (none) | | | | | | | | | | | |\n");

    // The exact kernel on the constructed set at offset 0 and 1e6: its
    // verdicts against the filtered kernel's (certified both: never safe
    // against collision; safe/undecided may differ by the balls' rounding).
    std::printf("\n### Exact kernel against filtered (both certified)\n\n"
                "The first 200 queries of the constructed set without its shallow crossings (thousands of nodes\n"
                "each in exact arithmetic) and of the degenerate set; verdicts may differ only between a decision\n"
                "and undecided (the balls are rounded differently), never safe against collision.\n\n"
                "| set | offset | f | n | same verdict | safe vs undecided | collision vs undecided | contradictions |"
                " exact [s] | filtered [s] |\n|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n");
    for (const HardSet& h : sets) {
      if (h.name == "ccd" || (h.offset != "0" && !(h.offset == "1e6" && h.name == "constructed"))) continue;
      if (!sets_filter.empty() && sets_filter != h.name + "/" + h.offset) continue;
      const double f = 1e-6;
      VerifyOptions options;
      options.epsilon = decimal(f * h.size);
      options.max_depth = 62;
      options.max_nodes = hard_nodes;
      std::vector<Verdict> v[2];
      double secs[2] = {0, 0};
      int slot = 0;
      for (KernelKind k : {KernelKind::Exact, KernelKind::Filtered}) {
        options.kernel = k;
        const Verifier verifier(h.set.scene, options);
        const auto start = Clock::now();
        for (const Query& q : h.set.queries) {
          if (q.kind.rfind("vf shallow", 0) == 0 || v[slot].size() >= 200) continue;
          const auto t0 = Clock::now();
          const CheckResult r = verifier.check(q.body_a, q.body_b);
          v[slot].push_back(r.verdict);
          if (verbose && since(t0) > 0.05)
            std::fprintf(stderr, "  %s %s %s (%s): %s, %llu nodes, %.3f s\n", h.name.c_str(), h.offset.c_str(),
                         to_string(k), q.kind.c_str(), to_string(r.verdict),
                         static_cast<unsigned long long>(r.stats.nodes), since(t0));
        }
        secs[slot++] = since(start);
      }
      int same = 0, su = 0, cu = 0, contra = 0;
      for (std::size_t i = 0; i < v[0].size(); ++i) {
        const Verdict a = v[0][i], b = v[1][i];
        if (a == b) ++same;
        else if (a == Verdict::Undecided || b == Verdict::Undecided)
          ((a == Verdict::Safe || b == Verdict::Safe) ? su : cu)++;
        else ++contra;
      }
      if (contra) ok = false;
      std::printf("| %s | %s | %.0e | %zu | %d | %d | %d | %d | %.3g | %.3g |\n", h.name.c_str(), h.offset.c_str(), f,
                  v[0].size(), same, su, cu, contra, secs[0], secs[1]);
    }
    // Far from the origin: the three kernels on the first CCD queries, all
    // translated by 1e6, at epsilon below the filtered kernel's floor.
    if (sets_filter.empty()) {
      QueryGenerator generator(seed);
      QuerySet far = generator.generate(10);
      translate_scene(far.scene, Vec3E{Exact(1'000'000), Exact(-600'000), Exact(800'000)});
      std::printf("\n### Far from the origin: the three kernels at offset 1e6\n\n"
                  "The first 10 CCD queries translated by (1, -0.6, 0.8) x 1e6, node budget 5000 per check; per kernel:\n"
                  "verdicts s/c/u, wrong verdicts against the truth, nodes, deepest level, exact fallbacks, seconds.\n\n"
                  "| f | epsilon | kernel | s/c/u | wrong | nodes | depth | exact fb | seconds |\n"
                  "|--:|--:|---|---|--:|--:|--:|--:|--:|\n");
      for (double f : {1e-7, 1e-9}) {
        VerifyOptions options;
        options.epsilon = decimal(f * 2 * std::sqrt(3.0));
        options.max_depth = 62;
        options.max_nodes = 5000;
        for (KernelKind k : {KernelKind::Exact, KernelKind::Filtered, KernelKind::Fast}) {
          options.kernel = k;
          const Verifier verifier(far.scene, options);
          int v[3] = {0, 0, 0}, wrong = 0, depth = 0;
          std::uint64_t nodes = 0, fb = 0;
          const auto start = Clock::now();
          for (const Query& q : far.queries) {
            const CheckResult r = verifier.check(q.body_a, q.body_b);
            ++v[static_cast<int>(r.verdict)];
            if ((r.verdict == Verdict::Safe && q.collides) || (r.verdict == Verdict::Collision && !q.collides)) ++wrong;
            nodes += r.stats.nodes;
            depth = std::max(depth, r.stats.max_depth);
            fb += r.stats.contact.exact_fallbacks;
          }
          if (wrong && k != KernelKind::Fast) ok = false;
          std::printf("| %.0e | %.3g | %s | %d/%d/%d | %d | %llu | %d | %llu | %.3g |\n", f,
                      CGAL::to_double(*options.epsilon), to_string(k), v[0], v[1], v[2], wrong,
                      static_cast<unsigned long long>(nodes), depth, static_cast<unsigned long long>(fb), since(start));
          std::fflush(stdout);
        }
      }
    }
    if (!hard_csv.empty()) {
      write_hard_csv(hard_csv, rows);
      std::printf("\n(CSV: %s)\n", hard_csv.c_str());
    }
    std::printf("\npart 2: %.1f s\n", since(hard_start));
  }
  std::printf("\ntotal: %.1f s; certified verdicts %s\n", since(all_start),
              ok ? "never contradict the truth or each other" : "CONTRADICT the truth or each other (see above)");
  return ok ? 0 : 1;
}
