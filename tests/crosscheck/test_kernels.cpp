// Fast (double) versus filtered versus exact, on the same inputs.
//
// Predicate level: the filtered kernel must agree with the exact one on every
// input (it is the same template with a certified filter); the double kernel
// is allowed to differ only on inputs that are degenerate by construction,
// and every disagreement is printed with its inputs as hex floats.
// Verification level: two certified kernels can never contradict each other
// (one safe, the other collision).
#define BOOST_TEST_MODULE tmcert_crosscheck
#include "kernels/contact.h"
#include "kernels/filtered.h"
#include "src/metric/metric.h"
#include "src/verify/prepared.h"
#include "src/verify/verify.h"
#include "tests/support/random_geometry.h"

#include <boost/test/unit_test.hpp>

#include <cstdio>
#include <cstdlib>

using namespace tmcert;
using namespace tmcert::testing;

namespace {

unsigned seed_from_env(unsigned fallback) {
  if (const char* s = std::getenv("TMCERT_SEED")) return static_cast<unsigned>(std::strtoul(s, nullptr, 10));
  return fallback;
}

void print_hex(const char* what, const Placement<double>& p) {
  std::printf("  %s g1 =", what);
  for (double x : p.g1) std::printf(" %a", x);
  std::printf("  r2 = %a\n", p.r2);
}

}  // namespace

BOOST_AUTO_TEST_CASE(predicates_fast_filtered_exact) {
  const unsigned seed = seed_from_env(424242);
  BOOST_TEST_MESSAGE("seed " << seed << " (replay: TMCERT_SEED=" << seed << ")");
  Rng r(seed);
  int total = 0, fallbacks = 0, fast_wrong = 0, fast_false_clear = 0;
  for (int iter = 0; iter < 300; ++iter) {
    std::array<Vec3E, 3> tm, tf;
    for (auto& p : tm) p = {Exact(r.d(-8, 8, 4)), Exact(r.d(-8, 8, 4)), Exact(r.d(-8, 8, 4))};
    for (auto& p : tf) p = {Exact(r.d(-8, 8, 4)), Exact(r.d(-8, 8, 4)), Exact(r.d(-8, 8, 4))};
    if (collinear(tm) || collinear(tf)) continue;
    Body bm = triangle_body("m", tm), bf = triangle_body("f", tf);
    bm.motion = Motion{0, 1, {Mat34E{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0}, Mat34E{1, 0, 0, 1, 0, 1, 0, 0, 0, 0, 1, 0}}, {1, 1}};
    const PreparedBody pm(bm), pf(bf);
    // Placement: a near-rigid center with non-representable perturbations,
    // so that intervals are not exact points, and a radius near the value
    // where pairs switch between cleared and not cleared.
    Placement<double> pd;
    for (int e = 0; e < 12; ++e) pd.g1[e] = (e % 5 == 0 ? 1.0 : 0.0) + 0.3 * r.noise();
    pd.r2 = 4.0 * std::abs(r.noise());
    Placement<Interval> pi;
    Placement<Exact> pe;
    for (int e = 0; e < 12; ++e) {
      pi.g1[e] = Interval(pd.g1[e]);
      pe.g1[e] = Exact(pd.g1[e]);
    }
    pi.r2 = Interval(pd.r2);
    pe.r2 = Exact(pd.r2);
    for (ContactKind kind : {ContactKind::VertexFace, ContactKind::EdgeEdge, ContactKind::FaceVertex}) {
      const FeatureTable& X = kind == ContactKind::VertexFace ? pm.vertices : kind == ContactKind::EdgeEdge ? pm.edges : pm.faces;
      const FeatureTable& Y = kind == ContactKind::VertexFace ? pf.faces : kind == ContactKind::EdgeEdge ? pf.edges : pf.vertices;
      const auto& Xe = kind == ContactKind::VertexFace ? pm.exact().vertices : kind == ContactKind::EdgeEdge ? pm.exact().edges : pm.exact().faces;
      const auto& Ye = kind == ContactKind::VertexFace ? pf.exact().faces : kind == ContactKind::EdgeEdge ? pf.exact().edges : pf.exact().vertices;
      for (std::size_t i = 0; i < X.size(); ++i)
        for (std::size_t j = 0; j < Y.size(); ++j) {
          ++total;
          const CGAL::Sign exact = contact_sign<Exact>(kind, Xe[i], Ye[j], pe);
          FilterCounters counters;
          const CGAL::Sign filt = filtered([&] { return contact_sign<Interval>(kind, X.interval[i], Y.interval[j], pi); },
                                           [&] { return contact_sign<Exact>(kind, Xe[i], Ye[j], pe); }, counters);
          fallbacks += static_cast<int>(counters.exact_fallbacks);
          const CGAL::Sign fast = contact_sign<double>(kind, X.approx[i], Y.approx[j], pd);
          if (filt != exact) {
            BOOST_ERROR("filtered disagrees with exact: iteration " << iter << " kind " << int(kind));
            print_hex("placement", pd);
          }
          const bool fast_clear = fast == CGAL::POSITIVE, exact_clear = exact == CGAL::POSITIVE;
          if (fast_clear != exact_clear) {
            ++fast_wrong;
            if (fast_clear) ++fast_false_clear;
            std::printf("fast disagrees (fast %d, exact %d) iteration %d kind %d\n", int(fast), int(exact), iter, int(kind));
            print_hex("placement", pd);
          }
        }
    }
  }
  BOOST_TEST_MESSAGE("predicate calls " << total << ", exact fallbacks " << fallbacks << ", fast disagreements "
                                        << fast_wrong << " (false clearances " << fast_false_clear << ")");
  BOOST_TEST(total > 1000);
  // The filter decides: random inputs are not degenerate, so the exact
  // fallback is rare (a filter that always fell back would still agree
  // with exact, and pass the comparison above, at many times the cost).
  BOOST_TEST(fallbacks * 100 <= total, "exact fallbacks " << fallbacks << " of " << total << " calls (at most 1%)");
  // Random inputs are not degenerate: double must agree on nearly all.
  BOOST_TEST(fast_wrong * 1000 <= total);
}

// Degenerate by construction: a vertex exactly at the orbit boundary
// (Phi = 0 at the minimum).  Exact says ZERO (not cleared), filtered must
// agree, and double is reported.
BOOST_AUTO_TEST_CASE(touching_orbit_boundary_is_never_cleared) {
  // Fixed triangle in z = 0; moving vertex at height h over it, g = identity.
  std::array<Vec3E, 3> tf{Vec3E{-4, -4, 0}, Vec3E{4, -4, 0}, Vec3E{0, 4, 0}};
  std::array<Vec3E, 3> tm{Vec3E{0, 0, 1}, Vec3E{1, 0, 2}, Vec3E{0, 1, 2}};
  Body bm = triangle_body("m", tm), bf = triangle_body("f", tf);
  bm.motion = Motion{0, 1, {Mat34E{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0}, Mat34E{1, 0, 0, 1, 0, 1, 0, 0, 0, 0, 1, 0}}, {1, 1}};
  const PreparedBody pm(bm), pf(bf);
  // R^2 rho(v0)^2 = 1 exactly: the fat vertex touches the plane z = 0.
  const Exact rho2 = pm.exact_metric().rho2(tm[0]);
  Placement<Exact> pe;
  pe.g1 = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
  pe.r2 = Exact(1) / rho2;
  BOOST_CHECK(contact_sign<Exact>(ContactKind::VertexFace, pm.exact().vertices[0], pf.exact().faces[0], pe) == CGAL::ZERO);
  Placement<Interval> pi;
  for (int e = 0; e < 12; ++e) pi.g1[e] = to_interval(pe.g1[e]);
  pi.r2 = to_interval(pe.r2);
  FilterCounters counters;
  const CGAL::Sign f = filtered(
      [&] { return contact_sign<Interval>(ContactKind::VertexFace, pm.vertices.interval[0], pf.faces.interval[0], pi); },
      [&] { return contact_sign<Exact>(ContactKind::VertexFace, pm.exact().vertices[0], pf.exact().faces[0], pe); },
      counters);
  BOOST_CHECK(f == CGAL::ZERO);
  BOOST_CHECK_EQUAL(counters.exact_fallbacks, 1u);  // the filter cannot decide a zero
}

BOOST_AUTO_TEST_CASE(certified_kernels_never_contradict) {
  const unsigned seed = seed_from_env(777);
  BOOST_TEST_MESSAGE("seed " << seed << " (replay: TMCERT_SEED=" << seed << ")");
  Rng r(seed);
  int counts[3][3] = {};
  int fast_false_safe = 0;
  for (int iter = 0; iter < 40; ++iter) {
    Scene scene;
    std::array<Vec3E, 3> tm{Vec3E{0, 0, 0}, Vec3E{1, 0, 0}, Vec3E{0, 1, 0}};
    Body fixed;
    fixed.name = "fixed";
    std::vector<Vec3E> sq{Vec3E{-1, -1, 0}, Vec3E{1, -1, 0}, Vec3E{1, 1, 0}, Vec3E{-1, 1, 0}};
    fixed.polygons = {sq};
    fixed.pieces = {ConvexPiece{0, sq}};
    fixed.mass = default_mass(sq, Exact(1));
    Body moving = triangle_body("moving", tm);
    Motion m;
    const int degree = r.i(1, 3);
    for (int k = 0; k <= degree; ++k) {
      Mat34E a{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
      for (int e = 0; e < 12; ++e) a[e] += Exact(r.i(-4, 4), 8);
      a[3] += Exact(r.i(-12, 12), 8);
      a[7] += Exact(r.i(-12, 12), 8);
      a[11] += Exact(r.i(-6, 10), 8);
      m.control_points.push_back(a);
      m.weights.push_back(Exact(r.i(1, 4)));
    }
    moving.motion = m;
    scene.bodies = {moving, fixed};
    scene.checks = {{0, 1}};
    VerifyOptions o;
    o.epsilon = Exact(1, 100);
    o.max_depth = 24;
    o.max_nodes = 20000;
    o.kernel = KernelKind::Filtered;
    const Verdict vf = verify_check(scene, 0, 1, o).verdict;
    o.kernel = KernelKind::Exact;
    const Verdict ve = verify_check(scene, 0, 1, o).verdict;
    o.kernel = KernelKind::Fast;
    const Verdict vd = verify_check(scene, 0, 1, o).verdict;
    counts[int(vf)][int(ve)]++;
    const bool contradiction = (vf == Verdict::Safe && ve == Verdict::Collision) ||
                               (vf == Verdict::Collision && ve == Verdict::Safe);
    BOOST_CHECK_MESSAGE(!contradiction, "filtered and exact contradict at iteration " << iter);
    if (vd == Verdict::Safe && (vf == Verdict::Collision || ve == Verdict::Collision)) ++fast_false_safe;
  }
  BOOST_TEST_MESSAGE("filtered x exact verdict table (safe, collision, undecided): "
                     << counts[0][0] << " " << counts[0][1] << " " << counts[0][2] << " / " << counts[1][0] << " "
                     << counts[1][1] << " " << counts[1][2] << " / " << counts[2][0] << " " << counts[2][1] << " "
                     << counts[2][2] << "; fast false safe " << fast_false_safe);
  // The random family must exercise both outcomes, or it checks nothing.
  BOOST_TEST(counts[0][0] > 0);
  BOOST_TEST(counts[1][1] > 0);
}
