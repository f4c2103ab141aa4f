// The checker's Bernstein arithmetic (src/certificate/check_bernstein.h):
// the joint curve, its restriction to a piece and the pose, against hand
// values; products, elevation and de Casteljau directly.
#include "tests/certificate/check_support.h"
#include "src/certificate/check_bernstein.h"

using namespace check_test;

BOOST_AUTO_TEST_SUITE(certificate_check)

BOOST_AUTO_TEST_CASE(joint_curve_by_hand) {
  // two-moving.json: p on z = 1, 2, 1 with weights 1, 2, 1 (degree 2); q on
  // z = 0, -1 with weights 1, 3 (degree 1).  Product form, degree 3:
  //   W   = [1, 7/3, 13/3, 3]     (e.g. W_1 = (2/3) 2*1 + (1/3) 1*3)
  //   N_a z-translation = [1, 11/3, 25/3, 3]  ((w_a z_a) = [1, 4, 1] times w_b)
  //   N_b z-translation = [0, -1, -4, -3]     ((w_b z_b) = [0, -3] times w_a)
  //   N_a, N_b diagonal = W, other entries 0.
  const Scene s = parse_scene_file(data("two-moving.json"));
  const auto c = cert::detail::joint_control_points(s.bodies[0], s.bodies[1], Exact(0), Exact(1));
  BOOST_REQUIRE_EQUAL(c.size(), 4u);
  const std::vector<std::string> w = {"1", "7/3", "13/3", "3"}, za = {"1", "11/3", "25/3", "3"},
                                  zb = {"0", "-1", "-4", "-3"};
  for (int k = 0; k < 4; ++k) {
    BOOST_TEST(c[k][24] == q(w[k]));
    BOOST_TEST(c[k][11] == q(za[k]));
    BOOST_TEST(c[k][12 + 11] == q(zb[k]));
    for (int blk = 0; blk < 2; ++blk)
      for (int e = 0; e < 12; ++e) {
        const Exact& x = c[k][12 * blk + e];
        if (e == 0 || e == 5 || e == 10) BOOST_TEST(x == q(w[k]));
        else if (e != 11) BOOST_TEST(x == 0);
      }
  }
  // Constant weights: elevation only.  probe (degree 2, z = 1, 1/2, 1/2)
  // and the fixed triangle (identity elevated to degree 2); restricted to
  // [0, 1/4] by hand: z = 1, 7/8, 25/32.
  const Scene p = parse_scene_file(data("probe-safe.json"));
  const auto r = cert::detail::joint_control_points(p.bodies[0], p.bodies[1], Exact(0), Exact(1, 4));
  BOOST_REQUIRE_EQUAL(r.size(), 3u);
  BOOST_TEST(r[0][11] == q("1"));
  BOOST_TEST(r[1][11] == q("7/8"));
  BOOST_TEST(r[2][11] == q("25/32"));
  // Both moving, constant weights 2, 2 and 1, 1, 1: degree elevation of
  // a's line z = 0, 1 to degree 2 (z = 0, 1/2, 1), b as it is, W = 1.
  const Scene both = parse_scene_text(R"({"format": "tmcert-scene/1", "bodies": [
    {"name": "a", "points": [[0, 0, 0]], "motion": {"type": "rational_bezier", "weights": [2, 2], "control_points": [
      [[1,0,0,0],[0,1,0,0],[0,0,1,0]], [[1,0,0,0],[0,1,0,0],[0,0,1,1]]]}},
    {"name": "b", "points": [[0, 0, 0]], "motion": {"type": "rational_bezier", "control_points": [
      [[1,0,0,0],[0,1,0,0],[0,0,1,0]], [[1,0,0,0],[0,1,0,0],[0,0,1,3]], [[1,0,0,0],[0,1,0,0],[0,0,1,0]]]}}],
    "checks": [["a", "b"]]})", "both.json");
  const auto e = cert::detail::joint_control_points(both.bodies[0], both.bodies[1], Exact(0), Exact(1));
  BOOST_REQUIRE_EQUAL(e.size(), 3u);
  const std::vector<std::string> ea = {"0", "1/2", "1"}, eb = {"0", "3", "0"};
  for (int k = 0; k < 3; ++k) {
    BOOST_TEST(e[k][24] == 1);
    BOOST_TEST(e[k][0] == 1);
    BOOST_TEST(e[k][11] == q(ea[k]));
    BOOST_TEST(e[k][12 + 11] == q(eb[k]));
  }
  BOOST_CHECK_THROW(cert::detail::joint_control_points(p.bodies[0], p.bodies[1], Exact(1, 2), Exact(1, 2)),
                    std::invalid_argument);
  BOOST_CHECK_THROW(cert::detail::joint_control_points(p.bodies[0], p.bodies[1], Exact(0), Exact(2)),
                    std::invalid_argument);
  for (int k = 0; k < 3; ++k) {
    BOOST_TEST(r[k][24] == 1);
    BOOST_TEST(r[k][12] == 1);
    BOOST_TEST(r[k][12 + 3] == 0);
    BOOST_TEST(r[k][3] == q("1/4"));
  }
}

BOOST_AUTO_TEST_CASE(restricted_joint_curve_is_the_motion) {
  // The first and last control points of every restriction are the two
  // bodies' poses (pose_at, a separate evaluation) at the piece's ends,
  // for the product form, the elevation form, and a fixed body.
  std::vector<Scene> scenes = {parse_scene_file(data("two-moving.json")), parse_scene_file(data("probe-safe.json")),
                               parse_scene_file(data("drop.json")), parse_scene_file(data("solid-singular.json"))};
  // Both moving with constant weights of different degrees and a rotation-like
  // rational motion of degree 3 against one of degree 2.
  const std::string both = R"({"format": "tmcert-scene/1", "bodies": [
    {"name": "a", "points": [[0, 0, 0]], "motion": {"type": "rational_bezier", "control_points": [
      [[1,0,0,0],[0,1,0,0],[0,0,1,0]], [[1,-1,0,"1/3"],[1,1,0,0],[0,0,2,1]], [[0,-1,0,1],[1,0,0,2],[0,0,1,0]],
      [[0,"-1/2",0,1],[2,0,0,3],[0,0,1,"0.25"]]], "weights": [1, "1/2", "0.5", 1]}},
    {"name": "b", "points": [[1, 1, 1]], "motion": {"type": "rational_bezier", "control_points": [
      [[1,0,0,0],[0,1,0,0],[0,0,1,0]], [[2,0,0,1],[0,1,0,0],[0,0,1,0]], [[1,0,0,0],[0,3,0,0],[0,1,1,-2]]],
      "weights": [2, 2, 2]}}], "checks": [["a", "b"]]})";
  scenes.push_back(parse_scene_text(both, "inline"));
  std::string swapped = both;
  const std::string pair = "[[\"a\", \"b\"]]";
  swapped.replace(swapped.find(pair), pair.size(), "[[\"b\", \"a\"]]");
  scenes.push_back(parse_scene_text(swapped, "inline-swapped"));
  std::mt19937_64 rng(3);
  for (const Scene& s : scenes)
    for (const auto& [ia, ib] : s.checks) {
      const Body& a = s.bodies[ia];
      const Body& b = s.bodies[ib];
      const Motion* m = a.motion && a.motion->degree() >= 1 ? &*a.motion : b.motion ? &*b.motion : nullptr;
      const Exact t0 = m ? m->t0 : Exact(0), t1 = m ? m->t1 : Exact(1);
      for (int trial = 0; trial < 12; ++trial) {
        const long d = 1 + static_cast<long>(rng() % 64);
        long i = static_cast<long>(rng() % d), j = static_cast<long>(rng() % d);
        if (i > j) std::swap(i, j);
        ++j;
        const Exact ua(i, d), ub(j, d);
        const auto c = cert::detail::joint_control_points(a, b, ua, ub);
        for (const auto& [cp, u] : {std::pair{c.front(), ua}, std::pair{c.back(), ub}}) {
          const Exact t = t0 + u * (t1 - t0);
          const Mat34E pa = cert::pose_at(a, t), pb = cert::pose_at(b, t);
          for (int e = 0; e < 12; ++e) {
            BOOST_TEST(cp[e] / cp[24] == pa[e]);
            BOOST_TEST(cp[12 + e] / cp[24] == pb[e]);
          }
        }
        for (const auto& cp : c) BOOST_TEST(cp[24] > 0);
      }
    }
}

BOOST_AUTO_TEST_CASE(pose_by_hand) {
  const Scene s = parse_scene_file(data("two-moving.json"));
  // p at t = 1/2: z = (1/4 + 2*(1/2)*2 + 1/4) / (1/4 + 2*(1/2) + 1/4) = (5/2) / (3/2) = 5/3.
  const Mat34E p = cert::pose_at(s.bodies[0], Exact(1, 2));
  BOOST_TEST(p[11] == Exact(5, 3));
  BOOST_TEST(p[0] == 1);
  BOOST_TEST(p[3] == 0);
  // q at t = 1/4: z = (3/4 * 0 + 3 * 1/4 * -1) / (3/4 + 3/4) = -1/2.
  BOOST_TEST(cert::pose_at(s.bodies[1], Exact(1, 4))[11] == Exact(-1, 2));
  // A body without motion: the identity.
  const Scene d = parse_scene_file(data("drop.json"));
  const Mat34E id = cert::pose_at(d.bodies[1], Exact(7));
  for (int e = 0; e < 12; ++e) BOOST_TEST(id[e] == ((e == 0 || e == 5 || e == 10) ? 1 : 0));
  BOOST_TEST(cert::pose_at(d.bodies[0], Exact(3, 8))[11] == Exact(1, 4));  // z = 1 - 2t
}

BOOST_AUTO_TEST_SUITE_END()

// The pieces of the Bernstein arithmetic directly, against hand values.
BOOST_AUTO_TEST_SUITE(check_bernstein)

namespace ci = tmcert::certificate::check_internal;

BOOST_AUTO_TEST_CASE(binomials_and_products_by_hand) {
  const std::vector<Exact> c = ci::binomials(4);
  BOOST_TEST((c == std::vector<Exact>{1, 4, 6, 4, 1}));
  // (1 + u) (3 + 3u) = 3 + 6u + 3u^2: Bernstein coefficients of degree 2
  // are 3, 3 + 6/2 = 6 and 3 + 6 + 3 = 12.
  const std::vector<Exact> p = ci::bernstein_product({Exact(1), Exact(2)}, {Exact(3), Exact(6)});
  BOOST_TEST((p == std::vector<Exact>{Exact(3), Exact(6), Exact(12)}));
  // Elevation: a product with the constant 1 of degree 1 keeps the curve.
  const std::vector<Exact> e = ci::bernstein_product({Exact(1), Exact(5)}, {Exact(1), Exact(1)});
  BOOST_TEST((e == std::vector<Exact>{Exact(1), Exact(3), Exact(5)}));
}

BOOST_AUTO_TEST_CASE(de_casteljau_restriction_by_hand) {
  // A curve whose coordinate 0 is u^2 (control points 0, 0, 1), weight 1.
  std::vector<ci::CP> c(3);
  for (ci::CP& p : c)
    for (Exact& x : p) x = 0;
  c[2][0] = 1;
  for (ci::CP& p : c) p[24] = 1;
  // On [1/2, 1]: u = 1/2 + s/2, u^2 = 1/4 + s/2 + s^2/4: control points
  // 1/4, 1/4 + 1/4 = 1/2, 1.
  const std::vector<ci::CP> r = ci::restrict_curve(c, Exact(1, 2), Exact(1));
  BOOST_REQUIRE_EQUAL(r.size(), 3u);
  BOOST_TEST(r[0][0] == Exact(1, 4));
  BOOST_TEST(r[1][0] == Exact(1, 2));
  BOOST_TEST(r[2][0] == Exact(1));
  // On [0, 1/2]: 0, 0, 1/4; the two halves meet at u = 1/2.
  const std::vector<ci::CP> left = ci::split(c, Exact(1, 2), true);
  BOOST_TEST(left[0][0] == Exact(0));
  BOOST_TEST(left[1][0] == Exact(0));
  BOOST_TEST(left[2][0] == Exact(1, 4));
  const std::vector<ci::CP> right = ci::split(c, Exact(1, 2), false);
  BOOST_TEST(right[0][0] == left[2][0]);
  for (const ci::CP& p : r) BOOST_TEST(p[24] == Exact(1));
}

BOOST_AUTO_TEST_CASE(rational_joint_curves_multiply_by_the_other_weights) {
  // a: degree 1 with weights 1, 2 (rational); b: fixed (identity).  The
  // joint curve has degree 1; block b is the identity times a's weights.
  Body a, b;
  Motion m;
  m.t0 = 0;
  m.t1 = 1;
  m.control_points = {ci::identity_pose(), ci::identity_pose()};
  m.control_points[1][3] = 4;  // x translation 4 at the end
  m.weights = {Exact(1), Exact(2)};
  a.motion = m;
  const std::vector<ci::CP> c = ci::joint_curve(a, b);
  BOOST_REQUIRE_EQUAL(c.size(), 2u);
  BOOST_TEST(c[0][24] == Exact(1));
  BOOST_TEST(c[1][24] == Exact(2));
  BOOST_TEST(c[1][3] == Exact(8));   // w_1 A_1 (x translation)
  BOOST_TEST(c[1][12] == Exact(2));  // b's identity times w_1
  BOOST_TEST(!ci::constant_weights(m.weights));
  // The pose at the curve's end is A_1: N / W = 8 / 2.
  BOOST_TEST(cert::pose_at(a, Exact(1))[3] == Exact(4));
}

BOOST_AUTO_TEST_SUITE_END()
