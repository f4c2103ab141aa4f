// src/verify/exact_resolution: a rational motion's curve in power basis
// (the same poses as its Bernstein form), the moving points of a feature,
// and the earliest contact of the alive feature pairs on a piece, exactly.
#include "src/verify/exact_resolution.h"
#include "src/motion/bezier.h"
#include "tests/verify/check_testing.h"

#include <boost/test/unit_test.hpp>

using namespace tmcert;
using namespace tmcert::detail;
using tmcert::testing::two_cubes;

namespace {

Exact eval(const PolyQ& p, const Exact& u) {
  Exact s = 0;
  for (std::size_t k = p.size(); k-- > 0;) s = s * u + p[k];
  return s;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(verify_exact_resolution)

BOOST_AUTO_TEST_CASE(power_basis_gives_the_bernstein_poses) {
  // A degree-2 rational curve with unequal weights.
  Motion m;
  m.control_points = {Mat34E{1, 0, 0, 1, 0, 1, 0, 2, 0, 0, 1, 3}, Mat34E{0, -1, 0, Exact(1, 2), 1, 0, 0, 0, 0, 0, 1, -1},
                      Mat34E{2, 0, 0, 0, 0, 2, 0, 5, 0, 0, 2, Exact(7, 3)}};
  m.weights = {1, 3, Exact(1, 2)};
  const HomogeneousCurve<Exact, 1> curve = homogeneous_curve(m);
  const std::vector<PolyQ> power = power_basis<1>(curve);
  BOOST_REQUIRE(power.size() == kHomogeneousSize<1>);
  for (const Exact& u : {Exact(0), Exact(1, 3), Exact(1, 2), Exact(5, 7), Exact(1)}) {
    const Mat34E pose = evaluate<1>(curve, u);
    const Exact w = eval(power.back(), u);
    BOOST_REQUIRE(w > 0);
    for (int e = 0; e < 12; ++e) BOOST_TEST(eval(power[e], u) / w == pose[e]);
    // moving_point: w(u) times the placed point.
    const Vec3E x{Exact(1, 2), -2, 3};
    const MovingPoint p = moving_point(power, 0, x);
    for (int i = 0; i < 3; ++i)
      BOOST_TEST(eval(p.x[i], u) == w * (pose[4 * i] * x[0] + pose[4 * i + 1] * x[1] + pose[4 * i + 2] * x[2] + pose[4 * i + 3]));
    // A fixed body (block < 0): w(u) times its world point.
    const MovingPoint f = moving_point(power, -1, x);
    for (int i = 0; i < 3; ++i) BOOST_TEST(eval(f.x[i], u) == w * x[i]);
  }
}

BOOST_AUTO_TEST_CASE(earliest_contact_on_a_piece) {
  // The mover's face x = -1/2 + (-3 + 6u) reaches the post at u = 1/3.
  const Scene scene = two_cubes("-3 0 0", "3 0 0");
  const PreparedBody mover(scene.bodies[0]), post(scene.bodies[1]);
  const std::vector<PolyQ> power = power_basis<1>(mover.curve);
  const std::vector<PairRef> alive = all_pairs(mover, post);
  const PieceResolution whole = resolve_piece<1>(mover, post, mover.curve, power, 0, 1, alive);
  BOOST_REQUIRE(whole.decided);
  BOOST_REQUIRE(whole.first);
  BOOST_TEST(whole.first->contact.t.is_rational());
  BOOST_TEST(whole.first->contact.t.lo == Exact(1, 3));
  // Before the contact: decided, none.
  const PieceResolution before = resolve_piece<1>(mover, post, mover.curve, power, 0, Exact(1, 4), alive);
  BOOST_TEST(before.decided);
  BOOST_TEST(!before.first);
  // A node pair alive: not decided (the caller keeps the piece).
  const PieceResolution nodes = resolve_piece<1>(mover, post, mover.curve, power, 0, 1, {node_pair(0, 0)});
  BOOST_TEST(!nodes.decided);
}

BOOST_AUTO_TEST_CASE(moving_and_other_vertices_follow_the_kind) {
  const Scene scene = two_cubes("-3 0 0", "3 0 0");
  const PreparedBody mover(scene.bodies[0]), post(scene.bodies[1]);
  BOOST_TEST(&moving_vertices(mover, ContactKind::VertexFace) == &mover.exact_vertices().vertices);
  BOOST_TEST(&moving_vertices(mover, ContactKind::EdgeEdge) == &mover.exact_vertices().edges);
  BOOST_TEST(&moving_vertices(mover, ContactKind::FaceVertex) == &mover.exact_vertices().faces);
  BOOST_TEST(&other_vertices(post, ContactKind::VertexFace) == &post.exact_vertices().faces);
  BOOST_TEST(&other_vertices(post, ContactKind::FaceVertex) == &post.exact_vertices().vertices);
  for (const auto& v : mover.exact_vertices().vertices) BOOST_TEST(v.size() == 1u);
  for (const auto& e : mover.exact_vertices().edges) BOOST_TEST(e.size() == 2u);
  for (const auto& f : mover.exact_vertices().faces) BOOST_TEST(f.size() >= 3u);
}

BOOST_AUTO_TEST_SUITE_END()
