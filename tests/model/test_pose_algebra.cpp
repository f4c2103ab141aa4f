// src/model/pose_algebra.h: exact rotations and poses, the keyframe
// interpolations that are rational curves, and the reader's checks.
#include "src/model/pose_algebra.h"

#include <boost/test/unit_test.hpp>

#include <string>

using namespace tmcert;

namespace {

Rotation quaternion_rotation(Exact w, Exact x, Exact y, Exact z) {
  Rotation r;
  r.kind = Rotation::Kind::Quaternion;
  r.quaternion = {w, x, y, z};
  return r;
}

Rotation matrix_rotation(const std::array<Exact, 9>& m) {
  Rotation r;
  r.kind = Rotation::Kind::Matrix;
  r.matrix = m;
  return r;
}

Rotation rpy_rotation(Exact roll, Exact pitch, Exact yaw) {
  Rotation r;
  r.kind = Rotation::Kind::Rpy;
  r.rpy = {roll, pitch, yaw};
  return r;
}

Pose pose_of(const Rotation& r, Vec3E t) {
  Pose p;
  p.rotation = r;
  p.translation = t;
  return p;
}

// The point of a rational Bezier motion at its parameter u in [0, 1] from
// the Bernstein form (degree <= 3 here).
Mat34E point_at(const Motion& m, const Exact& u) {
  const int n = m.degree();
  const long binomial[4][4] = {{1}, {1, 1}, {1, 2, 1}, {1, 3, 3, 1}};
  Mat34E num;
  for (Exact& x : num) x = 0;
  Exact w(0);
  for (int k = 0; k <= n; ++k) {
    Exact b(binomial[n][k]);
    for (int i = 0; i < k; ++i) b *= u;
    for (int i = k; i < n; ++i) b *= 1 - u;
    b *= m.weights[k];
    for (int e = 0; e < 12; ++e) num[e] += b * m.control_points[k][e];
    w += b;
  }
  for (Exact& x : num) x /= w;
  return num;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(model_pose_algebra)

BOOST_AUTO_TEST_CASE(exact_quaternions_and_poses) {
  // A quarter turn about z written three ways gives the same exact pose.
  const Vec3E t{Exact(1), Exact(2), Exact(3)};
  const Mat34E expected{0, -1, 0, 1, 1, 0, 0, 2, 0, 0, 1, 3};
  BOOST_TEST((*exact_pose(pose_of(quaternion_rotation(1, 0, 0, 1), t)) == expected));
  BOOST_TEST((*exact_pose(pose_of(quaternion_rotation(-7, 0, 0, -7), t)) == expected));
  BOOST_TEST((*exact_pose(pose_of(matrix_rotation({0, -1, 0, 1, 0, 0, 0, 0, 1}), t)) == expected));
  // A half turn about x (1 + trace = 0): the branch of the largest diagonal entry.
  const Rotation half = matrix_rotation({1, 0, 0, 0, -1, 0, 0, 0, -1});
  const auto q = exact_quaternion(half);
  BOOST_TEST_REQUIRE(q.has_value());
  BOOST_TEST((*q)[0] == 0);
  BOOST_TEST((*q)[2] == 0);
  BOOST_TEST((*q)[3] == 0);
  BOOST_TEST((*q)[1] != 0);
  // rpy is not exact, except all zeros (the identity).
  BOOST_TEST(!exact_quaternion(rpy_rotation(Exact(1, 2), 0, 0)).has_value());
  BOOST_TEST(!exact_pose(pose_of(rpy_rotation(Exact(1, 2), 0, 0), t)).has_value());
  BOOST_TEST((*exact_quaternion(rpy_rotation(0, 0, 0)) == std::array<Exact, 4>{1, 0, 0, 0}));
}

BOOST_AUTO_TEST_CASE(same_rotation_is_proven_exactly) {
  BOOST_TEST(same_rotation(quaternion_rotation(1, 0, 0, 1), quaternion_rotation(-2, 0, 0, -2)));
  BOOST_TEST(same_rotation(quaternion_rotation(1, 0, 0, 1), matrix_rotation({0, -1, 0, 1, 0, 0, 0, 0, 1})));
  BOOST_TEST(!same_rotation(quaternion_rotation(1, 0, 0, 1), quaternion_rotation(1, 0, 0, -1)));
  BOOST_TEST(same_rotation(rpy_rotation(Exact(1, 3), 0, 0), rpy_rotation(Exact(1, 3), 0, 0)));
  BOOST_TEST(!same_rotation(rpy_rotation(Exact(1, 3), 0, 0), quaternion_rotation(1, 0, 0, 0)));
}

BOOST_AUTO_TEST_CASE(rotation_matrix_problems) {
  BOOST_TEST(rotation_matrix_problem({0, -1, 0, 1, 0, 0, 0, 0, 1}).empty());
  BOOST_TEST(rotation_matrix_problem({2, 0, 0, 0, 1, 0, 0, 0, 1}) ==
             "the rows are not exactly orthonormal (row 0 . row 0 = 4)");
  BOOST_TEST(rotation_matrix_problem({-1, 0, 0, 0, 1, 0, 0, 0, 1}) == "the determinant is -1, not +1 (a reflection)");
}

BOOST_AUTO_TEST_CASE(rational_keyframe_segments) {
  const Pose a = pose_of(quaternion_rotation(1, 0, 0, 0), {Exact(0), Exact(0), Exact(0)});
  const Pose b = pose_of(quaternion_rotation(1, 0, 0, 1), {Exact(2), Exact(0), Exact(-1)});
  // nlerp between exact rotations: a cubic whose ends are the two poses, and whose middle is the
  // normalised mean quaternion's rotation at the mean translation.
  const auto m = rational_keyframe_segment(a, b, Interpolation::Nlerp, Exact(1), Exact(3));
  BOOST_TEST_REQUIRE(m.has_value());
  BOOST_TEST(m->degree() == 3);
  BOOST_TEST(m->nlerp);
  BOOST_TEST(m->t0 == 1);
  BOOST_TEST(m->t1 == 3);
  BOOST_TEST((point_at(*m, 0) == *exact_pose(a)));
  BOOST_TEST((point_at(*m, 1) == *exact_pose(b)));
  const Pose mid = pose_of(quaternion_rotation(2, 0, 0, 1), {Exact(1), Exact(0), Exact(-1, 2)});
  BOOST_TEST((point_at(*m, Exact(1, 2)) == *exact_pose(mid)));
  // slerp and screw between different rotations are not rational; between equal ones
  // every interpolation is the translation.
  BOOST_TEST(!rational_keyframe_segment(a, b, Interpolation::Slerp, Exact(0), Exact(1)).has_value());
  BOOST_TEST(!rational_keyframe_segment(a, b, Interpolation::Screw, Exact(0), Exact(1)).has_value());
  const Pose c = pose_of(quaternion_rotation(3, 0, 0, 0), {Exact(0), Exact(4), Exact(0)});
  const auto line = rational_keyframe_segment(a, c, Interpolation::Slerp, Exact(0), Exact(1));
  BOOST_TEST_REQUIRE(line.has_value());
  BOOST_TEST(line->degree() == 1);
  BOOST_TEST((point_at(*line, Exact(1, 4)) == Mat34E{1, 0, 0, 0, 0, 1, 0, 1, 0, 0, 1, 0}));
}

BOOST_AUTO_TEST_CASE(interpolable_pairs) {
  const Pose a = pose_of(quaternion_rotation(1, 0, 0, 0), {Exact(0), Exact(0), Exact(0)});
  const Pose half_turn = pose_of(quaternion_rotation(0, 1, 0, 0), {Exact(0), Exact(0), Exact(0)});
  BOOST_CHECK_THROW(require_interpolable(a, half_turn, Interpolation::Slerp), InputError);
  BOOST_CHECK_THROW(require_interpolable(a, half_turn, Interpolation::Screw), InputError);
  BOOST_CHECK_NO_THROW(require_interpolable(a, half_turn, Interpolation::Nlerp));
  const Pose quarter = pose_of(quaternion_rotation(1, 1, 0, 0), {Exact(0), Exact(0), Exact(0)});
  BOOST_CHECK_NO_THROW(require_interpolable(a, quarter, Interpolation::Slerp));
  // rpy: the arc is decided on enclosures.  An odd multiple of pi within 1e-13 (318309 pi, rounded
  // to 12 decimals) about x from the identity: the dot product cos(r / 2) is enclosed around 0.
  const Pose near_half =
      pose_of(rpy_rotation(Exact(999997215971513496L) / Exact(1000000000000L), 0, 0), {Exact(0), Exact(0), Exact(0)});
  BOOST_CHECK_THROW(require_interpolable(a, near_half, Interpolation::Slerp), InputError);
  const Pose small = pose_of(rpy_rotation(Exact(1, 10), 0, 0), {Exact(0), Exact(0), Exact(0)});
  BOOST_CHECK_NO_THROW(require_interpolable(a, small, Interpolation::Slerp));
}

BOOST_AUTO_TEST_CASE(weights_are_normalised_without_changing_the_curve) {
  Motion m;
  m.t0 = 0;
  m.t1 = 1;
  m.control_points = {Mat34E{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0}, Mat34E{1, 0, 0, 5, 0, 1, 0, 0, 0, 0, 1, 0},
                      Mat34E{1, 0, 0, 2, 0, 1, 0, 3, 0, 0, 1, 0}};
  Exact big(1);
  for (int i = 0; i < 100; ++i) big *= 10;  // 1e100: far outside (2^-32, 2^32)
  m.weights = {big, 3 * big, 2 * big};
  const Mat34E before = point_at(m, Exact(1, 3));
  normalise_weights(m);
  BOOST_TEST((m.weights == std::vector<Exact>{1, 3, 2}));
  BOOST_TEST((point_at(m, Exact(1, 3)) == before));
  // Comfortable weights stay as they are.
  m.weights = {Exact(1, 2), Exact(7), Exact(3, 5)};
  normalise_weights(m);
  BOOST_TEST((m.weights == std::vector<Exact>{Exact(1, 2), Exact(7), Exact(3, 5)}));
}

BOOST_AUTO_TEST_CASE(quaternion_scales_are_powers_of_two) {
  const Exact f = quaternion_scale({Exact(3), Exact(0), Exact(-1, 4), Exact(1)});
  BOOST_TEST(f * 3 > Exact(1, 2));
  BOOST_TEST(f * 3 < 2);
  BOOST_TEST(f == Exact(1, 2));
}

BOOST_AUTO_TEST_SUITE_END()
