// The checker's start claims at enclosed poses (src/certificate/
// check_enclosed.h, proofs/certificates.md section 5): the solid-frame box
// of a vertex and the separating axes by hand, and certificates of arms
// with rpy origins (tests/data/scenes/robots, own URDF fixtures) written,
// accepted, and rejected once tampered with.
#include "src/certificate/check_enclosed.h"
#include "src/certificate/check.h"
#include "src/certificate/writer.h"
#include "src/io/parse.h"
#include "src/verify/verify.h"

#include <boost/test/unit_test.hpp>
#include <nlohmann/json.hpp>

namespace {

using namespace tmcert;
using json = nlohmann::json;
namespace ci = tmcert::certificate::check_internal;

Vec3E p(const Exact& x, const Exact& y, const Exact& z) { return {x, y, z}; }

bool inside(const certificate::RBox& b, const Vec3E& x) {
  for (int i = 0; i < 3; ++i)
    if (x[i] < b[i].lo || b[i].hi < x[i]) return false;
  return true;
}

certificate::PoseBox exact_box(const Mat34E& m) {
  certificate::PoseBox b;
  b.center = m;
  for (Exact& r : b.radius) r = 0;
  return b;
}

struct Written {
  Scene scene;
  json certificate;
};

Written written(const std::string& name) {
  Written w{parse_scene_file(std::string(TMCERT_TEST_DATA) + "/scenes/" + name), {}};
  VerifyOptions options;
  options.epsilon = w.scene.epsilon ? *w.scene.epsilon : default_epsilon(w.scene);
  options.max_depth = w.scene.max_depth;
  options.record_cover = true;
  const SceneResult result = verify_scene(w.scene, options);
  w.certificate = json::parse(certificate::certificate_json(w.scene, result));
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

}  // namespace

BOOST_AUTO_TEST_SUITE(check_enclosed)

BOOST_AUTO_TEST_CASE(enclosed_start_boxes_by_hand) {
  // The solid turned about z by an angle with cos = 3/5 + e, sin = 4/5 - e
  // (a box of radius 2^-40 around 3/5, 4/5: the true rotation is any in it),
  // translated by (1, 0, 0); the other body at rest.  Its vertex (2, 0, 0)
  // is (3/5, -4/5, 0) in the solid's frame at the box's centre.
  certificate::PoseBox solid;
  solid.center = {Exact(3, 5), Exact(-4, 5), 0, 1, Exact(4, 5), Exact(3, 5), 0, 0, 0, 0, 1, 0};
  for (Exact& r : solid.radius) r = 0;
  Exact e(1);
  for (int i = 0; i < 40; ++i) e /= 2;  // 2^-40
  for (int k : {0, 1, 4, 5}) solid.radius[k] = e;
  const Mat34E id = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
  const std::optional<certificate::RBox> y = ci::solid_frame_box(solid, std::nullopt, exact_box(id), p(2, 0, 0));
  BOOST_REQUIRE(y);
  BOOST_TEST(inside(*y, p(Exact(3, 5), Exact(-4, 5), 0)));
  for (int i = 0; i < 3; ++i) BOOST_TEST(CGAL::to_double((*y)[i].hi - (*y)[i].lo) < 1e-11);
  // A rotation at an edge of the box: its image is in the box too.
  BOOST_TEST(inside(*y, p(Exact(3, 5) + e, -(Exact(4, 5) - e), 0)));
  // An exact affine pose (scale 2, shift (1, 1, 1)) is inverted exactly.
  const Mat34E scaled = {2, 0, 0, 1, 0, 2, 0, 1, 0, 0, 2, 1};
  const std::optional<certificate::RBox> z = ci::solid_frame_box(exact_box(scaled), scaled, exact_box(id), p(5, 5, 7));
  BOOST_REQUIRE(z);
  BOOST_TEST(((*z)[0].lo == 2 && (*z)[0].hi == 2 && (*z)[1].lo == 2 && (*z)[2].lo == 3 && (*z)[2].hi == 3));
  // A general exact matrix: the box is the single point A^-1 (x - a).
  const Mat34E m = {1, 2, 0, 0, 0, 1, 3, 0, 4, 0, 1, 0};  // det 25
  const Vec3E x = p(1, 2, 3);
  const std::optional<certificate::RBox> w = ci::solid_frame_box(exact_box(m), m, exact_box(id), x);
  BOOST_REQUIRE(w);
  const Vec3E back = ci::place_point(m, ci::box_center(*w));
  BOOST_TEST((back == x));
  BOOST_TEST(!ci::solid_frame_box(exact_box(Mat34E{}), Mat34E{}, exact_box(id), x));  // singular
}

BOOST_AUTO_TEST_CASE(box_clear_of_polygon_by_hand) {
  const std::vector<Vec3E> tri{p(0, 0, 0), p(1, 0, 0), p(0, 1, 0)};
  auto box = [](Exact x0, Exact x1, Exact y0, Exact y1, Exact z0, Exact z1) {
    return certificate::RBox{certificate::RInterval{x0, x1}, certificate::RInterval{y0, y1}, certificate::RInterval{z0, z1}};
  };
  BOOST_TEST(ci::box_clear_of_polygon(box(2, 3, 0, 1, -1, 1), tri));  // beside, along x
  BOOST_TEST(ci::box_clear_of_polygon(box(Exact(1, 10), Exact(2, 10), Exact(1, 10), Exact(2, 10), Exact(1, 2), 1),
                                      tri));  // above (the normal)
  BOOST_TEST(ci::box_clear_of_polygon(box(Exact(6, 10), Exact(7, 10), Exact(6, 10), Exact(7, 10), -1, 1),
                                      tri));  // beyond the hypotenuse (an edge x z)
  BOOST_TEST(!ci::box_clear_of_polygon(box(Exact(1, 10), Exact(2, 10), Exact(1, 10), Exact(2, 10), -1, 1),
                                       tri));  // through it
  BOOST_TEST(!ci::box_clear_of_polygon(box(1, 2, -1, 0, 0, 0), tri));  // touching a vertex (closed sets)
  BOOST_TEST(!ci::box_clear_of_polygon(box(Exact(1, 2), Exact(1, 2), Exact(1, 2), Exact(1, 2), 0, 0),
                                       tri));  // a point on the hypotenuse
  BOOST_TEST((ci::box_center(box(0, 1, 2, 4, -1, 0)) == p(Exact(1, 2), 3, Exact(-1, 2))));
}

// The turned slider (tests/data/scenes/robots/slider-turned.urdf: a fixed
// joint with rpy yaw 1.5707963267948966, so the tool's pose is never
// exact) against a solid block: the certificate's start claim is at an
// enclosed pose; written, accepted, and rejected once tampered with.
BOOST_AUTO_TEST_CASE(enclosed_start_claims_are_checked) {
  for (const char* name : {"robots/slider-turned-safe.json", "robots/slider-turned-collision.json"}) {
    BOOST_TEST_CONTEXT(name) {
      const Written w = written(name);
      BOOST_TEST(outcome(w, w.certificate) == "ok");
      json c = w.certificate;
      bool enclosed = false;
      for (const json& check : c["checks"])
        if (check.contains("start") && !check["start"].empty()) enclosed = true;
      BOOST_REQUIRE(enclosed);
      std::size_t k = 0;
      while (!c["checks"][k].contains("start") || c["checks"][k]["start"].empty()) ++k;
      // No entry: the other body could start inside the solid.
      json dropped = c;
      dropped["checks"][k]["start"] = json::array();
      BOOST_TEST(outcome(w, dropped).find("no claim for the solid") != std::string::npos, outcome(w, dropped));
      // A zero ray is degenerate.
      json zero = c;
      zero["checks"][k]["start"][0]["points"][0]["ray"] = json::array({0, 0, 0});
      BOOST_TEST(outcome(w, zero).find("is degenerate") != std::string::npos, outcome(w, zero));
      // Another scene: the verdict flipped.
      json flipped = c;
      const std::string verdict = flipped["checks"][k]["verdict"];
      flipped["checks"][k]["verdict"] = verdict == "safe" ? "collision" : "safe";
      BOOST_TEST(outcome(w, flipped) != "ok");
    }
  }
}

BOOST_AUTO_TEST_SUITE_END()
