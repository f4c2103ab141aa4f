// src/certificate/exact_claims: whether two exact elements (a point, a
// segment, a convex polygon, possibly collapsed) share a point, decided
// exactly, touching included (no_contact_error is exercised through the
// checker: tests/certificate/test_check*.cpp).
#include "src/certificate/exact_claims.h"

#include <boost/test/unit_test.hpp>

#include <vector>

using namespace tmcert;
using certificate::elements_meet;

namespace {

Vec3E v(const Exact& x, const Exact& y, const Exact& z) { return {x, y, z}; }

// The unit square in the plane z = h.
std::vector<Vec3E> square(const Exact& h) { return {v(0, 0, h), v(1, 0, h), v(1, 1, h), v(0, 1, h)}; }

}  // namespace

BOOST_AUTO_TEST_SUITE(exact_claims)

BOOST_AUTO_TEST_CASE(points) {
  BOOST_TEST(elements_meet({v(1, 2, 3)}, {v(1, 2, 3)}));
  BOOST_TEST(!elements_meet({v(1, 2, 3)}, {v(1, 2, Exact(3) + Exact(1, 1000000000))}));
}

BOOST_AUTO_TEST_CASE(point_and_segment) {
  const std::vector<Vec3E> seg = {v(0, 0, 0), v(2, 2, 2)};
  BOOST_TEST(elements_meet({v(Exact(1, 3), Exact(1, 3), Exact(1, 3))}, seg));
  BOOST_TEST(elements_meet(seg, {v(2, 2, 2)}));                      // an end
  BOOST_TEST(!elements_meet({v(3, 3, 3)}, seg));                     // on the line, past the end
  BOOST_TEST(!elements_meet({v(1, 1, Exact(1) + Exact(1, 1000))}, seg));  // off the line
}

BOOST_AUTO_TEST_CASE(segments) {
  const std::vector<Vec3E> a = {v(0, 0, 0), v(2, 0, 0)};
  BOOST_TEST(elements_meet(a, {v(1, -1, 0), v(1, 1, 0)}));             // crossing
  BOOST_TEST(elements_meet(a, {v(2, 0, 0), v(3, 5, 7)}));              // sharing an end
  BOOST_TEST(elements_meet(a, {v(1, 0, 0), v(5, 0, 0)}));              // overlapping, collinear
  BOOST_TEST(!elements_meet(a, {v(3, 0, 0), v(5, 0, 0)}));             // collinear, apart
  BOOST_TEST(!elements_meet(a, {v(1, -1, Exact(1, 1000)), v(1, 1, Exact(1, 1000))}));  // skew
  BOOST_TEST(!elements_meet(a, {v(0, 1, 0), v(2, 1, 0)}));             // parallel
}

BOOST_AUTO_TEST_CASE(polygons) {
  const std::vector<Vec3E> sq = square(0);
  BOOST_TEST(elements_meet(sq, {v(Exact(1, 2), Exact(1, 2), 0)}));        // a point inside
  BOOST_TEST(elements_meet(sq, {v(1, 1, 0)}));                            // a corner
  BOOST_TEST(!elements_meet(sq, {v(Exact(1, 2), Exact(1, 2), Exact(1, 10))}));  // above
  BOOST_TEST(elements_meet(sq, {v(Exact(1, 2), Exact(1, 2), -1), v(Exact(1, 2), Exact(1, 2), 1)}));  // piercing
  BOOST_TEST(!elements_meet(sq, {v(2, 2, -1), v(2, 2, 1)}));              // piercing the plane outside
  BOOST_TEST(elements_meet(sq, square(0)));
  BOOST_TEST(!elements_meet(sq, square(Exact(1, 1000))));                // parallel, apart
  // A triangle standing on the square's edge, and one just beside it.
  BOOST_TEST(elements_meet(sq, {v(0, 1, 0), v(1, 1, 0), v(Exact(1, 2), 1, 1)}));
  BOOST_TEST(!elements_meet(sq, {v(0, Exact(1001, 1000), 0), v(1, Exact(1001, 1000), 0), v(Exact(1, 2), 1, 1)}));
  // A polygon collapsed onto a segment behaves as that segment.
  const std::vector<Vec3E> flat = {v(0, 0, 1), v(1, 0, 1), v(2, 0, 1)};
  BOOST_TEST(elements_meet(flat, {v(Exact(3, 2), -1, 1), v(Exact(3, 2), 1, 1)}));
  BOOST_TEST(!elements_meet(flat, {v(Exact(5, 2), -1, 1), v(Exact(5, 2), 1, 1)}));
}

BOOST_AUTO_TEST_SUITE_END()
