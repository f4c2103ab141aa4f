// The checker's separation test (src/certificate/check_separation.h): the
// integer evaluation paths against exact rationals, and the separation
// claim with and without margins against hand values.
#include "tests/certificate/check_support.h"
#include "src/certificate/check_separation.h"
#include <random>

using namespace check_test;

BOOST_AUTO_TEST_SUITE(certificate_check)

BOOST_AUTO_TEST_CASE(integer_evaluation_paths_agree) {
  // min over points of alpha . x: the multi-limb path, the GMP path and a
  // plain rational reference agree, for small and for huge coefficients
  // (up to the 8-limb limit and beyond) and coordinates.
  std::mt19937_64 rng(5);
  auto big = [&](int digits) {
    std::string s = (rng() % 2) ? "-" : "";
    s += std::to_string(1 + rng() % 9);
    for (int i = 1; i < digits; ++i) s += static_cast<char>('0' + rng() % 10);
    if (rng() % 2) s += "/" + std::to_string(1 + rng() % 1000000007);
    return q(s);
  };
  for (int trial = 0; trial < 400; ++trial) {
    const int digits = 1 + static_cast<int>(rng() % 150);  // up to ~500 bits
    const std::array<Exact, 3> alpha{big(digits), big(1 + rng() % digits), rng() % 5 == 0 ? Exact(0) : big(digits)};
    std::vector<Vec3E> points;
    const int coord_digits = trial % 4 == 0 ? 25 : 1 + static_cast<int>(rng() % 8);
    for (int i = 0; i < 1 + static_cast<int>(rng() % 40); ++i) {
      Vec3E p;
      for (Exact& x : p) x = Exact(big(1 + rng() % coord_digits).numerator(), CGAL::Gmpz(rng() % 2 ? 1 : 1000));
      points.push_back(p);
    }
    Exact reference;
    for (std::size_t i = 0; i < points.size(); ++i) {
      const Exact x = alpha[0] * points[i][0] + alpha[1] * points[i][1] + alpha[2] * points[i][2];
      if (i == 0 || x < reference) reference = x;
    }
    BOOST_TEST(cert::detail::min_dot_for_testing(alpha, points, 2) == reference);
    BOOST_TEST(cert::detail::min_dot_for_testing(alpha, points, 0) == reference);
    try {
      BOOST_TEST(cert::detail::min_dot_for_testing(alpha, points, 1) == reference);
    } catch (const std::logic_error&) {
      // does not fit the limbs: the automatic path used GMP above
    }
  }
  // Extremes of the limb path: coefficients just below 2^480, coordinates
  // just below 2^62, all signs.
  CGAL::Gmpz p480 = 1, p62 = 1;
  for (int i = 0; i < 480; ++i) p480 *= 2;
  for (int i = 0; i < 62; ++i) p62 *= 2;
  const Exact a = Exact(p480 - 1), x = Exact(p62 - 1);
  const std::vector<Vec3E> corners = {{x, x, x}, {-x, x, -x}, {x, -x, x}, {-x, -x, -x}, {0, 0, 0}};
  for (const std::array<Exact, 3>& alpha :
       {std::array<Exact, 3>{a, a, a}, std::array<Exact, 3>{-a, a, -a}, std::array<Exact, 3>{a, Exact(0), -a}}) {
    Exact reference;
    for (std::size_t i = 0; i < corners.size(); ++i) {
      const Exact val = alpha[0] * corners[i][0] + alpha[1] * corners[i][1] + alpha[2] * corners[i][2];
      if (i == 0 || val < reference) reference = val;
    }
    BOOST_TEST(cert::detail::min_dot_for_testing(alpha, corners, 1) == reference);
    BOOST_TEST(cert::detail::min_dot_for_testing(alpha, corners, 2) == reference);
  }
}

BOOST_AUTO_TEST_CASE(huge_coordinates_use_the_gmp_path) {
  // The probe scene shifted by 10^30 + 1/3 in x: vertex coordinates no
  // longer fit 62 bits over their common denominator.  The certificate's
  // z-directions still hold; a flipped one still fails.
  const std::string shifted = R"({"format": "tmcert-scene/1", "bodies": [
    { "name": "probe", "segments": [ [["1000000000000000000000000000000.3", 0, 0], ["1000000000000000000000000000000.3", 0, "1/2"]] ],
      "points": [ ["1000000000000000000000000000000.3", 0, 0] ],
      "motion": { "type": "rational_bezier", "control_points": [
          [[1, 0, 0, "1/3"], [0, 1, 0, "1/4"], [0, 0, 1, 1]],
          [[1, 0, 0, "1/3"], [0, 1, 0, "1/4"], [0, 0, 1, "1/2"]],
          [[1, 0, 0, "1/3"], [0, 1, 0, "1/4"], [0, 0, 1, "1/2"]] ] } },
    { "name": "tri", "polygons": [ [["1e30", 0, 0], ["1.000000000000000000000000000001e30", 0, 0], ["1e30", 1, 0]] ] } ],
    "checks": [ ["probe", "tri"] ] })";
  Case c{parse_scene_text(shifted, "shifted.json"), cert::read_certificate_file(data("probe-safe.cert.json"))};
  check0(c)["pieces"][1]["proof"]["parts"][1]["sep"] = json::array({"0", "0", "1"});
  BOOST_TEST(check(c).ok, check(c).message);
  check0(c)["pieces"][2]["proof"]["sep"] = json::array({"0", "1/1000000000000000000000000000001", "-1"});
  expect_rejected(c, "pieces[2] [1/2, 1]: proof (groups 0, 0): separation fails at control point 0");
}

BOOST_AUTO_TEST_SUITE_END()

// The separation test's pieces directly, against hand values.
BOOST_AUTO_TEST_SUITE(check_separation)

namespace ci = tmcert::certificate::check_internal;

BOOST_AUTO_TEST_CASE(integer_coordinates_by_hand) {
  const ci::Coords c = ci::make_coords({v("1/2", "1/3", "0"), v("1", "0", "-1/6")});
  BOOST_TEST(mpz_get_si(c.D.v) == 6);
  const long X[6] = {3, 2, 0, 6, 0, -1};
  BOOST_REQUIRE(c.fits64);
  for (int i = 0; i < 6; ++i) BOOST_TEST(c.X64[i] == X[i]);
  const ci::Coords big = ci::make_coords({v("4611686018427387904", "0", "0")});  // 2^62
  BOOST_TEST(!big.fits64);
}

// Body a has vertices at x = 2, 3, body b at x = 0, 1; both fixed (one
// joint control point, the identity for both, weight 1).
struct TwoBodies {
  ci::Coords ca = ci::make_coords({v("2", "0", "0"), v("3", "0", "0")});
  ci::Coords cb = ci::make_coords({v("0", "0", "0"), v("1", "0", "0")});
  std::vector<std::uint32_t> ids{0, 1};
  ci::SeparationPiece piece;
  ci::Z dadb;
  ci::SeparationScratch scratch;
  TwoBodies() {
    ci::CP c;
    const Mat34E id = ci::identity_pose();
    for (int e = 0; e < 12; ++e) c[e] = c[12 + e] = id[e];
    c[24] = 1;
    piece.ints = ci::integer_control_points({c});
    mpz_mul(dadb.v, ca.D.v, cb.D.v);
  }
  std::optional<std::size_t> fails(const Vec3E& n, const Exact& margin) {
    piece.margins = margin > 0;
    return ci::separation_fails_at(n, ids, ca, ids, cb, piece, dadb, margin, scratch);
  }
};

BOOST_AUTO_TEST_CASE(separation_claims_by_hand) {
  TwoBodies t;
  BOOST_TEST(!t.fails(v("1", "0", "0"), 0).has_value());        // min over a (2) > max over b (1)
  BOOST_TEST(!t.fails(v("1/1000", "0", "0"), 0).has_value());   // any positive multiple
  BOOST_TEST((t.fails(v("-1", "0", "0"), 0) == std::size_t{0}));        // the wrong way
  BOOST_TEST((t.fails(v("0", "1", "0"), 0) == std::size_t{0}));         // a gap of 0 is no separation
  // With a margin: the gap (1 per unit direction) must exceed |n| margin.
  BOOST_TEST(!t.fails(v("1", "0", "0"), Exact(1, 2)).has_value());
  BOOST_TEST((t.fails(v("1", "0", "0"), Exact(1)) == std::size_t{0}));   // strict
  BOOST_TEST(!t.fails(v("3", "4", "0"), Exact(1, 10)).has_value());  // gap 3 > 5 / 10
  BOOST_TEST((t.fails(v("3", "4", "0"), Exact(3, 5)) == std::size_t{0}));    // gap 3 = 5 * 3/5
}

BOOST_AUTO_TEST_CASE(separation_with_a_penalty_by_hand) {
  // The pose boxes' radii as a penalty: sum_i |n_i| penalty_i must be below
  // the gap (1 for n = (1, 0, 0)).
  TwoBodies t;
  t.piece.margins = true;
  t.piece.penalty = {Exact(1, 2), Exact(7), Exact(7)};
  mpz_set_ui(t.piece.penalty_den.v, 2);
  mpz_set_ui(t.piece.penalty_num[0].v, 1);
  mpz_set_ui(t.piece.penalty_num[1].v, 14);
  mpz_set_ui(t.piece.penalty_num[2].v, 14);
  BOOST_TEST(!ci::separation_fails_at(v("1", "0", "0"), t.ids, t.ca, t.ids, t.cb, t.piece, t.dadb, 0, t.scratch).has_value());
  t.piece.penalty[0] = 1;
  mpz_set_ui(t.piece.penalty_num[0].v, 2);
  BOOST_TEST((ci::separation_fails_at(v("1", "0", "0"), t.ids, t.ca, t.ids, t.cb, t.piece, t.dadb, 0, t.scratch) == std::size_t{0}));
}

BOOST_AUTO_TEST_CASE(components_by_hand) {
  Body b;
  b.segments = {{v("0", "0", "0"), v("1", "0", "0")},
                {v("1", "0", "0"), v("2", "0", "0")},
                {v("5", "0", "0"), v("6", "0", "0")}};
  b.points = {v("2", "0", "0")};
  std::unique_ptr<ci::BodyData> d = ci::make_body_data(b);
  BOOST_TEST(d->vertices.size() == 5u);  // 0, 1, 2, 5, 6
  const std::vector<std::size_t>& comp = ci::components(*d);
  BOOST_TEST((comp == std::vector<std::size_t>{0, 0, 2, 0}));
}

BOOST_AUTO_TEST_CASE(weights_must_be_positive) {
  ci::CP c;
  for (Exact& x : c) x = 0;
  BOOST_CHECK_THROW(ci::integer_control_points({c}), std::logic_error);
}

BOOST_AUTO_TEST_SUITE_END()
