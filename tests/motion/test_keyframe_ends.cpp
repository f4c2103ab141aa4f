// A keyframe segment's rotations compared and its exact end poses
// (src/motion/segment.cpp; proofs/enclosures.md section 3b): equal
// rotations are found through the interval filter and the exact fallback
// alike (a translation motion), different ones under slerp give no
// rational segment, and the model's exact ends, computed when first
// asked, are exact_pose of the keyframes.
#include "src/motion/segment.h"
#include "src/motion/segment_kinds.h"

#include <boost/test/unit_test.hpp>

#include <cmath>

using namespace tmcert;

namespace {

Pose quaternion_pose(double w, double x, double y, double z, double tx) {
  Pose p;
  p.translation = {Exact(tx), Exact(0), Exact(0)};
  p.rotation.kind = Rotation::Kind::Quaternion;
  p.rotation.quaternion = {Exact(w), Exact(x), Exact(y), Exact(z)};
  return p;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(keyframe_ends)

BOOST_AUTO_TEST_CASE(proportional_quaternions_are_one_rotation) {
  // q, 2q, -q and -q/4: every minor is exactly 0 (the filter cannot exclude 0,
  // the exact test decides): a translation, whatever the interpolation.
  const Pose a = quaternion_pose(0.5, 0.25, -0.125, 1.0 / 3.0, 0);
  for (double f : {2.0, -1.0, -0.25}) {  // exact scalings of the doubles
    const Pose b = quaternion_pose(0.5 * f, 0.25 * f, -0.125 * f, (1.0 / 3.0) * f, 1);
    for (Interpolation how : {Interpolation::Slerp, Interpolation::Screw, Interpolation::Nlerp}) {
      const auto m = rational_keyframe_segment(a, b, how, Exact(0), Exact(1));
      BOOST_REQUIRE(m);
      BOOST_TEST(m->control_points.size() == 2u);
      BOOST_TEST((m->control_points.front() == *exact_pose(a)));
    }
  }
}

BOOST_AUTO_TEST_CASE(different_rotations_under_slerp_have_no_rational_segment) {
  // Decided by the filter (a minor far from 0) and, for rotations one
  // rounding apart, by the exact fallback (the minor 2^-104 lies inside
  // the enclosure of the difference of two rounded products).
  const double e = std::ldexp(1.0, -52);
  const Pose far_a = quaternion_pose(1, 0, 0, 0, 0), far_b = quaternion_pose(0, 1, 0, 0, 1);
  const Pose near_a = quaternion_pose(1 + e, 1, 0, 0, 0), near_b = quaternion_pose(1 + 2 * e, 1 + e, 0, 0, 1);
  BOOST_TEST((Exact(1 + e) * Exact(1 + e) - Exact(1) * Exact(1 + 2 * e) == Exact(std::ldexp(1.0, -104))));
  for (const auto& [a, b] : {std::pair{far_a, far_b}, std::pair{near_a, near_b}}) {
    BOOST_TEST(!rational_keyframe_segment(a, b, Interpolation::Slerp, Exact(0), Exact(1)));
    BOOST_TEST(!rational_keyframe_segment(a, b, Interpolation::Screw, Exact(0), Exact(1)));
    // nlerp: a rational segment of degree 3 through the exact ends.
    const auto n = rational_keyframe_segment(a, b, Interpolation::Nlerp, Exact(0), Exact(1));
    BOOST_REQUIRE(n);
    BOOST_TEST(n->control_points.size() == 4u);
  }
}

BOOST_AUTO_TEST_CASE(the_models_exact_ends_are_the_keyframes) {
  const Pose a = quaternion_pose(0.5, 0.25, -0.125, 1.0 / 3.0, 0.1);
  const Pose b = quaternion_pose(-0.75, 0.5, 0.0625, 0.2, 2.5);
  for (Interpolation how : {Interpolation::Slerp, Interpolation::Screw, Interpolation::Nlerp}) {
    const auto model = make_keyframe_model(a, b, how);
    for (int twice = 0; twice < 2; ++twice) {  // computed once, then remembered
      BOOST_TEST((model->exact_pose(Exact(0)) == exact_pose(a)));
      BOOST_TEST((model->exact_pose(Exact(1)) == exact_pose(b)));
      BOOST_TEST(!model->exact_pose(Exact(1, 2)));
    }
    // The enclosure at an end holds the exact end.
    RoundingGuard guard;
    const PoseInterval m = model->pose_values(Interval(1));
    const Mat34E e = *exact_pose(b);
    for (int k = 0; k < 12; ++k) BOOST_TEST((m[k].inf() <= CGAL::to_double(e[k]) && CGAL::to_double(e[k]) <= m[k].sup()));
  }
}

BOOST_AUTO_TEST_CASE(the_arc_is_decided_exactly_near_a_half_turn) {
  // The sign of the quaternions' dot product (which arc is shorter) is
  // taken from its interval enclosure only when that excludes 0
  // (proofs/enclosures.md section 3c).  (1, 1, 0, 0) against
  // (-1 - 2^-60, 1, 0, 0): the dot product -2^-60 lies inside the
  // enclosure's rounding, so the exact sign decides: accepted, and the
  // slerp takes the arc through the identity (p1 negated: R[1][1] = 1 at
  // s = 1/2, not -1 as on the other arc).  Exactly a half turn apart
  // (dot product 0): no shorter arc, refused.
  const Exact tiny = Exact(1, 1 << 30) * Exact(1, 1 << 30);  // 2^-60
  Pose a = quaternion_pose(1, 1, 0, 0, 0);
  Pose b = quaternion_pose(-1, 1, 0, 0, 0);
  b.rotation.quaternion[0] = Exact(-1) - tiny;
  for (Interpolation how : {Interpolation::Slerp, Interpolation::Screw}) {
    BOOST_CHECK_NO_THROW(require_interpolable(a, b, how));
    BOOST_CHECK_THROW(require_interpolable(a, quaternion_pose(-1, 1, 0, 0, 0), how), InputError);
  }
  const auto model = make_keyframe_model(a, b, Interpolation::Slerp);
  RoundingGuard guard;
  const auto mid = model->pose_values(Interval(0.5));
  BOOST_TEST(mid[5].inf() > 0.99);  // R[1][1]: near the identity
  const Exact minus_tiny = tiny - Exact(1);  // (-1 + 2^-60, 1, 0, 0): dot +2^-60, no negation
  b.rotation.quaternion[0] = minus_tiny;
  BOOST_CHECK_NO_THROW(require_interpolable(a, b, Interpolation::Slerp));
  const auto other = make_keyframe_model(a, b, Interpolation::Slerp)->pose_values(Interval(0.5));
  BOOST_TEST(other[5].sup() < -0.99);  // through the half turn about x
}

BOOST_AUTO_TEST_CASE(value_parts_are_the_jets_values_bit_for_bit) {
  // The model's value-only pose_values (slerp away from angle 0, nlerp,
  // equal rotations) against the value parts of pose(Jet(s)), at points
  // and over intervals; screw and a tiny slerp angle use the jets.
  const Pose a = quaternion_pose(0.5, 0.25, -0.125, 1.0 / 3.0, 0.1);
  const Pose b = quaternion_pose(-0.75, 0.5, 0.0625, 0.2, 2.5);
  const Pose same = quaternion_pose(1.0, 0.5, -0.25, 2.0 / 3.0, -1);  // 2a: the same rotation
  const Pose tiny = quaternion_pose(0.5, 0.25, -0.125, 1.0 / 3.0 + 1e-9, 3);
  const std::pair<Pose, Pose> ends[] = {{a, b}, {a, same}, {a, tiny}};
  for (const auto& [p, q] : ends)
    for (Interpolation how : {Interpolation::Slerp, Interpolation::Nlerp, Interpolation::Screw}) {
      const auto model = make_keyframe_model(p, q, how);
      RoundingGuard guard;
      for (const Interval& s : {Interval(0), Interval(1), Interval(0.375), Interval(0.25, 0.3125), Interval(0, 1)}) {
        const PoseInterval v = model->pose_values(s);
        const PoseJet j = model->pose(Jet(s));
        for (int e = 0; e < 12; ++e) {
          BOOST_TEST(v[e].inf() == j[e].v.inf());
          BOOST_TEST(v[e].sup() == j[e].v.sup());
        }
      }
    }
}

BOOST_AUTO_TEST_SUITE_END()
