// The asymptotic experiment of Schroecker & Weber, Section 7.2 (Tables 1
// and 2): two unit squares subdivided into n x n sub-squares, one moving by a
// rational rigid motion of degree 8, in a collision, a near-collision and a
// clear no-collision variant, with a global or an individual mass
// distribution.  Scenes come from bench/paper_grid.py.
//
// Usage: tmcert_paper_grid DIR [repeats] [threads]
//
// Runs verify_scene (filtered kernel, `threads` threads (default 1), the
// scene's epsilon and max_depth) `repeats` times (default 3; only once when
// a run takes longer than 60 s) on every scene file of DIR and prints a
// markdown table with the median wall time, the parse time, and for n <= 20
// the time of the all-pairs reference (no hierarchy) in the same run, next to
// the paper's figures for n <= 10.  Exit status 0 when every verdict is the
// expected one (collision / safe / safe) and the reference agrees, 1
// otherwise, 3 on bad usage.
#include "src/io/parse.h"
#include "src/verify/verify.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

using namespace tmcert;

// TMCERT_EXACT_RESOLUTION=0 runs the ball search alone (as before exact
// resolution), for before/after tables from one build.
inline bool exact_resolution_enabled() {
  const char* v = std::getenv("TMCERT_EXACT_RESOLUTION");
  return !(v && std::string(v) == "0");
}
namespace fs = std::filesystem;

namespace {

// Schroecker & Weber, Tables 1 (global mass) and 2 (individual masses):
// n = 1..10, columns total [s], average [s] for Collision, Near-Collision,
// No-Collision.  Copied from the paper's .tex source.
constexpr double kTable1[10][6] = {
    {0.17, 0.17, 0.49, 0.49, 0.11, 0.11},       {1.58, 0.10, 2.43, 0.15, 1.12, 0.07},
    {5.91, 0.07, 9.49, 0.12, 4.57, 0.06},       {16.07, 0.06, 25.78, 0.10, 12.17, 0.05},
    {35.09, 0.06, 57.05, 0.09, 27.60, 0.04},    {67.41, 0.05, 110.34, 0.09, 54.82, 0.04},
    {118.42, 0.05, 193.47, 0.08, 98.25, 0.04},  {194.16, 0.05, 318.39, 0.08, 164.00, 0.04},
    {300.88, 0.05, 494.69, 0.07, 258.29, 0.04}, {448.09, 0.04, 738.22, 0.07, 388.67, 0.04},
};
constexpr double kTable2[10][6] = {
    {0.17, 0.17, 0.49, 0.49, 0.11, 0.11},       {1.21, 0.07, 1.85, 0.12, 0.98, 0.06},
    {3.68, 0.04, 5.99, 0.07, 3.22, 0.04},       {9.12, 0.04, 15.23, 0.06, 8.27, 0.03},
    {19.01, 0.03, 32.59, 0.05, 18.74, 0.03},    {35.69, 0.03, 62.36, 0.05, 36.97, 0.03},
    {61.59, 0.03, 108.64, 0.04, 66.01, 0.03},   {99.71, 0.02, 177.00, 0.04, 109.79, 0.03},
    {153.22, 0.02, 274.48, 0.04, 172.29, 0.03}, {226.60, 0.02, 407.89, 0.04, 258.99, 0.03},
};

constexpr double kSingleRunAbove = 60.0;  // seconds: do not repeat longer runs

struct Entry {
  fs::path path;
  int n = 0;              // 0: not from paper_grid.py's naming pattern
  std::string strategy;   // "global" / "individual"
  std::string variant;    // "collision" / "near" / "clear"
  int variant_rank = 9;
  int strategy_rank = 9;
};

Entry classify(const fs::path& path) {
  Entry e;
  e.path = path;
  static const std::regex pattern(R"(n(\d+)-(global|individual)-(collision|near|clear)\.json)");
  std::smatch m;
  const std::string name = path.filename().string();
  if (std::regex_match(name, m, pattern)) {
    e.n = std::atoi(m[1].str().c_str());
    e.strategy = m[2];
    e.variant = m[3];
    e.strategy_rank = e.strategy == "global" ? 0 : 1;
    e.variant_rank = e.variant == "collision" ? 0 : e.variant == "near" ? 1 : 2;
  }
  return e;
}

// Contact features as the verifier counts them (src/verify/prepared.cpp):
// vertices = every polygon's vertices as written, edges = convex-piece edges
// with shared ones once, faces = convex pieces.
struct FeatureCounts {
  std::size_t vertices = 0, edges = 0, faces = 0;
};

FeatureCounts count_features(const Body& b) {
  FeatureCounts c;
  std::set<std::pair<Vec3E, Vec3E>> edges;
  for (const ConvexPiece& piece : b.pieces) {
    ++c.faces;
    for (std::size_t k = 0; k < piece.vertices.size(); ++k) {
      const Vec3E& p = piece.vertices[k];
      const Vec3E& q = piece.vertices[(k + 1) % piece.vertices.size()];
      edges.insert(p < q ? std::pair{p, q} : std::pair{q, p});
    }
  }
  c.edges = edges.size() + b.segments.size() + b.points.size();
  for (const auto& poly : b.polygons) c.vertices += poly.size();
  c.vertices += 2 * b.segments.size() + b.points.size();
  return c;
}

// Feature pairs at the root of every check (moving body's vertices x other
// faces + edges x edges + faces x vertices), summed over the checks.
std::uint64_t root_pairs(const Scene& scene) {
  std::vector<FeatureCounts> counts;
  for (const Body& b : scene.bodies) counts.push_back(count_features(b));
  std::uint64_t total = 0;
  for (const auto& [a, b] : scene.checks) {
    const FeatureCounts& x = counts[a];
    const FeatureCounts& y = counts[b];
    total += x.vertices * y.faces + x.edges * y.edges + x.faces * y.vertices;
  }
  return total;
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

struct Row {
  Entry entry;
  std::string verdict;
  bool expected = false;
  std::array<int, 3> by_verdict{};  // safe, collision, undecided checks
  int prefiltered = 0;              // checks cleared by the swept-box prefilter
  double seconds = 0;               // median wall time of verify_scene
  double parse_seconds = 0;         // one parse of the scene file
  double reference_seconds = -1;    // all pairs (no hierarchy), median; < 0: not run
  std::uint64_t sphere_tests = 0;
  int runs = 0;
  std::uint64_t nodes = 0, calls = 0, fallbacks = 0, pairs = 0;
  int max_depth = 0;
  std::size_t checks = 0;
  std::string error;
};

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || argc > 4) {
    std::fprintf(stderr, "usage: tmcert_paper_grid DIR [repeats] [threads]\n");
    return 3;
  }
  const fs::path dir = argv[1];
  const int repeats = argc > 2 ? std::max(1, std::atoi(argv[2])) : 3;
  const int threads = argc > 3 ? std::max(1, std::atoi(argv[3])) : 1;
  constexpr int kReferenceUpTo = 20;  // the all-pairs reference is run for n <= this
  std::vector<Entry> entries;
  std::error_code ec;
  for (const auto& item : fs::directory_iterator(dir, ec)) {
    const fs::path& p = item.path();
    if (item.is_regular_file() && p.extension() == ".json" && p.filename() != "paper_grid.json")
      entries.push_back(classify(p));
  }
  if (ec) {
    std::fprintf(stderr, "tmcert_paper_grid: %s: %s\n", dir.string().c_str(), ec.message().c_str());
    return 3;
  }
  std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
    const bool pa = a.n > 0, pb = b.n > 0;
    if (pa != pb) return pa;
    return std::tie(a.n, a.strategy_rank, a.variant_rank, a.path) <
           std::tie(b.n, b.strategy_rank, b.variant_rank, b.path);
  });

  std::printf("tmcert vs. Schroecker & Weber, Sec. 7.2 (Tables 1 and 2): two unit squares of n x n sub-squares,\n"
              "a degree-8 rational rigid motion, epsilon and max_depth from the scenes (bench/paper_grid.py).\n"
              "ours: %s, this 2-core machine, Release build, filtered kernel, %d thread(s), bounding-volume\n"
              "hierarchies; total = median wall time of verify_scene over %d run(s) (preparing the bodies and\n"
              "the search); parse = reading the scene file once (JSON, exact numbers, polygon checks, masses);\n"
              "all-pairs = the same verify_scene without hierarchies (every feature pair carried from the root),\n"
              "same runs, n <= %d; all-pairs/ours = ratio of the two.\n"
              "paper: Intel Core 2 Duo 3 GHz, g++ 4.8.2 (2014), average over 100 runs.\n"
              "per pair = total / n^4 (the paper's \"average\": per test of one moving vs one fixed sub-square);\n"
              "paper/ours = ratio of the total times. global = one mass distribution for the moving surface;\n"
              "individual = one body (own mass) per moving sub-square, n^2 checks against the fixed surface.\n"
              "checks s/c/u (pf) = safe/collision/undecided checks (pf: of them cleared by the swept-box prefilter);\n"
              "pairs = feature pairs at the roots of all checks without hierarchies; spheres = hierarchy node pairs\n"
              "tested; predicate calls = contact tests; fb = exact fallbacks of the interval filter.\n\n",
              cpu_model().c_str(), threads, repeats, kReferenceUpTo);
  std::printf("| n | mass | variant | verdict | checks s/c/u (pf) | total [s] | parse [s] | per pair [s] | nodes | max depth "
              "| pairs | spheres | predicate calls | fb | all-pairs [s] | all-pairs/ours | paper total [s] | paper avg [s] "
              "| paper/ours |\n");
  std::printf("|--:|---|---|---|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n");
  std::fflush(stdout);

  bool all_expected = true, any_single_run = false;
  std::vector<std::string> notes;
  for (const Entry& e : entries) {
    Row row;
    row.entry = e;
    try {
      const auto parse_start = std::chrono::steady_clock::now();
      const Scene scene = parse_scene_file(e.path.string());
      row.parse_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - parse_start).count();
      VerifyOptions options;
      options.exact_resolution = exact_resolution_enabled();
      options.kernel = KernelKind::Filtered;
      options.epsilon = scene.epsilon ? *scene.epsilon : default_epsilon(scene);
      options.max_depth = scene.max_depth;
      row.pairs = root_pairs(scene);
      row.checks = scene.checks.size();
      std::vector<double> times;
      SceneResult result;
      for (int r = 0; r < repeats; ++r) {
        const auto start = std::chrono::steady_clock::now();
        SceneResult run = verify_scene(scene, options, threads);
        times.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        if (r == 0) result = std::move(run);
        if (times.back() > kSingleRunAbove) break;
      }
      std::sort(times.begin(), times.end());
      row.runs = static_cast<int>(times.size());
      row.seconds = times[times.size() / 2];
      if (e.n > 0 && e.n <= kReferenceUpTo) {
        VerifyOptions reference = options;
        reference.hierarchy = false;
        std::vector<double> ref_times;
        for (int r = 0; r < repeats; ++r) {
          const auto start = std::chrono::steady_clock::now();
          const SceneResult run = verify_scene(scene, reference, threads);
          ref_times.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
          if (run.verdict != result.verdict) row.error = "the all-pairs reference gives " + std::string(to_string(run.verdict));
          if (ref_times.back() > kSingleRunAbove) break;
        }
        std::sort(ref_times.begin(), ref_times.end());
        row.reference_seconds = ref_times[ref_times.size() / 2];
      }
      row.verdict = to_string(result.verdict);
      for (const CheckResult& c : result.checks) {
        row.nodes += c.stats.nodes;
        row.calls += c.stats.contact.calls;
        row.fallbacks += c.stats.contact.exact_fallbacks;
        row.sphere_tests += c.stats.sphere_tests;
        row.max_depth = std::max(row.max_depth, c.stats.max_depth);
        ++row.by_verdict[c.verdict == Verdict::Safe ? 0 : c.verdict == Verdict::Collision ? 1 : 2];
        if (c.stats.prefiltered) ++row.prefiltered;
      }
      const Verdict want = e.variant == "collision" ? Verdict::Collision : Verdict::Safe;
      row.expected = e.n == 0 || result.verdict == want;
    } catch (const std::exception& ex) {
      row.error = ex.what();
    }
    if (!row.error.empty() || !row.expected) all_expected = false;

    const std::string name = e.n > 0 ? std::to_string(e.n) : e.path.filename().string();
    if (!row.error.empty()) {
      std::printf("| %s | %s | %s | ERROR | | | | | | | | | | | | | | | |\n", name.c_str(), e.strategy.c_str(),
                  e.variant.c_str());
      notes.push_back(e.path.filename().string() + ": " + row.error);
      std::fflush(stdout);
      continue;
    }
    char paper_total[32] = "-", paper_avg[32] = "-", ratio[32] = "-";
    if (e.n >= 1 && e.n <= 10) {
      const auto& table = e.strategy == "global" ? kTable1 : kTable2;
      const double total = table[e.n - 1][2 * e.variant_rank], avg = table[e.n - 1][2 * e.variant_rank + 1];
      std::snprintf(paper_total, sizeof paper_total, "%.2f", total);
      std::snprintf(paper_avg, sizeof paper_avg, "%.2f", avg);
      if (row.seconds > 0) std::snprintf(ratio, sizeof ratio, "%.0f", total / row.seconds);
    }
    if (row.runs < repeats) any_single_run = true;
    const double n4 = e.n > 0 ? static_cast<double>(e.n) * e.n * e.n * e.n : 1.0;
    std::string verdict = row.verdict;
    if (!row.expected) verdict += " (WRONG: expected " + std::string(e.variant == "collision" ? "collision" : "safe") + ")";
    char reference[32] = "-", reference_ratio[32] = "-";
    if (row.reference_seconds >= 0) {
      std::snprintf(reference, sizeof reference, "%.4f", row.reference_seconds);
      if (row.seconds > 0) std::snprintf(reference_ratio, sizeof reference_ratio, "%.1f", row.reference_seconds / row.seconds);
    }
    std::printf("| %s | %s | %s | %s | %d/%d/%d (%d) | %.4f%s | %.4f | %.2e | %llu | %d | %llu | %llu | %llu | %llu | %s | %s | %s | %s | %s |\n",
                name.c_str(), e.strategy.c_str(), e.variant.c_str(), verdict.c_str(), row.by_verdict[0],
                row.by_verdict[1], row.by_verdict[2], row.prefiltered, row.seconds, row.runs < repeats ? "*" : "",
                row.parse_seconds, row.seconds / n4, static_cast<unsigned long long>(row.nodes), row.max_depth,
                static_cast<unsigned long long>(row.pairs), static_cast<unsigned long long>(row.sphere_tests),
                static_cast<unsigned long long>(row.calls), static_cast<unsigned long long>(row.fallbacks), reference,
                reference_ratio, paper_total, paper_avg, ratio);
    std::fflush(stdout);
  }
  if (any_single_run) std::printf("\n* = a single run (it took more than %.0f s).\n", kSingleRunAbove);
  for (const std::string& n : notes) std::printf("error: %s\n", n.c_str());
  std::printf("%s\n", all_expected ? "all verdicts as expected (collision variant: collision; near, clear: safe)"
                                   : "SOME SCENES FAILED OR HAVE UNEXPECTED VERDICTS (see the verdict column and errors)");
  return all_expected ? 0 : 1;
}
