// The checker's judging (src/certificate/check_judge.cpp): each tampering
// with a tiling, a verdict, a witness or a start claim is rejected with the
// claim it breaks.
#include "src/certificate/writer.h"
#include "src/verify/verify.h"
#include "tests/certificate/check_support.h"

using namespace check_test;

namespace {
// A scene of tests/data/scenes, verified and certified here (its cover
// recorded for the certificate).
Case certified(const std::string& scene) {
  Case c;
  c.scene = parse_scene_file(std::string(TMCERT_TEST_DATA) + "/scenes/" + scene + ".json");
  tmcert::VerifyOptions options;
  options.record_cover = true;
  c.certificate = json::parse(cert::certificate_json(c.scene, tmcert::verify_scene(c.scene, options)));
  return c;
}
}  // namespace

BOOST_AUTO_TEST_SUITE(certificate_check)

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

// A toleranced contact at an enclosed pose (proofs/enclosures.md section
// 6): the plate, turning by slerp, is translated within its tolerance into
// the post; the checker translates its own pose box of the plate by the
// displacement and re-decides the tolerance (W = 6, r = 1/10).
BOOST_AUTO_TEST_CASE(enclosed_witness_with_displacement) {
  Case c = certified("tolerance-plate-post-slerp-collision");
  const json& w = check0(c)["witness"];
  BOOST_REQUIRE(w.contains("point_box"));
  BOOST_REQUIRE(w.contains("displacement"));
  BOOST_TEST(w["displaced"] == "a");
  BOOST_TEST(check(c).ok, check(c).message);
  {
    Case d = c;
    check0(d)["witness"]["displacement"] = json::array({"0", "0", "0"});  // the nominal poses do not touch
    expect_rejected(d, "is not certain over the enclosed poses");
  }
  {
    Case d = c;
    check0(d)["witness"]["displacement"] = json::array({"0", "1/24", "0"});  // (1/24)^2 * 6 > 1/100
    expect_rejected(d, "witness.displacement: (0, 1/24, 0) is not within the tolerance 1/10 of \"plate\"");
  }
  {
    Case d = c;
    check0(d)["witness"]["points"] = json::array({json::array({"0", "0", "0"}), json::array({"0", "0", "0"})});
    expect_malformed(d, "a witness at an enclosed pose has no points");
  }
}

// A clearance violated only between slerp keyframes (proofs/clearance.md
// section 6): each side gives an element and weights in its body's frame;
// the checker places the two points by its own pose boxes at t and bounds
// their distance by the clearance, exactly.
BOOST_AUTO_TEST_CASE(enclosed_clearance_witness) {
  Case c = certified("clearance-slerp-between-keyframes-violated");
  const json& w = check0(c)["witness"];
  BOOST_REQUIRE(w.contains("points_box"));
  BOOST_TEST(!w.contains("point"));
  BOOST_TEST(check(c).ok, check(c).message);
  {
    Case d = c;  // at the start the plate is 3/2 or more from the post
    check0(d)["witness"]["t"] = "0";
    expect_rejected(d, "may be farther apart than the clearance");
  }
  {
    Case d = c;  // the post's point moved to its end z = -1, the plate's to its far corner
    json& wa = check0(d)["witness"]["a"]["weights"];
    BOOST_REQUIRE(wa.size() == 2);
    wa = json::array({"1", "0"});
    json& wb = check0(d)["witness"]["b"]["weights"];
    BOOST_REQUIRE(wb.size() == 3);
    wb = json::array({"0", "0", "1"});
    expect_rejected(d, "may be farther apart than the clearance");
  }
  {
    Case d = c;
    check0(d)["witness"]["a"]["weights"][0] = "2";
    expect_rejected(d, "weights sum to");
  }
  {
    Case d = c;
    check0(d)["witness"]["points"] = json::array({json::array({"0", "0", "0"}), json::array({"0", "0", "0"})});
    expect_malformed(d, "a clearance witness at an enclosed pose has no points");
  }
}

// Both bodies toleranced (proofs/witness.md, "Two displacements"): the
// witness translates the box by `displacement` and the wall by
// `displacement_other`, each within its own tolerance; the checker applies
// both to the exact poses and bounds each by its body's tolerance.
BOOST_AUTO_TEST_CASE(two_displacements) {
  Case c = certified("tolerance-both-translation-violated");
  const json& w = check0(c)["witness"];
  BOOST_REQUIRE(w.contains("displacement"));
  BOOST_REQUIRE(w.contains("displacement_other"));
  BOOST_TEST(w["displaced"] == "a");
  BOOST_TEST(check(c).ok, check(c).message);
  {
    Case d = c;  // the wall left at its nominal pose: the point is not on it
    check0(d)["witness"].erase("displacement_other");
    expect_rejected(d, "witness.b: element");
  }
  {
    Case d = c;  // (1/20)^2 * 8 = 1/50 > 1/100
    check0(d)["witness"]["displacement_other"] = json::array({"0", "-1/20", "0"});
    expect_rejected(d, "witness.displacement_other: (0, -1/20, 0) is not within the tolerance 1/10 of \"wall\"");
  }
  {
    Case d = c;
    check0(d)["witness"].erase("displacement");
    check0(d)["witness"].erase("displaced");
    expect_malformed(d, "needs \"displacement\" and \"displaced\"");
  }
}

// A clearance and a tolerance together at an enclosed pose
// (proofs/clearance.md section 8): the plate's pose box translated by the
// displacement, the two weighted points within the clearance.
BOOST_AUTO_TEST_CASE(enclosed_clearance_witness_with_displacement) {
  Case c = certified("tolerance-clearance-slerp-between-keyframes-violated");
  const json& w = check0(c)["witness"];
  BOOST_REQUIRE(w.contains("points_box"));
  BOOST_REQUIRE(w.contains("displacement"));
  BOOST_TEST(w["displaced"] == "b");
  BOOST_TEST(check(c).ok, check(c).message);
  {
    Case d = c;  // without the translation the plate stays 3/10 or more away
    check0(d)["witness"]["displacement"] = json::array({"0", "0", "0"});
    expect_rejected(d, "may be farther apart than the clearance");
  }
  {
    Case d = c;  // (1/10)^2 * 4 = 1/25 > 9/400
    check0(d)["witness"]["displacement"] = json::array({"0", "-1/10", "0"});
    expect_rejected(d, "witness.displacement: (0, -1/10, 0) is not within the tolerance 3/20 of \"plate\"");
  }
}

BOOST_AUTO_TEST_SUITE_END()
