// Robots from URDF (src/io/robot.*, urdf.cpp, primitives.*; src/motion/chain.*): forward kinematics
// against an independent MPFR evaluation at rational joint values, the
// Taylor enclosures of link pieces against dense MPFR samples, the
// circumscribed primitives checked exactly, the C++ API (bodies, default
// checks, verdicts), and URDF errors naming the element.
#include "src/motion/enclosure.h"
#include "src/motion/segment.h"
#include "src/io/primitives.h"
#include "src/io/robot.h"
#include "src/io/parse.h"
#include "src/model/solid.h"
#include "src/verify/verify.h"
#include "tests/support/mp_reference.h"

#include <boost/test/unit_test.hpp>

#include <filesystem>
#include <fstream>
#include <random>

using namespace tmcert;
using namespace tmcert::testing;

namespace {

const std::string kData = TMCERT_TEST_DATA;
const std::string kChain = kData + "/robots/chain.urdf";

// ------------------------------------------------------------------ the MPFR reference
// The chain of tests/data/robots/chain.urdf written out by hand from the
// file (not read by the library's reader): joint origins, axes and the
// collision frames.  Rotations about an axis by the unit quaternion
// (cos(q/2), sin(q/2) u) (not Rodrigues, which the library uses).

MpPose mp_identity() {
  MpPose m;
  for (int e = 0; e < 12; ++e) m[e] = Mp(e % 5 == 0 ? 1 : 0);
  return m;
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
MpPose mp_origin(const std::array<Exact, 3>& xyz, const std::array<Exact, 3>& rpy) {
  const MpMat3 r = rpy_matrix(Mp(rpy[0]), Mp(rpy[1]), Mp(rpy[2]));
  MpPose m;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) m[4 * i + j] = r[3 * i + j];
    m[4 * i + 3] = Mp(xyz[i]);
  }
  return m;
}
MpPose mp_revolute(const std::array<Exact, 3>& axis, const Exact& q) {
  const Mp n = sqrt(Mp(axis[0]) * Mp(axis[0]) + Mp(axis[1]) * Mp(axis[1]) + Mp(axis[2]) * Mp(axis[2]));
  const Mp h = Mp(q) / Mp(2);
  const MpQuat quat = {cos(h), sin(h) * Mp(axis[0]) / n, sin(h) * Mp(axis[1]) / n, sin(h) * Mp(axis[2]) / n};
  const MpMat3 r = quat_matrix_unit(quat);
  MpPose m;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) m[4 * i + j] = r[3 * i + j];
    m[4 * i + 3] = Mp(0);
  }
  return m;
}
MpPose mp_prismatic(const std::array<Exact, 3>& axis, const Exact& q) {
  const Mp n = sqrt(Mp(axis[0]) * Mp(axis[0]) + Mp(axis[1]) * Mp(axis[1]) + Mp(axis[2]) * Mp(axis[2]));
  MpPose m = mp_identity();
  for (int i = 0; i < 3; ++i) m[4 * i + 3] = Mp(q) * Mp(axis[i]) / n;
  return m;
}

const std::array<Exact, 3> kZero{Exact(0), Exact(0), Exact(0)};
Exact d(const char* s) {
  Exact v;
  BOOST_REQUIRE(parse_exact(s, v));
  return v;
}

// The pose of link `link`'s body (in the world, base pose `base`) at
// joint values q = (j1, j2, j3, j4).
MpPose mp_link_body(const MpPose& base, const std::string& link, const std::array<Exact, 4>& q) {
  MpPose m = base;
  auto then = [&](const MpPose& x) { m = mp_compose(m, x); };
  if (link == "base") return m;
  then(mp_origin({0, 0, d("0.05")}, {d("0.1"), d("0.2"), d("0.3")}));
  then(mp_revolute({0, 0, 1}, q[0]));
  if (link == "l1") return m;
  then(mp_origin({d("0.1"), 0, d("0.5")}, kZero));
  then(mp_prismatic({1, 2, 2}, q[1]));
  if (link == "l2") {
    then(mp_origin({d("0.1"), 0, 0}, {d("0.25"), d("-0.5"), 1}));  // the rotated collision origin
    return m;
  }
  then(mp_origin({d("0.2"), 0, 0}, {0, 0, d("0.5")}));
  if (link == "l3") return m;
  then(mp_origin({0, 0, d("0.1")}, kZero));
  then(mp_revolute({1, 1, 0}, q[2]));
  if (link == "l4") return m;
  then(mp_origin({0, 0, d("0.2")}, {d("-0.3"), 0, 0}));
  then(mp_revolute({0, 1, 0}, q[3]));
  return m;
}

// Every entry of the enclosure holds the reference, and is narrow.
void check_pose_encloses(const PoseInterval& got, const MpPose& want, double max_width, const std::string& what) {
  for (int e = 0; e < 12; ++e)
    BOOST_TEST_CONTEXT(what << " entry " << e << " [" << got[e].inf() << ", " << got[e].sup() << "] vs "
                            << want[e].to_double()) {
      BOOST_TEST(mp_inside(want[e], got[e]));
      BOOST_TEST(got[e].sup() - got[e].inf() <= max_width);
    }
}

std::shared_ptr<const RobotModel> chain_model() {
  static const std::shared_ptr<const RobotModel> model = load_urdf(kChain);
  return model;
}

// A random rational in [lo, hi] with denominator 1000.
Exact random_in(std::mt19937_64& rng, const Exact& lo, const Exact& hi) {
  std::uniform_int_distribution<int> k(0, 1000);
  return lo + (hi - lo) * Exact(k(rng), 1000);
}

std::array<Exact, 4> random_joints(std::mt19937_64& rng) {
  return {random_in(rng, d("-2.5"), d("2.5")), random_in(rng, d("-0.1"), d("0.3")), random_in(rng, d("-1.5"), d("1.5")),
          random_in(rng, Exact(-7), Exact(7))};
}

JointPath two_waypoints(const std::array<Exact, 4>& a, const std::array<Exact, 4>& b) {
  JointPath p;
  p.joints = {"j1", "j2", "j3", "j4"};
  p.times = {0, 1};
  p.positions = {{a[0], a[1], a[2], a[3]}, {b[0], b[1], b[2], b[3]}};
  return p;
}

Pose some_base() {
  Pose base;
  base.translation = {Exact(1, 2), Exact(-1, 4), d("0.8")};
  base.rotation.kind = Rotation::Kind::Rpy;
  base.rotation.rpy = {Exact(0), Exact(0), d("0.7")};
  return base;
}

MpPose mp_base() { return mp_origin({Exact(1, 2), Exact(-1, 4), d("0.8")}, {0, 0, d("0.7")}); }

// The model of a body's motion at scene parameter t in [0, 1] (one segment).
PoseInterval body_pose(const Body& b, const Exact& t) {
  if (b.motion) {
    const Mat34E m = b.motion->degree() == 0 ? b.motion->control_points[0] : motion_pose(*b.motion, t);
    PoseInterval out;
    for (int e = 0; e < 12; ++e) out[e] = to_interval(m[e]);
    return out;
  }
  BOOST_REQUIRE(b.trajectory);
  const MotionSegment& seg = b.trajectory->segments.front();
  return enclose_pose(*make_segment_model(seg), (t - seg.t0) / (seg.t1 - seg.t0));
}

Scene scene_of(const std::string& text, const std::string& name) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "tmcert_robot_test";
  std::filesystem::create_directories(dir);
  const std::filesystem::path file = dir / name;
  std::ofstream(file) << text;
  return parse_scene_file(file.string());
}

std::string urdf_error(const std::string& urdf) {
  try {
    load_urdf_text(urdf, "t.urdf", kData + "/robots");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

const char* kTwoLinks = R"(<robot name="r">
  <link name="a"><collision><geometry><box size="1 1 1"/></geometry></collision></link>
  <link name="b"><collision><geometry>GEOM</geometry></collision></link>
  <joint name="j" type="TYPE"><parent link="a"/><child link="b"/><axis xyz="AXIS"/>LIMIT</joint>
</robot>)";

std::string two_links(const std::string& type, const std::string& geometry = "<box size=\"1 1 1\"/>",
                      const std::string& limit = "<limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/>", const std::string& axis = "0 0 1") {
  std::string s = kTwoLinks;
  auto put = [&](const std::string& key, const std::string& value) { s.replace(s.find(key), key.size(), value); };
  put("TYPE", type);
  put("GEOM", geometry);
  put("LIMIT", limit);
  put("AXIS", axis);
  return s;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(robot)

BOOST_AUTO_TEST_CASE(urdf_numbers_are_exact_and_structure_is_read) {
  const auto model = chain_model();
  BOOST_TEST(model->name == "chain");
  BOOST_TEST(model->links.size() == 6u);
  BOOST_TEST(model->joints.size() == 5u);
  BOOST_TEST(model->links[model->root].name == "base");
  const RobotJoint& j1 = model->joints[model->joint_index("j1")];
  BOOST_TEST((j1.type == RobotJoint::Type::Revolute));
  BOOST_TEST(j1.origin.rotation.rpy[0] == Exact(1, 10));  // exactly 1/10, not the double 0.1
  BOOST_TEST(*j1.lower == Exact(-5, 2));
  const RobotJoint& j2 = model->joints[model->joint_index("j2")];
  BOOST_TEST((j2.type == RobotJoint::Type::Prismatic));
  BOOST_TEST((j2.axis == Vec3E{1, 2, 2}));
  BOOST_TEST((model->joints[model->joint_index("f")].type == RobotJoint::Type::Fixed));
  BOOST_TEST((model->joints[model->joint_index("j4")].type == RobotJoint::Type::Continuous));
  // l1: a box and a sphere, both with rpy 0: one body in the link frame,
  // vertices moved by the origins exactly; the sphere enlarged.
  const RobotLink& l1 = model->links[model->link_index("l1")];
  BOOST_REQUIRE(l1.geometry);
  BOOST_TEST(l1.body_frame.empty());
  BOOST_TEST((l1.geometry->enlarged == std::vector<std::string>{"sphere"}));
  BOOST_TEST(l1.geometry->solid);
  // l2: one rotated collision origin becomes the body frame.
  const RobotLink& l2 = model->links[model->link_index("l2")];
  BOOST_TEST(l2.body_frame.size() == 1u);
  BOOST_TEST(l2.geometry->enlarged.empty());
  BOOST_TEST(l2.geometry->polygons.size() == 6u);
  // The box vertices are exactly +-size/2 (0.05 / 2 = 1/40).
  bool found = false;
  for (const auto& poly : l2.geometry->polygons)
    for (const Vec3E& v : poly) found = found || v == Vec3E{Exact(1, 10), Exact(1, 40), Exact(1, 40)};
  BOOST_TEST(found);
}

BOOST_AUTO_TEST_CASE(forward_kinematics_encloses_mpfr_reference) {
  // Every link body's pose along a two-waypoint path, at rational s, holds
  // the MPFR pose at the interpolated joint values, and is narrow.
  std::mt19937_64 rng(20261125);
  const PlacedRobot robot(chain_model(), "r", some_base());
  for (int trial = 0; trial < 20; ++trial) {
    const std::array<Exact, 4> a = random_joints(rng), b = random_joints(rng);
    Scene scene;
    const RobotBodies bodies = add_robot(scene, robot, two_waypoints(a, b));
    for (std::size_t l = 0; l < robot.model().links.size(); ++l) {
      const Body& body = scene.bodies.at(bodies.body[l]);
      for (const Exact& s : {Exact(0), Exact(1, 3), Exact(7, 10), Exact(1)}) {
        std::array<Exact, 4> q;
        for (int j = 0; j < 4; ++j) q[j] = a[j] + (b[j] - a[j]) * s;
        const MpPose want = mp_link_body(mp_base(), robot.model().links[l].name, q);
        check_pose_encloses(body_pose(body, s), want, 1e-12, body.name + " trial " + std::to_string(trial));
      }
    }
  }
}

BOOST_AUTO_TEST_CASE(exact_poses_where_they_exist) {
  // Revolute joints at 0 and an exact base: every pose is exact, the
  // prismatic joint's axis (1 2 2)/3 exactly; a prismatic-only motion is a
  // rational segment.
  const std::shared_ptr<const RobotModel> model = load_urdf_text(two_links("prismatic", "<box size=\"1 1 1\"/>",
                                                                          "<limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/>", "1 2 2"),
                                                                "p.urdf", ".");
  Pose base;
  base.translation = {Exact(1), Exact(0), Exact(0)};
  const PlacedRobot robot(model, "p", base);
  JointPath path{{"j"}, {0, 1}, {{Exact(0)}, {Exact(3, 5)}}};
  Scene scene;
  const RobotBodies bodies = add_robot(scene, robot, path);
  const Body& b = scene.bodies.at(bodies.body[1]);
  BOOST_REQUIRE(b.motion);  // one rational segment
  BOOST_TEST(b.motion->degree() == 1);
  const Mat34E end = b.motion->control_points[1];
  BOOST_TEST(end[3] == Exact(1) + Exact(1, 5));   // 1 + 3/5 * 1/3
  BOOST_TEST(end[7] == Exact(2, 5));
  BOOST_TEST(end[11] == Exact(2, 5));
  const Body& a = scene.bodies.at(bodies.body[0]);
  BOOST_REQUIRE(a.motion);
  BOOST_TEST(a.motion->degree() == 0);  // the root does not move
}

BOOST_AUTO_TEST_CASE(link_piece_enclosures_hold_dense_mpfr_samples) {
  // enclose_piece: every pose of the piece lies within `tube` (Frobenius
  // metric, G = I) of P0 + (s - s0)/(s1 - s0) (P1 - P0); checked at 33
  // rational samples per piece with the MPFR reference, rigorously: the
  // distance is bounded below from the interval controls.
  std::mt19937_64 rng(7);
  const PlacedRobot robot(chain_model(), "r", some_base());
  std::array<Interval, 16> g;
  for (int i = 0; i < 16; ++i) g[i] = Interval(i % 5 == 0 ? 1 : 0);
  for (int trial = 0; trial < 6; ++trial) {
    const std::array<Exact, 4> a = random_joints(rng), b = random_joints(rng);
    Scene scene;
    const RobotBodies bodies = add_robot(scene, robot, two_waypoints(a, b));
    for (const std::string link : {"l2", "l4", "l5"}) {
      const Body& body = scene.bodies.at(bodies.body[robot.model().link_index(link)]);
      BOOST_REQUIRE(body.trajectory);
      const std::unique_ptr<SegmentModel> model = make_segment_model(body.trajectory->segments[0]);
      for (const auto& [s0, s1] : {std::pair{Exact(0), Exact(1)}, std::pair{Exact(1, 4), Exact(3, 8)},
                                   std::pair{Exact(5, 8), Exact(41, 64)}}) {
        const PieceEnclosure pe = enclose_piece(*model, s0, s1, g);
        BOOST_REQUIRE(pe.valid);
        for (int k = 0; k <= 32; ++k) {
          const Exact u = Exact(k, 32), s = s0 + (s1 - s0) * u;
          std::array<Exact, 4> q;
          for (int j = 0; j < 4; ++j) q[j] = a[j] + (b[j] - a[j]) * s;
          const MpPose want = mp_link_body(mp_base(), link, q);
          Mp sum(0);
          for (int e = 0; e < 12; ++e) {
            // The line's entry at u lies in lo..hi (interval arithmetic).
            RoundingGuard guard;
            const Interval iu = to_interval(u);
            const Interval line = pe.controls[0][e] + iu * (pe.controls[1][e] - pe.controls[0][e]);
            const Mp lo(line.inf()), hi(line.sup());
            Mp gap(0);
            if (want[e] < lo) gap = lo - want[e];
            if (hi < want[e]) gap = want[e] - hi;
            sum = sum + gap * gap;
          }
          BOOST_TEST_CONTEXT(link << " trial " << trial << " piece [" << s0 << ", " << s1 << "] u " << u) {
            BOOST_TEST(!(Mp(pe.tube) < sqrt(sum)));
          }
        }
      }
    }
  }
}

BOOST_AUTO_TEST_CASE(circumscribed_primitives_contain_their_shapes_exactly) {
  // Every tangent normal is a unit vector exactly; every face lies in a
  // tangent plane at distance r (a cap of the cylinder at z = +-length/2);
  // every vertex is inside every tangent half-space: so the solid is the
  // intersection of the half-spaces and contains the shape.  Closed shells.
  const Exact r(3, 100), len(1, 5);
  auto check = [&](const PolygonList& faces, const std::vector<Vec3E>& normals, bool cylinder) {
    for (const Vec3E& n : normals) BOOST_TEST(n[0] * n[0] + n[1] * n[1] + n[2] * n[2] == Exact(1));
    std::vector<Vec3E> all;
    for (const auto& f : faces) all.insert(all.end(), f.begin(), f.end());
    for (const Vec3E& v : all) {
      for (const Vec3E& n : normals) BOOST_TEST(n[0] * v[0] + n[1] * v[1] + n[2] * v[2] <= r);
      if (cylinder) BOOST_TEST(CGAL::abs(v[2]) <= len / 2);
    }
    for (const auto& f : faces) {
      bool on_plane = false;
      for (const Vec3E& n : normals) {
        bool all_on = true;
        for (const Vec3E& v : f) all_on = all_on && n[0] * v[0] + n[1] * v[1] + n[2] * v[2] == r;
        on_plane = on_plane || all_on;
      }
      if (cylinder && !on_plane) {
        bool cap = true;
        for (const Vec3E& v : f) cap = cap && CGAL::abs(v[2]) == len / 2 && v[2] == f[0][2];
        on_plane = cap;
      }
      BOOST_TEST(on_plane);
    }
    Body b;
    for (const auto& f : faces) {
      auto [clean, pieces] = split_scene_polygon(f, static_cast<int>(b.polygons.size()));
      b.polygons.push_back(clean);
      for (auto& p : pieces) b.pieces.push_back(p);
    }
    BOOST_TEST(solid_problem(b).empty());
    BOOST_TEST(shell_intersection_problem(b).empty());
    return all;
  };
  const std::vector<Vec3E> cyl = check(cylinder_polyhedron(r, len), cylinder_tangent_normals(), true);
  BOOST_TEST(cylinder_tangent_normals().size() >= 8u);
  const std::vector<Vec3E> sph = check(sphere_polyhedron(r), sphere_tangent_normals(), false);
  // Enlarged, but not by much: every vertex within 1.05 r of the axis / centre.
  for (const Vec3E& v : cyl) BOOST_TEST(v[0] * v[0] + v[1] * v[1] <= r * r * Exact(105 * 105, 100 * 100));
  for (const Vec3E& v : sph) BOOST_TEST(v[0] * v[0] + v[1] * v[1] + v[2] * v[2] <= r * r * Exact(105 * 105, 100 * 100));
  // The box is exact.
  const PolygonList box = box_polyhedron({Exact(1), Exact(2), Exact(3)});
  BOOST_TEST(box.size() == 6u);
  for (const auto& f : box)
    for (const Vec3E& v : f) BOOST_TEST((CGAL::abs(v[0]) == Exact(1, 2) && CGAL::abs(v[1]) == 1 && CGAL::abs(v[2]) == Exact(3, 2)));
}

BOOST_AUTO_TEST_CASE(rotated_cylinders_beside_other_elements_are_circumscribed) {
  // A box at the link origin and a cylinder with a rotated origin elsewhere
  // in one link: the box stays exact in the link frame, the cylinder is
  // circumscribed with a rational rotation.  Points of the true cylinder
  // (its rims, in MPFR) lie inside every face of the prism (outward faces,
  // checked with the exact face planes); a rotated sphere elsewhere too.
  const char* urdf = R"(<robot name="m">
    <link name="a"><collision><geometry><box size="0.1 0.1 0.1"/></geometry></collision>
      <collision><origin xyz="0.3 0.1 -0.2" rpy="0.4 -1.1 2.3"/><geometry><cylinder radius="0.05" length="0.4"/></geometry></collision>
      <collision><origin xyz="-0.3 0 0.1" rpy="1 2 3"/><geometry><sphere radius="0.07"/></geometry></collision></link>
  </robot>)";
  const auto model = load_urdf_text(urdf, "m.urdf", ".");
  const RobotLink& link = model->links[0];
  BOOST_REQUIRE(link.geometry);
  BOOST_TEST(link.body_frame.empty());
  const Body& b = *link.geometry;
  BOOST_TEST((b.enlarged == std::vector<std::string>{"cylinder", "sphere"}));
  BOOST_REQUIRE(b.polygons.size() == 6u + 18u + 114u);
  for (const Vec3E& v : b.polygons[0]) BOOST_TEST((CGAL::abs(v[0]) == Exact(1, 20) && CGAL::abs(v[2]) == Exact(1, 20)));
  auto inside_faces = [&](std::size_t first, std::size_t count, const std::array<Mp, 3>& p) {
    for (std::size_t f = first; f < first + count; ++f) {
      const auto& poly = b.polygons[f];
      const Vec3E e1 = {poly[1][0] - poly[0][0], poly[1][1] - poly[0][1], poly[1][2] - poly[0][2]};
      const Vec3E e2 = {poly[2][0] - poly[0][0], poly[2][1] - poly[0][1], poly[2][2] - poly[0][2]};
      const Vec3E n = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
      Mp side(0);
      for (int i = 0; i < 3; ++i) side = side + Mp(n[i]) * (p[i] - Mp(poly[0][i]));
      if (Mp(kMpSlack) < side) {  // touching (a tangent point) is inside; MPFR's own error is far below the slack
        BOOST_TEST_MESSAGE("outside face " << f << " by " << side.to_double() << " at " << p[0].to_double() << " "
                                           << p[1].to_double() << " " << p[2].to_double());
        return false;
      }
    }
    return true;
  };
  const MpPose cyl = mp_origin({d("0.3"), d("0.1"), d("-0.2")}, {d("0.4"), d("-1.1"), d("2.3")});
  const MpPose sph = mp_origin({d("-0.3"), 0, d("0.1")}, {1, 2, 3});
  const Mp two_pi = mp_pi() * Mp(2);
  for (int k = 0; k < 64; ++k) {
    const Mp a = two_pi * Mp(k) / Mp(64);
    for (const Mp z : {Mp(Exact(-1, 5)), Mp(Exact(1, 5))}) {
      const std::array<Mp, 3> local = {Mp(Exact(1, 20)) * cos(a), Mp(Exact(1, 20)) * sin(a), z};
      std::array<Mp, 3> p;
      for (int i = 0; i < 3; ++i) p[i] = cyl[4 * i] * local[0] + cyl[4 * i + 1] * local[1] + cyl[4 * i + 2] * local[2] + cyl[4 * i + 3];
      BOOST_TEST(inside_faces(6, 18, p));
    }
    for (const Mp c : {Mp(Exact(-3, 5)), Mp(0), Mp(Exact(3, 5))}) {  // points of the sphere at three latitudes
      const Mp r = Mp(Exact(7, 100)) * sqrt(Mp(1) - c * c);
      std::array<Mp, 3> p = {r * cos(a) + sph[3], r * sin(a) + sph[7], Mp(Exact(7, 100)) * c + sph[11]};
      BOOST_TEST(inside_faces(24, 114, p));
    }
  }
  // The rotated-origin rules: differing rotated boxes are refused.
  const std::string two_boxes = R"(<robot name="m"><link name="a">
    <collision><origin rpy="0 0 1"/><geometry><box size="1 1 1"/></geometry></collision>
    <collision><origin xyz="1 0 0"/><geometry><box size="1 1 1"/></geometry></collision></link></robot>)";
  BOOST_TEST(urdf_error(two_boxes).find("link \"a\": collision[1]: a box or mesh whose origin differs") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(default_checks_follow_the_contract) {
  const PlacedRobot robot(chain_model(), "r", Pose{});
  Scene scene;
  Body wall;
  wall.name = "wall";
  scene.bodies.push_back(wall);
  JointPath path = two_waypoints({0, 0, 0, 0}, {1, Exact(1, 10), 1, 1});
  const RobotBodies bodies = add_robot(scene, robot, path);
  const RobotModel& m = robot.model();
  auto body_of = [&](const char* link) { return bodies.body[m.link_index(link)]; };
  auto has = [](const std::vector<std::pair<int, int>>& checks, int a, int b) {
    for (const auto& [x, y] : checks)
      if ((x == a && y == b) || (x == b && y == a)) return true;
    return false;
  };
  const auto without = robot_default_checks(robot, bodies, {0}, false, {});
  BOOST_TEST(without.size() == 6u);  // every link against the wall, nothing inside the robot
  for (int l = 0; l < 6; ++l) BOOST_TEST(has(without, bodies.body[l], 0));
  const auto with = robot_default_checks(robot, bodies, {0}, true, {{"l4", "base"}});
  // 15 link pairs, 5 parent-child pairs (l2-l3 are joined by the fixed joint), 1 allowed.
  BOOST_TEST(with.size() == 6u + 15u - 5u - 1u);
  BOOST_TEST(!has(with, body_of("base"), body_of("l1")));
  BOOST_TEST(!has(with, body_of("l2"), body_of("l3")));
  BOOST_TEST(!has(with, body_of("base"), body_of("l4")));
  BOOST_TEST(has(with, body_of("base"), body_of("l2")));
  BOOST_TEST(has(with, body_of("l1"), body_of("l5")));
  BOOST_CHECK_THROW(robot_default_checks(robot, bodies, {0}, true, {{"l4", "nope"}}), InputError);
}

BOOST_AUTO_TEST_CASE(joint_paths_are_validated_with_the_element) {
  const PlacedRobot robot(chain_model(), "r", Pose{});
  auto error = [&](const JointPath& p) -> std::pair<std::string, std::string> {
    Scene scene;
    try {
      add_robot(scene, robot, p);
    } catch (const JointPathError& e) {
      std::string where = e.field;
      for (std::size_t i : e.index) where += "[" + std::to_string(i) + "]";
      return {where, e.what()};
    }
    return {"", "(no error)"};
  };
  JointPath p = two_waypoints({0, 0, 0, 0}, {1, 0, 0, 0});
  p.positions[1][0] = d("2.51");
  auto [where, what] = error(p);
  BOOST_TEST(where == "positions[1][0]");
  BOOST_TEST(what.find("waypoint 1") != std::string::npos);
  BOOST_TEST(what.find("\"j1\"") != std::string::npos);
  BOOST_TEST(what.find("outside its limits") != std::string::npos);
  // Decimals, never p/q: 2.51 as written, a double as the shortest decimal
  // that reads back as it (from NumPy or a C++ double).
  BOOST_TEST(what.find("at 2.51 is outside") != std::string::npos, what);
  BOOST_TEST(what.find('/') == std::string::npos, what);
  p.positions[1][0] = Exact(2.51);
  BOOST_TEST(error(p).second.find("at 2.51 (a double) is outside") != std::string::npos, error(p).second);
  BOOST_TEST(error(p).second.find('/') == std::string::npos, error(p).second);
  p = two_waypoints({0, d("-0.11"), 0, 0}, {0, 0, 0, 0});
  BOOST_TEST(error(p).first == "positions[0][1]");
  p = two_waypoints({0, 0, 0, 100}, {0, 0, 0, -100});  // continuous: no limit
  BOOST_TEST(error(p).first == "");
  p.joints[2] = "nope";
  BOOST_TEST(error(p).first == "joints[2]");
  BOOST_TEST(error(p).second.find("unknown joint \"nope\"") != std::string::npos);
  p.joints[2] = "f";
  BOOST_TEST(error(p).second.find("fixed") != std::string::npos);
  p = two_waypoints({0, 0, 0, 0}, {0, 0, 0, 0});
  p.joints.pop_back();
  for (auto& row : p.positions) row.pop_back();
  BOOST_TEST(error(p).second.find("\"j4\" is missing") != std::string::npos);
  p = two_waypoints({0, 0, 0, 0}, {0, 0, 0, 0});
  p.positions[1].pop_back();
  BOOST_TEST(error(p).first == "positions[1]");
  p = two_waypoints({0, 0, 0, 0}, {0, 0, 0, 0});
  p.times = {1, 1};
  BOOST_TEST(error(p).first == "times[1]");
}

BOOST_AUTO_TEST_CASE(urdf_errors_name_the_element) {
  BOOST_TEST(urdf_error(two_links("floating")).find("joint \"j\": unsupported joint type \"floating\"") != std::string::npos);
  BOOST_TEST(urdf_error(two_links("planar")).find("joint \"j\"") != std::string::npos);
  BOOST_TEST(urdf_error(two_links("revolute", "<box size=\"1 1 1\"/>", "<limit lower=\"1\" upper=\"-1\" effort=\"1\" velocity=\"1\"/>"))
                 .find("joint \"j\": limit lower 1 is above upper -1") != std::string::npos);
  BOOST_TEST(urdf_error(two_links("revolute", "<box size=\"1 1 1\"/>", "<limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/>", "0 0 0"))
                 .find("joint \"j\": axis is zero") != std::string::npos);
  BOOST_TEST(urdf_error(two_links("revolute", "<box size=\"1 1 1\"/>", "<limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/>", "0 0 x"))
                 .find("joint \"j\": axis xyz: not a number: \"x\"") != std::string::npos);
  BOOST_TEST(urdf_error(two_links("fixed", "<mesh filename=\"missing.stl\"/>")).find("link \"b\": collision[0]: mesh:") !=
             std::string::npos);
  BOOST_TEST(urdf_error(two_links("fixed", "<mesh filename=\"package://x/y.stl\"/>")).find("package://") != std::string::npos);
  BOOST_TEST(urdf_error(two_links("fixed", "<box size=\"1 0 1\"/>")).find("link \"b\": collision[0]: box size must be positive") !=
             std::string::npos);
  BOOST_TEST(urdf_error(two_links("fixed", "<cylinder radius=\"1\"/>")).find("link \"b\": collision[0]: cylinder: missing attribute \"length\"") !=
             std::string::npos);
  BOOST_TEST(urdf_error(two_links("fixed", "<capsule radius=\"1\" length=\"1\"/>")).find("unsupported geometry <capsule>") !=
             std::string::npos);
  BOOST_TEST(urdf_error("<robot name=\"x\"><link name=\"a\"/>").find("XML error") != std::string::npos);
  BOOST_TEST(urdf_error("<robot name=\"x\"><link name=\"a\"/><link name=\"b\"/></robot>").find("not a valid URDF") !=
             std::string::npos);
  BOOST_CHECK_THROW(load_urdf(kData + "/robots/does-not-exist.urdf"), InputError);
  // xacro is expanded by the xacro tool: say so (by name, or by its namespace).
  const std::string xacro = R"(<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:property name="l" value="1"/><link name="a"/></robot>)";
  try {
    load_urdf_text(xacro, "arm.urdf.xacro", ".");
    BOOST_FAIL("xacro accepted");
  } catch (const InputError& e) {
    BOOST_TEST(std::string(e.what()) == "arm.urdf.xacro: this is xacro (URDF macros), not plain URDF: run xacro first: "
                                        "xacro arm.urdf.xacro > arm.urdf");
  }
  BOOST_TEST(urdf_error(xacro).find("t.urdf: this is xacro (URDF macros), not plain URDF: run xacro first: xacro t.urdf > t-expanded.urdf") !=
             std::string::npos, urdf_error(xacro));
}

BOOST_AUTO_TEST_CASE(verdicts_through_the_api) {
  // A one-joint arm (box link 1 long along x about a vertical axis) and a
  // wall crossing its sweep: collision with a witness; a wall beyond its
  // reach: safe.
  const char* urdf = R"(<robot name="one">
    <link name="base"/>
    <link name="bar"><collision><origin xyz="0.5 0 0"/><geometry><box size="1 0.1 0.1"/></geometry></collision></link>
    <joint name="turn" type="revolute"><parent link="base"/><child link="bar"/><axis xyz="0 0 1"/>
      <limit lower="-3" upper="3" effort="1" velocity="1"/></joint></robot>)";
  const auto model = load_urdf_text(urdf, "one.urdf", ".");
  const PlacedRobot arm(model, "arm", Pose{});
  for (const auto& [x, truth] : {std::pair{Exact(1, 2), Verdict::Collision}, std::pair{Exact(6, 5), Verdict::Safe}}) {
    Scene scene;
    Body wall;
    wall.name = "wall";
    wall.polygons = {{{x, Exact(1, 5), Exact(-1)}, {x, Exact(1), Exact(-1)}, {x, Exact(1), Exact(1)}, {x, Exact(1, 5), Exact(1)}}};
    wall.pieces = {ConvexPiece{0, wall.polygons[0]}};
    wall.mass.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    wall.mass.weights = {1, 1, 1, 1};
    scene.bodies.push_back(wall);
    const RobotBodies bodies = add_robot(scene, arm, JointPath{{"turn"}, {0, 1}, {{Exact(0)}, {Exact(3, 2)}}});
    scene.checks = robot_default_checks(arm, bodies, {0}, false, {});
    VerifyOptions options;
    options.epsilon = Exact(1, 1000);
    const SceneResult result = verify_scene(scene, options);
    BOOST_TEST(result.verdict == truth);
  }
}

BOOST_AUTO_TEST_SUITE_END()
