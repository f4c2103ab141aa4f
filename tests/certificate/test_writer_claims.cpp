// The certificate writer's witness and start-claim helpers
// (src/certificate/writer_check.h): convex weights placing a witness point
// on an element, the elements a feature name stands for, and the ray that
// decides whether a point is inside a solid.
#include "src/certificate/writer_check.h"
#include "src/io/parse.h"

#include <boost/test/unit_test.hpp>

namespace {

using namespace tmcert;
namespace wi = tmcert::certificate::writer_internal;

Vec3E p(const Exact& x, const Exact& y, const Exact& z) { return {x, y, z}; }

std::string data(const std::string& name) { return std::string(TMCERT_TEST_DATA) + "/certificates/" + name; }

}  // namespace

BOOST_AUTO_TEST_SUITE(writer_claims)

BOOST_AUTO_TEST_CASE(weights_by_hand) {
  const std::vector<Vec3E> segment{p(0, 0, 0), p(2, 0, 0)};
  const std::optional<std::vector<Exact>> w = wi::weights_at(segment, wi::kIdentity, p(Exact(1, 2), 0, 0));
  BOOST_REQUIRE(w);
  BOOST_TEST(((*w)[0] == Exact(3, 4) && (*w)[1] == Exact(1, 4)));
  BOOST_TEST(!wi::weights_at(segment, wi::kIdentity, p(3, 0, 0)));            // beyond the end
  BOOST_TEST(!wi::weights_at(segment, wi::kIdentity, p(1, Exact(1, 9), 0)));  // off the line
  const std::vector<Vec3E> triangle{p(0, 0, 0), p(1, 0, 0), p(0, 1, 0)};
  Mat34E shift = wi::kIdentity;
  shift[11] = 5;  // z + 5
  const std::optional<std::vector<Exact>> t = wi::weights_at(triangle, shift, p(Exact(1, 4), Exact(1, 4), 5));
  BOOST_REQUIRE(t);
  BOOST_TEST(((*t)[0] == Exact(1, 2) && (*t)[1] == Exact(1, 4) && (*t)[2] == Exact(1, 4)));
  BOOST_TEST(!wi::weights_at(triangle, wi::kIdentity, p(Exact(1, 4), Exact(1, 4), 5)));
}

BOOST_AUTO_TEST_CASE(feature_names) {
  Body b;
  b.name = "arm";
  b.segments = {{p(0, 0, 0), p(1, 0, 0)}, {p(0, 1, 0), p(1, 1, 0)}};
  b.points = {p(3, 3, 3)};
  BOOST_TEST((wi::named_elements(b, "arm segment 1 end 0") == std::vector<int>{1}));
  BOOST_TEST((wi::named_elements(b, "arm point 0") == std::vector<int>{2}));
  BOOST_TEST(wi::named_elements(b, "arm cylinder 0").empty());  // not a primitive body
  BOOST_TEST(wi::singular(Mat34E{}));
  BOOST_TEST(!wi::singular(wi::kIdentity));
}

BOOST_AUTO_TEST_CASE(inside_and_outside_a_solid) {
  const Scene scene = parse_scene_file(data("solid-outside.json"));
  const Body* solid = nullptr;
  for (const Body& b : scene.bodies)
    if (b.solid) solid = &b;
  BOOST_REQUIRE(solid);
  const std::vector<std::vector<Vec3E>> placed = wi::placed_pieces(*solid, wi::kIdentity);
  BOOST_TEST(placed.size() == solid->pieces.size());
  // The centroid of the solid's vertices is inside (convex solid); a point
  // beyond every vertex is outside.
  Vec3E c{0, 0, 0}, far{0, 0, 0};
  std::size_t n = 0;
  for (const ConvexPiece& piece : solid->pieces)
    for (const Vec3E& x : piece.vertices) {
      for (int i = 0; i < 3; ++i) {
        c[i] += x[i];
        far[i] = std::max(far[i], x[i] + 1);
      }
      ++n;
    }
  for (Exact& x : c) x /= Exact(static_cast<long>(n));
  const auto inside = wi::ray_from(*solid, placed, c);
  BOOST_REQUIRE(inside);
  BOOST_TEST(inside->second);
  const auto outside = wi::ray_from(*solid, placed, far);
  BOOST_REQUIRE(outside);
  BOOST_TEST(!outside->second);
}

BOOST_AUTO_TEST_SUITE_END()
