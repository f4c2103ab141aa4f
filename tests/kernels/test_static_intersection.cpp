// Exact static intersection: touching, coplanar, degenerate simplices.
#include "kernels/static_intersection.h"

#include <boost/test/unit_test.hpp>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/intersections.h>

#include <random>

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

// common_point decides with its own filtered predicates and builds one
// point; CGAL's exact do_intersect is the reference for the decision, and
// the point must lie on both simplices (CGAL's exact has_on).  Small integer
// and half-integer coordinates make coplanar, collinear, touching and
// overlapping configurations frequent; a third of the cases put a point of
// one simplex exactly on the other.
BOOST_AUTO_TEST_CASE(agrees_with_cgal_on_random_degenerate_configurations) {
  using K = CGAL::Simple_cartesian<Exact>;
  auto to_point = [](const Vec3E& p) { return K::Point_3(p[0], p[1], p[2]); };
  auto reference = [&](const Simplex& a0, const Simplex& b0) {
    const Simplex a = canonical(a0), b = canonical(b0);
    auto shape = [&](const Simplex& s, auto&& f) {
      if (s.count == 1) return f(to_point(s.p[0]));
      if (s.count == 2) return f(K::Segment_3(to_point(s.p[0]), to_point(s.p[1])));
      return f(K::Triangle_3(to_point(s.p[0]), to_point(s.p[1]), to_point(s.p[2])));
    };
    return shape(a, [&](const auto& x) {
      return shape(b, [&](const auto& y) {
        if constexpr (std::is_same_v<std::decay_t<decltype(x)>, K::Point_3> &&
                      std::is_same_v<std::decay_t<decltype(y)>, K::Point_3>)
          return x == y;
        else
          return CGAL::do_intersect(x, y);
      });
    });
  };
  auto on = [&](const Vec3E& p, const Simplex& s0) {
    const Simplex s = canonical(s0);
    if (s.count == 1) return p == s.p[0];
    if (s.count == 2) return K::Segment_3(to_point(s.p[0]), to_point(s.p[1])).has_on(to_point(p));
    return K::Triangle_3(to_point(s.p[0]), to_point(s.p[1]), to_point(s.p[2])).has_on(to_point(p));
  };
  std::mt19937 gen(20261123);
  auto coord = [&] { return Exact(std::uniform_int_distribution<int>(-4, 4)(gen), 2); };
  auto point = [&] { return Vec3E{coord(), coord(), coord()}; };
  int hits = 0, total = 0;
  for (int iter = 0; iter < 30000; ++iter) {
    Simplex a, b;
    a.count = std::uniform_int_distribution<int>(1, 3)(gen);
    b.count = std::uniform_int_distribution<int>(1, 3)(gen);
    for (int k = 0; k < 3; ++k) a.p[k] = point(), b.p[k] = point();
    if (iter % 3 == 0) {  // a point of a (a rational convex combination) as a vertex of b
      const Exact w0(std::uniform_int_distribution<int>(0, 4)(gen), 4);
      const Exact w1 = (1 - w0) * Exact(std::uniform_int_distribution<int>(0, 3)(gen), 3);
      const Exact w2 = a.count == 3 ? 1 - w0 - w1 : Exact(0);
      const Exact v1 = a.count == 3 ? w1 : 1 - w0;
      Vec3E q;
      for (int c = 0; c < 3; ++c) q[c] = w0 * a.p[0][c] + v1 * a.p[1 % a.count][c] + w2 * a.p[2 % a.count][c];
      b.p[std::uniform_int_distribution<int>(0, b.count - 1)(gen)] = q;
    }
    for (int k = a.count; k < 3; ++k) a.p[k] = a.p[a.count - 1];
    for (int k = b.count; k < 3; ++k) b.p[k] = b.p[b.count - 1];
    const std::optional<Vec3E> p = common_point(a, b);
    const bool expected = reference(a, b);
    ++total;
    hits += expected;
    BOOST_TEST_REQUIRE(p.has_value() == expected, "case " << iter << ": counts " << a.count << ", " << b.count);
    if (p) BOOST_TEST_REQUIRE((on(*p, a) && on(*p, b)), "case " << iter);
    // Symmetric.
    BOOST_TEST_REQUIRE(common_point(b, a).has_value() == expected, "case " << iter << " swapped");
  }
  BOOST_TEST(hits > total / 5);
  BOOST_TEST(hits < total * 4 / 5);
}

BOOST_AUTO_TEST_SUITE_END()
