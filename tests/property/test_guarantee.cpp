// Property tests of the guarantee (DESIGN.md sections 4-6, SCENE_FORMAT.md
// "verdict"): never a false `safe`, never a false `collision`, every
// collision carries an exact witness inside its first-contact bracket, a
// clearance m is certified for epsilon <= m/4 (and m/2, DESIGN.md 6), an
// interpenetrating start is caught at t0, and verdicts do not depend on where
// the scene sits or on its unit of length.
//
// Every scene is built directly in C++ from exact rationals (small integers
// over small denominators), so the facts the properties rely on (a contact at
// a known time t*, a clearance m, a gap of exactly 10^-17) hold exactly.  The
// oracle used to check witnesses (rational Bezier evaluation, point in
// triangle / on segment) is written independently of the library, in
// tests/support/scene_testing.h (shared with test_two_bodies.cpp).  Default
// masses are computed as the parser does, so the scene printed in a failure
// log is the scene that was verified.
//
// Replay a failure with RC_PARAMS="seed=N" (the seed is printed at the start
// of the run) or with the RC_PARAMS="reproduce=..." line printed on failure;
// the failing scene is printed in the log as tmcert-scene/1 JSON.
// RC_PARAMS="max_success=N" changes the number of cases (the exact-kernel
// properties run half of them).

#include "tests/support/scene_testing.h"

#include <array>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

using namespace tmcert;
using namespace tmcert::testing;

namespace {

// ------------------------------------------------------------------ scenes

std::vector<Vec3E> square_z0(const Exact& h) { return {{-h, -h, 0}, {h, -h, 0}, {h, h, 0}, {-h, h, 0}}; }

// ------------------------------------------------------------------ generators (inside properties)

// A translation motion of `count` control points over a random interval, x
// and y in [-xy, xy], z in [-z, z].
Motion pick_translation_motion(int count, double xy, double z) {
  Motion m;
  std::tie(m.t0, m.t1) = pick_interval();
  for (int k = 0; k < count; ++k) m.control_points.push_back(translation(pick(-xy, xy), pick(-xy, xy), pick(-z, z)));
  m.weights = pick_weights(count);
  return m;
}

// ------------------------------------------------------------------ scene kinds

// (b) A moving triangle whose every vertex, under every affine control point,
// has z >= m (with equality at the first or last control point), over the
// fixed square [-4,4]^2 x {0}.  The convex hull property gives clearance m.
Scene clearance_scene(Exact& m_out, int eps_divisor = 0) {
  const int count = uniform(2, 4);  // degree 1..3
  const Exact m = pick(0.25, 2) / *rc::gen::element(1, 1, 4, 8);  // 1/32 .. 2
  const std::vector<Vec3E> tri = pick_triangle(-1, 1);
  Motion motion;
  std::tie(motion.t0, motion.t1) = pick_interval();
  const int tight = *rc::gen::element(0, count - 1);
  for (int k = 0; k < count; ++k) {
    Mat34E p = pick_affine(2, 3);
    std::optional<Exact> zmin;
    for (const Vec3E& v : tri) {
      const Exact z = p[8] * v[0] + p[9] * v[1] + p[10] * v[2];
      if (!zmin || z < *zmin) zmin = z;
    }
    const Exact extra = k == tight ? Exact(0) : pick(0, 1);
    p[11] = m - *zmin + extra;
    motion.control_points.push_back(p);
  }
  motion.weights = pick_weights(count);
  m_out = m;
  const Exact epsilon = m / (eps_divisor > 0 ? eps_divisor : *rc::gen::element(4, 4, 8));
  return make_scene(make_body("mover", {tri}, motion), make_body("table", {square_z0(4)}), epsilon);
}

// (c) A triangle with one vertex below z = 0 and two above (or the reverse),
// its footprint in [-1,1]^2, so an edge pierces the interior of the square
// [-2,2]^2 x {0}; the motion only slides it by at most 1/2 in x, y and 1/4 in
// z, so the crossing stays strictly inside the square and no vertex comes
// near z = 0: no contact event ever happens, the bodies interpenetrate
// throughout.
Scene interpenetration_scene() {
  const int lone = uniform(0, 2);
  const int sign = *rc::gen::element(1, -1);
  std::vector<Vec3E> tri(3);
  for (int i = 0; i < 3; ++i) {
    const Exact h = pick(0.5, 2);
    tri[i] = {pick(-1, 1), pick(-1, 1), i == lone ? -sign * h : sign * h};
  }
  RC_PRE(nondegenerate(tri));
  const int count = uniform(2, 4);
  Motion motion = pick_translation_motion(count, 0.5, 0.25);
  return make_scene(make_body("blade", {tri}, motion), make_body("table", {square_z0(2)}), Exact(1, 100));
}

// A tilted triangle (vertex heights 0, in [1/4,1] and in [1,2] above its
// lowest vertex, footprint in [-1,1]^2) carried by a translation whose z goes
// from +3 at the start to -3 at the end (intermediate control points anywhere
// in [-3,3]) and whose x, y stay in [-1/2,1/2], through the square
// [-2,2]^2 x {0}: it passes clean through the square in the middle of the
// motion.
Scene sweep_scene() {
  std::vector<Vec3E> tri = {{pick(-1, 1), pick(-1, 1), 0}, {pick(-1, 1), pick(-1, 1), pick(0.25, 1)},
                            {pick(-1, 1), pick(-1, 1), pick(1, 2)}};
  RC_PRE(nondegenerate(tri));
  const int count = uniform(2, 4);
  Motion motion = pick_translation_motion(count, 0.5, 3);
  motion.control_points.front()[11] = 3;
  motion.control_points.back()[11] = -3;
  return make_scene(make_body("blade", {tri}, motion), make_body("table", {square_z0(2)}), Exact(1, 100));
}

// ------------------------------------------------------------------ property bodies

// (a) A contact built at a known rational time t* is never `safe`.
void contact_never_safe(KernelKind kernel, std::uint64_t max_nodes) {
  auto [fixed, fixed_hull] = pick_shape("fixed", -2, 2, false);
  if (*rc::gen::element(false, false, true)) {  // a fixed body under a constant (maybe singular) pose
    Motion pose;
    pose.control_points = {pick_affine(2, 1)};
    pose.weights = {1};
    for (Vec3E& v : fixed_hull) v = place(pose.control_points[0], v);
    fixed.motion = pose;
  }
  auto [mover, hull] = pick_shape("mover", -1, 1, true);
  const int count = uniform(2, 4);
  Motion motion;
  std::tie(motion.t0, motion.t1) = pick_interval();
  for (int k = 0; k < count; ++k) motion.control_points.push_back(pick_affine(2, 6));
  motion.weights = pick_weights(count);

  // Contact at t*: the point p of the moving body (a vertex in half the
  // cases, else any point: edge-edge, edge-face and face-vertex contacts
  // too) at the point q of the fixed body (vertices and edges included).
  const Exact s = pick(0, 1);
  const Exact t_star = motion.t0 + s * (motion.t1 - motion.t0);
  const bool at_vertex = *rc::gen::arbitrary<bool>();
  const Vec3E p = at_vertex ? hull[uniform(std::size_t(0), hull.size() - 1)] : barycentric_point(hull);
  const Vec3E q = barycentric_point(fixed_hull);
  const Vec3E x = place(eval_motion(motion, t_star), p);
  for (Mat34E& c : motion.control_points)
    for (int r = 0; r < 3; ++r) c[4 * r + 3] += q[r] - x[r];
  RC_ASSERT(place(eval_motion(motion, t_star), p) == q);  // the construction itself
  mover.motion = motion;

  const Exact epsilon = *rc::gen::element(Exact(1, 16), Exact(1, 100), Exact(1, 1000));
  Scene scene = make_scene(mover, fixed, epsilon);
  const bool swap = *rc::gen::arbitrary<bool>();
  const int a = swap ? 1 : 0, b = swap ? 0 : 1;
  scene.checks = {{a, b}};
  const CheckResult r = verify_check(scene, a, b, options_for(epsilon, kernel, max_nodes));
  RC_LOG() << describe(scene) << "\ncontact at t* = " << str(t_star) << " (body point " << str(p) << " at " << str(q)
           << ")\nkernel " << to_string(kernel) << ": " << describe(r) << "\n";
  RC_TAG(stop_label(r), nodes_label(r));
  RC_ASSERT(r.verdict != Verdict::Safe);
  const std::string problem = consistency_problem(scene, a, b, r);
  RC_ASSERT(problem == "");
  RC_ASSERT(r.first_contact->first <= t_star);  // everything before it is certified contact-free
}

// (a, touching) A body that touches the square [-1,1]^2 x {0} at exactly one
// instant t* and is strictly above it at every other time: a vertex, an
// edge or a whole face (flat bottom) comes down onto a point q of the closed
// square and goes back up.  The linear part is constant (identity, or a
// random possibly singular matrix); the translation is a polynomial
// parabola in z, (u - s)^2 k, with a linear drift in x and y, written at
// degree 2 or elevated to degree 3, with equal (not necessarily unit)
// weights.  Never safe; a collision can only be witnessed at t* itself.
void touching_never_safe(KernelKind kernel, std::uint64_t max_nodes) {
  const bool flat = *rc::gen::arbitrary<bool>();
  std::vector<Vec3E> tri;
  std::array<Exact, 9> lin = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  if (flat) {
    for (int i = 0; i < 3; ++i)
      tri.push_back({pick(-1, 1), pick(-1, 1), i == 0 ? Exact(0) : *rc::gen::element(Exact(0), pick(0.25, 1))});
    RC_PRE(nondegenerate(tri));
  } else {
    tri = pick_triangle(-1, 1);
    for (Exact& e : lin) e = pick(-2, 2);
  }
  // The lowest vertex under the linear part.
  std::vector<Vec3E> img;
  for (const Vec3E& v : tri)
    img.push_back({lin[0] * v[0] + lin[1] * v[1] + lin[2] * v[2], lin[3] * v[0] + lin[4] * v[1] + lin[5] * v[2],
                   lin[6] * v[0] + lin[7] * v[1] + lin[8] * v[2]});
  int low = 0;
  for (int i = 1; i < 3; ++i)
    if (img[i][2] < img[low][2]) low = i;
  const Vec3E q = {pick(-1, 1), pick(-1, 1), 0};
  const Exact s = pick(0, 1), k = pick(0.25, 4), vx = pick(-2, 2), vy = pick(-2, 2);
  // Translation a(u) = alpha + beta u + gamma u^2 per coordinate.
  const std::array<Exact, 3> alpha = {q[0] - img[low][0] - vx * s, q[1] - img[low][1] - vy * s, k * s * s - img[low][2]};
  const std::array<Exact, 3> beta = {vx, vy, -2 * k * s};
  const std::array<Exact, 3> gamma = {0, 0, k};
  std::vector<std::array<Exact, 3>> ctrl(3);
  for (int c = 0; c < 3; ++c) {
    ctrl[0][c] = alpha[c];
    ctrl[1][c] = alpha[c] + beta[c] / 2;
    ctrl[2][c] = alpha[c] + beta[c] + gamma[c];
  }
  if (*rc::gen::arbitrary<bool>()) {  // degree elevation to 3
    std::vector<std::array<Exact, 3>> e(4);
    for (int c = 0; c < 3; ++c) {
      e[0][c] = ctrl[0][c];
      e[1][c] = (ctrl[0][c] + 2 * ctrl[1][c]) / 3;
      e[2][c] = (2 * ctrl[1][c] + ctrl[2][c]) / 3;
      e[3][c] = ctrl[2][c];
    }
    ctrl = e;
  }
  Motion motion;
  std::tie(motion.t0, motion.t1) = pick_interval();
  const Exact w = pick(0.25, 4);
  for (const auto& a : ctrl) {
    motion.control_points.push_back({lin[0], lin[1], lin[2], a[0], lin[3], lin[4], lin[5], a[1], lin[6], lin[7], lin[8], a[2]});
    motion.weights.push_back(w);
  }
  const Exact t_star = motion.t0 + s * (motion.t1 - motion.t0);
  RC_ASSERT(place(eval_motion(motion, t_star), tri[low]) == q);  // the construction itself

  const Exact epsilon = *rc::gen::element(Exact(1, 16), Exact(1, 100), Exact(1, 1000));
  const Scene scene = make_scene(make_body("mover", {tri}, motion), make_body("table", {square_z0(1)}), epsilon);
  const CheckResult r = verify_check(scene, 0, 1, options_for(epsilon, kernel, max_nodes));
  RC_LOG() << describe(scene) << "\ntouching at t* = " << str(t_star) << " (vertex " << low << " at " << str(q)
           << ")\nkernel " << to_string(kernel) << ": " << describe(r) << "\n";
  RC_TAG(stop_label(r), nodes_label(r));
  RC_ASSERT(r.verdict != Verdict::Safe);
  RC_ASSERT(consistency_problem(scene, 0, 1, r) == "");
  RC_ASSERT(r.first_contact->first <= t_star);
  if (r.verdict == Verdict::Collision) RC_ASSERT(r.witness->t == t_star);  // the only contact instant
}

// (b) The clearance scene is safe at epsilon = m / eps_divisor (clearance_scene
// picks m/4 or m/8 when eps_divisor is 0).
void clearance_is_safe(int eps_divisor) {
  Exact m;
  const Scene scene = clearance_scene(m, eps_divisor);
  const CheckResult r = verify_check(scene, 0, 1, options_for(*scene.epsilon, KernelKind::Filtered));
  RC_LOG() << describe(scene) << "\nclearance m = " << str(m) << "\n" << describe(r) << "\n";
  RC_TAG(stop_label(r), nodes_label(r));
  RC_ASSERT(r.verdict == Verdict::Safe);
  RC_ASSERT(consistency_problem(scene, 0, 1, r) == "");
}

}  // namespace

BOOST_AUTO_TEST_SUITE(guarantee)

// ------------------------------------------------------------------ (a)

RC_BOOST_PROP(contact_at_known_time_is_never_safe_filtered, ()) { contact_never_safe(KernelKind::Filtered, 20000); }

BOOST_AUTO_TEST_CASE(contact_at_known_time_is_never_safe_exact) {
  check_cases([] { contact_never_safe(KernelKind::Exact, 20000); }, 50);
}

RC_BOOST_PROP(touching_at_known_time_is_never_safe_filtered, ()) { touching_never_safe(KernelKind::Filtered, 20000); }

BOOST_AUTO_TEST_CASE(touching_at_known_time_is_never_safe_exact) {
  check_cases([] { touching_never_safe(KernelKind::Exact, 20000); }, 50);
}

// ------------------------------------------------------------------ (b)

RC_BOOST_PROP(clearance_m_is_safe_for_epsilon_up_to_m_over_4, ()) { clearance_is_safe(0); }

// DESIGN.md section 6 claims more: safe for every epsilon <= m/2.  Checked
// at epsilon = m/2 exactly.
RC_BOOST_PROP(clearance_m_is_safe_for_epsilon_m_over_2, ()) { clearance_is_safe(2); }

// ------------------------------------------------------------------ (c)

RC_BOOST_PROP(interpenetration_from_the_start_is_a_collision_at_t0, ()) {
  const Scene scene = interpenetration_scene();
  const Motion& m = *scene.bodies[0].motion;
  for (KernelKind kernel : {KernelKind::Filtered, KernelKind::Exact}) {
    const CheckResult r = verify_check(scene, 0, 1, options_for(*scene.epsilon, kernel));
    RC_LOG() << describe(scene) << "\nkernel " << to_string(kernel) << ": " << describe(r) << "\n";
    RC_ASSERT(r.verdict == Verdict::Collision);
    RC_ASSERT(consistency_problem(scene, 0, 1, r) == "");
    RC_ASSERT(r.witness->t == m.t0);
    RC_ASSERT(r.first_contact->first == m.t0);
    RC_ASSERT(r.first_contact->second == m.t0);
  }
}

// ------------------------------------------------------------------ (d)

// The lowest vertex of a triangle translated over the square [-1,1]^2 x {0}
// comes within exactly 10^-17 of it (above its interior, an edge or a corner)
// and never closer; the rest of the triangle stays higher.  Either a
// polynomial parabola whose minimum 10^-17 is reached at the middle of the
// motion (a dyadic parameter the search evaluates exactly), or a rational
// curve whose z control values are >= 10^-17 with equality at an end.
RC_BOOST_PROP(vertex_1e17_above_face_is_never_a_collision, ()) {
  const Exact delta = pow10(-17);
  std::vector<Vec3E> tri = {{0, 0, 0}, {pick(-1, 1), pick(-1, 1), pick(0.25, 1)}, {pick(-1, 1), pick(-1, 1), pick(0.25, 1)}};
  RC_PRE(nondegenerate(tri));
  Motion motion;
  std::tie(motion.t0, motion.t1) = pick_interval();
  const bool parabola = *rc::gen::arbitrary<bool>();
  if (parabola) {
    const Exact cx = pick(-1, 1), cy = pick(-1, 1), vx = pick(-2, 2), vy = pick(-2, 2), k = pick(0.25, 4);
    motion.control_points = {translation(cx - vx, cy - vy, delta + k / 4), translation(cx, cy, delta - k / 4),
                             translation(cx + vx, cy + vy, delta + k / 4)};
    motion.weights = {1, 1, 1};
  } else {
    const int count = uniform(2, 4);
    const int low = *rc::gen::element(0, count - 1);
    for (int k = 0; k < count; ++k)
      motion.control_points.push_back(translation(pick(-1, 1), pick(-1, 1), k == low ? delta : delta + pick(0, 2)));
    motion.weights = pick_weights(count);
  }
  const Exact epsilon(1, 1000);
  const Scene scene = make_scene(make_body("mover", {tri}, motion), make_body("table", {square_z0(1)}), epsilon);
  const CheckResult r = verify_check(scene, 0, 1, options_for(epsilon, KernelKind::Filtered));
  RC_LOG() << describe(scene) << "\n" << describe(r) << "\n";
  RC_TAG(stop_label(r), nodes_label(r));
  RC_ASSERT(r.verdict != Verdict::Collision);
  RC_ASSERT(consistency_problem(scene, 0, 1, r) == "");
}

// ------------------------------------------------------------------ (e)

RC_BOOST_PROP(verdicts_invariant_under_translation_by_1e6_and_scaling_by_1e_6, ()) {
  const int kind = uniform(0, 2);
  Exact m;
  const Scene scene = kind == 0 ? clearance_scene(m) : kind == 1 ? interpenetration_scene() : sweep_scene();
  const Verdict expected = kind == 0 ? Verdict::Safe : Verdict::Collision;
  const Exact big = pow10(6);
  const Vec3E d = {*rc::gen::element(1, -1) * big, *rc::gen::element(1, -1) * big, *rc::gen::element(1, -1) * big};
  const Scene variants[3] = {scene, translated(scene, d), scaled(scene, pow10(-6))};
  const char* names[3] = {"original", "translated by 10^6", "scaled by 10^-6"};
  std::optional<Verdict> first;
  for (int v = 0; v < 3; ++v) {
    const Scene& s = variants[v];
    const CheckResult r = verify_check(s, 0, 1, options_for(*s.epsilon, KernelKind::Filtered));
    RC_LOG() << names[v] << ": " << describe(s) << "\n" << describe(r) << "\n";
    RC_ASSERT(consistency_problem(s, 0, 1, r) == "");
    if (!first) first = r.verdict;
    RC_ASSERT(r.verdict == *first);
    RC_ASSERT(r.verdict == expected);
  }
}

// ------------------------------------------------------------------ deterministic cases

namespace {

// A tilted triangle, lowest vertex at its origin.
std::vector<Vec3E> tilted_triangle() { return {{0, 0, 0}, {1, 0, Exact(1, 2)}, {0, 1, 1}}; }

}  // namespace

BOOST_AUTO_TEST_CASE(sweep_through_the_middle_is_a_collision_after_t0) {
  // z translation 3 -> -3 over [0,1]: the lowest vertex reaches the square at
  // t* = 1/2 and nothing touches before.
  Motion motion;
  motion.t0 = 0;
  motion.t1 = 1;
  motion.control_points = {translation(0, 0, 3), translation(0, 0, -3)};
  motion.weights = {1, 1};
  const Exact t_star(1, 2);
  const Scene scene =
      make_scene(make_body("blade", {tilted_triangle()}, motion), make_body("table", {square_z0(2)}), Exact(1, 1000));
  for (KernelKind kernel : {KernelKind::Filtered, KernelKind::Exact}) {
    const CheckResult r = verify_check(scene, 0, 1, options_for(*scene.epsilon, kernel));
    BOOST_TEST_INFO(to_string(kernel) << ": " << describe(r));
    BOOST_TEST(consistency_problem(scene, 0, 1, r) == "");
    BOOST_REQUIRE((r.verdict == Verdict::Collision));
    BOOST_TEST(r.first_contact->first > motion.t0);
    BOOST_TEST(r.first_contact->first <= t_star);
    BOOST_TEST(r.witness->t >= t_star);
  }
}

BOOST_AUTO_TEST_CASE(rational_sweep_through_the_middle_is_a_collision_after_t0) {
  // Interval [2, 5], a rational cubic with unequal weights, z control values
  // 3, 1, -1, -3 (monotone: variation diminishing), x and y wandering.
  Motion motion;
  motion.t0 = 2;
  motion.t1 = 5;
  motion.control_points = {translation(0, 0, 3), translation(Exact(1, 2), -Exact(1, 3), 1),
                           translation(-Exact(1, 4), Exact(1, 2), -1), translation(0, 0, -3)};
  motion.weights = {1, 3, Exact(1, 2), 2};
  const Scene scene =
      make_scene(make_body("blade", {tilted_triangle()}, motion), make_body("table", {square_z0(2)}), Exact(1, 1000));
  const CheckResult r = verify_check(scene, 0, 1, options_for(*scene.epsilon, KernelKind::Filtered));
  BOOST_TEST_INFO(describe(r));
  BOOST_TEST(consistency_problem(scene, 0, 1, r) == "");
  BOOST_REQUIRE((r.verdict == Verdict::Collision));
  if (r.witness->root) {
    // An exact first contact at an irrational time: strictly inside its
    // open isolating interval, which starts at or after t0.
    BOOST_TEST(r.first_contact_exact);
    BOOST_TEST(r.witness->root->lo >= motion.t0);
    BOOST_TEST(r.witness->root->hi <= motion.t1);
  } else {
    BOOST_TEST(r.first_contact->first > motion.t0);
    BOOST_TEST(r.first_contact->first < motion.t1);
  }
}

BOOST_AUTO_TEST_CASE(pass_with_a_clear_margin_is_safe) {
  // Over the square at height 1 (lowest vertex), then beside it.
  Motion over;
  over.t0 = 0;
  over.t1 = 1;
  over.control_points = {translation(-6, 0, 1), translation(0, 1, 1), translation(6, 0, 1)};
  over.weights = {1, 2, 1};
  Motion beside;
  beside.t0 = -1;
  beside.t1 = 1;
  beside.control_points = {translation(3, -6, -1), translation(3, 6, 0)};
  beside.weights = {1, 1};
  for (const Motion& motion : {over, beside}) {
    const Scene scene =
        make_scene(make_body("blade", {tilted_triangle()}, motion), make_body("table", {square_z0(2)}), Exact(1, 1000));
    for (KernelKind kernel : {KernelKind::Filtered, KernelKind::Exact}) {
      const CheckResult r = verify_check(scene, 0, 1, options_for(*scene.epsilon, kernel));
      BOOST_TEST_INFO(to_string(kernel) << ": " << describe(r));
      BOOST_TEST((r.verdict == Verdict::Safe));
      BOOST_TEST(consistency_problem(scene, 0, 1, r) == "");
    }
  }
}

BOOST_AUTO_TEST_CASE(vertex_1e17_above_face_hovering_is_not_a_collision) {
  // The lowest vertex hovers at exactly 10^-17 above the square's interior
  // for the whole motion.
  const Exact delta = pow10(-17);
  Motion motion;
  motion.control_points = {translation(-Exact(1, 2), 0, delta), translation(Exact(1, 2), 0, delta)};
  motion.weights = {1, 1};
  const Scene scene =
      make_scene(make_body("blade", {tilted_triangle()}, motion), make_body("table", {square_z0(2)}), Exact(1, 1000));
  for (KernelKind kernel : {KernelKind::Filtered, KernelKind::Exact}) {
    const CheckResult r = verify_check(scene, 0, 1, options_for(*scene.epsilon, kernel, 2000));
    BOOST_TEST_INFO(to_string(kernel) << ": " << describe(r));
    BOOST_TEST((r.verdict != Verdict::Collision));
    BOOST_TEST(consistency_problem(scene, 0, 1, r) == "");
  }
}

BOOST_AUTO_TEST_CASE(the_oracle_itself) {
  // The independent evaluation and point-in-triangle test used as oracle.
  Motion m;
  m.t0 = 1;
  m.t1 = 3;
  m.control_points = {translation(0, 0, 0), translation(2, 0, 0), translation(4, 4, 0)};
  m.weights = {1, 2, 1};
  // u = 1/2: (0*1/4 + 2*2*1/2 + 4*1/4) / (1/4 + 1 + 1/4) = 3 / (3/2) = 2; y = 1 / (3/2) = 2/3.
  const Mat34E p = eval_motion(m, 2);
  BOOST_TEST(p[3] == Exact(2));
  BOOST_TEST(p[7] == Exact(2, 3));
  BOOST_TEST(in_triangle({Exact(1, 3), Exact(1, 3), 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}));
  BOOST_TEST(in_triangle({Exact(1, 2), Exact(1, 2), 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}));
  BOOST_TEST(!in_triangle({Exact(1, 2), Exact(1, 2), pow10(-17)}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}));
  BOOST_TEST(!in_triangle({Exact(1, 2) + pow10(-17), Exact(1, 2), 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}));
  BOOST_TEST(in_triangle({1, 1, 1}, {0, 0, 0}, {2, 2, 2}, {1, 1, 1}));  // degenerate
  BOOST_TEST(!in_triangle({3, 3, 3}, {0, 0, 0}, {2, 2, 2}, {1, 1, 1}));
}

BOOST_AUTO_TEST_SUITE_END()
