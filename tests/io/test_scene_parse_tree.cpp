// The scene reader's JSON tree (src/io/parse.cpp: every value in one
// array, keys and text pooled, paths spelled out only for messages) and the
// result writer (src/report/report.cpp), against what they replaced: error
// paths into containers that follow nested ones, duplicate keys in large
// objects, number tokens near the double range, and the result document
// byte for byte as nlohmann's dump(2) writes it.
#include "src/report/report.h"
#include "src/io/parse.h"

#include <boost/test/unit_test.hpp>
#include <nlohmann/json.hpp>

#include <string>

using tmcert::Exact;
using tmcert::InputError;
using tmcert::Scene;

namespace {

const std::string kPoint = R"({"name": "a", "points": [[0,0,0]]})";

std::string error_of(const std::string& text) {
  try {
    tmcert::parse_scene_text(text, "t.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string scene_of(const std::string& bodies, const std::string& extra = "") {
  return R"({"format": "tmcert-scene/1", "bodies": [)" + bodies + "]" + (extra.empty() ? "" : ", " + extra) + "}";
}

// An object of `n` annotation members "_k0" .. "_k<n-1>", then `tail`.
std::string annotations(int n, const std::string& tail) {
  std::string out = "{";
  for (int i = 0; i < n; ++i) out += "\"_k" + std::to_string(i) + "\": " + std::to_string(i) + ", ";
  return out + tail + "}";
}

}  // namespace

BOOST_AUTO_TEST_CASE(error_paths_count_items_after_nested_containers) {
  // The bad value follows finished containers at every level.
  const std::string b = R"({"name": "b", "polygons": [[[0,0,0],[1,0,0],[0,1,0]], [[0,0,0],[1,0,0],[0,1,true]]]})";
  BOOST_TEST(error_of(scene_of(kPoint + ", " + b)) ==
             "t.json: bodies[1].polygons[1][2][2]: expected a number, got a boolean");
  BOOST_TEST(error_of(scene_of(kPoint, R"("_x": [[1, [2]], {"a": [3]}, [[[]]]], "checks": [["a", "a"], 7])")) ==
             "t.json: checks[0]: a body cannot be checked against itself");
  // Found while the containers are open: a duplicate key, too many levels.
  BOOST_TEST(error_of(scene_of(kPoint, R"("_x": [[1, [2]], {"a": [3]}, {"b": {"c": 1, "c": 2}}])")) ==
             "t.json: _x[2].b.c: duplicate key \"c\"");
  BOOST_TEST(error_of(scene_of(kPoint, R"("_x": [{}, [], {"we ird": [0, {"k": 1, "k": 1}]}])")) ==
             "t.json: _x[2][\"we ird\"][1].k: duplicate key \"k\"");
  BOOST_TEST(error_of(scene_of(kPoint, R"("_x": [[], [[]], )" + std::string(70, '[') + std::string(70, ']') + "]")) ==
             "t.json: _x[2]" + [] {
               std::string p;
               for (int i = 0; i < 62; ++i) p += "[0]";  // with _x and [2]: 64 levels
               return p;
             }() + ": nesting deeper than 64 levels");
}

BOOST_AUTO_TEST_CASE(duplicate_keys_in_large_objects) {
  for (int n : {1, 15, 16, 17, 40}) {
    BOOST_TEST_INFO("members before the duplicate: " << n);
    BOOST_TEST(error_of(scene_of(annotations(n, R"("_k0": 1, "name": "a", "points": [[0,0,0]])"))) ==
               "t.json: bodies[0]._k0: duplicate key \"_k0\"");
    BOOST_TEST(error_of(scene_of(annotations(n, "\"_k" + std::to_string(n - 1) + "\": 1"))) ==
               "t.json: bodies[0]._k" + std::to_string(n - 1) + ": duplicate key \"_k" + std::to_string(n - 1) + "\"");
  }
  const std::string both = scene_of(annotations(40, R"("name": "a", "points": [[0,0,0]])") + "," +
                                        R"({"name": "b", "points": [[1,0,0]], "motion": {"type": "rational_bezier",
                                            "control_points": [[[1,0,0,0],[0,1,0,0],[0,0,1,0]]]}})");
  BOOST_TEST(tmcert::parse_scene_text(both, "t.json").bodies.size() == 2u);
}

BOOST_AUTO_TEST_CASE(number_tokens_near_the_double_range) {
  auto z = [](const std::string& token) {
    return tmcert::parse_scene_text(scene_of(R"({"name": "a", "points": [[0,0,)" + token + "]]}"), "t.json")
        .bodies[0]
        .points[0][2];
  };
  Exact expected;
  for (const std::string digits : {std::string(300, '9'), std::string(308, '9'), std::string(309, '9'),
                                   std::string(320, '9') + ".5"}) {
    BOOST_REQUIRE(tmcert::parse_exact(digits, expected));
    BOOST_TEST(z(digits) == expected);
    BOOST_TEST(z("-" + digits) == -expected);
  }
  BOOST_REQUIRE(tmcert::parse_exact("17e307", expected));
  BOOST_TEST(z("1.7e308") == expected);
  BOOST_REQUIRE(tmcert::parse_exact("2e308", expected));
  BOOST_TEST(z("2e308") == expected);
  BOOST_REQUIRE(tmcert::parse_exact("1e-400", expected));
  BOOST_TEST(z("1e-400") == expected);
}

namespace {

// The double nearest to x (ties: either), from the tight interval CGAL
// encloses it in: an approximation computed independently of
// kernels/decimal.
double nearest_double(const Exact& x) {
  const std::pair<double, double> range = CGAL::to_interval(x);
  if (range.first == range.second) return range.first;
  return x - Exact(range.first) <= Exact(range.second) - x ? range.first : range.second;
}

// The result document as nlohmann's ordered_json wrote it before the
// writer of report.cpp replaced it.
std::string reference_json(const Scene& scene, const tmcert::SceneResult& r) {
  using nlohmann::ordered_json;
  using tmcert::to_string;
  ordered_json j;
  j["format"] = "tmcert-result/1";
  j["verdict"] = to_string(r.verdict);
  j["kernel"] = to_string(r.kernel);
  j["certified"] = r.certified;
  j["epsilon"] = to_string(r.epsilon);
  j["epsilon_approx"] = nearest_double(r.epsilon);
  j["epsilon_per_check"] = r.epsilon_per_check;
  j["checks"] = ordered_json::array();
  for (const tmcert::CheckResult& c : r.checks) {
    ordered_json k;
    k["bodies"] = {scene.bodies[c.bodies[0]].name, scene.bodies[c.bodies[1]].name};
    k["verdict"] = to_string(c.verdict);
    k["epsilon"] = to_string(c.epsilon);
    k["epsilon_approx"] = nearest_double(c.epsilon);
    k["refined"] = c.refined;
    // An irrational time as the contract writes it.
    auto root = [](const tmcert::AlgebraicTime& a) {
      ordered_json coefficients = ordered_json::array();
      for (const CGAL::Gmpz& x : a.root_of) coefficients.push_back(to_string(Exact(x)));
      return ordered_json{{"root_of", coefficients}, {"interval", {to_string(a.lo), to_string(a.hi)}}, {"approx", a.approx}};
    };
    const tmcert::AlgebraicTime* at = c.witness && c.witness->root ? &*c.witness->root : nullptr;
    // The approximations: doubles of the exact numbers (the test's values
    // are all far from rounding ties), an algebraic number's own approx.
    auto approx = [](const Exact& x) { return nearest_double(x); };
    const double at_approx = at ? std::stod(at->approx) : 0.0;
    if (c.first_contact && at)
      k["first_contact"] = {{"t", {c.first_contact_exact ? root(*at) : ordered_json(to_string(c.first_contact->first)), root(*at)}},
                            {"t_approx", {c.first_contact_exact ? at_approx : approx(c.first_contact->first), at_approx}}};
    else if (c.first_contact)
      k["first_contact"] = {{"t", {to_string(c.first_contact->first), to_string(c.first_contact->second)}},
                            {"t_approx", {approx(c.first_contact->first), approx(c.first_contact->second)}}};
    if (c.witness && at) {
      ordered_json box = ordered_json::array(), box_approx = ordered_json::array();
      if (c.witness->point_box)
        for (const auto& range : *c.witness->point_box) {
          box.push_back({to_string(range[0]), to_string(range[1])});
          box_approx.push_back({approx(range[0]), approx(range[1])});
        }
      k["witness"] = {{"t", root(*at)}, {"t_approx", at_approx}, {"features", {c.witness->features[0], c.witness->features[1]}},
                      {"point_box", box}, {"point_box_approx", box_approx}};
    } else if (c.witness) {
      const tmcert::Vec3E& p = c.witness->point;
      k["witness"] = {{"t", to_string(c.witness->t)},
                      {"t_approx", approx(c.witness->t)},
                      {"features", {c.witness->features[0], c.witness->features[1]}},
                      {"point", {to_string(p[0]), to_string(p[1]), to_string(p[2])}},
                      {"point_approx", {approx(p[0]), approx(p[1]), approx(p[2])}}};
    }
    ordered_json und = ordered_json::array();
    for (const tmcert::UndecidedInterval& u : c.undecided)
      und.push_back({{"t", {to_string(u.t0), to_string(u.t1)}},
                     {"t_approx", {approx(u.t0), approx(u.t1)}},
                     {"reason", to_string(u.reason)}});
    k["undecided"] = und;
    // The witness ends the claims: [its time, the interval's end] not searched.
    if (c.witness && at)
      k["not_searched"] = {root(*at), to_string(c.interval.second)}, k["not_searched_approx"] = {at_approx, approx(c.interval.second)};
    else if (c.witness)
      k["not_searched"] = {to_string(c.witness->t), to_string(c.interval.second)},
      k["not_searched_approx"] = {approx(c.witness->t), approx(c.interval.second)};
    const tmcert::CheckStats& s = c.stats;
    k["stats"] = {{"nodes", s.nodes},
                  {"max_depth", s.max_depth},
                  {"predicate_calls", s.contact.calls},
                  {"exact_fallbacks", s.contact.exact_fallbacks},
                  {"vertex_face_calls", s.by_kind[0].calls},
                  {"vertex_face_exact", s.by_kind[0].exact_fallbacks},
                  {"edge_edge_calls", s.by_kind[1].calls},
                  {"edge_edge_exact", s.by_kind[1].exact_fallbacks},
                  {"face_vertex_calls", s.by_kind[2].calls},
                  {"face_vertex_exact", s.by_kind[2].exact_fallbacks},
                  {"exact_static_tests", s.static_tests},
                  {"static_configurations", s.static_configurations},
                  {"static_filter_pairs", s.static_filter_pairs},
                  {"static_filter_exact", s.static_filter_exact},
                  {"sphere_tests", s.sphere_tests},
                  {"slab_clears", s.slab_clears},
                  {"swept_clears", s.swept_clears},
                  {"hull_clears", s.hull_clears},
                  {"axis_clears", s.axis_clears},
                  {"stops", s.stops},
                  {"exact_pieces", s.exact_pieces},
                  {"exact_undecided", s.exact_unknown},
                  {"prefiltered", s.prefiltered},
                  {"seconds", s.seconds}};
    j["checks"].push_back(k);
  }
  return j.dump(2) + "\n";
}

}  // namespace

BOOST_AUTO_TEST_CASE(result_json_is_written_as_nlohmann_dumps_it) {
  Scene scene;
  for (const char* name : {"plain", "qu\"ote \\ tab\t nl\n ctl\x01 del\x7f", "r\xc3\xa9sum\xc3\xa9 \xe2\x9c\x93"}) {
    tmcert::Body b;
    b.name = name;
    scene.bodies.push_back(b);
  }
  tmcert::SceneResult r;
  r.verdict = tmcert::Verdict::Collision;
  r.epsilon = Exact(1, 1000);
  BOOST_TEST(tmcert::result_json(scene, r) == reference_json(scene, r));  // no checks

  tmcert::CheckResult safe;
  safe.bodies = {0, 1};
  safe.verdict = tmcert::Verdict::Safe;
  safe.stats.prefiltered = true;
  safe.stats.seconds = 1e-05;
  r.checks.push_back(safe);

  tmcert::CheckResult hit;
  hit.bodies = {2, 1};
  hit.verdict = tmcert::Verdict::Collision;
  hit.first_contact = std::make_pair(Exact(3, 8), Exact(25, 64));
  hit.witness = tmcert::Witness{Exact(3, 8), {scene.bodies[2].name + " polygon 0 vertex 2", "b segment 1"},
                                {Exact(1, 2), Exact(-1, 3), Exact(0)}};
  hit.undecided.push_back({Exact(1, 2), Exact(33, 64), tmcert::StopReason::Epsilon});
  hit.undecided.push_back({Exact(5, 8), Exact(1), tmcert::StopReason::Depth});
  hit.undecided.push_back({Exact(1), Exact(2), tmcert::StopReason::AfterUndecided});
  hit.interval = {Exact(0), Exact(7, 3)};
  hit.stats.nodes = 173;
  hit.stats.max_depth = 8;
  hit.stats.contact.calls = 18446744073709551615ull;
  hit.stats.by_kind[1].exact_fallbacks = 3;
  hit.stats.seconds = 2.0;
  hit.epsilon = Exact(248723, 100000000);
  r.checks.push_back(hit);

  // A contact at an irrational time: root, interval and point box.
  tmcert::CheckResult algebraic = hit;
  algebraic.undecided.clear();
  tmcert::AlgebraicTime sqrt_half{{CGAL::Gmpz(-1), CGAL::Gmpz(0), CGAL::Gmpz(2)}, Exact(7, 10), Exact(71, 100), "0.707106781186548"};
  algebraic.witness->root = sqrt_half;
  algebraic.witness->t = sqrt_half.lo;
  algebraic.witness->point_box = {{{Exact(0), Exact(1, 4)}, {Exact(-1), Exact(1)}, {Exact(3), Exact(3)}}};
  algebraic.first_contact = std::make_pair(sqrt_half.lo, sqrt_half.hi);
  algebraic.first_contact_exact = true;
  r.checks.push_back(algebraic);
  algebraic.first_contact = std::make_pair(Exact(1, 2), sqrt_half.hi);  // an undecided piece before it
  algebraic.first_contact_exact = false;
  r.checks.push_back(algebraic);

  tmcert::CheckResult slow = safe;
  slow.verdict = tmcert::Verdict::Undecided;
  slow.stats.seconds = 123456.789;
  r.checks.push_back(slow);

  r.kernel = tmcert::KernelKind::Fast;
  r.certified = false;
  BOOST_TEST(tmcert::result_json(scene, r) == reference_json(scene, r));
}
