// The tests of one configuration (src/verify/static_config.h): the filtered
// first common point agrees with the exact test and reports the first pair
// in part order; under interval-only placements a hit is a certain crossing
// and an unresolved pair is reported as uncertain; the closest pair within a
// bound is exact (proofs/static-test.md, proofs/witness.md).
#include "src/verify/static_config.h"

#include <boost/test/unit_test.hpp>

using namespace tmcert;
using namespace tmcert::detail;

namespace {
Vec3E v(long x, long y, long z) { return {Exact(x), Exact(y), Exact(z)}; }
Simplex tri(Vec3E a, Vec3E b, Vec3E c) { return Simplex{3, {a, b, c}}; }
Simplex seg(Vec3E a, Vec3E b) { return Simplex{2, {a, b, b}}; }
StaticPart part(const std::string& name, std::vector<Simplex> s) { return StaticPart{name, std::move(s)}; }

bool in_triangle_plane_z0(const Vec3E& p) { return p[2] == 0; }

using Maps = std::optional<std::pair<std::optional<Mat34E>, std::optional<Mat34E>>>;
}  // namespace

BOOST_AUTO_TEST_SUITE(verify_static_config)

BOOST_AUTO_TEST_CASE(first_hit_is_exact_and_in_part_order) {
  const std::vector<StaticPart> floor = {part("floor", {tri(v(0, 0, 0), v(4, 0, 0), v(0, 4, 0))})};
  // Part 0 is apart (1 above), part 1 touches the floor at (1, 1, 0) with a vertex.
  const std::vector<StaticPart> body = {part("above", {seg(v(1, 1, 1), v(2, 1, 1))}),
                                        part("down", {seg(v(1, 1, 0), v(1, 1, 3))}),
                                        part("also", {seg(v(1, 1, -1), v(1, 1, 1))})};
  CheckStats stats;
  const std::optional<StaticHit> hit = first_hit(body, floor, nullptr, stats);
  BOOST_REQUIRE(hit);
  BOOST_TEST(hit->part_moving == 1);  // the first part in order, not "also"
  BOOST_TEST(hit->part_other == 0);
  BOOST_TEST(in_triangle_plane_z0(hit->point));
  BOOST_TEST((hit->point == v(1, 1, 0)));
  BOOST_TEST(stats.static_tests >= 1u);
  // Restricted to the pair (0, 0): no hit.
  const std::set<std::pair<int, int>> only = {{0, 0}};
  BOOST_TEST(!first_hit(body, floor, &only, stats));
  // Restricted to (2, 0): the crossing segment.
  const std::set<std::pair<int, int>> third = {{2, 0}};
  const auto h2 = first_hit(body, floor, &third, stats);
  BOOST_REQUIRE(h2);
  BOOST_TEST(h2->part_moving == 2);
}

BOOST_AUTO_TEST_CASE(a_gap_of_one_part_in_ten_to_the_seventeen_is_no_hit) {
  const std::vector<StaticPart> floor = {part("floor", {tri(v(0, 0, 0), v(4, 0, 0), v(0, 4, 0))})};
  const Vec3E hover{Exact(1), Exact(1), Exact(1, CGAL::Gmpz("100000000000000000"))};
  const std::vector<StaticPart> body = {part("hover", {seg(hover, v(1, 1, 3))})};
  CheckStats stats;
  BOOST_TEST(!first_hit(body, floor, nullptr, stats));
}

BOOST_AUTO_TEST_CASE(exact_maps_are_asked_only_when_the_filter_leaves_a_pair) {
  const std::vector<StaticPart> a = {part("a", {seg(v(0, 0, 0), v(1, 0, 0))})};
  const std::vector<StaticPart> b = {part("b", {seg(v(5, 5, 5), v(6, 5, 5))})};
  CheckStats stats;
  int asked = 0;
  const auto hit = filtered_first_hit(a, nullptr, b, nullptr, nullptr, [&]() -> Maps { ++asked; return Maps(std::in_place); },
                                      stats);
  BOOST_TEST(!hit);
  BOOST_TEST(asked == 0);
}

BOOST_AUTO_TEST_CASE(interval_only_placements_need_a_certain_crossing) {
  // A segment crossing a triangle transversally, both at the identity given
  // only as interval maps: the hit is a box, not a point.
  const std::array<Interval, 12> id = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
  const std::vector<StaticPart> floor = {part("floor", {tri(v(0, 0, 0), v(4, 0, 0), v(0, 4, 0))})};
  const std::vector<StaticPart> pin = {part("pin", {seg(v(1, 1, -1), v(1, 1, 1))})};
  CheckStats stats;
  bool uncertain = false;
  auto none = []() -> Maps { return std::nullopt; };
  const auto hit = filtered_first_hit(pin, &id, floor, &id, nullptr, none, stats, &uncertain);
  BOOST_REQUIRE(hit);
  BOOST_REQUIRE(hit->box);
  BOOST_TEST((*hit->box)[0].inf() <= 1);
  BOOST_TEST((*hit->box)[0].sup() >= 1);
  BOOST_TEST(!uncertain);
  // Touching only (the pin ends on the face): neither separated nor a
  // certain crossing.
  const std::vector<StaticPart> touch = {part("touch", {seg(v(1, 1, 0), v(1, 1, 1))})};
  const auto h2 = filtered_first_hit(touch, &id, floor, &id, nullptr, none, stats, &uncertain);
  BOOST_TEST(!h2);
  BOOST_TEST(uncertain);
}

BOOST_AUTO_TEST_CASE(closest_within_is_exact_and_bounded) {
  const std::vector<StaticPart> a = {part("a", {seg(v(0, 0, 0), v(2, 0, 0))})};
  const std::vector<StaticPart> b = {part("b", {seg(v(1, 3, 0), v(1, 3, 5))})};
  CheckStats stats;
  const auto hit = closest_within(a, nullptr, b, nullptr, Exact(9), nullptr, stats);
  BOOST_REQUIRE(hit);
  BOOST_TEST(hit->points.d2 == Exact(9));
  BOOST_TEST((hit->points.a == v(1, 0, 0)));
  BOOST_TEST((hit->points.b == v(1, 3, 0)));
  BOOST_TEST(!closest_within(a, nullptr, b, nullptr, Exact(9) - Exact(1, 1000000), nullptr, stats));
  // Placed by an exact map: b moved down by 3 touches a.
  const Mat34E down = {1, 0, 0, 0, 0, 1, 0, -3, 0, 0, 1, 0};
  const auto touch = closest_within(a, nullptr, b, &down, Exact(0), nullptr, stats);
  BOOST_REQUIRE(touch);
  BOOST_TEST(touch->points.d2 == Exact(0));
}

BOOST_AUTO_TEST_SUITE_END()
