#include "src/cli/report.h"

#include <nlohmann/json.hpp>

#include <sstream>

namespace tmcert {

namespace {

nlohmann::ordered_json check_json(const Scene& scene, const CheckResult& c) {
  nlohmann::ordered_json j;
  j["bodies"] = {scene.bodies[c.bodies[0]].name, scene.bodies[c.bodies[1]].name};
  j["verdict"] = to_string(c.verdict);
  if (c.first_contact) j["first_contact"] = {{"t", {to_string(c.first_contact->first), to_string(c.first_contact->second)}}};
  if (c.witness) {
    const Witness& w = *c.witness;
    j["witness"] = {{"t", to_string(w.t)},
                    {"features", {w.features[0], w.features[1]}},
                    {"point", {to_string(w.point[0]), to_string(w.point[1]), to_string(w.point[2])}}};
  }
  nlohmann::ordered_json und = nlohmann::ordered_json::array();
  for (const UndecidedInterval& u : c.undecided)
    und.push_back({{"t", {to_string(u.t0), to_string(u.t1)}}, {"reason", to_string(u.reason)}});
  j["undecided"] = und;
  const CheckStats& s = c.stats;
  j["stats"] = {{"nodes", s.nodes},
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
                {"hull_clears", s.hull_clears},
                {"axis_clears", s.axis_clears},
                {"stops", s.stops},
                {"prefiltered", s.prefiltered},
                {"seconds", s.seconds}};
  return j;
}

}  // namespace

std::string result_json(const Scene& scene, const SceneResult& r) {
  nlohmann::ordered_json j;
  j["format"] = "tmcert-result/1";
  j["verdict"] = to_string(r.verdict);
  j["kernel"] = to_string(r.kernel);
  j["certified"] = r.certified;
  j["epsilon"] = to_string(r.epsilon);
  j["checks"] = nlohmann::ordered_json::array();
  for (const CheckResult& c : r.checks) j["checks"].push_back(check_json(scene, c));
  return j.dump(2) + "\n";
}

std::string result_summary(const Scene& scene, const SceneResult& r) {
  std::ostringstream out;
  out << "tmcert: " << to_string(r.verdict);
  if (!r.certified) out << " (kernel fast: NOT CERTIFIED)";
  out << "  [kernel " << to_string(r.kernel) << ", epsilon " << to_string(r.epsilon) << "]\n";
  for (const CheckResult& c : r.checks) {
    out << "  " << scene.bodies[c.bodies[0]].name << " x " << scene.bodies[c.bodies[1]].name << ": "
        << to_string(c.verdict);
    if (c.witness)
      out << " at t = " << to_string(c.witness->t) << " (" << c.witness->features[0] << " meets "
          << c.witness->features[1] << ")";
    if (c.first_contact)
      out << "; no contact before t = " << to_string(c.first_contact->first);
    if (!c.undecided.empty()) out << "; " << c.undecided.size() << " undecided interval(s)";
    out << "  (" << c.stats.nodes << " nodes, depth " << c.stats.max_depth << ", " << c.stats.contact.calls
        << " tests, " << c.stats.contact.exact_fallbacks << " exact, " << c.stats.seconds << " s)\n";
  }
  return out.str();
}

}  // namespace tmcert
