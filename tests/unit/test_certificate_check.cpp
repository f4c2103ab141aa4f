// The independent certificate checker (src/certificate/check.h,
// docs/certificate-format.md, proofs/certificates.md): hand-built
// certificates for tiny scenes (tests/data/certificates, numbers checked by
// hand in the comments of each scene and below) pass; each tampering is
// rejected with the claim it breaks; malformed documents are InputError;
// seeded fuzzing of valid certificates never crashes and never proves a
// false claim; the ray test, the joint curve, the pose and the integer
// evaluation paths are checked against hand values and brute force.
#include "src/certificate/check.h"
#include "src/certificate/motions.h"
#include "src/motion/chain.h"
#include "src/motion/segment.h"
#include "src/io/parse.h"

#include <boost/test/unit_test.hpp>
#include <nlohmann/json.hpp>

#include <chrono>
#include <fstream>
#include <functional>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace tmcert;
using json = nlohmann::json;
namespace cert = tmcert::certificate;

std::string data(const std::string& name) { return std::string(TMCERT_TEST_DATA) + "/certificates/" + name; }

Exact q(const std::string& text) {
  Exact value;
  BOOST_REQUIRE_MESSAGE(parse_exact(text, value), text);
  return value;
}
// A rational written as a JSON string or integer.
Exact rat(const json& x) { return x.is_string() ? q(x.get<std::string>()) : Exact(static_cast<long>(x.get<std::int64_t>())); }

Vec3E v(const std::string& x, const std::string& y, const std::string& z) { return {q(x), q(y), q(z)}; }

struct Case {
  Scene scene;
  json certificate;
};

Case load(const std::string& scene, const std::string& certificate) {
  return {parse_scene_file(data(scene + ".json")), cert::read_certificate_file(data(certificate + ".cert.json"))};
}

cert::CheckOutcome check(const Case& c) { return cert::check_certificate(c.scene, c.certificate, "cert.json"); }

// Rejected (ok = false) with a message containing `what`.
void expect_rejected(const Case& c, const std::string& what) {
  const cert::CheckOutcome out = check(c);
  BOOST_TEST(!out.ok, "expected a rejection containing '" << what << "'");
  BOOST_TEST(out.message.find(what) != std::string::npos, "message: " << out.message << "\n  expected: " << what);
  BOOST_TEST(out.message.find('\n') == std::string::npos);
  BOOST_TEST(out.message.rfind("cert.json: ", 0) == 0, out.message);
}

// Malformed: InputError with a message containing `what`.
void expect_malformed(const Case& c, const std::string& what) {
  try {
    const cert::CheckOutcome out = check(c);
    BOOST_ERROR("expected InputError containing '" << what << "', got ok=" << out.ok << " " << out.message);
  } catch (const InputError& e) {
    const std::string m = e.what();
    BOOST_TEST(m.find(what) != std::string::npos, "message: " << m << "\n  expected: " << what);
  }
}

json& check0(Case& c) { return c.certificate["checks"][0]; }

const std::vector<std::pair<std::string, std::string>> kValid = {
    {"probe-safe", "probe-safe"},       {"drop", "drop-collision"},
    {"drop", "drop-undecided"},         {"two-moving", "two-moving"},
    {"solid-outside", "solid-outside"}, {"solid-inside", "solid-inside-collision"},
    {"solid-singular", "solid-singular"}, {"drop", "drop-exact"},
    {"slide-beside", "slide-exact"},    {"solid-crossing", "solid-crossing-undecided"}};

}  // namespace

BOOST_AUTO_TEST_SUITE(certificate_check)

BOOST_AUTO_TEST_CASE(elements_in_the_documented_order) {
  const Scene probe = parse_scene_file(data("probe-safe.json"));
  const auto pe = cert::elements(probe.bodies[0]);  // segments, then points
  BOOST_REQUIRE_EQUAL(pe.size(), 2u);
  BOOST_TEST((pe[0] == std::vector<Vec3E>{v("0", "0", "0"), v("0", "0", "1/2")}));
  BOOST_TEST((pe[1] == std::vector<Vec3E>{v("1/8", "0", "0")}));
  const Scene inside = parse_scene_file(data("solid-inside.json"));
  const auto te = cert::elements(inside.bodies[0]);
  BOOST_REQUIRE_EQUAL(te.size(), 1u);
  BOOST_TEST(te[0][0] == v("1/4", "1/4", "1/2"));  // the witness vertex
  const auto be = cert::elements(inside.bodies[1]);
  BOOST_REQUIRE_EQUAL(be.size(), 6u);
  BOOST_TEST((be[3] == std::vector<Vec3E>{v("1", "0", "0"), v("1", "1", "0"), v("1", "1", "1"), v("1", "0", "1")}));
}

BOOST_AUTO_TEST_CASE(hand_built_certificates_pass) {
  for (const auto& [scene, certificate] : kValid) {
    const cert::CheckOutcome out = check(load(scene, certificate));
    BOOST_TEST(out.ok, certificate << ": " << out.message);
    BOOST_TEST(out.proven.size() == 1u);
  }
  BOOST_TEST(check(load("probe-safe", "probe-safe")).proven[0] == "probe x tri: safe proven (3 pieces, 4 separations)");
  BOOST_TEST(check(load("drop", "drop-collision")).proven[0] ==
             "drop x tri: collision proven at t = 1/2; no contact before t = 3/8 proven (2 pieces, 2 separations)");
  BOOST_TEST(check(load("drop", "drop-undecided")).proven[0].find("no contact before t = 3/8") != std::string::npos);
  BOOST_TEST(check(load("solid-outside", "solid-outside")).proven[0] ==
             "tri x box: safe proven (1 piece, 1 separation, 2 start points)");
}

BOOST_AUTO_TEST_CASE(a_triangle_inside_a_solid_is_not_safe) {
  // Every face is separated from the triangle, but it starts inside the
  // cube: the start claim's ray crosses one face (odd).
  Case c = load("solid-inside", "solid-inside-safe");
  expect_rejected(c, "start[0] (solid \"box\").points[0] (\"tri\" element 0 vertex 0): the ray crosses shell 0 of \"box\" 1 time, an odd number");
  // Without the start claim it is rejected as missing.
  check0(c)["start"] = json::array();
  expect_rejected(c, "start: no claim for the solid \"box\"");
  // The separations themselves hold: with the box not solid the same
  // proof is accepted (the surfaces never touch).
  Case hollow = load("solid-inside", "solid-inside-safe");
  hollow.scene.bodies[1].solid = false;
  check0(hollow)["start"] = json::array();
  BOOST_TEST(check(hollow).ok, check(hollow).message);
  // A start claim about a body that is not solid is rejected.
  Case stray = load("solid-inside", "solid-inside-safe");
  stray.scene.bodies[1].solid = false;
  expect_rejected(stray, "\"box\" is not solid");
}

BOOST_AUTO_TEST_CASE(tampered_separations_are_rejected) {
  {
    Case c = load("probe-safe", "probe-safe");
    check0(c)["pieces"][0]["proof"]["sep"][2] = "-1";  // direction flipped
    expect_rejected(c, "checks[0] (\"probe\" x \"tri\"): pieces[0] [0, 1/4]: proof (groups 0, 0): separation fails at control point 0");
  }
  {
    // The point at x = 3/8, z >= 1/2: -x + z/4 <= -1/8 < 0 = max over the triangle.
    Case c = load("probe-safe", "probe-safe");
    check0(c)["pieces"][1]["proof"]["parts"][1]["sep"][2] = "1/4";
    expect_rejected(c, "pieces[1] [1/4, 1/2]: proof.parts[1] (groups 2, 0): separation fails at control point 0");
  }
  {
    // x + z on [1/2, 1], where the probe sits at z = 1/2 (+ the segment's
    // 0..1/2) and x = 1/4 (segment) or 3/8 (point): min 3/4 against the
    // triangle's max x + z = 1: fails.  On [0, 1/4] (z >= 25/32) it holds.
    Case c = load("probe-safe", "probe-safe");
    check0(c)["pieces"][2]["proof"]["sep"] = json::array({"1", "0", "1"});
    expect_rejected(c, "pieces[2] [1/2, 1]: proof (groups 0, 0): separation fails at control point 0");
    check0(c)["pieces"][2]["proof"]["sep"] = json::array({"0", "0", "1"});
    check0(c)["pieces"][0]["proof"]["sep"] = json::array({"1", "0", "1"});
    BOOST_TEST(check(c).ok, check(c).message);
  }
  {
    // Two moving bodies, product form (hand computation in
    // joint_curve_by_hand): with n = (1, 0, 1) the first control point gives
    // 1 > 1, false; (1/2, 0, 1) holds.
    Case c = load("two-moving", "two-moving");
    check0(c)["pieces"][0]["proof"]["sep"] = json::array({"1", "0", "1"});
    expect_rejected(c, "pieces[0] [0, 1/2]: proof (groups 0, 0): separation fails at control point 0");
    check0(c)["pieces"][0]["proof"]["sep"] = json::array({"1/2", "0", "1"});
    BOOST_TEST(check(c).ok, check(c).message);
    check0(c)["pieces"][0]["proof"]["sep"] = json::array({"0", "0", "0"});
    expect_rejected(c, "separation fails at control point 0");
  }
  {
    // The collision prefix cannot extend past the contact at t = 1/2.
    Case c = load("drop", "drop-collision");
    check0(c)["pieces"].push_back({{"t", {"3/8", "1/2"}}, {"proof", {{"sep", {"0", "0", "1"}}}}});
    check0(c)["first_contact"][0] = "1/2";
    expect_rejected(c, "pieces[2] [3/8, 1/2]: proof (groups 0, 0): separation fails at control point 1");
  }
}

BOOST_AUTO_TEST_CASE(tampered_tilings_are_rejected) {
  {
    Case c = load("probe-safe", "probe-safe");
    check0(c)["pieces"][1]["t"][0] = "5/16";  // gap between 1/4 and 5/16
    expect_rejected(c, "pieces[1] [5/16, 1/2] starts at 5/16, but the previous piece ends at 1/4 (gap)");
  }
  {
    Case c = load("probe-safe", "probe-safe");
    check0(c)["pieces"][1]["t"][0] = "1/8";
    expect_rejected(c, "(overlap)");
  }
  {
    Case c = load("probe-safe", "probe-safe");
    check0(c)["pieces"][0]["t"][0] = "1/16";
    expect_rejected(c, "pieces[0] [1/16, 1/4] starts at 1/16, but the check starts at t0 = 0");
  }
  {
    Case c = load("probe-safe", "probe-safe");
    check0(c)["pieces"].erase(2);  // pieces not reaching t1
    expect_rejected(c, "the pieces end at 1/2, not at t1 = 1");
  }
  {
    Case c = load("probe-safe", "probe-safe");
    check0(c)["pieces"][2]["t"][1] = "2";
    expect_rejected(c, "ends after t1 = 1");
  }
  {
    Case c = load("probe-safe", "probe-safe");
    check0(c)["pieces"][2]["t"] = json::array({"1/2", "1/2"});
    expect_rejected(c, "pieces[2] [1/2, 1/2] is empty");
  }
  {
    // Undecided: the pieces and undecided intervals must tile [t0, t1].
    Case c = load("drop", "drop-undecided");
    check0(c)["undecided"][0]["t"][1] = "1/2";
    expect_rejected(c, "do not tile [0, 1]: the previous one ends at 1/2, pieces[2] starts at 5/8");
    Case d = load("drop", "drop-undecided");
    check0(d)["pieces"].erase(2);
    expect_rejected(d, "end at 5/8, not at t1 = 1");
    Case e = load("drop", "drop-undecided");
    check0(e)["undecided"] = json::array();
    expect_rejected(e, "an undecided check with no undecided interval");
    Case f = load("drop", "drop-undecided");
    check0(f)["first_contact"][0] = "1/2";
    expect_rejected(f, "lo is after the first undecided interval, which starts at 3/8");
    // A bare [lo, hi] pair is accepted as an undecided entry.
    Case g = load("drop", "drop-undecided");
    check0(g)["undecided"][0] = json::array({"3/8", "5/8"});
    BOOST_TEST(check(g).ok, check(g).message);
  }
}

BOOST_AUTO_TEST_CASE(tampered_groups_and_proof_trees_are_rejected) {
  {
    Case c = load("probe-safe", "probe-safe");
    check0(c)["groups"][0][2]["elements"][0] = 0;  // element 1 (the point) no longer reached
    expect_rejected(c, "groups[0]: group 0 does not reach element 1 of \"probe\"");
  }
  {
    Case c = load("solid-outside", "solid-outside");
    check0(c)["groups"][1][0]["elements"] = json::array({0, 1, 2, 3, 5});  // a group missing an element
    expect_rejected(c, "groups[1]: group 0 does not reach element 4 of \"box\"");
  }
  {
    Case c = load("probe-safe", "probe-safe");
    check0(c)["pieces"][1]["proof"]["parts"].push_back({{"sep", {"0", "0", "1"}}});
    expect_rejected(c, "pieces[1] [1/4, 1/2]: proof (groups 0, 0): split 0 has 3 parts, group 0 has 2 children");
  }
  {
    Case c = load("probe-safe", "probe-safe");
    check0(c)["pieces"][1]["proof"]["parts"].erase(1);  // the point's part missing
    expect_rejected(c, "pieces[1] [1/4, 1/2]: proof (groups 0, 0): split 0 has 1 parts, group 0 has 2 children");
  }
  {
    Case c = load("probe-safe", "probe-safe");
    check0(c)["pieces"][1]["proof"]["split"] = 1;  // the triangle's group 0 has no children
    expect_rejected(c, "split 1 of group 0, which has no children");
  }
  {
    Case c = load("solid-inside", "solid-inside-safe");
    c.scene.bodies[1].solid = false;  // surfaces only: the proof tree decides
    check0(c)["start"] = json::array();
    BOOST_TEST(check(c).ok, check(c).message);
    // Splitting the box in a different order pairs the directions with the wrong faces.
    auto& parts = check0(c)["pieces"][0]["proof"]["parts"];
    std::swap(parts[0], parts[1]);
    expect_rejected(c, "proof.parts[0] (groups 0, 1): separation fails at control point 0");
  }
}

BOOST_AUTO_TEST_CASE(tampered_witnesses_are_rejected) {
  {
    Case c = load("drop", "drop-collision");
    check0(c)["witness"]["b"]["weights"] = json::array({"1/2", "1/3", "1/6"});  // still sums to 1
    expect_rejected(c, "witness.b: element 0 of \"tri\" with these weights is at (1/3, 1/6, 0) at t = 1/2, not at the point (1/4, 1/4, 0)");
  }
  {
    Case c = load("drop", "drop-collision");
    check0(c)["witness"]["b"]["weights"] = json::array({"1", "1/4", "-1/4"});
    expect_rejected(c, "witness.b.weights[2] = -1/4 is negative");
  }
  {
    Case c = load("drop", "drop-collision");
    check0(c)["witness"]["b"]["weights"] = json::array({"1/2", "1/4", "1/2"});
    expect_rejected(c, "witness.b.weights sum to 5/4, not 1");
  }
  {
    Case c = load("drop", "drop-collision");
    check0(c)["witness"]["point"][2] = "1/100";  // the point moved
    expect_rejected(c, "witness.a: element 0 of \"drop\" with these weights is at (1/4, 1/4, 0) at t = 1/2");
  }
  {
    Case c = load("drop", "drop-collision");
    check0(c)["witness"]["t"] = "5/8";  // the drop is below the triangle then
    expect_rejected(c, "witness.a: element 0 of \"drop\"");
  }
  {
    Case c = load("drop", "drop-collision");
    check0(c)["witness"]["t"] = "3/2";
    expect_rejected(c, "witness: t = 3/2 is outside the check's interval [0, 1]");
  }
  {
    Case c = load("drop", "drop-collision");
    check0(c)["first_contact"] = json::array({"1/4", "1/2"});  // lo before the pieces' end
    expect_rejected(c, "first_contact [1/4, 1/2]: the pieces end at 3/8, not at lo = 1/4");
  }
  {
    // lo after a piece end, with a piece added so the pieces end at lo:
    // the witness then comes before lo.
    Case c = load("drop", "drop-collision");
    check0(c)["witness"]["t"] = "1/4";
    check0(c)["witness"]["point"] = json::array({"1/4", "1/4", "1/2"});
    check0(c)["witness"]["b"]["weights"] = json::array({"1/2", "1/4", "1/4"});
    expect_rejected(c, "witness.b: element 0 of \"tri\"");
  }
  {
    Case c = load("drop", "drop-collision");
    check0(c)["first_contact"][0] = "7/16";  // lo after the pieces' end
    expect_rejected(c, "first_contact [7/16, 1/2]: the pieces end at 3/8, not at lo = 7/16");
  }
  {
    // lo after the witness (the piece added to reach lo cannot be proven
    // either, but the bracket is reported first).
    Case c = load("drop", "drop-collision");
    check0(c)["pieces"].push_back({{"t", {"3/8", "9/16"}}, {"proof", {{"sep", {"0", "0", "1"}}}}});
    check0(c)["first_contact"] = json::array({"9/16", "5/8"});
    expect_rejected(c, "first_contact [9/16, 5/8]: lo is after the witness t = 1/2");
  }
  {
    Case c = load("drop", "drop-collision");
    check0(c)["first_contact"][1] = "7/16";
    expect_rejected(c, "the witness t = 1/2 is after hi");
  }
  {
    Case c = load("solid-inside", "solid-inside-collision");
    check0(c)["witness"]["b"]["interior"]["ray"] = json::array({"3/4", "3/4", "1/2"});  // through the corner (1, 1, 1)
    expect_rejected(c, "witness.b.interior: the ray from the point along (3/4, 3/4, 1/2) is degenerate");
    check0(c)["witness"]["b"]["interior"]["ray"] = json::array({"1", "0", "0"});
    BOOST_TEST(check(c).ok, check(c).message);
    check0(c)["witness"]["point"] = json::array({"1/4", "1/4", "3/2"});  // above the cube
    check0(c)["witness"]["a"] = {{"interior", {{"ray", {"1", "0", "0"}}}}};
    expect_rejected(c, "witness.a: \"tri\" is not solid");
  }
  {
    // An interior claim for a point outside the solid: the triangle beside
    // the cube claims to be inside it at t = 0; the ray crosses nothing.
    Case c = load("solid-outside", "solid-outside");
    check0(c)["verdict"] = "collision";
    check0(c)["pieces"] = json::array();
    check0(c)["start"] = json::array();
    check0(c)["first_contact"] = json::array({"0", "0"});
    check0(c)["witness"] = {{"t", "0"}, {"point", {"2", "0", "0"}}, {"a", {{"element", 0}, {"weights", {"1", "0", "0"}}}},
                            {"b", {{"interior", {{"ray", {"1", "1/3", "1/5"}}}}}}};
    expect_rejected(c, "witness.b.interior: the ray crosses every shell of \"box\" an even number of times (0): the point is not inside");
    check0(c)["witness"]["b"]["interior"]["ray"] = json::array({"-1", "1/3", "1/5"});  // starts in the face plane y = 0, crosses twice
    expect_rejected(c, "the ray crosses every shell of \"box\" an even number of times (2)");
  }
  {
    Case c = load("solid-inside", "solid-inside-collision");
    check0(c)["witness"]["point"] = json::array({"1/4", "1/4", "3/2"});
    check0(c)["witness"]["a"]["weights"] = json::array({"1", "0", "0"});
    expect_rejected(c, "witness.a: element 0 of \"tri\"");
  }
}

BOOST_AUTO_TEST_CASE(tampered_start_claims_are_rejected) {
  {
    Case c = load("solid-outside", "solid-outside");
    check0(c)["start"][0]["points"].erase(1);  // the second triangle's component
    expect_rejected(c, "start[0] (solid \"box\"): no point of the component of \"tri\" element 1 is listed");
  }
  {
    Case c = load("solid-outside", "solid-outside");
    check0(c)["start"][0]["points"][0]["ray"] = json::array({"-1", "0", "1/2"});  // through the edge x = 1, y = 0
    expect_rejected(c, "start[0] (solid \"box\").points[0] (\"tri\" element 0 vertex 0): the ray along (-1, 0, 1/2) is degenerate");
  }
  {
    Case c = load("solid-outside", "solid-outside");
    check0(c)["start"][0]["points"][0]["ray"] = json::array({"-1", "0", "0"});  // through the vertex (1, 0, 0)
    expect_rejected(c, "is degenerate");
  }
  {
    Case c = load("solid-outside", "solid-outside");
    check0(c)["start"][0]["points"][0]["ray"] = json::array({"0", "0", "0"});
    expect_rejected(c, "is degenerate");
  }
  {
    Case c = load("solid-outside", "solid-outside");
    check0(c)["start"] = json::array();
    expect_rejected(c, "start: no claim for the solid \"box\" (\"b\")");
  }
  {
    Case c = load("solid-outside", "solid-outside");
    check0(c)["start"][0]["solid"] = "a";
    expect_rejected(c, "\"tri\" is not solid");
  }
}

// A run of pieces after an undecided interval needs start claims at its
// own start (proofs/partition.md §5): the point crosses the solid cube
// (inside for t in (1/4, 3/4)); separations from each face prove the
// surfaces apart on [3/8, 5/8], but the point entered during the
// undecided [1/8, 3/8].  Before the fix this certificate was accepted.
BOOST_AUTO_TEST_CASE(pieces_after_an_undecided_interval_need_start_claims_there) {
  Case c = load("solid-crossing", "solid-crossing-inside");
  expect_rejected(c, "start: no claim for the solid \"box\" (\"b\") at t = 3/8");
  // With a claim there, its ray shows the point inside.
  json at = check0(c)["start"][0];
  at["t"] = "3/8";
  at["points"][0]["ray"] = json::array({"1", "1/3", "1/5"});
  check0(c)["start"].push_back(at);
  expect_rejected(c, "start[1] (solid \"box\").points[0] (\"pt\" element 0 vertex 0): the ray crosses shell 0 of \"box\" 1 time, an odd number: the vertex is inside \"box\" at t = 3/8");
  // The valid certificate of the crossing: pieces before and after the
  // undecided [1/8, 7/8], start claims at 0 and at 7/8.
  Case d = load("solid-crossing", "solid-crossing-undecided");
  BOOST_TEST(check(d).proven[0] ==
             "pt x box: undecided: no contact before t = 1/8 proven (2 pieces, 2 separations, 2 start points; 1 "
             "interval not cleared)");
  check0(d)["start"].erase(1);
  expect_rejected(d, "start: no claim for the solid \"box\" (\"b\") at t = 7/8");
  // A claim's instant must lie in the check's interval; one per side and instant.
  Case e = load("solid-crossing", "solid-crossing-undecided");
  check0(e)["start"][1]["t"] = "9/8";
  expect_malformed(e, "start[1].t: 9/8 is outside the check's interval [0, 1]");
  Case f = load("solid-crossing", "solid-crossing-undecided");
  check0(f)["start"][1]["t"] = "0";
  expect_malformed(f, "start[1].solid: a second entry for \"b\"");
}

// Exact "no contact" claims (src/certificate/exact_claims.h,
// proofs/exact-resolution.md §6): they hold where the elements never touch,
// also when the contact polynomial vanishes identically (sliding in the
// face's plane), and are rejected where the pair touches inside the piece,
// at its closed end, only in a coplanar slide, or overlaps from the start
// without any vertex or edge contact.
BOOST_AUTO_TEST_CASE(exact_no_contact_claims) {
  BOOST_TEST(check(load("slide-beside", "slide-exact")).ok);
  BOOST_TEST(check(load("drop", "drop-exact")).ok);
  // The same claim where the point slides into the triangle (t = 5/12).
  expect_rejected(load("slide-into", "slide-exact"),
                  "pieces[0] [0, 1]: proof (groups 0, 0): exact no-contact claim fails: elements 0 and 0: vertex 0 of "
                  "the a element touches the polygon at u ~ 0.41666");
  // A rod through the triangle's interior all along: no vertex-element or
  // edge-edge contact ever, but the elements meet at the piece's start.
  expect_rejected(load("pierce", "pierce-exact-false-safe"), "the elements meet at the start of the piece");
  {  // A safe claim over the drop's contact at t = 1/2.
    Case c = load("drop", "drop-exact");
    json& ch = check0(c);
    ch = {{"bodies", ch["bodies"]}, {"verdict", "safe"}, {"interval", ch["interval"]}, {"groups", ch["groups"]},
          {"pieces", json::array({{{"t", {"0", "1"}}, {"proof", {{"exact", "no_contact"}}}}})}};
    expect_rejected(c, "exact no-contact claim fails: elements 0 and 0: vertex 0 of the a element touches the polygon at u ~ 0.5");
  }
  {  // The piece widened to the contact time (touching at its closed end).
    Case c = load("drop", "drop-exact");
    check0(c)["pieces"][0]["t"][1] = "1/2";
    check0(c)["before_witness"]["from"] = "1/2";
    expect_rejected(c, "pieces[0] [0, 1/2]: proof (groups 0, 0): exact no-contact claim fails");
  }
  {  // ... and past it.
    Case c = load("drop", "drop-exact");
    check0(c)["pieces"][0]["t"][1] = "5/8";
    check0(c)["before_witness"]["from"] = "5/8";
    expect_rejected(c, "pieces[0] [0, 5/8]: proof (groups 0, 0): exact no-contact claim fails");
  }
  {  // Pieces up to the witness time, before_witness from there: the pieces fail.
    Case c = load("drop", "drop-exact");
    check0(c)["pieces"][0] = {{"t", {"0", "1/4"}}, {"proof", {{"sep", {"0", "0", "1"}}}}};
    check0(c)["pieces"].push_back({{"t", {"1/4", "1/2"}}, {"proof", {{"sep", {"0", "0", "1"}}}}});
    check0(c)["before_witness"]["from"] = "1/2";
    expect_rejected(c, "separation fails at control point 1");
  }
  {  // A separation on [3/8, 1/2] is checked on the closed piece: it fails at 1/2.
    Case c = load("drop", "drop-exact");
    check0(c)["before_witness"]["proof"] = {{"sep", {"0", "0", "1"}}};
    expect_rejected(c, "before_witness [3/8, witness): proof (groups 0, 0): separation fails at control point 1");
  }
  {  // The pieces must end where before_witness starts.
    Case c = load("drop", "drop-exact");
    check0(c)["before_witness"]["from"] = "1/4";
    expect_rejected(c, "the pieces end at 3/8, not at before_witness.from = 1/4");
  }
  {  // Without before_witness the bracket [1/2, 1/2] is not proven.
    Case c = load("drop", "drop-exact");
    check0(c).erase("before_witness");
    expect_rejected(c, "the pieces end at 3/8, not at lo = 1/2");
  }
  {  // Malformed leaves.
    Case c = load("drop", "drop-exact");
    check0(c)["pieces"][0]["proof"]["exact"] = "yes";
    expect_malformed(c, "checks[0].pieces[0].proof.exact: expected \"no_contact\"");
    Case d = load("drop", "drop-exact");
    check0(d)["pieces"][0]["proof"]["sep"] = {"0", "0", "1"};
    expect_malformed(d, "checks[0].pieces[0].proof: expected exactly one of \"sep\", \"split\" and \"exact\"");
    Case e = load("drop", "drop-exact");
    check0(e)["before_witness"].erase("from");
    expect_malformed(e, "checks[0].before_witness.from: missing required field");
  }
}

BOOST_AUTO_TEST_CASE(another_scene_is_rejected) {
  {
    Case c = load("drop", "probe-safe");  // same shape of scene, other bodies
    expect_rejected(c, "scene_bodies[0]: \"probe\" with 2 elements, but the scene's body 0 is \"drop\" with 1 elements (the certificate belongs to another scene)");
  }
  {
    Case c = load("probe-safe", "probe-safe");
    c.certificate["scene_bodies"][1]["elements"] = 2;
    expect_rejected(c, "the certificate belongs to another scene");
  }
  {
    Case c = load("probe-safe", "probe-safe");
    c.certificate["scene_bodies"].push_back({{"name", "x"}, {"elements", 1}});
    expect_rejected(c, "scene_bodies: 3 bodies, the scene has 2");
  }
  {
    Case c = load("probe-safe", "probe-safe");
    check0(c)["bodies"] = json::array({"tri", "probe"});
    expect_rejected(c, "checks[0].bodies: [\"tri\", \"probe\"], but the scene's check 0 is [\"probe\", \"tri\"]");
  }
  {
    Case c = load("probe-safe", "probe-safe");
    c.certificate["checks"].push_back(check0(c));
    expect_rejected(c, "checks: 2 checks, the scene has 1");
  }
  {
    Case c = load("probe-safe", "probe-safe");
    check0(c)["interval"] = json::array({"0", "2"});
    expect_rejected(c, "interval [0, 2], but the check's parameter interval is [0, 1]");
  }
}

BOOST_AUTO_TEST_CASE(malformed_certificates_are_input_errors) {
  const auto base = [] { return load("probe-safe", "probe-safe"); };
  struct Mutation {
    std::function<void(json&)> apply;
    std::string what;
  };
  const std::vector<Mutation> mutations = {
      {[](json& d) { d["format"] = "tmcert-certificate/2"; }, "format: unknown format"},
      {[](json& d) { d.erase("format"); }, "format: missing required field"},
      {[](json& d) { d.erase("checks"); }, "checks: missing required field"},
      {[](json& d) { d = json::array(); }, "document: expected an object"},
      {[](json& d) { d["checks"][0]["pieces"][0]["proof"]["sep"] = json::array({"0", "0"}); },
       "checks[0].pieces[0].proof.sep: expected 3 entries, got 2"},
      {[](json& d) { d["checks"][0]["pieces"][0]["proof"]["sep"][0] = 0.5; },
       "checks[0].pieces[0].proof.sep[0]: expected a rational"},
      {[](json& d) { d["checks"][0]["pieces"][0]["proof"]["sep"][0] = "1e99999"; }, "decimal exponent beyond 10000"},
      {[](json& d) { d["checks"][0]["pieces"][0]["proof"]["sep"][0] = "1e10001"; }, "decimal exponent beyond 10000"},
      {[](json& d) { d["checks"][0]["pieces"][0]["proof"]["sep"][0] = std::string(100001, '7'); },
       "number of 100001 characters (at most 100000)"},
      {[](json& d) { d["checks"][0]["pieces"][0]["proof"]["sep"][0] = "1/0"; }, "not a rational: \"1/0\""},
      {[](json& d) { d["checks"][0]["pieces"][0]["proof"]["sep"][0] = "nan"; }, "not a rational"},
      {[](json& d) { d["checks"][0]["pieces"][0]["proof"]["sep"][0] = nullptr; }, "expected a rational"},
      {[](json& d) { d["checks"][0]["pieces"][0]["proof"] = {{"sep", {0, 0, 1}}, {"split", 0}}; },
       "expected exactly one of \"sep\", \"split\" and \"exact\""},
      {[](json& d) { d["checks"][0]["pieces"][1]["proof"]["split"] = 2; }, "proof.split: 2 is out of range (0 or 1)"},
      {[](json& d) { d["checks"][0]["pieces"][1]["proof"]["split"] = -1; }, "out of range"},
      {[](json& d) { d["checks"][0]["pieces"][1]["proof"].erase("parts"); }, "proof.parts: missing required field"},
      {[](json& d) { d["checks"][0]["pieces"][0].erase("proof"); }, "checks[0].pieces[0].proof: missing required field"},
      {[](json& d) { d["checks"][0]["groups"][0][0]["children"] = json::array({1, 0}); },
       "groups[0][0].children[1]: child 0 must be after its group 0"},
      {[](json& d) { d["checks"][0]["groups"][0][1] = {{"children", {1, 2}}}; },
       "groups[0][1].children[0]: child 1 must be after its group 1"},
      {[](json& d) { d["checks"][0]["groups"][0][0]["children"] = json::array({1}); }, "at least two children"},
      {[](json& d) { d["checks"][0]["groups"][0][0]["children"] = json::array({1, 7}); },
       "children[1]: 7 is out of range (3 groups)"},
      {[](json& d) { d["checks"][0]["groups"][0][1]["elements"] = json::array({2}); },
       "groups[0][1].elements[0]: 2 is out of range (\"probe\" has 2 elements)"},
      {[](json& d) { d["checks"][0]["groups"][0][1]["elements"] = json::array(); }, "at least one element"},
      {[](json& d) { d["checks"][0]["groups"][0][1] = json::object(); },
       "expected exactly one of \"elements\" and \"children\""},
      {[](json& d) { d["checks"][0]["groups"][1] = json::array(); }, "groups[1]: no groups"},
      {[](json& d) { d["checks"][0]["groups"].erase(1); }, "groups: expected 2 entries"},
      {[](json& d) { d["checks"][0]["verdict"] = "maybe"; }, "checks[0].verdict: expected \"safe\""},
      {[](json& d) { d["checks"][0]["pieces"] = json::object(); }, "checks[0].pieces: expected an array"},
      {[](json& d) { d["checks"][0].erase("interval"); }, "checks[0].interval: missing required field"},
      {[](json& d) { d["checks"][0]["witness"] = json::object(); }, "a safe check has no witness"},
      {[](json& d) { d["checks"][0]["undecided"] = json::array({json::array({"0", "1"})}); },
       "a safe check has no undecided intervals"},
      {[](json& d) { d["scene_bodies"][0]["elements"] = -2; }, "scene_bodies[0].elements: -2 is out of range"},
      {[](json& d) { d["scene_bodies"][0]["name"] = 3; }, "scene_bodies[0].name: expected a string"},
      {[](json& d) { d["checks"][0]["start"] = {{"solid", "b"}}; }, "checks[0].start: expected an array"},
      {[](json& d) { d["checks"][0]["start"] = json::array({{{"solid", "c"}, {"points", json::array()}}}); },
       "start[0].solid: expected \"a\" or \"b\""},
  };
  for (const Mutation& m : mutations) {
    Case c = base();
    m.apply(c.certificate);
    expect_malformed(c, m.what);
    try {
      check(c);
    } catch (const InputError& e) {
      BOOST_TEST(std::string(e.what()).rfind("cert.json: ", 0) == 0, e.what());  // names the certificate
    }
  }
  // Malformed input is bad input even after a false claim (the document is
  // validated before any claim is judged).
  {
    Case c = base();
    check0(c)["pieces"][0]["proof"]["sep"][2] = "-1";                // false
    check0(c)["pieces"][2]["proof"]["sep"][1] = "one";               // malformed, later
    expect_malformed(c, "checks[0].pieces[2].proof.sep[1]: not a rational: \"one\"");
    Case d = base();
    check0(d)["pieces"][1]["t"][0] = "5/16";                          // a gap
    check0(d)["pieces"][1]["proof"]["parts"][1] = json::array();      // malformed
    expect_malformed(d, "checks[0].pieces[1].proof.parts[1]: expected an object, got an array");
  }
  // Witness and start shapes on their own scenes.
  {
    Case c = load("drop", "drop-collision");
    check0(c)["witness"]["b"]["weights"].erase(2);
    expect_malformed(c, "witness.b.weights: 2 weights, element 0 has 3 vertices");
    Case d = load("drop", "drop-collision");
    check0(d)["witness"]["a"]["element"] = 1;
    expect_malformed(d, "witness.a.element: 1 is out of range (\"drop\" has 1 elements)");
    Case e = load("drop", "drop-collision");
    check0(e).erase("witness");
    expect_malformed(e, "checks[0].witness: missing required field");
    Case f = load("drop", "drop-collision");
    check0(f).erase("first_contact");
    expect_malformed(f, "checks[0].first_contact: missing required field");
    Case g = load("solid-outside", "solid-outside");
    check0(g)["start"][0]["points"][0]["vertex"] = 3;
    expect_malformed(g, "start[0].points[0].vertex: 3 is out of range (element 0 has 3 vertices)");
    Case h = load("solid-outside", "solid-outside");
    check0(h)["start"].push_back(check0(h)["start"][0]);
    expect_malformed(h, "start[1].solid: a second entry for \"b\"");
  }
}

BOOST_AUTO_TEST_CASE(deep_and_garbage_documents_are_input_errors) {
  // A proof tree deeper than the limit (a chain of groups split one by one).
  {
    Case c = load("probe-safe", "probe-safe");
    const int depth = cert::kMaxProofDepth + 5;
    json groups = json::array();
    for (int k = 0; k < depth; ++k) groups.push_back({{"children", {k + 1, k + 2}}});
    // groups[k] = children {k+1, k+2} for k < depth; the last two are leaves.
    groups.push_back({{"elements", {0}}});
    groups.push_back({{"elements", {0, 1}}});
    json proof = {{"sep", {"0", "0", "1"}}};
    for (int k = depth - 1; k >= 0; --k) proof = {{"split", 0}, {"parts", {proof, {{"sep", {"0", "0", "1"}}}}}};
    check0(c)["groups"][0] = groups;
    check0(c)["pieces"][0]["proof"] = proof;
    expect_malformed(c, "proof tree deeper than 256 splits");
  }
  // Text: deep nesting, truncation, garbage bytes, big integers.
  BOOST_CHECK_THROW(cert::parse_certificate_text(std::string(100000, '[') + std::string(100000, ']'), "x"),
                    InputError);
  BOOST_CHECK_THROW(cert::parse_certificate_text("", "x"), InputError);
  BOOST_CHECK_THROW(cert::parse_certificate_text("{\"format\": ", "x"), InputError);
  BOOST_CHECK_THROW(cert::read_certificate_file(data("does-not-exist.cert.json")), InputError);
  const Scene scene = parse_scene_file(data("probe-safe.json"));
  {
    json d = cert::parse_certificate_text(
        "{\"format\": \"tmcert-certificate/1\", \"scene_bodies\": [{\"name\": \"probe\", \"elements\": "
        "123456789012345678901234567890}, {\"name\": \"tri\", \"elements\": 1}]}",
        "x");
    BOOST_CHECK_THROW(cert::check_certificate(scene, d, "x"), InputError);
  }
  std::ifstream in(data("probe-safe.cert.json"));
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  std::mt19937_64 rng(20261123);
  int input_errors = 0;
  for (int i = 0; i < 400; ++i) {
    std::string t = text;
    switch (i % 4) {
      case 0: t.resize(rng() % t.size()); break;                                             // truncated
      case 1: t[rng() % t.size()] = static_cast<char>(rng() % 256); break;                   // one byte
      case 2: for (int k = 0; k < 8; ++k) t[rng() % t.size()] = static_cast<char>(rng()); break;
      default: {                                                                              // random bytes
        t.assign(rng() % 200, ' ');
        for (char& ch : t) ch = static_cast<char>(rng());
      }
    }
    try {
      const json d = cert::parse_certificate_text(t, "garbage.json");
      const cert::CheckOutcome out = cert::check_certificate(scene, d, "garbage.json");
      (void)out;
    } catch (const InputError& e) {
      ++input_errors;
      BOOST_TEST(std::string(e.what()).rfind("garbage.json: ", 0) == 0, e.what());
    } catch (const std::exception& e) {
      BOOST_ERROR("garbage input " << i << " threw " << e.what());
    }
  }
  BOOST_TEST(input_errors > 300);
}

BOOST_AUTO_TEST_CASE(fuzzed_certificates_never_crash_nor_prove_false_claims) {
  // Random values in random fields, deleted and duplicated entries, of
  // every valid certificate.  Each result must be ok, rejected or
  // InputError; and on the drop and solid-inside scenes (contact at t = 1/2,
  // and at every t) an accepted certificate must not claim what is false.
  std::mt19937_64 rng(7);
  const std::vector<json> atoms = {nullptr, true, 0, 1, 2, -1, 7, 1u << 31, "0", "1", "-1", "1/2", "3/8", "1/4", "5/8",
                                   "1/0", "0.5", "1e-3", "abc", "", 0.5, json::array(), json::object(),
                                   json::array({"0", "0", "1"}), json::array({0, 1}),
                                   json::array({"0", "1"}), json::object({{"sep", {"0", "0", "1"}}}),
                                   json::object({{"exact", "no_contact"}}),
                                   json::object({{"elements", {0}}}), json::object({{"children", {1, 2}}}),
                                   "safe", "collision", "undecided", "a", "b", "123456789012345678901234567890/7"};
  int ok = 0, rejected = 0, malformed = 0;
  for (int iteration = 0; iteration < 4000; ++iteration) {
    const auto& [scene_name, cert_name] = kValid[iteration % kValid.size()];
    static std::map<std::string, Case> cache;
    if (!cache.count(cert_name)) cache.emplace(cert_name, load(scene_name, cert_name));
    Case c = cache.at(cert_name);
    const int mutations = 1 + static_cast<int>(rng() % 3);
    for (int m = 0; m < mutations; ++m) {
      // Collect every value with its parent.
      std::vector<json*> nodes;
      std::vector<json*> stack{&c.certificate};
      while (!stack.empty()) {
        json* n = stack.back();
        stack.pop_back();
        nodes.push_back(n);
        if (n->is_object() || n->is_array())
          for (auto& child : *n) stack.push_back(&child);
      }
      json* target = nodes[rng() % nodes.size()];
      switch (rng() % 6) {
        case 0:
        case 1: *target = atoms[rng() % atoms.size()]; break;
        case 2:
          if (target->is_array() && !target->empty()) target->erase(rng() % target->size());
          else if (target->is_object() && !target->empty()) {
            auto it = target->begin();
            std::advance(it, rng() % target->size());
            target->erase(it.key());
          }
          break;
        case 3:
          if (target->is_array() && !target->empty()) target->push_back((*target)[rng() % target->size()]);
          break;
        case 4:
          if (target->is_string()) {
            // Nudge a rational.
            Exact x;
            if (parse_exact(target->get<std::string>(), x))
              *target = to_string(x + Exact(static_cast<int>(rng() % 5) - 2) / Exact(static_cast<int>(1 + rng() % 8)));
          }
          break;
        default:
          if (target->is_number_integer()) *target = static_cast<int>(rng() % 9) - 1;
      }
    }
    try {
      const cert::CheckOutcome out = cert::check_certificate(c.scene, c.certificate, "fuzz.json");
      if (!out.ok) {
        ++rejected;
        BOOST_TEST(!out.message.empty());
        continue;
      }
      ++ok;
      // No false claim about the drop (contact exactly at t = 1/2 only
      // within [3/8, 5/8]... the drop meets the triangle at t = 1/2) or the
      // triangle inside the solid (contact at every t).
      const json& ch = c.certificate["checks"][0];
      const std::string verdict = ch["verdict"].get<std::string>();
      const Exact contact = scene_name == "drop" ? Exact(1, 2) : scene_name == "solid-inside" ? Exact(0) : Exact(-1);
      if (contact >= 0) {
        BOOST_TEST(verdict != "safe", cert_name << " fuzzed into a false safe: " << ch.dump());
        if (verdict == "collision") BOOST_TEST(rat(ch.at("first_contact").at(0)) <= contact, ch.dump());
        if (verdict == "undecided") {
          const json& u = ch.at("undecided").at(0);
          BOOST_TEST(rat(u.is_object() ? u.at("t").at(0) : u.at(0)) <= contact, ch.dump());
        }
      }
    } catch (const InputError& e) {
      ++malformed;
      BOOST_TEST(std::string(e.what()).rfind("fuzz.json: ", 0) == 0, e.what());
    } catch (const std::exception& e) {
      BOOST_ERROR("fuzz iteration " << iteration << " threw " << e.what() << "\n" << c.certificate.dump());
    }
  }
  BOOST_TEST_MESSAGE("fuzz: " << ok << " accepted, " << rejected << " rejected, " << malformed << " malformed");
  BOOST_TEST(ok > 100);
  BOOST_TEST(rejected > 100);
  BOOST_TEST(malformed > 100);
}

BOOST_AUTO_TEST_CASE(scenes_that_cannot_be_certified) {
  // Two moving bodies with different intervals: bad input (the verifier
  // refuses the scene too).
  Case c = load("two-moving", "two-moving");
  c.scene.bodies[1].motion->t1 = 2;
  expect_malformed(c, "two moving bodies must share their motion interval");
}

// The checker's pose box of `body` at scene time t and the verifier's jet
// of `model` at segment parameter s: both tight, overlapping in every
// entry; returns the entries compared.
int compare_pose_enclosures(const Body& body, const SegmentModel& model, const Exact& t, const Exact& s,
                            const std::string& what) {
  const std::optional<cert::PoseBox> box = cert::pose_box_at(body, t);
  BOOST_REQUIRE(box);
  PoseJet jet;
  {
    RoundingGuard guard;
    jet = model.pose(Jet(to_interval(s)));
  }
  for (int e = 0; e < 12; ++e) {
    const double lo = CGAL::to_double(box->center[e] - box->radius[e]);
    const double hi = CGAL::to_double(box->center[e] + box->radius[e]);
    BOOST_TEST(hi - lo < 1e-12);
    BOOST_TEST(jet[e].v.sup() - jet[e].v.inf() < 1e-9);
    BOOST_TEST((jet[e].v.inf() <= hi && lo <= jet[e].v.sup()),
               what << " entry " << e << ": checker [" << lo << ", " << hi << "], verifier " << jet[e].v);
  }
  return 12;
}

// The checker's pose boxes (src/certificate/motions.cpp, Arb from the
// interpolations' definitions; the screw through V(phi)^-1) and the
// verifier's jets (src/motion/segment.cpp; the screw through a point on its
// axis) enclose the same poses: at sample parameters both boxes are tight
// and overlap in every entry.  A wrong sign or factor in either screw
// formula separates them by far more than their widths.
BOOST_AUTO_TEST_CASE(screw_enclosure_matches_the_verifiers) {
  int compared = 0;
  for (Interpolation how : {Interpolation::Slerp, Interpolation::Screw, Interpolation::Nlerp}) {
    for (int variant = 0; variant < 3; ++variant) {
      MotionSegment seg;
      seg.t0 = 0;
      seg.t1 = 2;
      seg.interpolation = how;
      seg.from.translation = v("0.5", "-1", "2");
      seg.to.translation = v("3", "0.25", "-1");
      seg.from.rotation.kind = Rotation::Kind::Rpy;
      seg.from.rotation.rpy = {q("0.3"), q("-0.2"), q("1.1")};
      if (variant == 0) {
        seg.to.rotation.kind = Rotation::Kind::Rpy;
        seg.to.rotation.rpy = {q("1.2"), q("0.4"), q("-0.5")};
      } else if (variant == 1) {
        seg.to.rotation.kind = Rotation::Kind::Quaternion;
        seg.to.rotation.quaternion = {q("2"), q("1"), q("-1"), q("3")};
      } else {
        seg.to.rotation.kind = Rotation::Kind::Rpy;
        seg.to.rotation.rpy = {q("0.3"), q("-0.2"), q("1.2")};  // a small turn
      }
      Body body;
      body.name = "b";
      body.trajectory = Trajectory{{seg}};
      const std::unique_ptr<SegmentModel> model = make_segment_model(seg);
      for (const char* st : {"0", "1/7", "1/2", "0.9", "1"})
        compared += compare_pose_enclosures(body, *model, q(st) * 2, q(st),
                                            "interpolation " + std::to_string(static_cast<int>(how)) + " variant " +
                                                std::to_string(variant) + " s = " + st);
    }
  }
  BOOST_TEST(compared == 3 * 3 * 5 * 12);
}

// The same for robot links: the checker's product of Rodrigues rotations
// and the verifier's sparse chain jets (src/motion/chain.*) on a chain with
// rpy and quaternion constants, two revolute joints (one axis not of unit
// length) and a prismatic one.
BOOST_AUTO_TEST_CASE(link_enclosure_matches_the_verifiers) {
  auto pose = [&](const char* x, const char* y, const char* z, std::array<const char*, 3> rpy) {
    Pose p;
    p.translation = v(x, y, z);
    p.rotation.kind = Rotation::Kind::Rpy;
    p.rotation.rpy = {q(rpy[0]), q(rpy[1]), q(rpy[2])};
    return p;
  };
  Pose quat;
  quat.translation = v("0", "0.1", "0.3");
  quat.rotation.kind = Rotation::Kind::Quaternion;
  quat.rotation.quaternion = {q("3"), q("1"), q("0"), q("-2")};
  std::vector<std::vector<Pose>> constants = {{pose("0", "0", "0.8", {"0", "0", "0.4"})},
                                              {pose("0.2", "0", "0.5", {"0.1", "-0.3", "0"}), quat},
                                              {pose("0.6", "0", "0", {"0", "0", "0"})},
                                              {pose("0", "0.05", "0.2", {"0.7", "0", "-0.2"})}};
  std::vector<ChainJoint> joints(3);
  joints[0].axis = v("0", "0", "1");
  joints[1].axis = v("0", "2", "1");  // length sqrt 5
  joints[2].kind = ChainJoint::Kind::Prismatic;
  joints[2].axis = v("1", "0", "0");
  auto link = std::make_shared<LinkMotion>();
  link->chain = std::make_shared<const LinkChain>(constants, joints);
  link->from = {q("-0.5"), q("0.25"), q("0")};
  link->to = {q("1.2"), q("-0.75"), q("0.3")};
  MotionSegment seg;
  seg.t0 = 0;
  seg.t1 = 1;
  seg.link = link;
  Body body;
  body.name = "link";
  body.trajectory = Trajectory{{seg}};
  const std::unique_ptr<SegmentModel> model = make_segment_model(seg);
  int compared = 0;
  for (const char* st : {"0", "1/3", "0.5", "0.77", "1"})
    compared += compare_pose_enclosures(body, *model, q(st), q(st), std::string("link s = ") + st);
  BOOST_TEST(compared == 5 * 12);
}

// The checker's exact link pose at a waypoint (its own product of the
// chain's constants and joints, src/certificate/motions.cpp) against the
// verifier's LinkChain::exact_pose: equal where the pose is rational (exact
// constants, revolute joints at 0, prismatic axes of rational length or at
// 0), absent in both elsewhere (a revolute joint off 0, a prismatic axis of
// irrational length off 0, an rpy constant).
BOOST_AUTO_TEST_CASE(exact_link_pose_matches_the_verifiers) {
  Pose quat;
  quat.translation = v("0", "0.1", "0.3");
  quat.rotation.kind = Rotation::Kind::Quaternion;
  quat.rotation.quaternion = {q("3"), q("1"), q("0"), q("-2")};
  Pose matrix;
  matrix.translation = v("1/3", "0", "-2");
  matrix.rotation.kind = Rotation::Kind::Matrix;
  matrix.rotation.matrix = {q("0"), q("-1"), q("0"), q("1"), q("0"), q("0"), q("0"), q("0"), q("1")};
  Pose rpy;
  rpy.translation = v("0", "0", "0.5");
  rpy.rotation.kind = Rotation::Kind::Rpy;
  rpy.rotation.rpy = {q("0.1"), q("0"), q("0")};
  Pose shift;
  shift.translation = v("0.25", "0", "0");
  std::vector<ChainJoint> joints(3);
  joints[0].axis = v("0", "0", "1");
  joints[1].kind = ChainJoint::Kind::Prismatic;
  joints[1].axis = v("3", "0", "4");  // length 5
  joints[2].kind = ChainJoint::Kind::Prismatic;
  joints[2].axis = v("1", "1", "0");  // length sqrt 2
  int exact = 0, compared = 0;
  for (const bool with_rpy : {false, true}) {
    const std::vector<std::vector<Pose>> constants = {
        {quat, matrix}, {shift}, {}, {with_rpy ? rpy : shift, matrix}};
    auto link = std::make_shared<LinkMotion>();
    const auto chain = std::make_shared<const LinkChain>(constants, joints);
    link->chain = chain;
    for (const std::vector<const char*>& from : std::vector<std::vector<const char*>>{
             {"0", "0", "0"}, {"0", "-1/7", "0"}, {"0", "2", "0.5"}, {"0.5", "0", "0"}, {"0", "3", "0"}}) {
      link->from = {q(from[0]), q(from[1]), q(from[2])};
      link->to = {q("1"), q("1"), q("1")};
      MotionSegment seg;
      seg.t0 = 0;
      seg.t1 = 1;
      seg.link = link;
      Body body;
      body.name = "link";
      body.trajectory = Trajectory{{seg}};
      const std::optional<Mat34E> theirs = chain->exact_pose(link->from);
      const std::optional<Mat34E> ours = cert::exact_pose_at(body, Exact(0));
      BOOST_TEST(theirs.has_value() == ours.has_value(), "from " << from[0] << " " << from[1] << " " << from[2]);
      if (theirs && ours) {
        BOOST_TEST((*theirs == *ours));
        ++exact;
      }
      ++compared;
    }
  }
  BOOST_TEST(compared == 10);
  BOOST_TEST(exact == 3);  // without rpy: every joint at 0, or only the prismatic of length 5 off 0
}

BOOST_AUTO_TEST_CASE(joint_curve_by_hand) {
  // two-moving.json: p on z = 1, 2, 1 with weights 1, 2, 1 (degree 2); q on
  // z = 0, -1 with weights 1, 3 (degree 1).  Product form, degree 3:
  //   W   = [1, 7/3, 13/3, 3]     (e.g. W_1 = (2/3) 2*1 + (1/3) 1*3)
  //   N_a z-translation = [1, 11/3, 25/3, 3]  ((w_a z_a) = [1, 4, 1] times w_b)
  //   N_b z-translation = [0, -1, -4, -3]     ((w_b z_b) = [0, -3] times w_a)
  //   N_a, N_b diagonal = W, other entries 0.
  const Scene s = parse_scene_file(data("two-moving.json"));
  const auto c = cert::detail::joint_control_points(s.bodies[0], s.bodies[1], Exact(0), Exact(1));
  BOOST_REQUIRE_EQUAL(c.size(), 4u);
  const std::vector<std::string> w = {"1", "7/3", "13/3", "3"}, za = {"1", "11/3", "25/3", "3"},
                                  zb = {"0", "-1", "-4", "-3"};
  for (int k = 0; k < 4; ++k) {
    BOOST_TEST(c[k][24] == q(w[k]));
    BOOST_TEST(c[k][11] == q(za[k]));
    BOOST_TEST(c[k][12 + 11] == q(zb[k]));
    for (int blk = 0; blk < 2; ++blk)
      for (int e = 0; e < 12; ++e) {
        const Exact& x = c[k][12 * blk + e];
        if (e == 0 || e == 5 || e == 10) BOOST_TEST(x == q(w[k]));
        else if (e != 11) BOOST_TEST(x == 0);
      }
  }
  // Constant weights: elevation only.  probe (degree 2, z = 1, 1/2, 1/2)
  // and the fixed triangle (identity elevated to degree 2); restricted to
  // [0, 1/4] by hand: z = 1, 7/8, 25/32.
  const Scene p = parse_scene_file(data("probe-safe.json"));
  const auto r = cert::detail::joint_control_points(p.bodies[0], p.bodies[1], Exact(0), Exact(1, 4));
  BOOST_REQUIRE_EQUAL(r.size(), 3u);
  BOOST_TEST(r[0][11] == q("1"));
  BOOST_TEST(r[1][11] == q("7/8"));
  BOOST_TEST(r[2][11] == q("25/32"));
  // Both moving, constant weights 2, 2 and 1, 1, 1: degree elevation of
  // a's line z = 0, 1 to degree 2 (z = 0, 1/2, 1), b as it is, W = 1.
  const Scene both = parse_scene_text(R"({"format": "tmcert-scene/1", "bodies": [
    {"name": "a", "points": [[0, 0, 0]], "motion": {"type": "rational_bezier", "weights": [2, 2], "control_points": [
      [[1,0,0,0],[0,1,0,0],[0,0,1,0]], [[1,0,0,0],[0,1,0,0],[0,0,1,1]]]}},
    {"name": "b", "points": [[0, 0, 0]], "motion": {"type": "rational_bezier", "control_points": [
      [[1,0,0,0],[0,1,0,0],[0,0,1,0]], [[1,0,0,0],[0,1,0,0],[0,0,1,3]], [[1,0,0,0],[0,1,0,0],[0,0,1,0]]]}}],
    "checks": [["a", "b"]]})", "both.json");
  const auto e = cert::detail::joint_control_points(both.bodies[0], both.bodies[1], Exact(0), Exact(1));
  BOOST_REQUIRE_EQUAL(e.size(), 3u);
  const std::vector<std::string> ea = {"0", "1/2", "1"}, eb = {"0", "3", "0"};
  for (int k = 0; k < 3; ++k) {
    BOOST_TEST(e[k][24] == 1);
    BOOST_TEST(e[k][0] == 1);
    BOOST_TEST(e[k][11] == q(ea[k]));
    BOOST_TEST(e[k][12 + 11] == q(eb[k]));
  }
  BOOST_CHECK_THROW(cert::detail::joint_control_points(p.bodies[0], p.bodies[1], Exact(1, 2), Exact(1, 2)),
                    std::invalid_argument);
  BOOST_CHECK_THROW(cert::detail::joint_control_points(p.bodies[0], p.bodies[1], Exact(0), Exact(2)),
                    std::invalid_argument);
  for (int k = 0; k < 3; ++k) {
    BOOST_TEST(r[k][24] == 1);
    BOOST_TEST(r[k][12] == 1);
    BOOST_TEST(r[k][12 + 3] == 0);
    BOOST_TEST(r[k][3] == q("1/4"));
  }
}

BOOST_AUTO_TEST_CASE(restricted_joint_curve_is_the_motion) {
  // The first and last control points of every restriction are the two
  // bodies' poses (pose_at, a separate evaluation) at the piece's ends,
  // for the product form, the elevation form, and a fixed body.
  std::vector<Scene> scenes = {parse_scene_file(data("two-moving.json")), parse_scene_file(data("probe-safe.json")),
                               parse_scene_file(data("drop.json")), parse_scene_file(data("solid-singular.json"))};
  // Both moving with constant weights of different degrees and a rotation-like
  // rational motion of degree 3 against one of degree 2.
  const std::string both = R"({"format": "tmcert-scene/1", "bodies": [
    {"name": "a", "points": [[0, 0, 0]], "motion": {"type": "rational_bezier", "control_points": [
      [[1,0,0,0],[0,1,0,0],[0,0,1,0]], [[1,-1,0,"1/3"],[1,1,0,0],[0,0,2,1]], [[0,-1,0,1],[1,0,0,2],[0,0,1,0]],
      [[0,"-1/2",0,1],[2,0,0,3],[0,0,1,"0.25"]]], "weights": [1, "1/2", "0.5", 1]}},
    {"name": "b", "points": [[1, 1, 1]], "motion": {"type": "rational_bezier", "control_points": [
      [[1,0,0,0],[0,1,0,0],[0,0,1,0]], [[2,0,0,1],[0,1,0,0],[0,0,1,0]], [[1,0,0,0],[0,3,0,0],[0,1,1,-2]]],
      "weights": [2, 2, 2]}}], "checks": [["a", "b"]]})";
  scenes.push_back(parse_scene_text(both, "inline"));
  std::string swapped = both;
  const std::string pair = "[[\"a\", \"b\"]]";
  swapped.replace(swapped.find(pair), pair.size(), "[[\"b\", \"a\"]]");
  scenes.push_back(parse_scene_text(swapped, "inline-swapped"));
  std::mt19937_64 rng(3);
  for (const Scene& s : scenes)
    for (const auto& [ia, ib] : s.checks) {
      const Body& a = s.bodies[ia];
      const Body& b = s.bodies[ib];
      const Motion* m = a.motion && a.motion->degree() >= 1 ? &*a.motion : b.motion ? &*b.motion : nullptr;
      const Exact t0 = m ? m->t0 : Exact(0), t1 = m ? m->t1 : Exact(1);
      for (int trial = 0; trial < 12; ++trial) {
        const long d = 1 + static_cast<long>(rng() % 64);
        long i = static_cast<long>(rng() % d), j = static_cast<long>(rng() % d);
        if (i > j) std::swap(i, j);
        ++j;
        const Exact ua(i, d), ub(j, d);
        const auto c = cert::detail::joint_control_points(a, b, ua, ub);
        for (const auto& [cp, u] : {std::pair{c.front(), ua}, std::pair{c.back(), ub}}) {
          const Exact t = t0 + u * (t1 - t0);
          const Mat34E pa = cert::pose_at(a, t), pb = cert::pose_at(b, t);
          for (int e = 0; e < 12; ++e) {
            BOOST_TEST(cp[e] / cp[24] == pa[e]);
            BOOST_TEST(cp[12 + e] / cp[24] == pb[e]);
          }
        }
        for (const auto& cp : c) BOOST_TEST(cp[24] > 0);
      }
    }
}

BOOST_AUTO_TEST_CASE(pose_by_hand) {
  const Scene s = parse_scene_file(data("two-moving.json"));
  // p at t = 1/2: z = (1/4 + 2*(1/2)*2 + 1/4) / (1/4 + 2*(1/2) + 1/4) = (5/2) / (3/2) = 5/3.
  const Mat34E p = cert::pose_at(s.bodies[0], Exact(1, 2));
  BOOST_TEST(p[11] == Exact(5, 3));
  BOOST_TEST(p[0] == 1);
  BOOST_TEST(p[3] == 0);
  // q at t = 1/4: z = (3/4 * 0 + 3 * 1/4 * -1) / (3/4 + 3/4) = -1/2.
  BOOST_TEST(cert::pose_at(s.bodies[1], Exact(1, 4))[11] == Exact(-1, 2));
  // A body without motion: the identity.
  const Scene d = parse_scene_file(data("drop.json"));
  const Mat34E id = cert::pose_at(d.bodies[1], Exact(7));
  for (int e = 0; e < 12; ++e) BOOST_TEST(id[e] == ((e == 0 || e == 5 || e == 10) ? 1 : 0));
  BOOST_TEST(cert::pose_at(d.bodies[0], Exact(3, 8))[11] == Exact(1, 4));  // z = 1 - 2t
}

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

BOOST_AUTO_TEST_CASE(a_larger_certificate_is_checked_quickly) {
  // A 24 x 24 grid of triangles (1152 elements) hovering 1/100 above a
  // 4 x 4 plate, moving on a rational cubic; a binary hierarchy of groups
  // on the grid, 64 pieces, each proven by splitting down to groups of 9
  // triangles: 8192 separations.
  std::ostringstream s;
  s << R"({"format": "tmcert-scene/1", "bodies": [ {"name": "grid", "polygons": [)";
  const int n = 24;
  bool first = true;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < 2; ++k) {
        const std::string x0 = std::to_string(i) + "/" + std::to_string(n), x1 = std::to_string(i + 1) + "/" + std::to_string(n);
        const std::string y0 = std::to_string(j) + "/" + std::to_string(n), y1 = std::to_string(j + 1) + "/" + std::to_string(n);
        s << (first ? "" : ",") << "[[\"" << x0 << "\",\"" << y0 << "\",0],[\"" << (k ? x0 : x1) << "\",\"" << (k ? y1 : y0)
          << "\",0],[\"" << x1 << "\",\"" << y1 << "\",\"0.001\"]]";
        first = false;
      }
  s << R"(], "motion": {"type": "rational_bezier", "control_points": [
      [[1,0,0,0],[0,1,0,0],[0,0,1,"0.01"]], [[1,0,0,"0.3"],[0,1,0,0],[0,0,1,"0.02"]],
      [[1,0,0,"0.6"],[0,1,0,"0.1"],[0,0,1,"0.011"]], [[1,0,0,1],[0,1,0,"0.2"],[0,0,1,"0.0105"]]],
      "weights": [1, "1.5", 2, 1]}},
    {"name": "plate", "polygons": [[[-1,-1,0],[3,-1,0],[3,3,0],[-1,3,0]]]} ],
    "checks": [["grid", "plate"]]})";
  const Scene scene = parse_scene_text(s.str(), "grid.json");
  const std::size_t elements = 2 * n * n;
  // Groups: a complete binary split of the element range down to 16 elements.
  json groups = json::array();
  std::vector<std::pair<std::size_t, std::size_t>> ranges{{0, elements}};
  for (std::size_t k = 0; k < ranges.size(); ++k) {
    const auto [lo, hi] = ranges[k];
    if (hi - lo <= 16) {
      json e = json::array();
      for (std::size_t x = lo; x < hi; ++x) e.push_back(x);
      groups.push_back({{"elements", e}});
    } else {
      const std::size_t mid = (lo + hi) / 2;
      groups.push_back({{"children", {ranges.size(), ranges.size() + 1}}});
      ranges.push_back({lo, mid});
      ranges.push_back({mid, hi});
    }
  }
  std::function<json(std::size_t)> proof = [&](std::size_t g) -> json {
    if (groups[g].contains("elements")) return {{"sep", {"0", "0", "1"}}};
    return {{"split", 0}, {"parts", {proof(groups[g]["children"][0]), proof(groups[g]["children"][1])}}};
  };
  json pieces = json::array();
  for (int k = 0; k < 64; ++k)
    pieces.push_back({{"t", {std::to_string(k) + "/64", std::to_string(k + 1) + "/64"}}, {"proof", proof(0)}});
  const json doc = {{"format", "tmcert-certificate/1"},
                    {"scene_bodies", {{{"name", "grid"}, {"elements", elements}}, {{"name", "plate"}, {"elements", 1}}}},
                    {"checks", {{{"bodies", {"grid", "plate"}},
                                 {"verdict", "safe"},
                                 {"interval", {"0", "1"}},
                                 {"groups", {groups, json::array({{{"elements", {0}}}})}},
                                 {"pieces", pieces}}}}};
  const auto started = std::chrono::steady_clock::now();
  const cert::CheckOutcome out = cert::check_certificate(scene, doc, "grid.cert.json");
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  BOOST_TEST(out.ok, out.message);
  BOOST_TEST_MESSAGE("grid certificate: " << (out.proven.empty() ? out.message : out.proven[0]) << " in " << seconds << " s");
  BOOST_TEST(seconds < 20.0);
  // Lowering the hover below the grid's relief (0.001) breaks one claim.
  json low = doc;
  low["checks"][0]["pieces"][63]["proof"] = {{"sep", {"1", "0", "20"}}};
  const cert::CheckOutcome bad = cert::check_certificate(scene, low, "grid.cert.json");
  BOOST_TEST(!bad.ok);
  BOOST_TEST(bad.message.find("pieces[63] [63/64, 1]: proof (groups 0, 0): separation fails") != std::string::npos,
             bad.message);
}

BOOST_AUTO_TEST_SUITE_END()
