// The checker's ray parity test (src/certificate/check_ray.cpp): crossings
// and every degenerate case against hand values.
#include "tests/certificate/check_support.h"
#include "src/certificate/check_ray.h"

using namespace check_test;

BOOST_AUTO_TEST_SUITE(certificate_check)

BOOST_AUTO_TEST_CASE(ray_test) {
  const Scene s = parse_scene_file(data("solid-inside.json"));
  const auto cube = cert::elements(s.bodies[1]);  // the unit cube, identity pose
  auto crossings = [&](const Vec3E& p, const Vec3E& d) { return cert::ray_crossings(cube, p, d); };
  BOOST_TEST((crossings(v("1/2", "1/2", "1/2"), v("1", "1/3", "1/5")) == std::optional<int>(1)));
  BOOST_TEST((crossings(v("2", "1/2", "1/2"), v("-1", "1/3", "1/5")) == std::optional<int>(2)));
  BOOST_TEST((crossings(v("2", "1/2", "1/2"), v("1", "1/3", "1/5")) == std::optional<int>(0)));
  BOOST_TEST(!crossings(v("2", "0", "0"), v("-1", "0", "0")));        // through a vertex
  BOOST_TEST(!crossings(v("2", "0", "0"), v("-1", "0", "1/2")));      // through an edge
  BOOST_TEST(!crossings(v("2", "1/2", "1"), v("-1", "0", "0")));      // in the top face's plane, meeting it
  BOOST_TEST((crossings(v("2", "1/2", "1"), v("1", "0", "0")) == std::optional<int>(0)));  // in the plane, away
  BOOST_TEST(!crossings(v("1", "1/2", "1/2"), v("1", "1/3", "1/5")));  // p on a face
  BOOST_TEST(!crossings(v("1/2", "1/2", "1/2"), v("0", "0", "0")));    // no direction
  BOOST_TEST(!crossings(v("1/2", "1/2", "1/2"), v("1", "1", "1")));    // through a corner from inside
  // A ray in a polygon's plane touching it at one corner only.
  const std::vector<std::vector<Vec3E>> square = {{v("0", "0", "0"), v("1", "0", "0"), v("1", "1", "0"), v("0", "1", "0")}};
  BOOST_TEST(!cert::ray_crossings(square, v("2", "1", "0"), v("-1", "-1", "0")));  // only the corner (1, 0, 0)
  BOOST_TEST(!cert::ray_crossings(square, v("2", "-1", "0"), v("-1", "1", "0")));  // along the diagonal
  BOOST_TEST((cert::ray_crossings(square, v("2", "-1", "0"), v("-1", "3", "0")) == std::optional<int>(0)));
  BOOST_TEST((cert::ray_crossings(square, v("1/2", "1/2", "1"), v("0", "0", "-1")) == std::optional<int>(1)));
  BOOST_TEST((cert::ray_crossings(square, v("1/2", "1/2", "-1"), v("0", "0", "-1")) == std::optional<int>(0)));
  // Flat (singular) images: a polygon squashed onto a segment is degenerate
  // only when the ray meets it.
  const std::vector<std::vector<Vec3E>> flat = {{v("0", "0", "0"), v("1", "0", "0"), v("1", "0", "0"), v("0", "0", "0")}};
  BOOST_TEST(!cert::ray_crossings(flat, v("1/2", "-1", "0"), v("0", "1", "0")));
  BOOST_TEST((cert::ray_crossings(flat, v("1/2", "-1", "1"), v("0", "1", "0")) == std::optional<int>(0)));
  BOOST_TEST((cert::ray_crossings(flat, v("2", "0", "0"), v("1", "0", "0")) == std::optional<int>(0)));
  BOOST_TEST(!cert::ray_crossings(flat, v("2", "0", "0"), v("-1", "0", "0")));
  // Random rational points and directions against the cube's definition:
  // a generic ray crosses an odd number of faces iff the point is strictly
  // inside; points on the surface are always degenerate.
  std::mt19937_64 rng(11);
  auto coordinate = [&](int range) { return Exact(static_cast<int>(rng() % (2 * range + 1)) - range, 4); };
  int generic = 0;
  for (int i = 0; i < 3000; ++i) {
    const Vec3E p{coordinate(6), coordinate(6), coordinate(6)};
    Vec3E d{coordinate(4), coordinate(4), coordinate(4)};
    if (i % 3 == 0) d[rng() % 3] = 0;  // axis-parallel planes: more degenerate cases
    const auto n = crossings(p, d);
    bool inside = true, closed = true;
    for (const Exact& x : p) {
      inside = inside && x > 0 && x < 1;
      closed = closed && x >= 0 && x <= 1;
    }
    const bool on_surface = closed && !inside;
    if (on_surface || (d[0] == 0 && d[1] == 0 && d[2] == 0)) BOOST_TEST(!n);
    if (n) {
      ++generic;
      BOOST_TEST((*n % 2 == 1) == inside, "p " << to_string(p[0]) << " " << to_string(p[1]) << " " << to_string(p[2]));
      BOOST_TEST(*n <= 2);
    }
  }
  BOOST_TEST(generic > 1000);
}

BOOST_AUTO_TEST_SUITE_END()

// The ray test's helpers directly.
BOOST_AUTO_TEST_SUITE(check_ray)

namespace ci = tmcert::certificate::check_internal;

BOOST_AUTO_TEST_CASE(ray_meets_segment_by_hand) {
  const Vec3E o = v("0", "0", "0"), x = v("1", "0", "0");
  BOOST_TEST(ci::ray_meets_segment(o, x, v("2", "-1", "0"), v("2", "1", "0")));    // ahead
  BOOST_TEST(!ci::ray_meets_segment(o, x, v("-2", "-1", "0"), v("-2", "1", "0")));  // behind
  BOOST_TEST(!ci::ray_meets_segment(o, x, v("2", "-1", "1"), v("2", "1", "1")));    // skew
  BOOST_TEST(ci::ray_meets_segment(o, x, v("2", "0", "0"), v("2", "1", "0")));      // through an end
  BOOST_TEST(ci::ray_meets_segment(o, x, v("3", "0", "0"), v("4", "0", "0")));      // on the ray's line, ahead
  BOOST_TEST(!ci::ray_meets_segment(o, x, v("-4", "0", "0"), v("-3", "0", "0")));   // on the line, behind
  BOOST_TEST(ci::ray_meets_segment(o, x, v("-1", "0", "0"), v("1", "0", "0")));     // around p
  BOOST_TEST(ci::ray_meets_segment(o, x, v("0", "0", "0"), v("0", "0", "0")));      // the point p itself
}

BOOST_AUTO_TEST_CASE(shells_and_counts) {
  BOOST_TEST(ci::counts_text({1, 0, 3}) == "1, 0, 3");
  BOOST_TEST(ci::counts_text({}) == "");
  const Case c = load("solid-outside", "solid-outside");
  int solids = 0;
  for (const Body& b : c.scene.bodies) {
    if (!b.solid) continue;
    ++solids;
    const std::vector<int> shells = ci::piece_shells(b);
    BOOST_TEST(shells.size() == b.pieces.size());
    for (int s : shells) BOOST_TEST(s == 0);  // one closed shell
  }
  BOOST_TEST(solids >= 1);
}

BOOST_AUTO_TEST_SUITE_END()
