// Exact static intersection: touching, coplanar, degenerate simplices.
#include "kernels/static_intersection.h"

#include <boost/test/unit_test.hpp>

using namespace tmcert;

namespace {
Vec3E v(long x, long y, long z) { return {Exact(x), Exact(y), Exact(z)}; }
Simplex tri(Vec3E a, Vec3E b, Vec3E c) { return Simplex{3, {a, b, c}}; }
Simplex seg(Vec3E a, Vec3E b) { return Simplex{2, {a, b, b}}; }
Simplex pt(Vec3E a) { return Simplex{1, {a, a, a}}; }

bool on_both(const std::optional<Vec3E>& p, const Simplex& a, const Simplex& b) {
  return p && common_point(pt(*p), a) && common_point(pt(*p), b);
}
}  // namespace

BOOST_AUTO_TEST_SUITE(static_test)

BOOST_AUTO_TEST_CASE(touching_counts_as_contact) {
  const Simplex floor = tri(v(0, 0, 0), v(4, 0, 0), v(0, 4, 0));
  // A vertex exactly on the face.
  const Simplex above = tri(v(1, 1, 0), v(1, 1, 3), v(2, 1, 3));
  BOOST_CHECK(on_both(common_point(above, floor), above, floor));
  // A vertex 1e-17 above: disjoint.
  const Vec3E eps{Exact(1), Exact(1), Exact(1, CGAL::Gmpz("100000000000000000"))};
  const Simplex hover = tri(eps, v(1, 1, 3), v(2, 1, 3));
  BOOST_CHECK(!common_point(hover, floor));
}

BOOST_AUTO_TEST_CASE(crossing_without_vertex_contact) {
  // Two linked triangles: each pierces the other, no vertex in a face.
  const Simplex a = tri(v(-2, 0, -1), v(2, 0, -1), v(0, 0, 3));
  const Simplex b = tri(v(0, -2, 1), v(0, 2, 1), v(0, 0, -3));
  BOOST_CHECK(on_both(common_point(a, b), a, b));
}

BOOST_AUTO_TEST_CASE(coplanar_overlap_and_edge_touch) {
  const Simplex a = tri(v(0, 0, 0), v(2, 0, 0), v(0, 2, 0));
  const Simplex b = tri(v(1, 1, 0), v(3, 1, 0), v(1, 3, 0));  // shares only the point (1,1,0)
  BOOST_CHECK(on_both(common_point(a, b), a, b));
  const Simplex c = tri(v(2, 2, 0), v(4, 2, 0), v(2, 4, 0));
  BOOST_CHECK(!common_point(a, c));
}

BOOST_AUTO_TEST_CASE(degenerate_simplices) {
  const Simplex floor = tri(v(0, 0, 0), v(4, 0, 0), v(0, 4, 0));
  // A triangle collapsed to a segment that pierces the floor.
  const Simplex flat = tri(v(1, 1, -1), v(1, 1, 1), v(1, 1, 0));
  BOOST_CHECK(canonical(flat).count == 2);
  BOOST_CHECK(on_both(common_point(flat, floor), flat, floor));
  // A segment of length zero on the floor's edge.
  const Simplex dot = seg(v(2, 0, 0), v(2, 0, 0));
  BOOST_CHECK(canonical(dot).count == 1);
  BOOST_CHECK(common_point(dot, floor));
  BOOST_CHECK(!common_point(pt(v(3, 3, 0)), floor));
  // Parallel segments, collinear overlapping and disjoint.
  BOOST_CHECK(common_point(seg(v(0, 0, 0), v(2, 0, 0)), seg(v(1, 0, 0), v(5, 0, 0))));
  BOOST_CHECK(!common_point(seg(v(0, 0, 0), v(2, 0, 0)), seg(v(3, 0, 0), v(5, 0, 0))));
  BOOST_CHECK(!common_point(seg(v(0, 0, 0), v(2, 0, 0)), seg(v(0, 1, 0), v(2, 1, 0))));
}

BOOST_AUTO_TEST_SUITE_END()
