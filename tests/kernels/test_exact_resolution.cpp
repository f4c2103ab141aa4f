// Exact roots (kernels/real_roots.h) and exact first contacts of moving
// features (kernels/moving_contact.h), on hand-made and degenerate cases
// whose answers are known in closed form (proofs/exact-resolution.md).
#include "kernels/moving_contact.h"

#include <boost/test/unit_test.hpp>

#include <cmath>

using namespace tmcert;

namespace {

Exact q(long n, long d = 1) { return Exact(n, d); }

PolyZ z(std::initializer_list<long> c) {
  PolyZ p;
  for (long x : c) p.push_back(Integer(x));
  trim(p);
  return p;
}

PolyZ times(const PolyZ& a, const PolyZ& b) {
  PolyQ x(a.begin(), a.end()), y(b.begin(), b.end());
  return primitive(mul(x, y));
}

// A point with polynomial coordinates (weight 1).
MovingPoint at(PolyQ x, PolyQ y, PolyQ zc) { return MovingPoint{{std::move(x), std::move(y), std::move(zc)}}; }
MovingPoint fixed(Exact x, Exact y, Exact zc) { return at({x}, {y}, {zc}); }
PolyQ lin(Exact c0, Exact c1) {
  PolyQ p{c0, c1};
  trim(p);
  return p;
}
PolyQ cst(Exact c) {
  PolyQ p{c};
  trim(p);
  return p;
}

double value(RealRoot r) {
  refine_to(r, Exact(1, 1 << 30));
  return CGAL::to_double((r.lo + r.hi) / 2);
}

const std::vector<MovingPoint> kTriangle = {fixed(0, 0, 0), fixed(1, 0, 0), fixed(0, 1, 0)};
const PolyQ kOne = {Exact(1)};

}  // namespace

BOOST_AUTO_TEST_SUITE(exact_roots)

BOOST_AUTO_TEST_CASE(rational_and_irrational_roots_in_order) {
  // (3x - 1)(2x - 1)(x^2 - 2) on [0, 2]: 1/3, 1/2, sqrt 2.
  const PolyZ p = times(times(z({-1, 3}), z({-1, 2})), z({-2, 0, 1}));
  std::vector<RealRoot> r = real_roots(p, q(0), q(2));
  BOOST_REQUIRE_EQUAL(r.size(), 3u);
  BOOST_TEST(settle_rational(r[0]));
  BOOST_TEST(r[0].lo == q(1, 3));
  BOOST_TEST(settle_rational(r[1]));
  BOOST_TEST(r[1].lo == q(1, 2));
  BOOST_TEST(!settle_rational(r[2]));
  BOOST_TEST(std::fabs(value(r[2]) - std::sqrt(2.0)) < 1e-9);
  BOOST_TEST(sign_at(z({-2, 0, 1}), r[2]) == CGAL::ZERO);
  BOOST_TEST(sign_at(z({-141421356, 100000000}), r[2]) == CGAL::POSITIVE);
  BOOST_TEST(sign_at(z({-141421357, 100000000}), r[2]) == CGAL::NEGATIVE);
}

BOOST_AUTO_TEST_CASE(closed_interval_ends_count) {
  // Roots exactly at both ends of the interval are included.
  const PolyZ p = times(z({0, 1}), z({-1, 1}));  // x (x - 1)
  std::vector<RealRoot> r = real_roots(p, q(0), q(1));
  BOOST_REQUIRE_EQUAL(r.size(), 2u);
  BOOST_TEST((r[0].is_rational() && r[0].lo == 0));
  BOOST_TEST((r[1].is_rational() && r[1].lo == 1));
  BOOST_TEST(real_roots(p, q(1, 4), q(3, 4)).empty());
}

BOOST_AUTO_TEST_CASE(roots_closer_than_1e_12) {
  // (x - a)(x - a - 1e-13) with a = 1/3: two distinct roots.
  PolyQ f = mul(PolyQ{-q(1, 3), q(1)}, PolyQ{-q(1, 3) - Exact(1, CGAL::Gmpz("10000000000000")), q(1)});
  std::vector<RealRoot> r = real_roots(square_free(primitive(f)), q(0), q(1));
  BOOST_REQUIRE_EQUAL(r.size(), 2u);
  BOOST_TEST(compare(r[0], r[1]) == CGAL::SMALLER);
  BOOST_TEST(settle_rational(r[0]));
  BOOST_TEST(r[0].lo == q(1, 3));
}

BOOST_AUTO_TEST_CASE(double_roots_are_found_once) {
  const PolyZ p = times(times(z({-1, 2}), z({-1, 2})), z({-3, 4}));  // (2x-1)^2 (4x-3)
  const PolyZ s = square_free(p);
  BOOST_TEST(degree(s) == 2);
  BOOST_TEST(real_roots(s, q(0), q(1)).size() == 2u);
}

BOOST_AUTO_TEST_CASE(equal_roots_of_different_polynomials) {
  std::vector<RealRoot> a = real_roots(z({-2, 0, 1}), q(0), q(2));
  std::vector<RealRoot> b = real_roots(times(z({-2, 0, 1}), z({-5, 0, 0, 1})), q(0), q(2));
  BOOST_REQUIRE_EQUAL(a.size(), 1u);
  BOOST_REQUIRE_EQUAL(b.size(), 2u);  // cbrt 5 = 1.71 and sqrt 2
  BOOST_TEST(compare(a[0], b[0]) == CGAL::EQUAL);
  BOOST_TEST(compare(a[0], b[1]) == CGAL::SMALLER);
  BOOST_TEST(compare(b[1], a[0]) == CGAL::LARGER);
}

BOOST_AUTO_TEST_CASE(rational_roots_with_huge_denominators) {
  // (a x - b)(c x - d)(x^2 - 2) with 2100-bit a, b, c, d: settle_rational
  // must narrow below 1 / (2 lc^2), about 2^-8400, which plain bisection
  // cannot do within its 4000-step cap (ExactLimit, i.e. undecided, before
  // the quadratic refinement of refine_to); the irrational root keeps a
  // valid bracket at any width.
  Integer a(1), c(1);
  a <<= 2100;
  c <<= 2101;
  a += 12345;
  c -= 777;
  const Integer b = a / 3 + 1, d = c / 5 * 4 - 1;  // b/a near 1/3, d/c near 4/5
  PolyQ f = mul(mul(PolyQ{-Exact(b), Exact(a)}, PolyQ{-Exact(d), Exact(c)}), PolyQ{q(-2), q(0), q(1)});
  const PolyZ p = primitive(f);
  std::vector<RealRoot> r = real_roots(p, q(0), q(2));
  BOOST_REQUIRE_EQUAL(r.size(), 3u);
  BOOST_TEST(settle_rational(r[0]));
  BOOST_TEST(r[0].lo == Exact(b, a));
  BOOST_TEST(settle_rational(r[1]));
  BOOST_TEST(r[1].lo == Exact(d, c));
  BOOST_TEST(!settle_rational(r[2]));
  Integer tiny(1);
  tiny <<= 9000;
  refine_to(r[2], Exact(Integer(1), tiny));
  BOOST_TEST(r[2].hi - r[2].lo <= Exact(Integer(1), tiny));
  BOOST_TEST(sign_at(p, r[2].lo) == CGAL::NEGATIVE);  // p < 0 just below sqrt 2 (a, c > 0, both roots below)
  BOOST_TEST(sign_at(p, r[2].hi) == CGAL::POSITIVE);
  BOOST_TEST(sign_at(z({-2, 0, 1}), r[2]) == CGAL::ZERO);
}

BOOST_AUTO_TEST_CASE(affine_change_of_variable) {
  // p(u) = u^2 - 1/2 (as 2u^2 - 1); t = 2 + 4u: u = (t - 2) / 4.
  const PolyZ t = compose_affine(z({-1, 0, 2}), q(-1, 2), q(1, 4));
  std::vector<RealRoot> r = real_roots(t, q(2), q(6));
  BOOST_REQUIRE_EQUAL(r.size(), 1u);
  BOOST_TEST(std::fabs(value(r[0]) - (2 + 4 * std::sqrt(0.5))) < 1e-8);
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(moving_contact)

BOOST_AUTO_TEST_CASE(vertex_crosses_face_at_a_cubic_root) {
  // z(u) = u^3 + u - 1 crosses the face z = 0 at u ~ 0.6823 (irrational).
  const MovingPoint v = at({q(1, 4)}, {q(1, 4)}, {q(-1), q(1), q(0), q(1)});
  const ContactSolver s(q(0), q(1));
  std::optional<Contact> c = s.vertex_face(v, kTriangle);
  BOOST_REQUIRE(c);
  BOOST_TEST(!settle_rational(c->t));
  BOOST_TEST(std::fabs(value(c->t) - 0.6823278038280193) < 1e-9);
  const auto box = point_box(*c, kOne);
  BOOST_TEST((box[0][0] <= q(1, 4) && q(1, 4) <= box[0][1]));
  BOOST_TEST((box[2][0] <= 0 && 0 <= box[2][1]));
  BOOST_TEST(CGAL::to_double(box[2][1] - box[2][0]) < 1e-12);
  // Outside the face's triangle at that time: no contact.
  const MovingPoint w = at({q(3, 4)}, {q(3, 4)}, {q(-1), q(1), q(0), q(1)});
  BOOST_TEST(!s.vertex_face(w, kTriangle));
  // The piece ends before the root: no contact in it.
  BOOST_TEST(!ContactSolver(q(0), q(1, 2)).vertex_face(v, kTriangle));
}

BOOST_AUTO_TEST_CASE(vertex_sliding_on_the_face_plane) {
  // In the plane z = 0 throughout, entering the triangle at 2 - 3u = 3/4.
  const ContactSolver s(q(0), q(1));
  std::optional<Contact> c = s.vertex_face(at(lin(q(2), q(-3)), {q(1, 4)}, {}), kTriangle);
  BOOST_REQUIRE(c);
  BOOST_TEST(settle_rational(c->t));
  BOOST_TEST(c->t.lo == q(5, 12));
  // Sliding along, never entering.
  BOOST_TEST(!s.vertex_face(at(lin(q(2), q(-1)), {q(1, 4)}, {}), kTriangle));
  // Inside from the start.
  c = s.vertex_face(at(lin(q(1, 8), q(1, 8)), {q(1, 8)}, {}), kTriangle);
  BOOST_REQUIRE(c);
  BOOST_TEST((c->t.is_rational() && c->t.lo == 0));
}

BOOST_AUTO_TEST_CASE(tangential_grazing_and_near_miss) {
  // z(u) = (u - 1/2)^2: touches the face at u = 1/2 only (a double root).
  const ContactSolver s(q(0), q(1));
  std::optional<Contact> c = s.vertex_face(at({q(1, 4)}, {q(1, 4)}, {q(1, 4), q(-1), q(1)}), kTriangle);
  BOOST_REQUIRE(c);
  BOOST_TEST((c->t.is_rational() && c->t.lo == q(1, 2)));
  // Lifted by 1e-15: no contact.
  const Exact lift(1, CGAL::Gmpz("1000000000000000"));
  BOOST_TEST(!s.vertex_face(at({q(1, 4)}, {q(1, 4)}, {q(1, 4) + lift, q(-1), q(1)}), kTriangle));
}

BOOST_AUTO_TEST_CASE(contact_at_the_ends_of_the_piece) {
  const ContactSolver s(q(0), q(1));
  // z(u) = 1 - u: reaches the face exactly at u = 1.
  std::optional<Contact> c = s.vertex_face(at({q(1, 4)}, {q(1, 4)}, lin(q(1), q(-1))), kTriangle);
  BOOST_REQUIRE(c);
  BOOST_TEST((c->t.is_rational() && c->t.lo == 1));
  // z(u) = u: on the face at u = 0.
  c = s.vertex_face(at({q(1, 4)}, {q(1, 4)}, lin(q(0), q(1))), kTriangle);
  BOOST_REQUIRE(c);
  BOOST_TEST((c->t.is_rational() && c->t.lo == 0));
}

BOOST_AUTO_TEST_CASE(parallel_edges_sliding_along_one_line) {
  const ContactSolver s(q(0), q(1));
  const MovingPoint a0 = fixed(0, 0, 0), a1 = fixed(1, 0, 0);
  // [3 - 2u, 4 - 2u] on the x axis: meets [0, 1] at u = 1.
  std::optional<Contact> c = s.edge_edge(a0, a1, at(lin(q(3), q(-2)), {}, {}), at(lin(q(4), q(-2)), {}, {}));
  BOOST_REQUIRE(c);
  BOOST_TEST((c->t.is_rational() && c->t.lo == 1));
  // Parallel, one unit above: never.
  BOOST_TEST(!s.edge_edge(a0, a1, at(lin(q(3), q(-3)), {}, {q(1)}), at(lin(q(4), q(-3)), {}, {q(1)})));
  // Parallel in one plane, sliding sideways onto the line at y = 1 - 2u = 0.
  c = s.edge_edge(a0, a1, at({q(0)}, lin(q(1), q(-2)), {}), at({q(1)}, lin(q(1), q(-2)), {}));
  BOOST_REQUIRE(c);
  BOOST_TEST((c->t.is_rational() && c->t.lo == q(1, 2)));
}

BOOST_AUTO_TEST_CASE(edges_cross_at_an_irrational_time) {
  // Edge a on the x axis; edge b parallel to y at x = 1/2, height z = u^2 - 1/2.
  const ContactSolver s(q(0), q(1));
  const MovingPoint a0 = fixed(0, 0, 0), a1 = fixed(1, 0, 0);
  const PolyQ h{q(-1, 2), q(0), q(1)};
  std::optional<Contact> c = s.edge_edge(a0, a1, at({q(1, 2)}, {q(-1)}, h), at({q(1, 2)}, {q(1)}, h));
  BOOST_REQUIRE(c);
  BOOST_TEST(!settle_rational(c->t));
  BOOST_TEST(std::fabs(value(c->t) - std::sqrt(0.5)) < 1e-9);
  const auto box = point_box(*c, kOne);
  BOOST_TEST((box[0][0] <= q(1, 2) && q(1, 2) <= box[0][1]));
  BOOST_TEST((box[1][0] <= 0 && 0 <= box[1][1]));
  // The same crossing beside the end of edge a (x = 3/2): no contact.
  BOOST_TEST(!s.edge_edge(a0, a1, at({q(3, 2)}, {q(-1)}, h), at({q(3, 2)}, {q(1)}, h)));
}

BOOST_AUTO_TEST_CASE(collapsing_face_and_coincident_points) {
  const ContactSolver s(q(0), q(1));
  // A triangle in z = 0 whose third vertex passes through the first at
  // u = 1/2 (the face is the segment [0, 1] on the x axis there).  The
  // vertex (1/2, 0, 0) lies on its first edge throughout (the contact
  // polynomial vanishes identically): contact from the start.  The vertex
  // (1/2, 0, 1/4) is coplanar with the face's plane only at u = 1/2, where
  // the face is collapsed and does not hold it: no contact.
  const std::vector<MovingPoint> collapsing = {fixed(0, 0, 0), fixed(1, 0, 0), at({q(0)}, lin(q(1), q(-2)), {})};
  std::optional<Contact> c = s.vertex_face(fixed(q(1, 2), 0, 0), collapsing);
  BOOST_REQUIRE(c);
  BOOST_TEST((c->t.is_rational() && c->t.lo == 0));
  BOOST_TEST(!s.vertex_face(fixed(q(1, 2), 0, q(1, 4)), collapsing));
  // Two points meeting at u = 1/3 (x = 3u - 1) and points equal throughout.
  c = s.vertex_vertex(at(lin(q(-1), q(3)), {}, {}), fixed(0, 0, 0));
  BOOST_REQUIRE(c);
  BOOST_TEST(settle_rational(c->t));
  BOOST_TEST(c->t.lo == q(1, 3));
  c = s.vertex_vertex(fixed(1, 2, 3), fixed(1, 2, 3));
  BOOST_REQUIRE(c);
  BOOST_TEST(c->t.lo == 0);
  // Points passing each other in different planes: never.
  BOOST_TEST(!s.vertex_vertex(at(lin(q(-1), q(3)), {}, {q(1)}), fixed(0, 0, 0)));
}

BOOST_AUTO_TEST_CASE(far_from_the_origin_with_small_motions) {
  // The triangle and vertex translated by 1e8, the vertex moving by 1e-6:
  // z(u) = 1e-6 (u^3 + u - 1) crosses at the same irrational time.
  const Exact far(100000000), small(1, 1000000);
  const std::vector<MovingPoint> tri = {fixed(far, far, far), fixed(far + 1, far, far), fixed(far, far + 1, far)};
  const MovingPoint v = at({far + q(1, 4)}, {far + q(1, 4)}, {far - small, small, q(0), small});
  std::optional<Contact> c = ContactSolver(q(0), q(1)).vertex_face(v, tri);
  BOOST_REQUIRE(c);
  BOOST_TEST(std::fabs(value(c->t) - 0.6823278038280193) < 1e-9);
}

BOOST_AUTO_TEST_SUITE_END()

// ------------------------------------------------------------------ regression scenes

#include "src/io/parse.h"
#include "src/verify/verify.h"

namespace {

CheckResult verified(const std::string& name) {
  const Scene scene = parse_scene_file(std::string(TMCERT_TEST_DATA) + "/scenes/" + name);
  VerifyOptions options;
  options.epsilon = scene.epsilon ? *scene.epsilon : default_epsilon(scene);
  options.max_depth = scene.max_depth;
  return verify_scene(scene, options).checks[0];
}

// The scene parameter of an algebraic witness, to about 1e-12.
double witness_time(const CheckResult& r) {
  const AlgebraicTime& a = *r.witness->root;
  PolyZ p(a.root_of.begin(), a.root_of.end());
  RealRoot root{p, a.lo, a.hi};
  refine_to(root, Exact(Integer(1), Integer(1) << 50));
  return CGAL::to_double((root.lo + root.hi) / 2);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(exact_resolution_scenes)

// Hard cases with their exact first contacts known in closed form
// (tests/data/scenes; EXPECTED holds their verdicts for the CLI).
BOOST_AUTO_TEST_CASE(first_contacts_are_exact) {
  for (const char* name : {"cubic-crossing-irrational.json", "far-cubic-crossing.json"}) {
    BOOST_TEST_CONTEXT(name) {
      const CheckResult r = verified(name);
      BOOST_REQUIRE(r.verdict == Verdict::Collision);
      BOOST_REQUIRE(r.witness->root);
      BOOST_TEST(r.first_contact_exact);
      BOOST_TEST(std::fabs(witness_time(r) - 0.6823278038280193) < 1e-12);  // u^3 + u - 1 = 0
    }
  }
  {
    const CheckResult r = verified("edges-cross-at-sqrt-half.json");
    BOOST_REQUIRE(r.verdict == Verdict::Collision);
    BOOST_REQUIRE(r.witness->root);
    BOOST_TEST(std::fabs(witness_time(r) - std::sqrt(0.5)) < 1e-12);
    // The point box holds (1/2, 0, 0).
    BOOST_TEST(((*r.witness->point_box)[0][0] <= q(1, 2) && q(1, 2) <= (*r.witness->point_box)[0][1]));
    BOOST_TEST(((*r.witness->point_box)[1][0] <= 0 && 0 <= (*r.witness->point_box)[1][1]));
  }
  for (const auto& [name, t] : {std::pair{"vertex-sliding-into-face.json", q(5, 12)},
                                std::pair{"parallel-edges-sliding.json", q(4, 5)}}) {
    BOOST_TEST_CONTEXT(name) {
      const CheckResult r = verified(name);
      BOOST_REQUIRE(r.verdict == Verdict::Collision);
      BOOST_TEST(!r.witness->root);
      BOOST_TEST(r.witness->t == t);
      BOOST_TEST(r.first_contact_exact);
      BOOST_TEST((r.first_contact->first == t && r.first_contact->second == t));
    }
  }
  for (const char* name : {"vertex-sliding-beside-face.json", "parallel-edges-passing.json", "hover-1e-17.json"})
    BOOST_TEST(verified(name).verdict == Verdict::Safe, name);
}

BOOST_AUTO_TEST_SUITE_END()
