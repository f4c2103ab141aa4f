// The checker's own enclosures of the scene's motions
// (src/certificate/motions.h) against the verifier's (src/motion/).
#include "tests/certificate/check_support.h"
#include "src/certificate/motions.h"
#include "src/motion/chain.h"
#include "src/motion/segment.h"

using namespace check_test;

namespace {

// The checker's pose box of `body` at scene time t and the verifier's jet
// of `model` at segment parameter s: both tight, overlapping in every
// entry; returns the entries compared.
int compare_pose_enclosures(const Body& body, const SegmentModel& model, const Exact& t, const Exact& s,
                            const std::string& what) {
  const std::optional<cert::PoseBox> box = cert::pose_box_at(body, t);
  BOOST_REQUIRE(box);
  PoseJet jet;
  {
    RoundingGuard guard;
    jet = model.pose(Jet(to_interval(s)));
  }
  for (int e = 0; e < 12; ++e) {
    const double lo = CGAL::to_double(box->center[e] - box->radius[e]);
    const double hi = CGAL::to_double(box->center[e] + box->radius[e]);
    BOOST_TEST(hi - lo < 1e-12);
    BOOST_TEST(jet[e].v.sup() - jet[e].v.inf() < 1e-9);
    BOOST_TEST((jet[e].v.inf() <= hi && lo <= jet[e].v.sup()),
               what << " entry " << e << ": checker [" << lo << ", " << hi << "], verifier " << jet[e].v);
  }
  return 12;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(certificate_check)

// The checker's pose boxes (src/certificate/motions.cpp, Arb from the
// interpolations' definitions; the screw through V(phi)^-1) and the
// verifier's jets (src/motion/segment.cpp; the screw through a point on its
// axis) enclose the same poses: at sample parameters both boxes are tight
// and overlap in every entry.  A wrong sign or factor in either screw
// formula separates them by far more than their widths.
BOOST_AUTO_TEST_CASE(screw_enclosure_matches_the_verifiers) {
  int compared = 0;
  for (Interpolation how : {Interpolation::Slerp, Interpolation::Screw, Interpolation::Nlerp}) {
    for (int variant = 0; variant < 3; ++variant) {
      MotionSegment seg;
      seg.t0 = 0;
      seg.t1 = 2;
      seg.interpolation = how;
      seg.from.translation = v("0.5", "-1", "2");
      seg.to.translation = v("3", "0.25", "-1");
      seg.from.rotation.kind = Rotation::Kind::Rpy;
      seg.from.rotation.rpy = {q("0.3"), q("-0.2"), q("1.1")};
      if (variant == 0) {
        seg.to.rotation.kind = Rotation::Kind::Rpy;
        seg.to.rotation.rpy = {q("1.2"), q("0.4"), q("-0.5")};
      } else if (variant == 1) {
        seg.to.rotation.kind = Rotation::Kind::Quaternion;
        seg.to.rotation.quaternion = {q("2"), q("1"), q("-1"), q("3")};
      } else {
        seg.to.rotation.kind = Rotation::Kind::Rpy;
        seg.to.rotation.rpy = {q("0.3"), q("-0.2"), q("1.2")};  // a small turn
      }
      Body body;
      body.name = "b";
      body.trajectory = Trajectory{{seg}};
      const std::unique_ptr<SegmentModel> model = make_segment_model(seg);
      for (const char* st : {"0", "1/7", "1/2", "0.9", "1"})
        compared += compare_pose_enclosures(body, *model, q(st) * 2, q(st),
                                            "interpolation " + std::to_string(static_cast<int>(how)) + " variant " +
                                                std::to_string(variant) + " s = " + st);
    }
  }
  BOOST_TEST(compared == 3 * 3 * 5 * 12);
}

// The same for robot links: the checker's product of Rodrigues rotations
// and the verifier's sparse chain jets (src/motion/chain.*) on a chain with
// rpy and quaternion constants, two revolute joints (one axis not of unit
// length) and a prismatic one.
BOOST_AUTO_TEST_CASE(link_enclosure_matches_the_verifiers) {
  auto pose = [&](const char* x, const char* y, const char* z, std::array<const char*, 3> rpy) {
    Pose p;
    p.translation = v(x, y, z);
    p.rotation.kind = Rotation::Kind::Rpy;
    p.rotation.rpy = {q(rpy[0]), q(rpy[1]), q(rpy[2])};
    return p;
  };
  Pose quat;
  quat.translation = v("0", "0.1", "0.3");
  quat.rotation.kind = Rotation::Kind::Quaternion;
  quat.rotation.quaternion = {q("3"), q("1"), q("0"), q("-2")};
  std::vector<std::vector<Pose>> constants = {{pose("0", "0", "0.8", {"0", "0", "0.4"})},
                                              {pose("0.2", "0", "0.5", {"0.1", "-0.3", "0"}), quat},
                                              {pose("0.6", "0", "0", {"0", "0", "0"})},
                                              {pose("0", "0.05", "0.2", {"0.7", "0", "-0.2"})}};
  std::vector<ChainJoint> joints(3);
  joints[0].axis = v("0", "0", "1");
  joints[1].axis = v("0", "2", "1");  // length sqrt 5
  joints[2].kind = ChainJoint::Kind::Prismatic;
  joints[2].axis = v("1", "0", "0");
  auto link = std::make_shared<LinkMotion>();
  link->chain = std::make_shared<const ChainDescription>(constants, joints);
  link->from = {q("-0.5"), q("0.25"), q("0")};
  link->to = {q("1.2"), q("-0.75"), q("0.3")};
  MotionSegment seg;
  seg.t0 = 0;
  seg.t1 = 1;
  seg.link = link;
  Body body;
  body.name = "link";
  body.trajectory = Trajectory{{seg}};
  const std::unique_ptr<SegmentModel> model = make_segment_model(seg);
  int compared = 0;
  for (const char* st : {"0", "1/3", "0.5", "0.77", "1"})
    compared += compare_pose_enclosures(body, *model, q(st), q(st), std::string("link s = ") + st);
  BOOST_TEST(compared == 5 * 12);
  // Cubic and quintic joint polynomials (kind robot_link_hermite): the
  // checker's Hermite basis form and the verifier's power basis on jets
  // (proofs/trajectories.md sections 3 and 4), over a segment of 2 s.
  for (const bool quintic : {false, true}) {
    auto poly = std::make_shared<LinkMotion>(*link);
    poly->duration = 2;
    poly->from_rate = {q("0.3"), q("-0.2"), q("0.05")};
    poly->to_rate = {q("-0.4"), q("0.1"), q("0")};
    if (quintic) {
      poly->from_accel = {q("0.5"), q("0"), q("-0.1")};
      poly->to_accel = {q("-0.25"), q("0.2"), q("0.1")};
    }
    MotionSegment pseg = seg;
    pseg.t1 = 2;
    pseg.link = poly;
    Body pbody = body;
    pbody.trajectory = Trajectory{{pseg}};
    const std::unique_ptr<SegmentModel> pmodel = make_segment_model(pseg);
    int pcompared = 0;
    for (const char* st : {"0", "1/3", "0.5", "0.77", "1"})
      pcompared += compare_pose_enclosures(pbody, *pmodel, q(st) * 2, q(st),
                                           std::string(quintic ? "quintic" : "cubic") + " link s = " + st);
    BOOST_TEST(pcompared == 5 * 12);
  }
}

// The checker's exact link pose at a waypoint (its own product of the
// chain's constants and joints, src/certificate/motions.cpp) against the
// verifier's ChainDescription::exact_pose: equal where the pose is rational (exact
// constants, revolute joints at 0, prismatic axes of rational length or at
// 0), absent in both elsewhere (a revolute joint off 0, a prismatic axis of
// irrational length off 0, an rpy constant).
BOOST_AUTO_TEST_CASE(exact_link_pose_matches_the_verifiers) {
  Pose quat;
  quat.translation = v("0", "0.1", "0.3");
  quat.rotation.kind = Rotation::Kind::Quaternion;
  quat.rotation.quaternion = {q("3"), q("1"), q("0"), q("-2")};
  Pose matrix;
  matrix.translation = v("1/3", "0", "-2");
  matrix.rotation.kind = Rotation::Kind::Matrix;
  matrix.rotation.matrix = {q("0"), q("-1"), q("0"), q("1"), q("0"), q("0"), q("0"), q("0"), q("1")};
  Pose rpy;
  rpy.translation = v("0", "0", "0.5");
  rpy.rotation.kind = Rotation::Kind::Rpy;
  rpy.rotation.rpy = {q("0.1"), q("0"), q("0")};
  Pose shift;
  shift.translation = v("0.25", "0", "0");
  std::vector<ChainJoint> joints(3);
  joints[0].axis = v("0", "0", "1");
  joints[1].kind = ChainJoint::Kind::Prismatic;
  joints[1].axis = v("3", "0", "4");  // length 5
  joints[2].kind = ChainJoint::Kind::Prismatic;
  joints[2].axis = v("1", "1", "0");  // length sqrt 2
  int exact = 0, compared = 0;
  for (const bool with_rpy : {false, true}) {
    const std::vector<std::vector<Pose>> constants = {
        {quat, matrix}, {shift}, {}, {with_rpy ? rpy : shift, matrix}};
    auto link = std::make_shared<LinkMotion>();
    const auto chain = std::make_shared<const ChainDescription>(constants, joints);
    link->chain = chain;
    for (const std::vector<const char*>& from : std::vector<std::vector<const char*>>{
             {"0", "0", "0"}, {"0", "-1/7", "0"}, {"0", "2", "0.5"}, {"0.5", "0", "0"}, {"0", "3", "0"}}) {
      link->from = {q(from[0]), q(from[1]), q(from[2])};
      link->to = {q("1"), q("1"), q("1")};
      MotionSegment seg;
      seg.t0 = 0;
      seg.t1 = 1;
      seg.link = link;
      Body body;
      body.name = "link";
      body.trajectory = Trajectory{{seg}};
      const std::optional<Mat34E> theirs = chain->exact_pose(link->from);
      const std::optional<Mat34E> ours = cert::exact_pose_at(body, Exact(0));
      BOOST_TEST(theirs.has_value() == ours.has_value(), "from " << from[0] << " " << from[1] << " " << from[2]);
      if (theirs && ours) {
        BOOST_TEST((*theirs == *ours));
        ++exact;
      }
      ++compared;
    }
  }
  BOOST_TEST(compared == 10);
  BOOST_TEST(exact == 3);  // without rpy: every joint at 0, or only the prismatic of length 5 off 0
}

// A piece's pose box (piece_motion) holds the poses sampled on the piece
// and is close to their spread: enclosed over parts of the piece, not over
// one ball of its whole parameter range, where the slerp formula's
// dependency blow-up made the box several times wider (the planner
// pieces' penalty, hence many more certificate pieces).
BOOST_AUTO_TEST_CASE(piece_box_is_close_to_the_poses_spread) {
  MotionSegment seg;
  seg.t0 = 0;
  seg.t1 = 1;
  seg.interpolation = Interpolation::Slerp;
  seg.from.translation = v("0", "0", "0");
  seg.to.translation = v("1", "2", "-1");
  seg.from.rotation.kind = Rotation::Kind::Rpy;
  seg.from.rotation.rpy = {q("0.3"), q("-0.2"), q("1.1")};
  seg.to.rotation.kind = Rotation::Kind::Rpy;
  seg.to.rotation.rpy = {q("1.2"), q("0.4"), q("-0.5")};
  Body body;
  body.name = "b";
  body.trajectory = Trajectory{{seg}};
  std::string why;
  const std::optional<cert::PieceMotion> m = cert::piece_motion(body, q("0.4"), q("0.5"), why);
  BOOST_REQUIRE(m);
  BOOST_REQUIRE(!m->exact);
  std::array<double, 12> lo, hi;
  lo.fill(HUGE_VAL);
  hi.fill(-HUGE_VAL);
  for (int k = 0; k <= 200; ++k) {
    const std::optional<cert::PoseBox> at = cert::pose_box_at(body, q("0.4") + Exact(k) / 2000);
    BOOST_REQUIRE(at);
    for (int e = 0; e < 12; ++e) {
      // Every sampled pose in the piece's box.
      BOOST_TEST(at->center[e] - at->radius[e] >= m->box.center[e] - m->box.radius[e]);
      BOOST_TEST(at->center[e] + at->radius[e] <= m->box.center[e] + m->box.radius[e]);
      lo[e] = std::min(lo[e], CGAL::to_double(at->center[e]));
      hi[e] = std::max(hi[e], CGAL::to_double(at->center[e]));
    }
  }
  // Over the 12 entries, the radii at most 3/4 of the spreads (a box as
  // wide as the spread has radii of half of it; one ball of the whole
  // piece gave radii of 1.6 times the spreads).
  double radii = 0, spreads = 0;
  for (int e = 0; e < 12; ++e) {
    radii += CGAL::to_double(m->box.radius[e]);
    spreads += hi[e] - lo[e];
  }
  BOOST_TEST(radii <= 0.75 * spreads, "radii " << radii << ", spreads " << spreads);
}

BOOST_AUTO_TEST_SUITE_END()
