// The independent certificate checker as a whole (src/certificate/check.h,
// docs/certificate-format.md, proofs/certificates.md): hand-built
// certificates for tiny scenes pass; another scene's certificate is
// rejected; seeded fuzzing of valid certificates never crashes and never
// proves a false claim; a larger certificate is checked quickly.
#include "tests/certificate/check_support.h"
#include <chrono>
#include <functional>
#include <random>
#include <sstream>

using namespace check_test;

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
