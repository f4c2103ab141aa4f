// tmcert and Tight-Inclusion on the same continuous-collision query files,
// in one process, alternating (bench/tight_inclusion.sh builds this against
// a Tight-Inclusion source tree; it is not part of the default build).
//
//   ccd_side_by_side ROUNDS FILE.csv...   (files under .../vertex-face/ or .../edge-edge/)
//
// Each query is read exactly (the files' rationals): tmcert checks it as two
// linearly moving bodies (bench/ccd_queries.h, the same scene as
// scripts/ccd_csv_to_scene.py writes) with the filtered kernel and epsilon
// 1e-6 of the largest query box diagonal, one verifier for all (a body is
// prepared on its first check, inside that check's time: the first round
// includes it, later rounds do not); Tight-Inclusion gets the coordinates
// rounded to doubles, as its own benchmark does, with ms = 0, tolerance
// 1e-6, t_max = 1, max_itr = 10^6 and err computed by it.  Times are the
// thread's CPU time per query (the machine may be shared); every round runs
// all queries with tmcert, then all with Tight-Inclusion.
#include "bench/ccd_queries.h"
#include "src/verify/verify.h"

#include <tight_inclusion/ccd.hpp>

#include <gmp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace tmcert;

namespace {

struct Query {
  bool edge_edge = false;
  bool truth = false;
  std::array<Vec3E, 8> v;
};

double cpu_us() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return ts.tv_sec * 1e6 + ts.tv_nsec * 1e-3;
}

std::vector<Query> read_file(const std::string& path) {
  const bool ee = path.find("edge-edge") != std::string::npos;
  std::ifstream in(path);
  std::vector<Query> out;
  std::string line;
  Query q;
  int k = 0;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    std::stringstream ss(line);
    std::string field;
    std::vector<std::string> f;
    while (std::getline(ss, field, ',')) f.push_back(field);
    if (f.size() < 7) throw std::runtime_error(path + ": a line with fewer than 7 fields");
    for (int c = 0; c < 3; ++c) q.v[k][c] = Exact(CGAL::Gmpz(f[2 * c]), CGAL::Gmpz(f[2 * c + 1]));
    q.truth = std::stoi(f[6]) != 0;
    if (++k == 8) {
      q.edge_edge = ee;
      out.push_back(q);
      k = 0;
    }
  }
  return out;
}

struct Stats {
  int n = 0, colliding = 0, false_safe = 0, false_collision = 0, undecided = 0, proven = 0;
  std::vector<double> us;
  void add(double t) { us.push_back(t); }
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
double maximum(const std::vector<double>& v) { return v.empty() ? 0 : *std::max_element(v.begin(), v.end()); }
int over(const std::vector<double>& v, double limit) {
  return static_cast<int>(std::count_if(v.begin(), v.end(), [&](double x) { return x > limit; }));
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: ccd_side_by_side ROUNDS FILE.csv...\n");
    return 2;
  }
  const int rounds = std::max(1, std::atoi(argv[1]));
  std::vector<Query> queries;
  for (int i = 2; i < argc; ++i) {
    std::vector<Query> f = read_file(argv[i]);
    queries.insert(queries.end(), f.begin(), f.end());
  }
  // One scene: two bodies and one check per query.
  Scene scene;
  for (std::size_t i = 0; i < queries.size(); ++i) {
    const Query& q = queries[i];
    const std::string id = "q" + std::to_string(i);
    if (q.edge_edge) {
      scene.bodies.push_back(bench::linear_body(id + "-ea", {q.v[0], q.v[1]}, {q.v[4], q.v[5]}));
      scene.bodies.push_back(bench::linear_body(id + "-eb", {q.v[2], q.v[3]}, {q.v[6], q.v[7]}));
    } else {
      scene.bodies.push_back(bench::linear_body(id + "-p", {q.v[0]}, {q.v[4]}));
      scene.bodies.push_back(bench::linear_body(id + "-f", {q.v[1], q.v[2], q.v[3]}, {q.v[5], q.v[6], q.v[7]}));
    }
    scene.checks.push_back({static_cast<int>(2 * i), static_cast<int>(2 * i + 1)});
  }
  // Epsilon: 1e-6 of the largest query box diagonal (scripts/ccd_csv_to_scene.py's default).
  double diagonal = 0;
  for (const Query& q : queries) {
    double d2 = 0;
    for (int c = 0; c < 3; ++c) {
      double lo = 1e300, hi = -1e300;
      for (const Vec3E& p : q.v) {
        lo = std::min(lo, CGAL::to_double(p[c]));
        hi = std::max(hi, CGAL::to_double(p[c]));
      }
      d2 += (hi - lo) * (hi - lo);
    }
    diagonal = std::max(diagonal, std::sqrt(d2));
  }
  VerifyOptions options;
  options.epsilon = Exact(std::max(1e-6 * diagonal, 1e-12));
  const Verifier verifier(scene, options);  // one verifier: bodies are prepared once, on first use
  Stats tm, ti;
  std::vector<double> tm_sum(queries.size(), 0), ti_sum(queries.size(), 0);
  int exact_first = 0;
  for (int round = 0; round < rounds; ++round) {
    for (std::size_t i = 0; i < queries.size(); ++i) {
      const double start = cpu_us();
      const CheckResult r = verifier.check(scene.checks[i].first, scene.checks[i].second);
      tm_sum[i] += cpu_us() - start;
      if (round > 0) continue;
      const bool truth = queries[i].truth;
      ++tm.n;
      tm.colliding += truth;
      tm.false_safe += truth && r.verdict == Verdict::Safe;
      tm.false_collision += !truth && r.verdict == Verdict::Collision;
      tm.undecided += r.verdict == Verdict::Undecided;
      tm.proven += r.verdict == Verdict::Collision;
      exact_first += r.verdict == Verdict::Collision && r.first_contact_exact;
    }
    for (std::size_t i = 0; i < queries.size(); ++i) {
      const Query& q = queries[i];
      ticcd::Vector3 v[8];
      for (int k = 0; k < 8; ++k)
        v[k] = ticcd::Vector3(CGAL::to_double(q.v[k][0]), CGAL::to_double(q.v[k][1]), CGAL::to_double(q.v[k][2]));
      const ticcd::Array3 err(-1, -1, -1);
      double toi = 0, out_tol = 0;
      const double start = cpu_us();
      const bool hit = q.edge_edge ? ticcd::edgeEdgeCCD(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], err, 0, toi,
                                                        1e-6, 1, 1000000, out_tol)
                                   : ticcd::vertexFaceCCD(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], err, 0, toi,
                                                          1e-6, 1, 1000000, out_tol);
      ti_sum[i] += cpu_us() - start;
      if (round > 0) continue;
      ++ti.n;
      ti.colliding += q.truth;
      ti.false_safe += q.truth && !hit;
      ti.false_collision += !q.truth && hit;
    }
  }
  for (std::size_t i = 0; i < queries.size(); ++i) {
    tm.add(tm_sum[i] / rounds);
    ti.add(ti_sum[i] / rounds);
  }
  std::printf("%zu queries (%d colliding), %d rounds alternating, thread CPU time per query (mean over rounds)\n\n",
              queries.size(), tm.colliding, rounds);
  std::printf("| | tmcert (filtered, exact resolution) | Tight-Inclusion (ms 0, tol 1e-6, max_itr 1e6) | ratio tmcert/TI |\n");
  std::printf("|---|---|---|---|\n");
  std::printf("| false safe / false negative | %d | %d | |\n", tm.false_safe, ti.false_safe);
  std::printf("| false collision / false positive | %d | %d of %d free | |\n", tm.false_collision, ti.false_collision,
              ti.n - ti.colliding);
  std::printf("| undecided | %d | (no such answer) | |\n", tm.undecided);
  std::printf("| colliding queries proven (exact first contact) | %d of %d (%d) | no witness | |\n", tm.proven,
              tm.colliding, exact_first);
  std::printf("| median us | %.2f | %.2f | %.2f |\n", percentile(tm.us, 0.5), percentile(ti.us, 0.5),
              percentile(tm.us, 0.5) / percentile(ti.us, 0.5));
  std::printf("| mean us | %.2f | %.2f | %.2f |\n", mean(tm.us), mean(ti.us), mean(tm.us) / mean(ti.us));
  std::printf("| slowest us | %.1f | %.1f | %.2f |\n", maximum(tm.us), maximum(ti.us), maximum(tm.us) / maximum(ti.us));
  std::printf("| queries over 1 ms | %d | %d | |\n", over(tm.us, 1000), over(ti.us, 1000));
  std::printf("| queries over 5 ms | %d | %d | |\n", over(tm.us, 5000), over(ti.us, 5000));
  return tm.false_safe == 0 && tm.false_collision == 0 ? 0 : 1;
}
