// Continuous-collision queries (vertex-face, edge-edge, linear motion, both
// primitives moving), generated with known ground truth: false safe, false
// collision, undecided rates and time per query for epsilon from 1e-2 to
// 1e-8 of each query's size.  Usage: tmcert_ccd_bench [queries] [seed] [fraction] [max_stops]
// (a fraction restricts the run to that one epsilon row, for profiling;
// max_stops replaces VerifyOptions::max_stops, to see what the stop budget
// costs).
//
// tmcert_ccd_bench --scene SCENE.json [--truth TRUTH.json] [--max-stops N] [--slowest K]
// [--cpu-time] [--kernel filtered|exact]: times every
// check of a given scene the same way (one by one, in process, one
// verifier for the scene), e.g. a set converted by
// scripts/ccd_csv_to_scene.py, with its --truth-out list for false safe /
// false collision.
#include "bench/ccd_queries.h"
#include "src/io/parse.h"
#include "src/verify/verify.h"

#include <nlohmann/json.hpp>

#include <fstream>
#include <string>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <map>

using namespace tmcert;
using namespace tmcert::bench;

// TMCERT_EXACT_RESOLUTION=0 runs the ball search alone (as before exact
// resolution), for before/after tables from one build.
inline bool exact_resolution_enabled() {
  const char* v = std::getenv("TMCERT_EXACT_RESOLUTION");
  return !(v && std::string(v) == "0");
}

namespace {

struct Row {
  int queries = 0, colliding = 0, false_safe = 0, false_collision = 0;
  int undecided_free = 0, free = 0, undecided_colliding = 0, collision_found = 0, prefiltered = 0;
  int bracket_violations = 0;
  std::vector<double> micros;
};

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[static_cast<std::size_t>(p * (v.size() - 1))];
}

double mean(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x;
  return v.empty() ? 0 : s / v.size();
}

// Queries are generated in [-1, 1]^3 (scene size 2 per axis); epsilon is a
// fraction of that.
std::uint64_t g_max_stops = VerifyOptions{}.max_stops;
std::size_t g_slowest = 0;  // --slowest K: list the K slowest checks on stderr
// --cpu-time: time each check by the thread's CPU clock instead of the wall
// clock (on a loaded machine, wall times of single checks include the
// time slices other processes took).
bool g_cpu_time = false;
KernelKind g_kernel = KernelKind::Filtered;  // --kernel (--scene only)

double now_us() {
  if (g_cpu_time) {
    timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return ts.tv_sec * 1e6 + ts.tv_nsec * 1e-3;
  }
  return std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

Row run(const QuerySet& set, double fraction, std::map<std::string, Row>* by_kind, double* setup_us) {
  Row row;
  VerifyOptions options;
  options.exact_resolution = exact_resolution_enabled();
  options.max_stops = g_max_stops;
  char text[64];
  std::snprintf(text, sizeof text, "%.3g", 2 * fraction);
  Exact epsilon;
  parse_exact(text, epsilon);
  options.epsilon = epsilon;
  options.max_depth = 60;
  // One verifier for the whole scene: its set-up (a swept box per body) is
  // reported separately, per query; bodies are prepared lazily inside the
  // timed checks.
  const auto setup_start = std::chrono::steady_clock::now();
  const Verifier verifier(set.scene, options);
  *setup_us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - setup_start).count() /
              set.queries.size();
  for (const Query& q : set.queries) {
    const auto start = std::chrono::steady_clock::now();
    const CheckResult r = verifier.check(q.body_a, q.body_b);
    const double us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
    Row* group = by_kind ? &(*by_kind)[q.collides ? "~all colliding" : "~all non-colliding"] : nullptr;
    for (Row* target : {&row, by_kind ? &(*by_kind)[q.kind] : nullptr, group}) {
      if (!target) continue;
      Row& t = *target;
      ++t.queries;
      t.micros.push_back(us);
      if (r.stats.prefiltered) ++t.prefiltered;
      if (q.collides) {
        ++t.colliding;
        if (r.verdict == Verdict::Safe) ++t.false_safe;
        if (r.verdict == Verdict::Undecided) ++t.undecided_colliding;
        if (r.verdict == Verdict::Collision) ++t.collision_found;
        if (q.contact_time && r.first_contact && r.first_contact->first > *q.contact_time) ++t.bracket_violations;
      } else {
        ++t.free;
        if (r.verdict == Verdict::Collision) ++t.false_collision;
        if (r.verdict == Verdict::Undecided) ++t.undecided_free;
      }
    }
  }
  return row;
}

void print_row(const char* label, const Row& r, double setup_us) {
  std::printf("| %-16s | %6d | %5d | %4d | %4d | %8.2f%% | %8.2f%% | %6.1f%% | %8.2f | %9.2f | %9.1f | %7.2f |\n", label, r.queries,
              r.colliding, r.false_safe, r.false_collision, r.free ? 100.0 * r.undecided_free / r.free : 0.0,
              r.colliding ? 100.0 * r.undecided_colliding / r.colliding : 0.0,
              r.queries ? 100.0 * r.prefiltered / r.queries : 0.0, percentile(r.micros, 0.5), mean(r.micros),
              r.micros.empty() ? 0.0 : *std::max_element(r.micros.begin(), r.micros.end()), setup_us);
}

void header(const char* first) {
  std::printf("| %-16s | %6s | %5s | %4s | %4s | %9s | %9s | %7s | %8s | %9s | %9s | %7s |\n", first, "n", "coll",
              "FS", "FC", "und.free", "und.coll", "prefilt", "med us", "mean us", "max us", "setup");
  std::printf("|%s|\n", std::string(130, '-').c_str());
}

}  // namespace

// --scene: every check of a scene file, timed one by one.
static int run_scene(const std::string& scene_file, const std::string& truth_file) {
  const Scene scene = parse_scene_file(scene_file);
  VerifyOptions options;
  options.exact_resolution = exact_resolution_enabled();
  options.kernel = g_kernel;
  options.epsilon = scene.epsilon ? *scene.epsilon : default_epsilon(scene);
  options.max_depth = scene.max_depth;
  options.max_stops = g_max_stops;
  std::vector<int> truth(scene.checks.size(), -1);  // 1 colliding, 0 free, -1 unknown
  if (!truth_file.empty()) {
    std::ifstream in(truth_file);
    const nlohmann::json t = nlohmann::json::parse(in);
    if (!t.is_array() || t.size() != scene.checks.size()) {
      std::fprintf(stderr, "%s: expected a list of %zu entries\n", truth_file.c_str(), scene.checks.size());
      return 3;
    }
    for (std::size_t i = 0; i < t.size(); ++i)
      if (t[i].contains("truth") && t[i]["truth"].is_boolean()) truth[i] = t[i]["truth"].get<bool>() ? 1 : 0;
  }
  const auto setup_start = std::chrono::steady_clock::now();
  const Verifier verifier(scene, options);
  const double setup_us =
      std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - setup_start).count();
  std::map<std::string, Row> groups;
  std::vector<std::pair<double, std::size_t>> times;
  for (std::size_t i = 0; i < scene.checks.size(); ++i) {
    const double start = now_us();
    const CheckResult r = verifier.check(scene.checks[i].first, scene.checks[i].second);
    const double us = now_us() - start;
    times.emplace_back(us, i);
    const std::string group = truth[i] == 1 ? "~colliding" : truth[i] == 0 ? "~free" : "~no truth";
    for (Row* t : {&groups["all"], &groups[group]}) {
      ++t->queries;
      t->micros.push_back(us);
      if (r.stats.prefiltered) ++t->prefiltered;
      if (truth[i] == 1) {
        ++t->colliding;
        if (r.verdict == Verdict::Safe) ++t->false_safe;
        if (r.verdict == Verdict::Undecided) ++t->undecided_colliding;
      } else if (truth[i] == 0) {
        ++t->free;
        if (r.verdict == Verdict::Collision) ++t->false_collision;
        if (r.verdict == Verdict::Undecided) ++t->undecided_free;
      }
    }
  }
  std::printf("tmcert CCD scene %s: %zu checks, %s kernel, epsilon %s; %s times per check, one by one;\n"
              "setup = the verifier's set-up divided by the number of checks\n\n",
              scene_file.c_str(), scene.checks.size(), to_string(options.kernel), to_string(*options.epsilon).c_str(),
              g_cpu_time ? "thread CPU" : "wall");
  header("checks");
  for (const auto& [name, r] : groups) print_row(name.c_str(), r, setup_us / scene.checks.size());
  std::sort(times.rbegin(), times.rend());
  for (std::size_t k = 0; k < std::min(g_slowest, times.size()); ++k) {
    const std::size_t i = times[k].second;
    const CheckResult r = verifier.check(scene.checks[i].first, scene.checks[i].second);
    std::fprintf(stderr, "slow: check %zu (%s x %s) %.1f us: %s, truth %d, nodes %llu, exact pieces %llu, %s\n", i,
                 scene.bodies[scene.checks[i].first].name.c_str(), scene.bodies[scene.checks[i].second].name.c_str(),
                 times[k].first, to_string(r.verdict), truth[i], static_cast<unsigned long long>(r.stats.nodes),
                 static_cast<unsigned long long>(r.stats.exact_pieces),
                 r.witness ? (r.witness->root ? "irrational witness" : "rational witness") : "no witness");
  }
  return groups["all"].false_safe == 0 && groups["all"].false_collision == 0 ? 0 : 1;
}


int main(int argc, char** argv) {
  if (argc > 1 && std::string(argv[1]) == "--scene") {
    std::string truth;
    bool ok = argc >= 3;
    for (int i = 3; ok && i < argc; i += 2) {
      const std::string flag = argv[i];
      if (flag == "--cpu-time") {
        g_cpu_time = true;
        --i;  // no value
      } else if (i + 1 >= argc) ok = false;
      else if (flag == "--truth") truth = argv[i + 1];
      else if (flag == "--max-stops") g_max_stops = std::strtoull(argv[i + 1], nullptr, 10);
      else if (flag == "--slowest") g_slowest = std::strtoull(argv[i + 1], nullptr, 10);
      else if (flag == "--kernel" && std::string(argv[i + 1]) == "filtered") g_kernel = KernelKind::Filtered;
      else if (flag == "--kernel" && std::string(argv[i + 1]) == "exact") g_kernel = KernelKind::Exact;
      else ok = false;
    }
    if (!ok) {
      std::fprintf(stderr,
                   "usage: tmcert_ccd_bench --scene SCENE.json [--truth TRUTH.json] [--max-stops N] [--slowest K] "
                   "[--cpu-time] [--kernel filtered|exact]\n");
      return 2;
    }
    try {
      return run_scene(argv[2], truth);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "tmcert_ccd_bench: %s\n", e.what());
      return 3;
    }
  }
  const int count = argc > 1 ? std::atoi(argv[1]) : 4000;
  const unsigned seed = argc > 2 ? static_cast<unsigned>(std::atoi(argv[2])) : 1;
  QueryGenerator generator(seed);
  const QuerySet set = generator.generate(count);
  std::printf("tmcert CCD queries: %d (seed %u), filtered kernel, one scene, a check per query;\n"
              "epsilon = fraction x 2 (queries are generated in [-1,1]^3); times are per check, measured one by one;\n"
              "setup = the verifier's per-scene set-up (swept boxes) divided by the number of queries\n",
              count, seed);
  std::printf("FS = false safe (must be 0), FC = false collision (must be 0), und.free = undecided among\n"
              "non-colliding, und.coll = undecided among colliding (no exact witness found), prefilt = cleared by the\n"
              "swept-hull prefilter alone\n\n");
  header("epsilon");
  std::map<std::string, Row> kinds;
  int total_fs = 0, total_fc = 0, violations = 0;
  double kinds_setup = 0;
  std::vector<double> fractions{1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8};
  if (argc > 3) fractions = {std::atof(argv[3])};
  if (argc > 4) g_max_stops = std::strtoull(argv[4], nullptr, 10);
  for (double fraction : fractions) {
    double setup_us = 0;
    const Row r = run(set, fraction, fraction == 1e-6 ? &kinds : nullptr, &setup_us);
    if (fraction == 1e-6) kinds_setup = setup_us;
    char label[32];
    std::snprintf(label, sizeof label, "%.0e", fraction);
    print_row(label, r, setup_us);
    total_fs += r.false_safe;
    total_fc += r.false_collision;
    violations += r.bracket_violations;
  }
  std::printf("\nBy kind at epsilon = 1e-6:\n\n");
  header("kind");
  for (const auto& [kind, r] : kinds) print_row(kind.c_str(), r, kinds_setup);
  std::printf("\nfirst_contact lower ends after a known contact time: %d (must be 0)\n", violations);
  return total_fs == 0 && total_fc == 0 && violations == 0 ? 0 : 1;
}
