// The certificate writer's proofs (src/certificate/writer_prover.h): a
// separating direction is found and certified for separated groups, a
// split where only the children separate, and nothing for elements that
// touch (where the exact "no contact" claim is refused too).
#include "src/certificate/writer_prover.h"
#include "src/certificate/check.h"

#include <boost/test/unit_test.hpp>

namespace {

using namespace tmcert;
namespace wi = tmcert::certificate::writer_internal;

Vec3E p(int x, int y, int z) { return {Exact(x), Exact(y), Exact(z)}; }

// One joint control point: both bodies at rest (identity), weight 1.
wi::CurveE fixed_curve() {
  wi::CurveE c(1);
  const Mat34E id = wi::kIdentity;
  for (int e = 0; e < 12; ++e) c[0][e] = c[0][12 + e] = id[e];
  c[0][wi::kWeight] = 1;
  return c;
}

struct Proof {
  Body a, b;
  certificate::WriteStats stats;
  std::optional<nlohmann::json> run() {
    const wi::BodyGroups ga(a), gb(b);
    const wi::Prover prover(ga, gb, stats);
    prover.no_contact = [](int, int) { return false; };
    const wi::CurveE exact = fixed_curve();
    const wi::PieceImages im = prover.images(enclose(exact));
    const std::optional<int> node = prover.prove(im, [&]() -> const wi::CurveE& { return exact; }, 0, 0);
    if (!node) return std::nullopt;
    return prover.nodes.expand(*node);
  }
};

}  // namespace

BOOST_AUTO_TEST_SUITE(writer_prover)

BOOST_AUTO_TEST_CASE(separated_bodies_get_one_plane) {
  Proof t;
  t.a.segments = {{p(2, 0, 0), p(3, 1, 0)}};
  t.b.segments = {{p(0, 0, 0), p(1, 1, 0)}};
  const std::optional<nlohmann::json> proof = t.run();
  BOOST_REQUIRE(proof);
  BOOST_TEST(proof->contains("sep"), proof->dump());
  BOOST_TEST(t.stats.separations == 1u);
}

BOOST_AUTO_TEST_CASE(groups_that_do_not_separate_are_split) {
  // a: two points left and right of b's point; no plane separates a's
  // group from b, each of a's points does.
  Proof t;
  t.a.points = {p(-1, 0, 0), p(1, 0, 0)};
  t.b.points = {p(0, 0, 0)};
  const std::optional<nlohmann::json> proof = t.run();
  BOOST_REQUIRE(proof);
  BOOST_TEST((*proof)["split"] == 0, proof->dump());
  BOOST_TEST((*proof)["parts"].size() == 2u);
  BOOST_TEST(t.stats.separations == 2u);
}

BOOST_AUTO_TEST_CASE(touching_elements_have_no_proof) {
  Proof t;
  t.a.segments = {{p(0, 0, 0), p(2, 0, 0)}};
  t.b.segments = {{p(1, -1, 0), p(1, 1, 0)}};  // crosses a's segment
  BOOST_TEST(!t.run());
  BOOST_TEST(t.stats.separations == 0u);
}

BOOST_AUTO_TEST_CASE(directions_are_rounded_to_twenty_bits) {
  // The unit is 2^(ilogb(max |n_i|) - 20) = 2^(-1 - 20) for 0.75.
  const std::array<double, 3> r = wi::rounded({1.0 / 3, 1e-9, -0.75});
  BOOST_TEST(r[0] == std::ldexp(std::nearbyint(std::ldexp(1.0 / 3, 21)), -21));
  BOOST_TEST(r[0] != 1.0 / 3);
  BOOST_TEST(r[1] == 0.0);
  BOOST_TEST(r[2] == -0.75);
}

BOOST_AUTO_TEST_SUITE_END()
