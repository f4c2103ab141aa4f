// Certificates of URDF cylinders and spheres (src/certificate/
// check_primitive.h, proofs/certificates.md §8): the checker's polyhedra
// circumscribe the true shapes at every level it accepts, its true-shape
// test decides exactly, and the wand's certificates (tests/data/scenes/
// robots/wand*.json) are written, accepted, and rejected once tampered with.
#include "src/certificate/check_primitive.h"
#include "src/certificate/check.h"
#include "src/certificate/writer.h"
#include "src/io/parse.h"
#include "src/io/primitives.h"
#include "src/verify/verify.h"

#include <boost/test/unit_test.hpp>
#include <nlohmann/json.hpp>

namespace {

using namespace tmcert;
using json = nlohmann::json;
namespace ci = tmcert::certificate::check_internal;

struct Written {
  Scene scene;
  json certificate;
  SceneResult result;
};

Written written(const std::string& name) {
  Written w{parse_scene_file(std::string(TMCERT_TEST_DATA) + "/scenes/" + name), {}, {}};
  VerifyOptions options;
  options.epsilon = w.scene.epsilon ? *w.scene.epsilon : default_epsilon(w.scene);
  options.max_depth = w.scene.max_depth;
  options.record_cover = true;
  w.result = verify_scene(w.scene, options);
  w.certificate = json::parse(certificate::certificate_json(w.scene, w.result));
  return w;
}

// ok, or the rejection's message (an InputError's too).
std::string outcome(const Written& w, const json& certificate) {
  try {
    const certificate::CheckOutcome out = certificate::check_certificate(w.scene, certificate, "c.json");
    return out.ok ? "ok" : out.message;
  } catch (const InputError& e) {
    return std::string("input error: ") + e.what();
  }
}

bool has(const std::string& text, const std::string& what) { return text.find(what) != std::string::npos; }

// The largest value of n . x over the true shape (support function), compared
// exactly with the face's offset d: n . x <= d on the whole shape iff
// (ball) d >= 0 and d^2 >= r^2 |n|^2; (cylinder) d' = d - |n_z| l/2 >= 0 and
// d'^2 >= r^2 (n_x^2 + n_y^2).
bool face_holds_shape(const Body::Primitive& p, const Vec3E& n, const Exact& d) {
  if (p.kind == Body::Primitive::Kind::Sphere)
    return d >= 0 && d * d >= p.radius * p.radius * (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  const Exact e = d - CGAL::abs(n[2]) * p.length / 2;
  return e >= 0 && e * e >= p.radius * p.radius * (n[0] * n[0] + n[1] * n[1]);
}

// Every face of the body's polyhedron has the true shape on its inner side
// (its outward normal from the face's vertices, the origin inside), and
// (when `convex_check`) every vertex lies in every face's closed half-space,
// so the polyhedron is the intersection of those half-spaces: it contains
// the shape.
bool circumscribes(const Body& body, bool convex_check) {
  const Body::Primitive& p = *body.primitive;
  std::vector<std::pair<Vec3E, Exact>> planes;
  for (const auto& f : body.polygons) {
    const Vec3E e1 = {f[1][0] - f[0][0], f[1][1] - f[0][1], f[1][2] - f[0][2]};
    const Vec3E e2 = {f[2][0] - f[0][0], f[2][1] - f[0][1], f[2][2] - f[0][2]};
    Vec3E n = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
    Exact d = n[0] * f[0][0] + n[1] * f[0][1] + n[2] * f[0][2];
    if (d < 0) {  // oriented inward: flip (the origin, inside the shape, is inside)
      for (Exact& c : n) c = -c;
      d = -d;
    }
    if (!face_holds_shape(p, n, d)) return false;
    planes.push_back({n, d});
  }
  if (convex_check)
    for (const auto& f : body.polygons)
      for (const Vec3E& v : f)
        for (const auto& [n, d] : planes)
          if (n[0] * v[0] + n[1] * v[1] + n[2] * v[2] > d) return false;
  return true;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(check_primitive)

// The polyhedra the checker builds for a check's "levels" (the scene
// reader's construction, refine_primitive) circumscribe the true cylinder
// and ball at every level it accepts: each face plane at least the shape's
// support from the centre, exactly.  A polyhedron shrunk by 1% does not.
BOOST_AUTO_TEST_CASE(checker_polyhedra_circumscribe_the_true_shapes) {
  const Scene scene = parse_scene_file(std::string(TMCERT_TEST_DATA) + "/scenes/robots/wand-sphere-safe.json");
  int seen = 0;
  for (const Body& b : scene.bodies) {
    if (!b.primitive) continue;
    ++seen;
    Body body = b;
    const bool sphere = body.primitive->kind == Body::Primitive::Kind::Sphere;
    for (int level = 0;; ++level) {
      BOOST_TEST_CONTEXT(b.name << " level " << level) {
        BOOST_TEST(body.primitive->level == level);
        // Every vertex against every plane where that stays fast.
        BOOST_TEST(circumscribes(body, sphere ? level == 0 : level <= 1));
      }
      if (!refine_primitive(body)) break;
    }
    BOOST_TEST(body.primitive->level == (sphere ? kMaxSphereLevel : kMaxCylinderLevel));
    Body shrunk = b;
    for (auto& f : shrunk.polygons)
      for (Vec3E& v : f)
        for (Exact& c : v) c *= Exact(99, 100);
    BOOST_TEST(!circumscribes(shrunk, false));
  }
  BOOST_TEST(seen == 2);
}

// The true-shape test decides on exact squares: on the boundary is inside,
// anything beyond is not; a vertex of the level-0 prism (inside the
// polyhedron) is outside the true cylinder.
BOOST_AUTO_TEST_CASE(true_shape_boxes_are_decided_exactly) {
  Body::Primitive cyl;
  cyl.kind = Body::Primitive::Kind::Cylinder;
  cyl.radius = Exact(1, 20);
  cyl.length = Exact(3, 5);
  auto point = [](const Exact& x, const Exact& y, const Exact& z) {
    return certificate::RBox{certificate::RInterval{x, x}, certificate::RInterval{y, y}, certificate::RInterval{z, z}};
  };
  const Exact tiny = Exact(1, 1000000) * Exact(1, 1000000);  // 10^-12
  BOOST_TEST(ci::box_in_primitive(cyl, point(Exact(3, 100), Exact(4, 100), Exact(3, 10))));  // on the rim
  BOOST_TEST(!ci::box_in_primitive(cyl, point(Exact(3, 100) + tiny, Exact(4, 100), 0)));
  BOOST_TEST(!ci::box_in_primitive(cyl, point(0, 0, Exact(3, 10) + tiny)));
  BOOST_TEST(ci::box_in_primitive(cyl, point(0, 0, -Exact(3, 10))));
  // A box: its farthest corner decides.
  BOOST_TEST(ci::box_in_primitive(cyl, {certificate::RInterval{-Exact(3, 100), Exact(1, 100)},
                                        certificate::RInterval{Exact(-4, 100), 0}, certificate::RInterval{0, 0}}));
  BOOST_TEST(!ci::box_in_primitive(cyl, {certificate::RInterval{-Exact(3, 100) - tiny, Exact(1, 100)},
                                         certificate::RInterval{Exact(-4, 100), 0}, certificate::RInterval{0, 0}}));
  Body::Primitive ball;
  ball.kind = Body::Primitive::Kind::Sphere;
  ball.radius = Exact(7, 100);
  BOOST_TEST(ci::box_in_primitive(ball, point(Exact(2, 100), Exact(3, 100), Exact(6, 100))));  // 4 + 9 + 36 = 49
  BOOST_TEST(!ci::box_in_primitive(ball, point(Exact(2, 100), Exact(3, 100), Exact(6, 100) + tiny)));

  // Through a body at rest: the level-0 prism's vertex (r, r/5, 0) (where
  // the tangent lines of azimuths (1, 0) and (12/13, 5/13) meet) is in the
  // polyhedron, not in the cylinder.
  Body body;
  body.name = "rod";
  body.primitive = cyl;
  const Vec3E vertex = {Exact(1, 20), Exact(1, 100), 0};
  BOOST_TEST(has(ci::true_shape_error(body, 0, ci::identity_box(), vertex), "not proven inside the true cylinder"));
  BOOST_TEST(ci::true_shape_error(body, 0, ci::identity_box(), Vec3E{Exact(1, 20), 0, 0}).empty());
  Body plain;
  plain.name = "block";
  BOOST_TEST(has(ci::true_shape_error(plain, 0, ci::identity_box(), vertex), "is not a URDF cylinder or sphere"));
}

// The wand's rod turning through a cube: the witness is a true_shape side
// for the rod (its pose enclosed: the joint is away from 0) and a point of
// the cube; accepted; rejected when the point leaves the true cylinder,
// when the rod's side is a point of its polyhedron, or when the levels lie.
BOOST_AUTO_TEST_CASE(wand_collision_certificate_is_checked_on_the_true_shape) {
  const Written w = written("robots/wand-cylinder-collision.json");
  // The rod's check (the ball's, beside it, is safe).
  std::size_t k = 0;
  while (k < w.result.checks.size() && w.result.checks[k].verdict != Verdict::Collision) ++k;
  BOOST_REQUIRE(k < w.result.checks.size());
  BOOST_TEST(w.result.verdict == Verdict::Collision);
  BOOST_TEST(outcome(w, w.certificate) == "ok");
  const json& check = w.certificate["checks"][k];
  BOOST_REQUIRE(check.contains("witness"));
  const json& wit = check["witness"];
  const int rod = wit["a"].contains("true_shape") ? 0 : 1;
  const char* rk = rod == 0 ? "a" : "b";
  const char* ok = rod == 0 ? "b" : "a";
  BOOST_REQUIRE(wit[rk].contains("true_shape"));

  // The cube's point moved to one of its vertices far from the rod.
  json far = w.certificate;
  json& fw = far["checks"][k]["witness"];
  const bool with_point = fw.contains("point");
  if (with_point) {
    fw["point"] = json::array({"0.308", "0.308", "1.025"});  // true shape sides are checked first
  } else {
    const std::size_t n = fw[ok]["weights"].size();
    json ws = json::array();
    for (std::size_t i = 0; i < n; ++i) ws.push_back(i == 0 ? 1 : 0);
    fw[ok]["weights"] = ws;
  }
  const std::string far_out = outcome(w, far);
  BOOST_TEST(has(far_out, "not proven inside the true cylinder"), far_out);

  // The rod's side as a point of its polyhedron (an element with weights).
  json poly = w.certificate;
  const Body& rod_body = w.scene.bodies[rod == 0 ? w.scene.checks[k].first : w.scene.checks[k].second];
  BOOST_REQUIRE(rod_body.primitive);
  json first = json::array({1});
  for (std::size_t i = 1; i < rod_body.pieces[0].vertices.size(); ++i) first.push_back(0);
  poly["checks"][k]["witness"][rk] = {{"element", 0}, {"weights", first}};
  if (!poly["checks"][k]["witness"].contains("point")) poly["checks"][k]["witness"]["point"] = json::array({0, 0, 0});
  const std::string poly_out = outcome(w, poly);
  BOOST_TEST(has(poly_out, "a collision needs a point of its true shape"), poly_out);

  // Levels: beyond the finest, for a body without a primitive, or other
  // than the proofs were written for.
  json beyond = w.certificate;
  beyond["checks"][k]["levels"] = rod == 0 ? json::array({3, 0}) : json::array({0, 3});
  BOOST_TEST(has(outcome(w, beyond), "input error"), outcome(w, beyond));
  json plain = w.certificate;
  plain["checks"][k]["levels"] = rod == 0 ? json::array({0, 1}) : json::array({1, 0});
  BOOST_TEST(has(outcome(w, plain), "has no finer level"), outcome(w, plain));
  json other = w.certificate;
  other["checks"][k]["levels"] = rod == 0 ? json::array({1, 0}) : json::array({0, 1});
  BOOST_TEST(outcome(w, other) != "ok");
}

// Safe checks resting on finer polyhedra: the near misses (a gap of 1% and
// 2% of r, inside the level-0 polyhedra) are certified at the level the
// verifier reached, and the certificate names it; the same proofs read at
// level 0 are rejected.
BOOST_AUTO_TEST_CASE(near_misses_are_certified_on_finer_polyhedra) {
  for (const char* name : {"robots/wand-cylinder-near-miss-safe.json", "robots/wand-sphere-near-miss-safe.json",
                           "robots/wand-sphere-safe.json"}) {
    BOOST_TEST_CONTEXT(name) {
      const Written w = written(name);
      BOOST_TEST(w.result.verdict == Verdict::Safe);
      BOOST_TEST(outcome(w, w.certificate) == "ok");
      bool finer = false;
      for (const json& check : w.certificate["checks"])
        if (check.contains("levels")) finer = true;
      if (std::string(name).find("near-miss") == std::string::npos) continue;
      BOOST_REQUIRE(finer);
      json coarse = w.certificate;
      for (json& check : coarse["checks"]) check.erase("levels");
      BOOST_TEST(outcome(w, coarse) != "ok");
    }
  }
}

BOOST_AUTO_TEST_SUITE_END()
