// The checker's proof trees (src/certificate/check_proof.cpp): each
// tampering with a separation, a group or a proof tree is rejected with
// the claim it breaks; exact no-contact claims are re-verified.
#include "tests/certificate/check_support.h"

using namespace check_test;

BOOST_AUTO_TEST_SUITE(certificate_check)

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

// Shared proof nodes (docs/certificate-format.md "Shared proof nodes"): a
// node is judged at every use, for the groups and the piece there; a
// tampered shared node is rejected where it is used.
BOOST_AUTO_TEST_CASE(shared_proof_nodes_are_judged_at_each_use) {
  auto shared = [] {
    Case c = load("probe-safe", "probe-safe");
    c.certificate["format"] = "tmcert-certificate/2";
    check0(c)["nodes"] = json::array({{{"sep", {0, 0, 1}}}, {{"sep", {-1, 0, 1}}}, json::array({0, 0, 1})});
    check0(c)["pieces"][0]["proof"] = 0;
    check0(c)["pieces"][1]["proof"] = 2;
    return c;
  };
  {
    const Case c = shared();
    BOOST_TEST(check(c).ok, check(c).message);
    BOOST_TEST(check(c).proven.size() == 1u);
  }
  {
    Case c = shared();
    check0(c)["nodes"][1]["sep"][2] = "1/4";  // as in tampered_separations_are_rejected
    expect_rejected(c, "pieces[1] [1/4, 1/2]: proof.parts[1] (groups 2, 0): separation fails at control point 0");
  }
  {
    // (1, 0, 1) holds on piece 0 and fails on piece 2, both using it.
    Case c = shared();
    check0(c)["nodes"].push_back({{"sep", {1, 0, 1}}});
    check0(c)["pieces"][0]["proof"] = 3;
    BOOST_TEST(check(c).ok, check(c).message);
    check0(c)["pieces"][2]["proof"] = 3;
    expect_rejected(c, "pieces[2] [1/2, 1]: proof (groups 0, 0): separation fails at control point 0");
  }
  {
    // A split of the triangle's group 0, which has no children.
    Case c = shared();
    check0(c)["nodes"][2] = json::array({1, 0});
    expect_rejected(c, "pieces[1] [1/4, 1/2]: proof (groups 0, 0): split 1 of group 0, which has no children");
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

BOOST_AUTO_TEST_SUITE_END()
