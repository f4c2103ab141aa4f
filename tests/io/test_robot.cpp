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
#include "src/model/segment_kind.h"
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
  JointPath path{{"j"}, {0, 1}, {{Exact(0)}, {Exact(3, 5)}}, JointInterpolation::Linear, {}, {}};
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
      for (const auto& [s0, s1] : {std::pair{Exact(0), Exact(1)}, std::pair{Exact(1, 4), Exact(1, 2)},
                                   std::pair{Exact(5, 8), Exact(3, 4)}}) {
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
      add_robot(scene, robot, JointPath{{"lift", "wrist", "finger1"}, {0, 1}, {{0, 0, 0}, {0, 0, Exact(1, 50)}}, JointInterpolation::Linear, {}, {}});
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
    const RobotBodies bodies = add_robot(scene, robot, JointPath{{}, {0, 1}, {{}, {}}, JointInterpolation::Linear, {}, {}});
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
    const RobotBodies bodies = add_robot(scene, arm, JointPath{{"turn"}, {0, 1}, {{Exact(0)}, {Exact(3, 2)}}, JointInterpolation::Linear, {}, {}});
    scene.checks = robot_default_checks(arm, bodies, {0}, false, {});
    VerifyOptions options;
    options.epsilon = Exact(1, 1000);
    const SceneResult result = verify_scene(scene, options);
    BOOST_TEST(result.verdict == truth);
  }
}

BOOST_AUTO_TEST_SUITE_END()

// ------------------------------------------------------------------ trajectories
// Cubic and quintic joint trajectories (SCENE_FORMAT.md "Real robots as
// they ship"; proofs/trajectories.md): the Hermite coefficients, the exact
// limit check on the whole polynomial, and the enclosures of link pieces
// against dense MPFR samples with a rigorous Lipschitz bound.

namespace {

// q(s) from the Hermite basis (the test's own form, not the library's
// coefficients): values p, s-derivatives D = T v and A = T^2 a at both ends.
Exact hermite_at(int degree, const Exact& p0, const Exact& p1, const Exact& D0, const Exact& D1, const Exact& A0,
                 const Exact& A1, const Exact& s) {
  const Exact s2 = s * s, s3 = s2 * s, s4 = s3 * s, s5 = s4 * s;
  if (degree == 3) return (2 * s3 - 3 * s2 + 1) * p0 + (s3 - 2 * s2 + s) * D0 + (3 * s2 - 2 * s3) * p1 + (s3 - s2) * D1;
  return (1 - 10 * s3 + 15 * s4 - 6 * s5) * p0 + (s - 6 * s3 + 8 * s4 - 3 * s5) * D0 +
         (s2 - 3 * s3 + 3 * s4 - s5) / 2 * A0 + (s3 - 2 * s4 + s5) / 2 * A1 + (7 * s4 - 4 * s3 - 3 * s5) * D1 +
         (10 * s3 - 15 * s4 + 6 * s5) * p1;
}

Exact poly_at(const std::vector<Exact>& c, const Exact& s) {
  Exact v = 0;
  for (std::size_t k = c.size(); k-- > 0;) v = v * s + c[k];
  return v;
}
std::vector<Exact> derivative(const std::vector<Exact>& c) {
  std::vector<Exact> out;
  for (std::size_t k = 1; k < c.size(); ++k) out.push_back(Exact(static_cast<int>(k)) * c[k]);
  return out;
}

// The message of validate_joint_path, or "" when the path is accepted.
std::string path_error(const RobotModel& model, const JointPath& path) {
  try {
    validate_joint_path(model, path);
  } catch (const JointPathError& e) {
    return e.field + ": " + e.what();
  }
  return "";
}

JointPath one_joint(JointInterpolation how, const std::string& joint, const std::vector<Exact>& p,
                    const std::vector<Exact>& v, const std::vector<Exact>& a = {}) {
  JointPath path;
  path.joints = {joint};
  path.times = {0, 1};
  path.interpolation = how;
  path.positions = {{p[0]}, {p[1]}};
  path.velocities = {{v[0]}, {v[1]}};
  if (!a.empty()) path.accelerations = {{a[0]}, {a[1]}};
  return path;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(robot_trajectories)

BOOST_AUTO_TEST_CASE(hermite_coefficients_meet_their_ends_exactly) {
  // The power-basis coefficients (src/model/chain.h) have the given values,
  // first and second derivatives at s = 0 and s = 1, and equal the Hermite
  // basis form everywhere (checked at 7 rationals: two polynomials of
  // degree <= 5 that agree at 6 points are equal).
  std::mt19937_64 rng(11);
  for (int trial = 0; trial < 20; ++trial) {
    const Exact p0 = random_in(rng, -3, 3), p1 = random_in(rng, -3, 3), v0 = random_in(rng, -2, 2),
                v1 = random_in(rng, -2, 2), a0 = random_in(rng, -5, 5), a1 = random_in(rng, -5, 5),
                T = random_in(rng, Exact(1, 10), 3);
    for (const int degree : {3, 5}) {
      const Exact A0 = degree == 5 ? a0 : Exact(0), A1 = degree == 5 ? a1 : Exact(0);
      const std::vector<Exact> c = hermite_coefficients(degree, p0, p1, v0, v1, A0, A1, T);
      BOOST_TEST(static_cast<int>(c.size()) == degree + 1);
      const std::vector<Exact> c1 = derivative(c), c2 = derivative(c1);
      BOOST_TEST(poly_at(c, 0) == p0);
      BOOST_TEST(poly_at(c, 1) == p1);
      BOOST_TEST(poly_at(c1, 0) == T * v0);
      BOOST_TEST(poly_at(c1, 1) == T * v1);
      if (degree == 5) {
        BOOST_TEST(poly_at(c2, 0) == T * T * a0);
        BOOST_TEST(poly_at(c2, 1) == T * T * a1);
      }
      for (const Exact s : {Exact(0), Exact(1, 7), Exact(1, 3), Exact(1, 2), Exact(5, 8), Exact(9, 10), Exact(1)})
        BOOST_TEST(poly_at(c, s) == hermite_at(degree, p0, p1, T * v0, T * v1, T * T * A0, T * T * A1, s));
    }
  }
}

BOOST_AUTO_TEST_CASE(limits_hold_on_the_whole_polynomial_exactly) {
  // Joint "j" of two_links has limits [-1, 1].
  const std::shared_ptr<const RobotModel> model = load_urdf_text(two_links("revolute"), "t.urdf", kData + "/robots");
  using JI = JointInterpolation;
  // 1 - (2/5)(s - 1/2)^2 as a cubic: p = 9/10 at both ends, D = +-2/5; its
  // maximum is the limit 1 exactly, at s = 1/2: within the limits.
  BOOST_TEST(path_error(*model, one_joint(JI::Cubic, "j", {d("0.9"), d("0.9")}, {d("0.4"), d("-0.4")})) == "");
  // A little faster: the cubic passes 1 between the waypoints, which are
  // within the limits.
  const std::string over = path_error(*model, one_joint(JI::Cubic, "j", {d("0.9"), d("0.9")}, {d("0.4001"), d("-0.4")}));
  BOOST_TEST(over.find("path: segment from waypoint 0 to 1 (cubic): joint \"j\" at t = ") == 0, over);
  BOOST_TEST(over.find(", outside its limits [-1, 1]") != std::string::npos, over);
  // 1 - (s^2 - s + 1/8)^2: touches the limit at the two irrational points
  // (1 +- sqrt(1/2))/2 and stays below elsewhere: within the limits,
  // decided exactly (no sampling or subdivision can show this).
  const std::vector<Exact> touch_p = {Exact(63, 64), Exact(63, 64)}, touch_v = {Exact(1, 4), Exact(-1, 4)},
                           touch_a = {Exact(-5, 2), Exact(-5, 2)};
  BOOST_TEST(path_error(*model, one_joint(JI::Quintic, "j", touch_p, touch_v, touch_a)) == "");
  // Its mirror image touches the lower limit.
  BOOST_TEST(path_error(*model, one_joint(JI::Quintic, "j", {-touch_p[0], -touch_p[1]}, {-touch_v[0], -touch_v[1]},
                                          {-touch_a[0], -touch_a[1]})) == "");
  // A slightly larger acceleration at the start lifts the first touch point
  // above the limit.
  const std::string lifted =
      path_error(*model, one_joint(JI::Quintic, "j", touch_p, touch_v, {d("-2.49"), touch_a[1]}));
  BOOST_TEST(lifted.find("path: segment from waypoint 0 to 1 (quintic): joint \"j\" at t = ") == 0, lifted);
  // The witness is real: the polynomial at the reported time is outside.
  {
    const std::size_t at = lifted.find(" is at ");
    BOOST_REQUIRE(at != std::string::npos);
    const std::string t_text = lifted.substr(lifted.find("at t = ") + 7, lifted.find(" is at ") - lifted.find("at t = ") - 7);
    Exact t;
    BOOST_REQUIRE(parse_exact(t_text, t));
    BOOST_TEST(hermite_at(5, touch_p[0], touch_p[1], touch_v[0], touch_v[1], d("-2.49"), touch_a[1], t) > 1);
  }
  // Linear paths keep their waypoint rule; velocities are refused there.
  JointPath linear = one_joint(JI::Linear, "j", {d("0.9"), d("0.9")}, {0, 0});
  BOOST_TEST(path_error(*model, linear).find("velocities: velocities are not used by linear interpolation") == 0);
  linear.velocities.clear();
  BOOST_TEST(path_error(*model, linear) == "");
  // A continuous joint has no limits to leave.
  const std::shared_ptr<const RobotModel> spin = load_urdf_text(two_links("continuous", "<box size=\"1 1 1\"/>", ""),
                                                                "t.urdf", kData + "/robots");
  BOOST_TEST(path_error(*spin, one_joint(JI::Cubic, "j", {0, 0}, {100, 100})) == "");
}

BOOST_AUTO_TEST_CASE(mimic_joints_follow_the_polynomial_within_their_limits) {
  // tests/data/bad/robots/mimic-limit.urdf: "follow" = 2 "slide", limited
  // to [0, 0.5] (slide: [0, 1]).  slide = 0.2 + ... peaks near 0.3 between
  // the waypoints: follow passes 0.5 there, though both waypoints are fine.
  const std::shared_ptr<const RobotModel> model = load_urdf(kData + "/bad/robots/mimic-limit.urdf");
  using JI = JointInterpolation;
  const std::string over = path_error(*model, one_joint(JI::Cubic, "slide", {d("0.2"), d("0.2")}, {d("0.5"), d("-0.5")}));
  BOOST_TEST(over.find("path: segment from waypoint 0 to 1 (cubic): joint \"follow\" (mimic of \"slide\": 2 q + 0) at t = ") == 0, over);
  // Slower: slide peaks at 0.2 + 0.2/4 = 0.25, follow at 0.5 exactly.
  BOOST_TEST(path_error(*model, one_joint(JI::Cubic, "slide", {d("0.2"), d("0.2")}, {d("0.2"), d("-0.2")})) == "");
}

BOOST_AUTO_TEST_CASE(hermite_link_pieces_hold_dense_mpfr_samples_with_a_lipschitz_bound) {
  // Cubic and quintic paths of chain.urdf (revolute, prismatic, rpy
  // origins, an axis of irrational length): enclose_piece's tube holds the
  // MPFR pose at N + 1 samples of each piece with room for the gaps:
  // between samples (spacing h) the pose moves by at most L h / 2 and the
  // line by M h / (2 w), so a sample distance below tube - (L + M / w) h / 2
  // puts every pose of the piece within the tube.  L bounds |d pose / ds|
  // (Frobenius): sum_j max|q_j'| (sqrt 2 + R) with R = 2 above every
  // distance from a joint to a link body origin in this chain (its
  // translations add up to less than 1.6), over the joints of the link's chain;
  // max|q_j'| from the Bernstein form of q_j'.  The enclosed pose at 9
  // rationals holds the MPFR pose and is narrow.
  std::mt19937_64 rng(23);
  const PlacedRobot robot(chain_model(), "r", some_base());
  std::array<Interval, 16> g;
  for (int i = 0; i < 16; ++i) g[i] = Interval(i % 5 == 0 ? 1 : 0);
  int checked = 0;
  for (int trial = 0; trial < 4; ++trial) {
    const int degree = trial % 2 ? 5 : 3;
    const Exact T = random_in(rng, Exact(1, 2), 2);
    const std::array<Exact, 4> lo{d("-1"), d("0.05"), d("-0.7"), d("-1")}, hi{d("1"), d("0.15"), d("0.7"), d("1")};
    const std::array<Exact, 4> vmax{d("0.5"), d("0.05"), d("0.4"), d("0.5")};
    std::array<Exact, 4> p0, p1, v0, v1, a0, a1;
    for (int j = 0; j < 4; ++j) {
      p0[j] = random_in(rng, lo[j], hi[j]), p1[j] = random_in(rng, lo[j], hi[j]);
      v0[j] = random_in(rng, -vmax[j], vmax[j]), v1[j] = random_in(rng, -vmax[j], vmax[j]);
      a0[j] = degree == 5 ? random_in(rng, -vmax[j], vmax[j]) : Exact(0);
      a1[j] = degree == 5 ? random_in(rng, -vmax[j], vmax[j]) : Exact(0);
    }
    JointPath path = two_waypoints(p0, p1);
    path.times = {0, T};
    path.interpolation = degree == 5 ? JointInterpolation::Quintic : JointInterpolation::Cubic;
    path.velocities = {{v0[0], v0[1], v0[2], v0[3]}, {v1[0], v1[1], v1[2], v1[3]}};
    if (degree == 5) path.accelerations = {{a0[0], a0[1], a0[2], a0[3]}, {a1[0], a1[1], a1[2], a1[3]}};
    Scene scene;
    const RobotBodies bodies = add_robot(scene, robot, path);  // within the limits by construction
    auto q_at = [&](const Exact& s) {
      std::array<Exact, 4> q;
      for (int j = 0; j < 4; ++j) q[j] = hermite_at(degree, p0[j], p1[j], T * v0[j], T * v1[j], T * T * a0[j], T * T * a1[j], s);
      return q;
    };
    // max |q_j'| on [0, 1] <= the largest |Bernstein coefficient| of q_j'
    // (a convex combination of them at every s), exactly.
    std::array<double, 4> rate{};
    for (int j = 0; j < 4; ++j) {
      const std::vector<Exact> c1 = derivative(hermite_coefficients(degree, p0[j], p1[j], v0[j], v1[j], a0[j], a1[j], T));
      const int n = static_cast<int>(c1.size()) - 1;
      auto choose = [](int a, int b) {
        long r = 1;
        for (int i = 1; i <= b; ++i) r = r * (a - b + i) / i;
        return Exact(static_cast<int>(r));
      };
      Exact most = 0;
      for (int i = 0; i <= n; ++i) {
        Exact b = 0;
        for (int k = 0; k <= i; ++k) b += choose(i, k) / choose(n, k) * c1[k];
        most = std::max(most, b < 0 ? -b : b);
      }
      rate[j] = to_interval(most).sup();
    }
    for (const std::string link : {"l2", "l5"}) {
      const int moving = link == "l2" ? 2 : 4;  // the chain's joints
      double L = 0;
      for (int j = 0; j < moving; ++j) L += rate[j] * (std::sqrt(2.0) + 2.0);
      L *= 1.0 + 1e-9;  // the double sums' rounding
      const Body& body = scene.bodies.at(bodies.body[robot.model().link_index(link)]);
      BOOST_REQUIRE(body.trajectory);
      const MotionSegment& seg = body.trajectory->segments[0];
      BOOST_TEST(kind_of(seg).name() == "robot_link_hermite");
      const std::unique_ptr<SegmentModel> model = make_segment_model(seg);
      for (int k = 0; k <= 8; ++k)
        check_pose_encloses(enclose_pose(*model, Exact(k, 8)), mp_link_body(mp_base(), link, q_at(Exact(k, 8))), 1e-9,
                            link + " point");
      for (const auto& [s0, s1] : {std::pair{Exact(0), Exact(1)}, std::pair{Exact(1, 4), Exact(1, 2)},
                                   std::pair{Exact(5, 8), Exact(3, 4)}}) {
        const PieceEnclosure pe = enclose_piece(*model, s0, s1, g);
        BOOST_REQUIRE(pe.valid);
        double M2 = 0;  // |P1 - P0|^2 bounded over the control boxes
        {
          RoundingGuard guard;
          for (int e = 0; e < 12; ++e) {
            const Interval diff = pe.controls[1][e] - pe.controls[0][e];
            const double m = std::max(std::abs(diff.inf()), std::abs(diff.sup()));
            M2 += m * m;
          }
        }
        const double w = to_interval(s1 - s0).inf();
        // The largest sample distance at N + 1 samples.
        auto worst_of = [&](int N) {
          Mp worst(0);
          for (int k = 0; k <= N; ++k) {
          const Exact u = Exact(k, N), s = s0 + (s1 - s0) * u;
          const MpPose want = mp_link_body(mp_base(), link, q_at(s));
          Mp sum(0);
          for (int e = 0; e < 12; ++e) {
            RoundingGuard guard;
            const Interval line = pe.controls[0][e] + to_interval(u) * (pe.controls[1][e] - pe.controls[0][e]);
            const Mp a(line.inf()), b(line.sup());
            Mp gap(0);
            if (want[e] < a) gap = a - want[e];
            if (b < want[e]) gap = want[e] - b;
            sum = sum + gap * gap;
          }
          if (worst < sqrt(sum)) worst = sqrt(sum);
          }
          return worst;
        };
        // Enough samples that the gaps' allowance is half of what the tube
        // leaves above a first pass (at most 1024).
        const double spread = (L + std::sqrt(M2) / w) * to_interval(s1 - s0).sup() / 2 * (1 + 1e-9);
        const double left = pe.tube - worst_of(16).to_double();
        const int N = left > 0 ? static_cast<int>(std::min(1024.0, std::ceil(2 * spread / left) + 1)) : 1024;
        const Mp room = Mp(pe.tube) - Mp(spread) / Mp(N);
        const Mp worst = worst_of(N);
        BOOST_TEST_CONTEXT(link << " trial " << trial << " piece [" << s0 << ", " << s1 << "] tube " << pe.tube
                                << " worst sample " << worst.to_double() << " room " << room.to_double() << " samples "
                                << N + 1) {
          BOOST_TEST(!(room < worst));
        }
        ++checked;
      }
    }
  }
  BOOST_TEST(checked == 4 * 2 * 3);
}

BOOST_AUTO_TEST_CASE(hermite_link_tubes_shrink_with_the_piece) {
  // The search subdivides the parameter: the tube of [1/3, 1/3 + 2^-k]
  // falls (quadratically: the remainder of a second-order Taylor form) as
  // the piece shrinks, so that every pose is eventually decided.
  const PlacedRobot robot(chain_model(), "r", some_base());
  std::array<Interval, 16> g;
  for (int i = 0; i < 16; ++i) g[i] = Interval(i % 5 == 0 ? 1 : 0);
  JointPath path = two_waypoints({d("-1"), d("0.1"), d("0.5"), d("2")}, {d("1"), d("0.2"), d("-0.5"), d("-1")});
  path.interpolation = JointInterpolation::Quintic;
  path.velocities = {{d("0.5"), 0, d("-0.3"), d("1")}, {d("-0.5"), 0, d("0.2"), d("2")}};
  path.accelerations = {{d("0.5"), 0, d("0.5"), d("-1")}, {d("0.2"), 0, d("-0.5"), d("1")}};
  Scene scene;
  const RobotBodies bodies = add_robot(scene, robot, path);
  const Body& body = scene.bodies.at(bodies.body[robot.model().link_index("l5")]);
  const std::unique_ptr<SegmentModel> model = make_segment_model(body.trajectory->segments[0]);
  double previous = 1e300;
  for (int k = 2; k <= 14; k += 2) {
    const PieceEnclosure pe = enclose_piece(*model, Exact(1, 3), Exact(1, 3) + Exact(1) / Exact(1 << k), g);
    BOOST_REQUIRE(pe.valid);
    BOOST_TEST_CONTEXT("k " << k << " tube " << pe.tube) {
      BOOST_TEST(pe.tube < previous / 8);
    }
    previous = pe.tube;
  }
  BOOST_TEST(previous < 1e-7);
}

BOOST_AUTO_TEST_CASE(a_segment_of_degree_one_stays_linear_and_a_still_link_stays_still) {
  // A cubic whose joint polynomials have no s^2 or s^3 term (velocities
  // equal to the chord's) is the linear motion exactly: the segment is the
  // linear kind (rational where its chain is), and a link whose joints do
  // not move on any segment is motionless.
  const PlacedRobot robot(chain_model(), "r", some_base());
  JointPath path = two_waypoints({d("0.5"), d("0.1"), d("0"), d("1")}, {d("0.5"), d("0.2"), d("0"), d("1")});
  path.times = {0, 2};
  path.interpolation = JointInterpolation::Cubic;
  path.velocities = {{0, d("0.05"), 0, 0}, {0, d("0.05"), 0, 0}};
  Scene scene;
  const RobotBodies bodies = add_robot(scene, robot, path);
  const Body& l1 = scene.bodies.at(bodies.body[robot.model().link_index("l1")]);
  BOOST_REQUIRE(l1.trajectory);  // j1 = 0.5: not exact, so a still link segment
  BOOST_TEST(l1.trajectory->segments.size() == 1u);
  BOOST_TEST(l1.trajectory->segments[0].link->degree() == 1);
  BOOST_TEST((l1.trajectory->segments[0].link->from == l1.trajectory->segments[0].link->to));
  const Body& l2 = scene.bodies.at(bodies.body[robot.model().link_index("l2")]);
  BOOST_REQUIRE(l2.trajectory);
  BOOST_TEST(kind_of(l2.trajectory->segments[0]).name() == "robot_link");
  // A velocity off the chord makes it a polynomial of degree 3.
  path.velocities[1][1] = d("0.06");
  Scene curved;
  const RobotBodies cb = add_robot(curved, robot, path);
  const Body& c2 = curved.bodies.at(cb.body[robot.model().link_index("l2")]);
  BOOST_REQUIRE(c2.trajectory);
  BOOST_TEST(kind_of(c2.trajectory->segments[0]).name() == "robot_link_hermite");
}

BOOST_AUTO_TEST_SUITE_END()
