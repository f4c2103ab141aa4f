// src/model/mass: the exact moment matrix, its positive definiteness (the
// interval test and the exact decision agree), and the default mass
// distribution (vertices with weight 1, offset points added when they are
// flat, by a tenth of the body's size).
#include "src/model/mass.h"

#include <boost/test/unit_test.hpp>

#include <string>
#include <vector>

using namespace tmcert;

namespace {

bool refused(const MassDistribution& m) {
  try {
    require_positive_definite(m);
    return false;
  } catch (const InputError& e) {
    BOOST_TEST(std::string(e.what()).rfind("moment matrix", 0) == 0u);
    return true;
  }
}

MassDistribution unit_weights(const std::vector<Vec3E>& points) {
  MassDistribution m;
  m.points = points;
  m.weights.assign(points.size(), Exact(1));
  return m;
}

const std::vector<Vec3E> kTetrahedron = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};

}  // namespace

BOOST_AUTO_TEST_SUITE(mass)

BOOST_AUTO_TEST_CASE(moment_matrix_exact) {
  MassDistribution m;
  m.points = {{1, 2, 3}, {1, 2, 3}, {Exact(1, 3), 0, -1}};
  m.weights = {Exact(1, 2), Exact(1, 4), 2};
  const Mat44E g = moment_matrix(m);
  // G[r][c] = sum w h_r h_c, h = (p, 1); the repeated point counts with weight 3/4.
  auto h = [](const Vec3E& p, int r) { return r < 3 ? p[r] : Exact(1); };
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) {
      const Exact expected = Exact(3, 4) * h(m.points[0], r) * h(m.points[0], c) + 2 * h(m.points[2], r) * h(m.points[2], c);
      BOOST_TEST(g[4 * r + c] == expected);
    }
}

BOOST_AUTO_TEST_CASE(inverse_when_positive_definite) {
  const Mat44E g = moment_matrix(unit_weights(kTetrahedron));
  Mat44E inv;
  BOOST_REQUIRE(invert_positive_definite(g, inv));
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) {
      Exact s = 0;
      for (int k = 0; k < 4; ++k) s += g[4 * r + k] * inv[4 * k + c];
      BOOST_TEST(s == Exact(r == c ? 1 : 0));
    }
  Mat44E negative = {};
  negative[0] = -1;
  negative[5] = negative[10] = negative[15] = 1;
  BOOST_TEST(!invert_positive_definite(negative, inv));
}

BOOST_AUTO_TEST_CASE(positive_definite_iff_not_flat) {
  BOOST_TEST(!refused(unit_weights(kTetrahedron)));
  BOOST_TEST(refused(unit_weights({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}})));  // a plane
  BOOST_TEST(refused(unit_weights({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}})));              // a line
  BOOST_TEST(refused(unit_weights({{5, 5, 5}})));                                   // a point
  // Off the plane by 10^-30 (near where the interval test gives way to the exact one).
  BOOST_TEST(!refused(unit_weights({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, Exact(1, CGAL::Gmpz("1" + std::string(30, '0')))}})));
}

BOOST_AUTO_TEST_CASE(default_mass_of_solid_and_flat_sets) {
  const MassDistribution solid = default_mass(kTetrahedron, 1);
  BOOST_TEST((solid.points == kTetrahedron));
  BOOST_TEST((solid.weights == std::vector<Exact>(4, Exact(1))));
  // A unit square in z = 0: two points off it along z, by a tenth of its size, at the centroid.
  const std::vector<Vec3E> square = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const MassDistribution flat = default_mass(square, 7);
  BOOST_REQUIRE(flat.points.size() == 6u);
  BOOST_TEST((flat.points[4] == Vec3E{Exact(1, 2), Exact(1, 2), Exact(1, 10)}));
  BOOST_TEST((flat.points[5] == Vec3E{Exact(1, 2), Exact(1, 2), Exact(-1, 10)}));
  BOOST_TEST(!refused(flat));
  // A segment along x of length 2: four points, along y and z.
  const MassDistribution line = default_mass({{0, 0, 0}, {2, 0, 0}}, 7);
  BOOST_TEST(line.points.size() == 6u);
  BOOST_TEST(!refused(line));
  // A single point: the fallback size (7), six points around it.
  const MassDistribution point = default_mass({{1, 1, 1}}, 7);
  BOOST_REQUIRE(point.points.size() == 7u);
  BOOST_TEST((point.points[1] == Vec3E{Exact(1) + Exact(7, 10), 1, 1}));
  BOOST_TEST(!refused(point));
  BOOST_TEST(default_mass({}, 1).points.empty());
}

BOOST_AUTO_TEST_CASE(fallback_size_is_the_scene_extent) {
  std::vector<Body> bodies(2);
  BOOST_TEST(default_mass_fallback_size(bodies) == 1);
  bodies[0].points = {{0, 0, 0}};
  BOOST_TEST(default_mass_fallback_size(bodies) == 1);  // zero extent
  bodies[1].segments.push_back({Vec3E{0, -3, 0}, Vec3E{1, 2, Exact(1, 2)}});
  BOOST_TEST(default_mass_fallback_size(bodies) == 5);
  bodies[0].polygons.push_back({{0, 0, 0}, {0, 0, 9}, {0, 1, 9}});
  BOOST_TEST(default_mass_fallback_size(bodies) == 9);
}

BOOST_AUTO_TEST_SUITE_END()
