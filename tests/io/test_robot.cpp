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

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
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

// The pose of link `link`'s first body (in the world, base pose `base`) at
// joint values q = (j1, j2, j3, j4): the link frame, then the body's frame
// in it (robot.h LinkPart: a rotated box's origin, a sphere's centre, a
// cylinder's origin).
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
  if (link == "l3") {
    then(mp_origin({0, 0, d("0.05")}, kZero));  // the sphere's centre
    return m;
  }
  then(mp_origin({0, 0, d("0.1")}, kZero));
  then(mp_revolute({1, 1, 0}, q[2]));
  if (link == "l4") {
    then(mp_origin({0, 0, d("0.1")}, kZero));  // the cylinder's origin
    return m;
  }
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

std::string robot_root_name(const std::string& urdf) {
  const std::shared_ptr<const RobotModel> model = load_urdf_text(urdf, "t.urdf", kData + "/robots");
  return model->links[model->root].name;
}

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
  // l1: a box and a sphere, both with rpy 0: the box in the link frame,
  // vertices moved by the origin exactly; the sphere a part of its own at
  // its centre, its polyhedron with the true shape.
  const RobotLink& l1 = model->links[model->link_index("l1")];
  BOOST_REQUIRE(l1.parts.size() == 2u);
  BOOST_TEST(l1.parts[0].frame.empty());
  BOOST_TEST(l1.parts[0].suffix == "");
  BOOST_TEST(l1.parts[0].geometry.enlarged.empty());
  BOOST_TEST(l1.parts[0].geometry.solid);
  BOOST_TEST(!l1.parts[0].geometry.primitive);
  BOOST_TEST(l1.parts[1].suffix == "/collision[1]");
  BOOST_TEST((l1.parts[1].geometry.enlarged == std::vector<std::string>{"sphere"}));
  BOOST_REQUIRE(l1.parts[1].geometry.primitive);
  BOOST_TEST(l1.parts[1].geometry.primitive->radius == Exact(6, 100));
  BOOST_REQUIRE(l1.parts[1].frame.size() == 1u);
  BOOST_TEST((l1.parts[1].frame[0].translation == Vec3E{Exact(0), Exact(0), Exact(45, 100)}));
  BOOST_TEST((l1.parts[1].frame[0].rotation.kind == Rotation::Kind::Identity));
  // l2: one rotated collision origin becomes the body frame.
  const RobotLink& l2 = model->links[model->link_index("l2")];
  BOOST_REQUIRE(l2.parts.size() == 1u);
  BOOST_TEST(l2.parts[0].frame.size() == 1u);
  BOOST_TEST(l2.parts[0].geometry.enlarged.empty());
  BOOST_TEST(l2.parts[0].geometry.polygons.size() == 6u);
  // The box vertices are exactly +-size/2 (0.05 / 2 = 1/40).
  bool found = false;
  for (const auto& poly : l2.parts[0].geometry.polygons)
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
  // At every refinement level: every tangent normal is a unit vector
  // exactly; every face lies in a tangent plane at distance r (a cap of the
  // cylinder at z = +-length/2); every vertex is inside every tangent
  // half-space: so the solid is the intersection of the half-spaces and
  // contains the shape.  Closed shells.  The enlargement shrinks with the
  // level as primitives.h says.
  const Exact r(3, 100), len(1, 5);
  // A face's plane normal scaled to its largest coordinate 1 (a key).
  auto key = [](Vec3E n) {
    Exact big = 0;
    for (const Exact& c : n) big = std::max(big, CGAL::abs(c));
    for (Exact& c : n) c /= big;
    return n;
  };
  auto check = [&](const PolygonList& faces, const std::vector<Vec3E>& normals, bool cylinder) {
    std::map<Vec3E, Vec3E> by_key;
    for (const Vec3E& n : normals) {
      BOOST_TEST(n[0] * n[0] + n[1] * n[1] + n[2] * n[2] == Exact(1));
      by_key[key(n)] = n;
    }
    std::vector<Vec3E> all;
    for (const auto& f : faces) all.insert(all.end(), f.begin(), f.end());
    for (const Vec3E& v : all) {
      for (const Vec3E& n : normals) {
        const double approx = CGAL::to_double(n[0]) * CGAL::to_double(v[0]) + CGAL::to_double(n[1]) * CGAL::to_double(v[1]) +
                              CGAL::to_double(n[2]) * CGAL::to_double(v[2]) - CGAL::to_double(r);
        if (approx < -1e-9) continue;  // far inside: the exact test below only near the plane
        BOOST_TEST(n[0] * v[0] + n[1] * v[1] + n[2] * v[2] <= r);
      }
      if (cylinder) BOOST_TEST(CGAL::abs(v[2]) <= len / 2);
    }
    for (const auto& f : faces) {
      const Vec3E e1 = {f[1][0] - f[0][0], f[1][1] - f[0][1], f[1][2] - f[0][2]};
      const Vec3E e2 = {f[2][0] - f[0][0], f[2][1] - f[0][1], f[2][2] - f[0][2]};
      const Vec3E c = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
      bool on_plane = false;
      if (const auto it = by_key.find(key(c)); it != by_key.end()) {
        const Vec3E& n = it->second;
        on_plane = true;
        for (const Vec3E& v : f) on_plane = on_plane && n[0] * v[0] + n[1] * v[1] + n[2] * v[2] == r;
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
  // Every vertex within (1 + bound) r of the axis / centre (squared).
  const Exact cylinder_bound[3] = {Exact(102, 100), Exact(10013, 10000), Exact(100008, 100000)};
  const Exact sphere_bound[2] = {Exact(1041, 1000), Exact(10025, 10000)};
  for (int level = 0; level <= 2; ++level) {
    BOOST_TEST_CONTEXT("level " << level) {
      const std::vector<Vec3E> cyl = check(cylinder_polyhedron(r, len, level), cylinder_tangent_normals(level), true);
      BOOST_TEST(cylinder_tangent_normals(level).size() == (16u << (2 * level)));
      for (const Vec3E& v : cyl)
        BOOST_TEST(v[0] * v[0] + v[1] * v[1] <= r * r * cylinder_bound[level] * cylinder_bound[level]);
      if (level > 1) continue;  // the sphere's finest level: 32k faces, too slow for this exact test
      const std::vector<Vec3E> sph = check(sphere_polyhedron(r, level), sphere_tangent_normals(level), false);
      for (const Vec3E& v : sph)
        BOOST_TEST(v[0] * v[0] + v[1] * v[1] + v[2] * v[2] <= r * r * sphere_bound[level] * sphere_bound[level]);
    }
  }
  // Level 0 is the historical construction: 16 azimuths, 114 sphere faces.
  BOOST_TEST(cylinder_polyhedron(r, len).size() == 18u);
  BOOST_TEST(sphere_polyhedron(r).size() == 114u);
  // refine_primitive: the next level, up to the finest, on a primitive only.
  Body b;
  b.primitive = Body::Primitive{Body::Primitive::Kind::Cylinder, r, len, 0};
  BOOST_TEST(refine_primitive(b));
  BOOST_TEST(b.primitive->level == 1);
  BOOST_TEST(b.polygons.size() == 66u);
  BOOST_TEST(refine_primitive(b));
  BOOST_TEST(!refine_primitive(b));  // a cylinder's finest: level 2
  Body ball;
  ball.primitive = Body::Primitive{Body::Primitive::Kind::Sphere, r, 0, 0};
  BOOST_TEST(refine_primitive(ball));
  BOOST_TEST(!refine_primitive(ball));  // a sphere's finest: level 1
  Body plain;
  BOOST_TEST(!refine_primitive(plain));
  // The box is exact.
  const PolygonList box = box_polyhedron({Exact(1), Exact(2), Exact(3)});
  BOOST_TEST(box.size() == 6u);
  for (const auto& f : box)
    for (const Vec3E& v : f) BOOST_TEST((CGAL::abs(v[0]) == Exact(1, 2) && CGAL::abs(v[1]) == 1 && CGAL::abs(v[2]) == Exact(3, 2)));
}

BOOST_AUTO_TEST_CASE(collision_elements_become_parts) {
  // A box at the link origin, a cylinder with a rotated origin and a
  // rotated sphere: three bodies moving with the link.  The box stays exact
  // in the link frame; the cylinder is the exact prism in its origin's
  // frame (no approximation of the rotation); the sphere's frame is its
  // centre.
  const char* urdf = R"(<robot name="m">
    <link name="a"><collision><geometry><box size="0.1 0.1 0.1"/></geometry></collision>
      <collision><origin xyz="0.3 0.1 -0.2" rpy="0.4 -1.1 2.3"/><geometry><cylinder radius="0.05" length="0.4"/></geometry></collision>
      <collision><origin xyz="-0.3 0 0.1" rpy="1 2 3"/><geometry><sphere radius="0.07"/></geometry></collision></link>
  </robot>)";
  const auto model = load_urdf_text(urdf, "m.urdf", ".");
  const RobotLink& link = model->links[0];
  BOOST_REQUIRE(link.parts.size() == 3u);
  const Body& box = link.parts[0].geometry;
  BOOST_TEST(link.parts[0].frame.empty());
  BOOST_TEST(box.polygons.size() == 6u);
  BOOST_TEST(box.solid);
  for (const Vec3E& v : box.polygons[0]) BOOST_TEST((CGAL::abs(v[0]) == Exact(1, 20) && CGAL::abs(v[2]) == Exact(1, 20)));
  const LinkPart& cyl = link.parts[1];
  BOOST_TEST(cyl.suffix == "/collision[1]");
  BOOST_REQUIRE(cyl.frame.size() == 1u);
  BOOST_TEST((cyl.frame[0].rotation.kind == Rotation::Kind::Rpy));
  BOOST_TEST((cyl.frame[0].rotation.rpy == std::array<Exact, 3>{d("0.4"), d("-1.1"), d("2.3")}));
  BOOST_TEST((cyl.geometry.polygons == cylinder_polyhedron(Exact(1, 20), Exact(2, 5))));
  BOOST_REQUIRE(cyl.geometry.primitive);
  BOOST_TEST((cyl.geometry.primitive->kind == Body::Primitive::Kind::Cylinder));
  BOOST_TEST(cyl.geometry.solid);
  const LinkPart& sph = link.parts[2];
  BOOST_TEST(sph.suffix == "/collision[2]");
  BOOST_REQUIRE(sph.frame.size() == 1u);
  BOOST_TEST((sph.frame[0].rotation.kind == Rotation::Kind::Identity));
  BOOST_TEST((sph.frame[0].translation == Vec3E{d("-0.3"), Exact(0), d("0.1")}));
  BOOST_TEST((sph.geometry.polygons == sphere_polyhedron(Exact(7, 100))));
  // Boxes with different origins, one rotated (the Panda's fingers): a part
  // per frame, named by its first element.
  const std::string fingers = R"(<robot name="m"><link name="a">
    <collision><origin xyz="0 0.1 0"/><geometry><box size="1 1 1"/></geometry></collision>
    <collision><origin xyz="0 0 2" rpy="0.5 0 0"/><geometry><box size="1 1 1"/></geometry></collision>
    <collision><origin xyz="0 0 4"/><geometry><box size="1 1 1"/></geometry></collision>
    <collision><origin xyz="0 0 6" rpy="0.5 0 0"/><geometry><box size="1 1 1"/></geometry></collision>
    <collision><origin xyz="0 0 2" rpy="0.5 0 0"/><geometry><box size="1 2 1"/></geometry></collision></link></robot>)";
  const auto f = load_urdf_text(fingers, "f.urdf", ".");
  const std::vector<LinkPart>& parts = f->links[0].parts;
  BOOST_REQUIRE(parts.size() == 3u);
  BOOST_TEST(parts[0].suffix == "");
  BOOST_TEST((parts[0].elements == std::vector<int>{0, 2}));
  BOOST_TEST(parts[0].frame.empty());
  BOOST_TEST(parts[1].suffix == "/collision[1]");
  BOOST_TEST((parts[1].elements == std::vector<int>{1, 4}));  // the same origin: one frame
  BOOST_TEST(parts[1].frame.size() == 1u);
  BOOST_TEST(parts[2].suffix == "/collision[3]");
  // Every element as one body with the same origin (rotated): one part in
  // that frame.
  const std::string one = R"(<robot name="m"><link name="a">
    <collision><origin xyz="1 0 0" rpy="0 0 1"/><geometry><box size="1 1 1"/></geometry></collision>
    <collision><origin xyz="1 0 0" rpy="0 0 1"/><geometry><box size="1 1 3"/></geometry></collision></link></robot>)";
  BOOST_TEST(load_urdf_text(one, "o.urdf", ".")->links[0].parts.size() == 1u);
}

BOOST_AUTO_TEST_CASE(closed_shells_keep_their_insides_beside_open_surfaces) {
  // A link of a box (closed) and an open surface (one triangle): the box is
  // a solid part of its own, the triangle a surface; a mesh holding both a
  // closed tetrahedron and an open flap splits the same way, the flap
  // named ".../open".
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "tmcert_robot_shells";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "flap.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  std::ofstream(dir / "both.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 5 0 0\nv 6 0 0\nv 5 1 0\n"
                                     "f 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\nf 5 6 7\n";
  const std::string urdf = R"(<robot name="m"><link name="a">
    <collision><geometry><box size="1 1 1"/></geometry></collision>
    <collision><origin xyz="3 0 0"/><geometry><mesh filename="flap.obj"/></geometry></collision></link>
    <link name="b"><collision><geometry><mesh filename="both.obj"/></geometry></collision></link>
    <joint name="j" type="fixed"><parent link="a"/><child link="b"/></joint></robot>)";
  const auto model = load_urdf_text(urdf, "m.urdf", dir.string());
  const std::vector<LinkPart>& a = model->links[0].parts;
  BOOST_REQUIRE(a.size() == 2u);
  BOOST_TEST(a[0].geometry.solid);
  BOOST_TEST(a[0].geometry.polygons.size() == 6u);
  BOOST_TEST(!a[1].geometry.solid);
  BOOST_TEST(a[1].suffix == "/collision[1]");
  BOOST_TEST(a[1].geometry.polygons.size() == 1u);
  const std::vector<LinkPart>& b = model->links[1].parts;
  BOOST_REQUIRE(b.size() == 2u);
  BOOST_TEST(b[0].geometry.solid);
  BOOST_TEST(b[0].geometry.polygons.size() == 4u);
  BOOST_TEST(b[1].suffix == "/collision[0]/open");
  BOOST_TEST(!b[1].geometry.solid);
  // The verdict the issue found wrong: a speck inside the box of a link that
  // also has an open mesh is a collision (the box keeps its inside).
  const std::string scene = R"({"format": "tmcert-scene/1",
    "robots": [{"name": "r", "urdf": ")" + (dir / "m.urdf").string() + R"(", "joints": [], "path": {"times": [0, 1], "positions": [[], []]}}],
    "bodies": [{"name": "speck", "points": [["0.1", "0.1", "0.1"]],
                "motion": {"type": "rational_bezier", "control_points": [[[1,0,0,0],[0,1,0,0],[0,0,1,0]], [[1,0,0,"0.01"],[0,1,0,0],[0,0,1,0]]], "weights": [1, 1]}}]})";
  std::ofstream(dir / "m.urdf") << urdf;
  const Scene s = scene_of(scene, "speck.json");
  VerifyOptions options;
  const SceneResult result = verify_scene(s, options);
  BOOST_TEST(result.verdict == Verdict::Collision);
}

BOOST_AUTO_TEST_CASE(self_intersecting_closed_shells_are_surfaces_with_a_note) {
  // Published meshes (the UR3's base, TIAGo's arm, the Bravo 7's link 4)
  // hold shells that close but intersect themselves.  Such a shell has no
  // inside the solid rule can use: it is a surface, the result says so in
  // a note, and the link loads (the self-intersection test read no convex
  // pieces here once, so the shell passed as closed and the scene was then
  // refused: "solid: shell 0 intersects itself").  Here a flat
  // "tetrahedron" (four coplanar vertices: every edge in two faces, the
  // faces overlapping) beside a closed tetrahedron in one mesh.
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "tmcert_robot_folded";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "folded.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
                                       "v 5 0 0\nv 6 0 0\nv 5 1 0\nv 6 1 0\n"
                                       "f 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n"
                                       "f 5 6 7\nf 5 6 8\nf 5 7 8\nf 6 7 8\n";
  const std::string urdf = R"(<robot name="m"><link name="a">
    <collision><geometry><mesh filename="folded.obj"/></geometry></collision></link></robot>)";
  std::ofstream(dir / "m.urdf") << urdf;
  const auto model = load_urdf_text(urdf, "m.urdf", dir.string());
  const std::vector<LinkPart>& a = model->links[0].parts;
  BOOST_REQUIRE(a.size() == 2u);
  BOOST_TEST(a[0].geometry.solid);
  BOOST_TEST(a[0].geometry.polygons.size() == 4u);
  BOOST_TEST(a[1].suffix == "/collision[0]/open");
  BOOST_TEST(!a[1].geometry.solid);
  BOOST_TEST(a[1].geometry.polygons.size() == 4u);
  BOOST_REQUIRE(model->notes.size() == 1u);
  BOOST_TEST(model->notes[0].find("collision[0] (") != std::string::npos, model->notes[0]);
  BOOST_TEST(model->notes[0].find("a closed shell of 4 polygons intersects itself: it counts as a surface") !=
                 std::string::npos,
             model->notes[0]);
  // The scene loads and is verified: a point crossing the flat shell's
  // plane inside it is a collision with the surface.
  const std::string scene = R"({"format": "tmcert-scene/1",
    "robots": [{"name": "r", "urdf": ")" + (dir / "m.urdf").string() + R"(", "joints": [], "path": {"times": [0, 1], "positions": [[], []]}}],
    "bodies": [{"name": "speck", "points": [["5.6", "0.5", "-0.5"]],
                "motion": {"type": "rational_bezier", "control_points": [[[1,0,0,0],[0,1,0,0],[0,0,1,0]], [[1,0,0,0],[0,1,0,0],[0,0,1,1]]], "weights": [1, 1]}}]})";
  const Scene s = scene_of(scene, "folded.json");
  VerifyOptions options;
  const SceneResult result = verify_scene(s, options);
  BOOST_TEST(result.verdict == Verdict::Collision);
}

BOOST_AUTO_TEST_CASE(package_uris_resolve_through_package_folders) {
  // package://NAME/...: the folder whose package.xml names NAME (here
  // gripper_pkg/ holds tiny_gripper), searched below the given folders up
  // to four levels, in order; else a folder named NAME; file:// as a path.
  const std::string pkgs = kData + "/robots/pkgs";
  BOOST_TEST(find_package("tiny_gripper", {pkgs}).value_or("") == pkgs + "/gripper_pkg");
  BOOST_TEST(find_package("tiny_gripper", {kData}).value_or("") == kData + "/robots/pkgs/gripper_pkg");  // two levels down
  BOOST_TEST(!find_package("tiny_gripper", {kData + "/scenes"}));
  BOOST_TEST(!find_package("gripper_pkg_missing", {pkgs}));
  // Without a package.xml naming it, a folder of that name.
  BOOST_TEST(find_package("gripper_pkg", {pkgs}).value_or("") == pkgs + "/gripper_pkg");
  // Five levels down is too deep.
  const std::filesystem::path deep = std::filesystem::temp_directory_path() / "tmcert_deep_pkg";
  std::filesystem::remove_all(deep);
  std::filesystem::create_directories(deep / "a/b/c/d/e/far_pkg");
  std::filesystem::create_directories(deep / "a/b/c/near_pkg");
  BOOST_TEST(!find_package("far_pkg", {deep.string()}));
  BOOST_TEST(find_package("near_pkg", {deep.string()}).value_or("") == (deep / "a/b/c/near_pkg").string());
  // The first folder that has it wins.
  BOOST_TEST(find_package("near_pkg", {pkgs, deep.string()}).value_or("") == (deep / "a/b/c/near_pkg").string());

  const std::string urdf = pkgs + "/gripper_pkg/urdf/gripper.urdf";
  UrdfOptions options;
  options.package_paths = {pkgs};
  const auto model = load_urdf(urdf, options);
  BOOST_TEST(model->links[model->link_index("palm")].parts.size() == 2u);
  // COLLADA: the node's floats, exactly (0.1 and 0.05 as floats: the
  // cube's bottom is at 0 exactly, its top at 0.05f + 0.05f).
  const Body& palm = model->links[model->link_index("palm")].parts[0].geometry;
  BOOST_TEST(palm.solid);
  Exact top = 0, bottom = 1, side = 0;
  for (const auto& poly : palm.polygons)
    for (const Vec3E& v : poly) {
      top = std::max(top, v[2]);
      bottom = std::min(bottom, v[2]);
      side = std::max(side, v[0]);
    }
  BOOST_TEST(bottom == Exact(0));
  BOOST_TEST(top == Exact(double(0.05f)) + Exact(double(0.1f)) * Exact(1, 2));
  BOOST_TEST(side == Exact(double(0.1f)) * Exact(1, 2));
  BOOST_TEST(model->notes.size() == 1u);
  BOOST_TEST(model->notes[0].find("palm.dae (COLLADA) is read from its single-precision floats") != std::string::npos);
  // Not found: the message names the URI and the folders searched.
  options.package_paths = {kData + "/scenes", kData + "/bad"};
  std::string message;
  try {
    load_urdf(urdf, options);
  } catch (const InputError& e) {
    message = e.what();
  }
  BOOST_TEST(message.find("link \"palm\": collision[0]: mesh \"package://tiny_gripper/meshes/palm.dae\": package "
                          "\"tiny_gripper\" not found in \"" + kData + "/scenes\", \"" + kData + "/bad\"") != std::string::npos);
  options.package_paths.clear();
  if (!std::getenv("ROS_PACKAGE_PATH")) {
    try {
      load_urdf(urdf, options);
    } catch (const InputError& e) {
      message = e.what();
    }
    BOOST_TEST(message.find("no package folders to search") != std::string::npos);
  }
  // file:// URIs are paths.
  const std::string file_uri = two_links("fixed", "<mesh filename=\"file://" + pkgs + "/gripper_pkg/meshes/flap.obj\"/>");
  BOOST_TEST(load_urdf_text(file_uri, "f.urdf", "/nonexistent")->links[1].parts.size() == 1u);
}

BOOST_AUTO_TEST_CASE(mimic_joints_follow_exactly) {
  UrdfOptions options;
  options.package_paths = {kData + "/robots/pkgs"};
  const auto model = load_urdf(kData + "/robots/pkgs/gripper_pkg/urdf/gripper.urdf", options);
  const RobotJoint& f2 = model->joints[model->joint_index("finger2")];
  BOOST_REQUIRE(f2.mimic);
  BOOST_TEST(model->joints[f2.mimic->joint].name == "finger1");
  BOOST_TEST(f2.mimic->multiplier == Exact(1));
  BOOST_TEST(f2.mimic->offset == Exact(0));
  // joint_values: the follower at m q + o; fixed joints 0.
  const std::vector<int> columns = {model->joint_index("lift"), model->joint_index("wrist"), model->joint_index("finger1")};
  const std::vector<Exact> all = joint_values(*model, columns, {Exact(1, 10), Exact(1, 2), Exact(3, 100)});
  BOOST_TEST(all[model->joint_index("finger2")] == Exact(3, 100));
  BOOST_TEST(all[model->joint_index("wrist")] == Exact(1, 2));
  // Along a path the follower's link moves exactly as its own joint says:
  // the right finger's body at finger1 = 0.02 sits 0.02 further along -y.
  const PlacedRobot robot(model, "g", Pose{});
  Scene scene;
  const RobotBodies bodies =
      add_robot(scene, robot, JointPath{{"lift", "wrist", "finger1"}, {0, 1}, {{0, 0, 0}, {0, 0, Exact(1, 50)}}});
  const Body& right = scene.bodies.at(bodies.body[model->link_index("finger_r")]);
  BOOST_REQUIRE(right.motion);  // prismatic only: exact
  BOOST_TEST(right.motion->control_points[1][7] - right.motion->control_points[0][7] == Exact(-1, 50));
  // A chain of mimics, multiplier and offset; a cycle is refused.
  const std::string chain = R"(<robot name="c"><link name="a"/><link name="b"/><link name="c"/><link name="d"/>
    <joint name="j1" type="revolute"><parent link="a"/><child link="b"/><axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
    <joint name="j2" type="revolute"><parent link="b"/><child link="c"/><axis xyz="0 0 1"/><limit lower="-9" upper="9" effort="1" velocity="1"/>
      <mimic joint="j1" multiplier="-2" offset="0.5"/></joint>
    <joint name="j3" type="continuous"><parent link="c"/><child link="d"/><axis xyz="0 0 1"/><mimic joint="j2" multiplier="3"/></joint>
    <joint name="f" type="fixed"><parent link="a"/><child link="x"/><mimic joint="j1"/></joint><link name="x"/></robot>)";
  const auto c = load_urdf_text(chain, "c.urdf", ".");
  const std::vector<Exact> v = joint_values(*c, {c->joint_index("j1")}, {Exact(1, 4)});
  BOOST_TEST(v[c->joint_index("j2")] == Exact(0));        // -2/4 + 1/2
  BOOST_TEST(v[c->joint_index("j3")] == Exact(0));
  BOOST_TEST(!c->joints[c->joint_index("f")].mimic);      // on a fixed joint: ignored
  std::string cycle = chain;
  cycle.replace(cycle.find("joint=\"j1\" multiplier=\"-2\""), 10, "joint=\"j3\"");  // j2 follows j3, j3 follows j2
  BOOST_TEST(urdf_error(cycle).find("the mimic joints form a cycle") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(srdf_disable_collisions_are_allowed_pairs) {
  UrdfOptions options;
  options.package_paths = {kData + "/robots/pkgs"};
  const auto model = load_urdf(kData + "/robots/pkgs/gripper_pkg/urdf/gripper.urdf", options);
  const auto pairs = read_srdf(kData + "/robots/pkgs/gripper_pkg/srdf/gripper.srdf", *model);
  BOOST_TEST(pairs.size() == 2u);
  BOOST_TEST((pairs[0] == std::pair<std::string, std::string>{"finger_l", "finger_r"}));
  std::string message;
  try {
    read_srdf(kData + "/bad/robots/unknown-link.srdf", *model);
  } catch (const InputError& e) {
    message = e.what();
  }
  BOOST_TEST(message.find("unknown-link.srdf: disable_collisions[1]: link2: unknown link \"thumb\"") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(collisions_of_cylinders_and_spheres_are_proven_on_the_true_shape) {
  // A sphere (radius 1 about the origin) against a point moving along x:
  // through the ball, a collision whose witness lies in the true ball; past
  // it by 3% of the radius where its polyhedron reaches (1.039 r), safe
  // (finer polyhedra); past it by 3% where the level-0 polyhedron is
  // tangent, safe at once.
  const char* urdf = R"(<robot name="s"><link name="ball"><collision><geometry><sphere radius="1"/></geometry></collision></link></robot>)";
  const auto model = load_urdf_text(urdf, "s.urdf", ".");
  const PlacedRobot robot(model, "s", Pose{});
  auto run = [&](const Vec3E& from, const Vec3E& to) {
    Scene scene;
    Body speck;
    speck.name = "speck";
    speck.points = {{Exact(0), Exact(0), Exact(0)}};
    speck.mass.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    speck.mass.weights = {1, 1, 1, 1};
    Motion m;
    m.t0 = 0;
    m.t1 = 1;
    m.control_points = {{1, 0, 0, from[0], 0, 1, 0, from[1], 0, 0, 1, from[2]}, {1, 0, 0, to[0], 0, 1, 0, to[1], 0, 0, 1, to[2]}};
    m.weights = {1, 1};
    speck.motion = m;
    scene.bodies.push_back(speck);
    const RobotBodies bodies = add_robot(scene, robot, JointPath{{}, {0, 1}, {{}, {}}});
    scene.checks = {{0, bodies.body[0]}};
    VerifyOptions options;
    options.epsilon = Exact(1, 10000);
    return verify_scene(scene, options);
  };
  // Through the centre: a collision, the witness inside the unit ball.
  SceneResult r = run({Exact(-2), Exact(0), Exact(0)}, {Exact(2), Exact(0), Exact(0)});
  BOOST_TEST(r.verdict == Verdict::Collision);
  BOOST_REQUIRE(r.checks[0].witness);
  const Witness& w = *r.checks[0].witness;
  BOOST_TEST(w.true_shape);
  BOOST_TEST(w.point[0] * w.point[0] + w.point[1] * w.point[1] + w.point[2] * w.point[2] <= Exact(1));
  BOOST_TEST(w.features[1] == "s/ball sphere");
  // The bulge of the level-0 polyhedron is at (1, 0.2, 0.2)/|.| (1.039 r):
  // a speck passing at 1.02 r there, across that direction.
  const double n = std::sqrt(1.08);
  const Exact px(1.02 / n), py(0.2 * 1.02 / n), pz(0.2 * 1.02 / n);
  r = run({px, py - Exact(1, 10), pz + Exact(1, 10)}, {px, py + Exact(1, 10), pz - Exact(1, 10)});
  BOOST_TEST(r.verdict == Verdict::Safe);
  // Before refinement this was a collision "of the enlarged model": the
  // polyhedron does contain that path's middle point.
  bool inside_polyhedron = true;
  for (const Vec3E& normal : sphere_tangent_normals())
    inside_polyhedron = inside_polyhedron && normal[0] * px + normal[1] * py + normal[2] * pz <= Exact(1);
  BOOST_TEST(inside_polyhedron);
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
  // Every body of every link against the wall (l1 has two: its box and its
  // sphere), nothing inside the robot.
  BOOST_TEST(without.size() == 7u);
  for (int l = 0; l < 6; ++l) BOOST_TEST(has(without, bodies.body[l], 0));
  BOOST_REQUIRE(bodies.parts[m.link_index("l1")].size() == 2u);
  const int l1_sphere = bodies.parts[m.link_index("l1")][1];
  BOOST_TEST(has(without, l1_sphere, 0));
  const auto with = robot_default_checks(robot, bodies, {0}, true, {{"l4", "base"}});
  // 15 link pairs, 5 parent-child pairs (l2-l3 are joined by the fixed
  // joint), 1 allowed: 9 pairs of links, of which 3 with l1 (l3, l4, l5)
  // count twice (two bodies); the parts of l1 are not checked together.
  BOOST_TEST(with.size() == 7u + 9u + 3u);
  BOOST_TEST(has(with, l1_sphere, body_of("l5")));
  BOOST_TEST(!has(with, l1_sphere, body_of("l1")));
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
  BOOST_TEST(urdf_error("<robot name=\"x\"><link name=\"a\"/><link name=\"b\"/></robot>").find("t.urdf: links \"a\" and \"b\" are both roots") !=
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
  // xacro's output keeps the namespace declaration (the published Panda
  // and UR5 of example-robot-data): without xacro elements it is plain URDF.
  const std::string expanded = R"(<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <link name="a"><collision><geometry><box size="1 1 1"/></geometry></collision></link></robot>)";
  BOOST_TEST(load_urdf_text(expanded, "t.urdf", ".")->links.size() == 1u);
}

// The links and joints must form a tree: every way they can fail to is
// refused naming the file, the links and the joints, never resolved by a
// silent choice (before, the last of two parent joints in file order won).
BOOST_AUTO_TEST_CASE(urdf_must_be_a_tree) {
  auto robot = [](const std::string& links, const std::string& joints) {
    std::string s = "<robot name=\"r\">";
    for (char c : links) s += std::string("<link name=\"") + c + "\"/>";
    return s + joints + "</robot>";
  };
  auto fixed = [](const std::string& name, char parent, char child) {
    return "<joint name=\"" + name + "\" type=\"fixed\"><parent link=\"" + parent + "\"/><child link=\"" + child +
           "\"/></joint>";
  };
  auto has = [](const std::string& error, const std::string& part) {
    const bool found = error.find(part) != std::string::npos;
    if (!found) BOOST_TEST_MESSAGE("error: " + error);
    return found;
  };
  // A tree is accepted.
  BOOST_TEST(robot_root_name(robot("abc", fixed("j1", 'a', 'b') + fixed("j2", 'a', 'c'))) == "a");
  // A link that is the child of two joints (in either order).
  const std::string two_parents = urdf_error(robot("abc", fixed("j1", 'a', 'b') + fixed("j2", 'b', 'c') + fixed("k", 'a', 'c')));
  BOOST_TEST(has(two_parents, "t.urdf: link \"c\": the child of two joints, \"j2\" and \"k\""));
  BOOST_TEST(has(urdf_error(robot("abc", fixed("k", 'a', 'c') + fixed("j1", 'a', 'b') + fixed("j2", 'b', 'c'))),
                 "link \"c\": the child of two joints, \"k\" and \"j2\""));
  // A cycle away from the root (urdfdom finds one root and accepts it).
  BOOST_TEST(has(urdf_error(robot("abc", fixed("j1", 'a', 'b') + fixed("j2", 'c', 'b') + fixed("j3", 'b', 'c'))),
                 "link \"b\": the child of two joints"));
  const std::string cycle = urdf_error(robot("rbc", fixed("j2", 'c', 'b') + fixed("j3", 'b', 'c')));
  BOOST_TEST(has(cycle, "t.urdf: joints"));
  BOOST_TEST(has(cycle, "form a cycle"));
  BOOST_TEST(has(cycle, "\"j2\""));
  BOOST_TEST(has(cycle, "\"j3\""));
  BOOST_TEST(has(urdf_error(robot("abcd", fixed("j1", 'a', 'b') + fixed("j2", 'd', 'c') + fixed("j3", 'c', 'd'))),
                 "form a cycle"));
  // No root at all (a cycle through every link), a joint from a link to itself.
  BOOST_TEST(has(urdf_error(robot("ab", fixed("j1", 'a', 'b') + fixed("j2", 'b', 'a'))), "form a cycle"));
  BOOST_TEST(has(urdf_error(robot("ab", fixed("j1", 'a', 'b') + fixed("s", 'b', 'b'))),
                 "joint \"s\": its parent and child are the same link \"b\""));
  // Two roots: a lone link, or two separate trees.
  BOOST_TEST(has(urdf_error(robot("abc", fixed("j1", 'a', 'b'))), "links \"a\" and \"c\" are both roots"));
  BOOST_TEST(has(urdf_error(robot("abcd", fixed("j1", 'a', 'b') + fixed("j2", 'c', 'd'))), "links \"a\" and \"c\" are both roots"));
  // Joint names once; links that exist.
  BOOST_TEST(has(urdf_error(robot("abc", fixed("j", 'a', 'b') + fixed("j", 'a', 'c'))), "joint \"j\": defined twice"));
  BOOST_TEST(has(urdf_error(robot("ab", fixed("j", 'a', 'x'))), "joint \"j\": unknown child link \"x\""));
  BOOST_TEST(has(urdf_error(robot("ab", fixed("j", 'x', 'b'))), "joint \"j\": unknown parent link \"x\""));
  BOOST_TEST(has(urdf_error("<robot name=\"r\"></robot>"), "t.urdf: no <link>"));
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
