// Property tests of robot link motions (issue 13, proofs/robot-links.md
// "Checked by"): random URDF chains (1-5 joints, each revolute, continuous,
// prismatic or fixed, with random exact origins (xyz, rpy or none), random
// integer axes of rational or irrational length, a box link with a random
// collision origin), random bases and random two-waypoint paths within the
// limits, loaded from their URDF text by the library, against an
// independent MPFR evaluation of the chain (tests/support/mp_reference.h:
// joint rotations by the unit quaternion (cos q/2, sin q/2 u), rpy from the
// elementary matrices):
//
//  (pose)  at 9 rational parameters, every link body's enclosed pose holds
//          the MPFR pose (error < 2^-240) and is narrow (<= 1e-9);
//  (tube)  on a random dyadic piece, `enclose_piece` is valid and at 17
//          rational samples the MPFR pose lies within `tube` (Frobenius,
//          G = I) of the enclosed segment P0 -> P1, the distance bounded
//          below from the interval controls (rigorous).
//
// Run: `tmcert_property --run_test=robot_links` (a few seconds).  A failure
// prints the URDF and the path; replay with RC_PARAMS="seed=N".

#include "tests/support/mp_reference.h"

#include "src/motion/enclosure.h"
#include "src/motion/segment.h"
#include "src/io/robot.h"

#include <rapidcheck.h>
#include <rapidcheck/boost_test.h>

#include <boost/test/unit_test.hpp>

#include <sstream>
#include <string>
#include <vector>

using namespace tmcert;
using namespace tmcert::testing;

namespace {

struct JointSpec {
  std::string type;
  std::array<int, 3> xyz;   // hundredths
  std::array<int, 3> rpy;   // hundredths; all zero: no rpy
  std::array<int, 3> axis;  // nonzero
  std::array<int, 3> box;   // hundredths, > 0
  std::array<int, 3> box_xyz;
  std::array<int, 3> box_rpy;
  int q0 = 0, q1 = 0;       // hundredths, within the limits
};

Exact h(int k) { return Exact(k, 100); }

std::string dec(int k) {
  std::ostringstream s;
  s << (k < 0 ? "-" : "") << std::abs(k) / 100 << "." << (std::abs(k) % 100 < 10 ? "0" : "") << std::abs(k) % 100;
  return s.str();
}
std::string triple(const std::array<int, 3>& v) { return dec(v[0]) + " " + dec(v[1]) + " " + dec(v[2]); }
std::string triple_int(const std::array<int, 3>& v) {
  return std::to_string(v[0]) + " " + std::to_string(v[1]) + " " + std::to_string(v[2]);
}

std::string urdf_of(const std::vector<JointSpec>& joints) {
  std::ostringstream u;
  u << "<robot name=\"random\">\n<link name=\"l0\"/>\n";
  for (std::size_t j = 0; j < joints.size(); ++j) {
    const JointSpec& s = joints[j];
    u << "<link name=\"l" << j + 1 << "\"><collision><origin xyz=\"" << triple(s.box_xyz) << "\" rpy=\""
      << triple(s.box_rpy) << "\"/><geometry><box size=\"" << triple(s.box) << "\"/></geometry></collision></link>\n";
    u << "<joint name=\"j" << j + 1 << "\" type=\"" << s.type << "\"><parent link=\"l" << j << "\"/><child link=\"l"
      << j + 1 << "\"/><origin xyz=\"" << triple(s.xyz) << "\"";
    if (s.rpy != std::array<int, 3>{0, 0, 0}) u << " rpy=\"" << triple(s.rpy) << "\"";
    u << "/><axis xyz=\"" << triple_int(s.axis) << "\"/>";
    if (s.type == "revolute") u << "<limit lower=\"-3\" upper=\"3\" effort=\"1\" velocity=\"1\"/>";
    if (s.type == "prismatic") u << "<limit lower=\"-0.5\" upper=\"0.5\" effort=\"1\" velocity=\"1\"/>";
    u << "</joint>\n";
  }
  u << "</robot>\n";
  return u.str();
}

rc::Gen<std::array<int, 3>> ints3(int lo, int hi) {
  return rc::gen::apply([](int a, int b, int c) { return std::array<int, 3>{a, b, c}; }, rc::gen::inRange(lo, hi + 1),
                        rc::gen::inRange(lo, hi + 1), rc::gen::inRange(lo, hi + 1));
}

rc::Gen<JointSpec> joint_spec() {
  return rc::gen::exec([] {
    JointSpec s;
    s.type = *rc::gen::element<std::string>("revolute", "continuous", "prismatic", "fixed");
    s.xyz = *ints3(-50, 50);
    s.rpy = *rc::gen::oneOf(rc::gen::just(std::array<int, 3>{0, 0, 0}), ints3(-314, 314));
    s.axis = *rc::gen::suchThat(ints3(-2, 2), [](const std::array<int, 3>& a) { return a != std::array<int, 3>{0, 0, 0}; });
    s.box = *ints3(1, 30);
    s.box_xyz = *ints3(-20, 20);
    s.box_rpy = *rc::gen::oneOf(rc::gen::just(std::array<int, 3>{0, 0, 0}), ints3(-314, 314));
    const int limit = s.type == "revolute" ? 300 : s.type == "prismatic" ? 50 : s.type == "continuous" ? 700 : 0;
    s.q0 = *rc::gen::inRange(-limit, limit + 1);
    s.q1 = *rc::gen::inRange(-limit, limit + 1);
    return s;
  });
}

MpPose mp_compose(const MpPose& a, const MpPose& b) {
  MpPose out;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) {
      Mp s = a[4 * r] * b[c] + a[4 * r + 1] * b[4 + c] + a[4 * r + 2] * b[8 + c];
      if (c == 3) s = s + a[4 * r + 3];
      out[4 * r + c] = s;
    }
  return out;
}
MpPose mp_frame(const std::array<int, 3>& xyz, const std::array<int, 3>& rpy) {
  const MpMat3 r = rpy_matrix(Mp(h(rpy[0])), Mp(h(rpy[1])), Mp(h(rpy[2])));
  MpPose m;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) m[4 * i + j] = r[3 * i + j];
    m[4 * i + 3] = Mp(h(xyz[i]));
  }
  return m;
}
MpPose mp_joint(const JointSpec& s, const Exact& q) {
  const Mp n = sqrt(Mp(s.axis[0] * s.axis[0] + s.axis[1] * s.axis[1] + s.axis[2] * s.axis[2]));
  MpPose m = mp_frame({0, 0, 0}, {0, 0, 0});
  if (s.type == "fixed") return m;
  if (s.type == "prismatic") {
    for (int i = 0; i < 3; ++i) m[4 * i + 3] = Mp(q) * Mp(s.axis[i]) / n;
    return m;
  }
  const Mp half = Mp(q) / Mp(2);
  const MpMat3 r = quat_matrix_unit({cos(half), sin(half) * Mp(s.axis[0]) / n, sin(half) * Mp(s.axis[1]) / n,
                                     sin(half) * Mp(s.axis[2]) / n});
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m[4 * i + j] = r[3 * i + j];
  return m;
}

// The body pose of link l (1-based) at parameter s.
MpPose mp_body(const MpPose& base, const std::vector<JointSpec>& joints, std::size_t l, const Exact& s) {
  MpPose m = base;
  for (std::size_t j = 0; j < l; ++j) {
    const JointSpec& js = joints[j];
    const Exact q = h(js.q0) + (h(js.q1) - h(js.q0)) * s;
    m = mp_compose(mp_compose(m, mp_frame(js.xyz, js.rpy)), mp_joint(js, q));
  }
  const JointSpec& own = joints[l - 1];
  if (own.box_rpy != std::array<int, 3>{0, 0, 0}) m = mp_compose(m, mp_frame(own.box_xyz, own.box_rpy));
  return m;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(robot_links)

RC_BOOST_PROP(random_chains_enclose_the_mpfr_poses_and_their_pieces, ()) {
  const std::vector<JointSpec> joints = *rc::gen::container<std::vector<JointSpec>>(
      static_cast<std::size_t>(*rc::gen::inRange(1, 6)), joint_spec());
  const std::array<int, 3> base_xyz = *ints3(-100, 100), base_rpy = *ints3(-314, 314);
  const std::string urdf = urdf_of(joints);
  RC_LOG() << urdf;
  const auto model = load_urdf_text(urdf, "random.urdf", ".");
  Pose base;
  base.translation = {h(base_xyz[0]), h(base_xyz[1]), h(base_xyz[2])};
  base.rotation.kind = Rotation::Kind::Rpy;
  base.rotation.rpy = {h(base_rpy[0]), h(base_rpy[1]), h(base_rpy[2])};
  const PlacedRobot robot(model, "r", base);
  JointPath path;
  path.times = {0, 1};
  path.positions.resize(2);
  for (std::size_t j = 0; j < joints.size(); ++j) {
    if (joints[j].type == "fixed") continue;
    path.joints.push_back("j" + std::to_string(j + 1));
    path.positions[0].push_back(h(joints[j].q0));
    path.positions[1].push_back(h(joints[j].q1));
  }
  Scene scene;
  const RobotBodies bodies = add_robot(scene, robot, path);
  const MpPose mbase = mp_frame(base_xyz, base_rpy);
  std::array<Interval, 16> g;
  for (int i = 0; i < 16; ++i) g[i] = Interval(i % 5 == 0 ? 1 : 0);
  const int a = *rc::gen::inRange(0, 16);
  const int b = *rc::gen::inRange(a + 1, 17);
  const Exact s0(a, 16), s1(b, 16);
  for (std::size_t l = 1; l <= joints.size(); ++l) {
    const Body& body = scene.bodies.at(bodies.body[l]);
    // (pose)
    for (int k = 0; k <= 8; ++k) {
      const Exact s(k, 8);
      PoseInterval got;
      if (body.motion) {
        const Mat34E m = body.motion->degree() == 0 ? body.motion->control_points[0] : motion_pose(*body.motion, s);
        for (int e = 0; e < 12; ++e) got[e] = to_interval(m[e]);
      } else {
        got = enclose_pose(*make_segment_model(body.trajectory->segments[0]), s);
      }
      const MpPose want = mp_body(mbase, joints, l, s);
      for (int e = 0; e < 12; ++e) {
        RC_ASSERT(mp_inside(want[e], got[e]));
        RC_ASSERT(got[e].sup() - got[e].inf() <= 1e-9);
      }
    }
    // (tube)
    if (!body.trajectory) continue;
    const std::unique_ptr<SegmentModel> model_l = make_segment_model(body.trajectory->segments[0]);
    const PieceEnclosure pe = enclose_piece(*model_l, s0, s1, g);
    RC_ASSERT(pe.valid);
    for (int k = 0; k <= 16; ++k) {
      const Exact u(k, 16), s = s0 + (s1 - s0) * u;
      const MpPose want = mp_body(mbase, joints, l, s);
      Mp sum(0);
      for (int e = 0; e < 12; ++e) {
        RoundingGuard guard;
        const Interval line = pe.controls[0][e] + to_interval(u) * (pe.controls[1][e] - pe.controls[0][e]);
        const Mp lo(line.inf()), hi(line.sup());
        Mp gap(0);
        if (want[e] < lo) gap = lo - want[e];
        if (hi < want[e]) gap = want[e] - hi;
        sum = sum + gap * gap;
      }
      RC_ASSERT(!(Mp(pe.tube) < sqrt(sum)));
    }
  }
}

BOOST_AUTO_TEST_SUITE_END()
