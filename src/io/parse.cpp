// Reading tmcert-scene/1 documents (SCENE_FORMAT.md): scene assembly.
//
// Two stages.  First the JSON text becomes a small tree of our own with
// exact numbers (src/io/json_tree.h).  Then the tree is validated and
// turned into the exact model (src/io/scene_reader.h); every error names
// the JSON path of the offending value.  This file reads the document, its
// bodies, polygons (checked and split into convex pieces by
// src/io/polygon.h) and meshes, masses and checks, and batch request
// lines; motions are read in motion_reader.cpp, robots in
// robot_reader.cpp.  Mesh files (src/io/mesh.h) are read relative to the
// scene file, and every face goes through the same polygon checks.
#include "src/io/parse.h"

#include "src/io/mesh.h"
#include "src/io/polygon.h"
#include "src/io/read_file.h"
#include "src/io/scene_document.h"
#include "src/io/scene_reader.h"
#include "src/model/mass.h"
#include "src/model/solid.h"

#include <gmp.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>
#include <unordered_map>
#include <utility>

namespace tmcert {

namespace reader {

namespace {

constexpr std::uintmax_t kMaxFileBytes = 1ull << 30;

constexpr const char* kFormat = "tmcert-scene/1";

}  // namespace

Scene SceneReader::read() {
  Scene scene;
  scene.source = source_;
  const Path document;
  const Members doc = object(tree_.root, document);

  const Node* format = find(doc, "format");
  if (!format) fail(document.member("format"), std::string("missing required field (expected \"") + kFormat + "\")");
  if (format->kind != Node::Kind::String || text(*format) != kFormat)
    fail(document.member("format"), "unknown format version " + describe(*format) + ", expected \"" + kFormat + "\"");
  reject_unknown_keys(doc, document,
                      {"format", "epsilon", "max_depth", "bodies", "checks", "clearance", "robots", "package_paths"});
  if (const Node* pp = find(doc, "package_paths")) package_paths(*pp, document.member("package_paths"));
  if (const Node* c = find(doc, "clearance")) scene.clearance = non_negative(*c, document.member("clearance"));

  if (const Node* eps = find(doc, "epsilon")) {
    const Path eps_path = document.member("epsilon");
    scene.epsilon = number(*eps, eps_path);
    if (!(*scene.epsilon > 0)) fail(eps_path, "must be positive");
  }
  if (const Node* depth = find(doc, "max_depth")) scene.max_depth = max_depth(*depth, document.member("max_depth"));

  const Path bodies_path = document.member("bodies");
  const Node* bodies = find(doc, "bodies");
  const Node* robots_node = find(doc, "robots");
  // A scene of robots alone (self-collision) needs no other body.
  if (!bodies && !robots_node) fail(bodies_path, "missing required field");
  const std::span<const Node> list = bodies ? array(*bodies, bodies_path) : std::span<const Node>();
  if (list.empty() && !robots_node) fail(bodies_path, "at least one body is required");
  std::unordered_map<std::string, std::size_t> names;
  names.reserve(list.size());
  scene.bodies.reserve(list.size());
  for (std::size_t i = 0; i < list.size(); ++i) {
    const Path path = bodies_path.index(i);
    scene.bodies.push_back(body(list[i], path));
    const std::string& name = scene.bodies.back().name;
    if (auto [it, fresh] = names.emplace(name, i); !fresh)
      fail(path.member("name"),
           "duplicate body name " + quote_text(name) + " (also " + index_path("bodies", it->second) + ")");
  }
  assign_masses(scene, bodies_path);
  const std::size_t plain_bodies = scene.bodies.size();
  std::vector<RobotInScene> placed;
  if (robots_node) placed = robots(scene, *robots_node, document.member("robots"), names);
  if (robots_out_)
    for (const RobotInScene& r : placed) {
      SceneRobot kept{r.robot, r.joints, {}, r.self_collision, r.allowed};
      for (const std::vector<int>& parts : r.bodies.parts)
        kept.bodies.insert(kept.bodies.end(), parts.begin(), parts.end());
      robots_out_->push_back(std::move(kept));
    }
  if (scene.bodies.empty()) fail(bodies_path, "at least one body is required (the robots have no collision geometry)");

  if (const Node* checks = find(doc, "checks"))
    scene.checks = explicit_checks(*checks, document.member("checks"), names, scene.check_clearance);
  else
    scene.checks = default_checks_with_robots(scene, plain_bodies, placed);
  scene.notes = std::move(notes_);
  scene.warnings = std::move(warnings_);
  return scene;
}

// A rational above 2 pi (2 pi < 6.283185307179587): an rpy angle beyond

// A request line of a batch run (docs/scene-format.md "Batch runs"):
// {"id", "body", "motion" or "robot", "path"; "checks", "clearance"}.  `out.id` is set first,
// so that a request rejected later is still reported under its id.
void SceneReader::read_request(RequestLine& out) const {
  const Path document;
  const Members doc = object(tree_.root, document);
  if (const Node* id = find(doc, "id")) out.id = compact(*id);
  reject_unknown_keys(doc, document, {"id", "body", "motion", "robot", "path", "checks", "clearance"});
  const Path body_path = document.member("body");
  const Node* b = find(doc, "body");
  if (const Node* r = find(doc, "robot")) {
    // A robot's path segment: {"robot": name, "path": {"times", "positions", ...}}.
    const Path robot_path = document.member("robot");
    if (b) fail(body_path, "a request moves a body or a robot, not both");
    if (find(doc, "motion")) fail(document.member("motion"), "a robot moves along its \"path\", not a motion");
    if (r->kind != Node::Kind::String || text(*r).empty()) fail(robot_path, "expected a robot name (a string)");
    out.robot = text(*r);
    const Path path_path = document.member("path");
    const Node* p = find(doc, "path");
    if (!p) fail(path_path, "missing required field");
    JointPath jp;
    joint_path_values(*p, path_path, jp);
    out.path_times = std::move(jp.times);
    out.path_positions = std::move(jp.positions);
    out.path_interpolation = jp.interpolation;
    out.path_velocities = std::move(jp.velocities);
    out.path_accelerations = std::move(jp.accelerations);
    read_request_checks(out);
    return;
  }
  if (find(doc, "path")) fail(document.member("path"), "a path moves a robot (give \"robot\")");
  if (!b) fail(body_path, "missing required field (a body name of the environment, or a body; or a robot)");
  if (b->kind == Node::Kind::String) {
    out.body = text(*b);
    if (out.body.empty()) fail(body_path, "a body name must be a non-empty string");
  } else if (b->kind == Node::Kind::Object) {
    Scene alone;  // its default mass from its own vertices
    alone.bodies.push_back(body(*b, body_path));
    if (alone.bodies[0].motion || alone.bodies[0].trajectory)
      fail(body_path.member("motion"), "the request's motion goes in its \"motion\" field");
    assign_masses(alone, body_path);
    out.body = alone.bodies[0].name;
    out.inline_body = std::move(alone.bodies[0]);
  } else {
    fail(body_path, std::string("expected a body name or a body object, got ") + kind_name(b->kind));
  }
  const Path motion_path = document.member("motion");
  const Node* m = find(doc, "motion");
  if (!m) fail(motion_path, "missing required field");
  Body moved;
  motion(moved, *m, motion_path);
  if (!moved.moves()) fail(motion_path, "the motion must move (a one-pose motion is not a request)");
  out.motion = std::move(moved.motion);
  out.trajectory = std::move(moved.trajectory);
  read_request_checks(out);
}

// A request's "checks" and "clearance".
void SceneReader::read_request_checks(RequestLine& out) const {
  const Path document;
  const Members doc = object(tree_.root, document);
  if (const Node* c = find(doc, "checks")) {
    const Path checks_path = document.member("checks");
    const std::span<const Node> list = array(*c, checks_path);
    if (list.empty()) fail(checks_path, "at least one body name is required (omit the field for every other body)");
    for (std::size_t k = 0; k < list.size(); ++k) {
      if (list[k].kind != Node::Kind::String)
        fail(checks_path.index(k), std::string("expected a body name, got ") + kind_name(list[k].kind));
      std::string name(text(list[k]));
      if (std::find(out.checks.begin(), out.checks.end(), name) != out.checks.end())
        fail(checks_path.index(k), "duplicate body " + quote_text(name));
      out.checks.push_back(std::move(name));
    }
  }
  if (const Node* c = find(doc, "clearance")) out.clearance = non_negative(*c, document.member("clearance"));
}

int SceneReader::max_depth(const Node& node, const Path& path) const {
  const Exact value = number(node, path);
  if (value.denominator() != 1) fail(path, "must be an integer");
  if (value < 1 || value > 200) fail(path, "must be between 1 and 200");
  return static_cast<int>(CGAL::to_double(value));
}

Body SceneReader::body(const Node& node, const Path& path) const {
  const Members obj = object(node, path);
  reject_unknown_keys(obj, path,
                      {"name", "polygons", "segments", "points", "mass", "motion", "solid", "mesh", "tolerance"});
  Body b;

  const Node* name = find(obj, "name");
  if (!name) fail(path.member("name"), "missing required field");
  if (name->kind != Node::Kind::String || text(*name).empty())
    fail(path.member("name"), "a body name must be a non-empty string");
  b.name = text(*name);
  // Names are printed in results and messages: no control characters
  // (C0, DEL, or C1 as UTF-8 C2 80..9F), which would print raw.
  for (std::size_t k = 0; k < b.name.size(); ++k) {
    const auto c = static_cast<unsigned char>(b.name[k]);
    const bool c1 = c == 0xC2 && k + 1 < b.name.size() && static_cast<unsigned char>(b.name[k + 1]) >= 0x80 &&
                    static_cast<unsigned char>(b.name[k + 1]) <= 0x9F;
    if (c < 0x20 || c == 0x7F || c1)
      fail(path.member("name"), "a body name cannot contain control characters, got " + quote_text(b.name));
  }

  if (const Node* polygons = find(obj, "polygons")) {
    const Path list_path = path.member("polygons");
    const std::span<const Node> list = array(*polygons, list_path);
    for (std::size_t i = 0; i < list.size(); ++i) polygon(b, list[i], list_path.index(i));
  }
  if (const Node* segments = find(obj, "segments")) {
    const Path list_path = path.member("segments");
    const std::span<const Node> list = array(*segments, list_path);
    for (std::size_t i = 0; i < list.size(); ++i) {
      const Path seg_path = list_path.index(i);
      const std::vector<Vec3E> ends = points(list[i], seg_path);
      if (ends.size() != 2) fail(seg_path, "a segment needs exactly 2 points, got " + std::to_string(ends.size()));
      if (ends[0] == ends[1]) fail(seg_path, "segment endpoints are equal");
      b.segments.push_back({ends[0], ends[1]});
    }
  }
  if (const Node* pts = find(obj, "points")) b.points = points(*pts, path.member("points"));
  // Mesh faces come after the explicit polygons (polygon indices go on).
  if (const Node* file = find(obj, "mesh")) mesh(b, *file, path.member("mesh"));
  if (b.polygons.empty() && b.segments.empty() && b.points.empty())
    fail(path, "body has no features (needs at least one of polygons, segments, points, mesh)");

  if (const Node* solid = find(obj, "solid")) {
    const Path solid_path = path.member("solid");
    if (solid->kind != Node::Kind::Boolean) fail(solid_path, "expected true or false");
    // The inside of a solid counts as contact, and "inside" is only
    // defined for a closed surface (proofs/containment.md).
    if (solid->boolean) require_closed(b, solid_path);
    b.solid = solid->boolean;
  }
  if (const Node* mass = find(obj, "mass")) {
    b.mass = explicit_mass(*mass, path.member("mass"));
    b.mass_is_default = false;
  }
  if (const Node* m = find(obj, "motion")) motion(b, *m, path.member("motion"));
  if (const Node* t = find(obj, "tolerance")) b.tolerance = non_negative(*t, path.member("tolerance"));
  if (!b.mass_is_default) normalise_mass_scale(b);
  return b;
}

// Mass weights far outside the double range (1e400, 1e-400) would
// overflow or vanish in every enclosure of the body's metric.  The
// metric's norm scales with the square root of the weights, so weights
// multiplied by 100^-m and the tolerance (a length in that metric) by
// 10^-m give the same set of admissible motions, the same distances and
// the same verdicts, exactly (proofs/input-exactness.md); a clearance is
// turned into the metric from the weights as they are then.  Weights
// whose largest is within (2^-32, 2^32) stay as written.
void SceneReader::normalise_mass_scale(Body& b) {
  long top = LONG_MIN;
  for (const Exact& w : b.mass.weights)
    top = std::max(top, static_cast<long>(mpz_sizeinbase(mpq_numref(w.mpq()), 2)) -
                            static_cast<long>(mpz_sizeinbase(mpq_denref(w.mpq()), 2)));
  if (top == LONG_MIN || (top > -32 && top < 32)) return;
  const long m = std::lround(static_cast<double>(top) * 0.30102999566398120 / 2);  // 100^m ~ 2^top
  CGAL::Gmpz ten;
  mpz_ui_pow_ui(ten.mpz(), 10, static_cast<unsigned long>(m < 0 ? -m : m));
  const Exact length = m > 0 ? Exact(CGAL::Gmpz(1), ten) : Exact(ten);  // 10^-m
  const Exact weight = length * length;                                 // 100^-m
  for (Exact& w : b.mass.weights) w *= weight;
  b.tolerance *= length;
}

void SceneReader::polygon(Body& b, const Node& node, const Path& path) const {
  const std::span<const Node> list = array(node, path);
  if (list.size() < 3)
    fail(path, "a polygon needs at least 3 vertices, got " + std::to_string(list.size()));
  if (list.size() > kMaxPolygonVertices)
    fail(path, "polygon has more than " + std::to_string(kMaxPolygonVertices) + " vertices");
  const std::vector<Vec3E> vertices = points(node, path);
  try {
    auto [clean, pieces] = split_polygon(vertices, static_cast<int>(b.polygons.size()));
    b.polygons.push_back(std::move(clean));
    for (ConvexPiece& piece : pieces) b.pieces.push_back(std::move(piece));
  } catch (const InputError& e) {
    fail(path, e.what());
  }
}

// "mesh": a file name relative to the scene file's directory.  Each face
// becomes a polygon through the same checks as explicit polygons; an
// error names the file and the face.
void SceneReader::mesh(Body& b, const Node& node, const Path& path) const {
  const std::string name(text(node));
  if (node.kind != Node::Kind::String || name.empty())
    fail(path, std::string("expected a mesh file name (a non-empty string), got ") +
                   (node.kind == Node::Kind::String ? "an empty string" : kind_name(node.kind)));
  if (name.find('\0') != std::string::npos) fail(path, "file name contains a NUL character");
  const std::string file = (base_ / std::filesystem::path(name)).string();
  MeshData data;
  try {
    data = read_mesh(file);
  } catch (const InputError& e) {
    fail(path, one_line(e.what()));
  }
  if (data.faces.empty()) fail(path, file + ": mesh has no faces");
  if (data.from_floats)
    notes_.push_back(source_ + ": " + path.str() + ": mesh " + file + " (" + data.format +
                     ") is read from its single-precision floats: its coordinates are their exact values");
  std::vector<Vec3E> vertices;
  MeshFaceCounts counts;
  for (std::size_t f = 0; f < data.faces.size(); ++f) {
    const std::vector<std::size_t>& face = data.faces[f];
    vertices.clear();
    for (std::size_t index : face) vertices.push_back(data.vertices[index]);
    try {
      add_mesh_face(b, vertices, f, counts);
    } catch (const InputError& e) {
      fail(path, file + ": face " + std::to_string(f) + ": " + e.what());
    }
  }
  for (std::string& note : mesh_face_notes(located(source_, path.str(), file + ": "), counts))
    notes_.push_back(std::move(note));
}

void SceneReader::require_closed(const Body& b, const Path& path) const {
  std::string problem = solid_problem(b);
  if (problem.empty()) problem = shell_intersection_problem(b);
  if (!problem.empty()) fail(path, problem);
}

MassDistribution SceneReader::explicit_mass(const Node& node, const Path& path) const {
  const Members obj = object(node, path);
  reject_unknown_keys(obj, path, {"points", "weights"});
  const Node* pts = find(obj, "points");
  if (!pts) fail(path.member("points"), "missing required field");
  const Node* weights = find(obj, "weights");
  if (!weights) fail(path.member("weights"), "missing required field");
  MassDistribution mass;
  mass.points = points(*pts, path.member("points"));
  if (mass.points.empty()) fail(path.member("points"), "at least one mass point is required");
  mass.weights = positive_weights(*weights, path.member("weights"), mass.points.size(), "mass point");
  try {
    require_positive_definite(mass);
  } catch (const InputError& e) {
    fail(path, e.what());
  }
  return mass;
}

// Default masses need the size of the whole scene, so they come after all
// bodies are read.  Every mass, default or not, must give a metric.
void SceneReader::assign_masses(Scene& scene, const Path& bodies_path) const {
  auto vertices_of = [](const Body& b) {
    std::vector<Vec3E> v;
    for (const auto& polygon : b.polygons) v.insert(v.end(), polygon.begin(), polygon.end());
    for (const auto& segment : b.segments) v.insert(v.end(), segment.begin(), segment.end());
    v.insert(v.end(), b.points.begin(), b.points.end());
    return v;
  };
  const Exact size = default_mass_fallback_size(scene.bodies);

  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    Body& b = scene.bodies[i];
    if (!b.mass_is_default) continue;
    b.mass = default_mass(vertices_of(b), size);
    try {
      require_positive_definite(b.mass);
    } catch (const InputError& e) {  // default_mass promises this cannot happen
      fail(bodies_path.index(i), std::string("default mass: ") + e.what());
    }
  }
}

std::vector<std::pair<int, int>> SceneReader::explicit_checks(const Node& node, const Path& checks_path,
                                                 const std::unordered_map<std::string, std::size_t>& names,
                                                 std::vector<std::optional<Exact>>& clearances) const {
  const std::span<const Node> list = array(node, checks_path);
  std::vector<std::pair<int, int>> out;
  std::map<std::pair<int, int>, std::size_t> seen;  // unordered pair -> where it was written
  std::set<std::pair<int, int>> expanded;           // the pairs checked
  for (std::size_t k = 0; k < list.size(); ++k) {
    const Path item_path = checks_path.index(k);
    const Path bodies_path = item_path.member("bodies");
    const Path* where = &item_path;
    const Node* pair_node = &list[k];
    clearances.emplace_back();
    if (list[k].kind == Node::Kind::Object) {
      // {"bodies": ["a", "b"], "clearance": d}
      const Members obj = object(list[k], item_path);
      reject_unknown_keys(obj, item_path, {"bodies", "clearance"});
      if (const Node* c = find(obj, "clearance")) clearances.back() = non_negative(*c, item_path.member("clearance"));
      pair_node = find(obj, "bodies");
      if (!pair_node) fail(bodies_path, "missing required field");
      where = &bodies_path;
    }
    const Path& path = *where;
    const std::span<const Node> pair = array(*pair_node, path);
    if (pair.size() != 2)
      fail(path, "a check names exactly 2 bodies, got " + std::to_string(pair.size()));
    int idx[2];
    for (std::size_t s = 0; s < 2; ++s) {
      const Path side = path.index(s);
      const Node& name = pair[s];
      if (name.kind != Node::Kind::String) fail(side, std::string("expected a body name, got ") + kind_name(name.kind));
      const std::string written(text(name));
      const auto it = names.find(written);
      if (it == names.end()) fail(side, "unknown body " + quote_text(written));
      idx[s] = static_cast<int>(it->second);
    }
    if (idx[0] == idx[1]) fail(path, "a body cannot be checked against itself");
    const auto key = std::minmax(idx[0], idx[1]);
    if (auto [it, fresh] = seen.emplace(key, k); !fresh)
      fail(path, "duplicate check (same pair as " + index_path("checks", it->second) + ")");
    // A robot link of several bodies (robot.h LinkPart) named by its
    // first: every part of it, each pair once.
    const std::optional<Exact> clearance = clearances.back();
    clearances.pop_back();
    auto parts = [&](int b) {
      const auto it = link_parts_.find(b);
      return it == link_parts_.end() ? std::vector<int>{b} : it->second;
    };
    for (int a : parts(idx[0]))
      for (int b : parts(idx[1])) {
        if (a == b || !expanded.insert(std::minmax(a, b)).second) continue;
        out.emplace_back(a, b);
        clearances.push_back(clearance);
      }
  }
  return out;
}

// Every pair with at least one moving body, once, in body order.
std::vector<std::pair<int, int>> SceneReader::default_checks(const Scene& scene) {
  std::vector<std::pair<int, int>> out;
  const int n = static_cast<int>(scene.bodies.size());
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      if (scene.bodies[i].motion || scene.bodies[i].trajectory || scene.bodies[j].motion || scene.bodies[j].trajectory)
        out.emplace_back(i, j);
  return out;
}

namespace {

Scene parse_with_base(const std::string& text, const std::string& source, const std::filesystem::path& base) {
  const Tree tree = parse_json(text, source);
  return SceneReader(source, base, tree).read();
}

Scene read_scene_file(const std::string& path, std::vector<SceneRobot>* robots, const ReadOptions& options = {}) {
  const InputRecord record;  // the scene's files (Scene::input_files)
  // Only a regular file, and at most kMaxFileBytes of it (docs/scene-format.md).
  std::string text = read_regular_file(path, kMaxFileBytes);
  // The text goes once it is parsed: for a large scene it is a good part of
  // the memory that reading the scene takes.
  const Tree tree = parse_json(text, path);
  std::string().swap(text);
  SceneReader scene_reader(path, std::filesystem::path(path).parent_path(), tree, options);
  scene_reader.robots_out_ = robots;
  Scene scene = scene_reader.read();
  scene.input_files = record.files();
  return scene;
}

}  // namespace

}  // namespace reader

// Mesh files are relative to the directory of `source` when it names an
// existing file, otherwise to the current directory.
Scene parse_scene_text(const std::string& text, const std::string& source) {
  std::error_code ec;
  std::filesystem::path base;
  if (!source.empty() && std::filesystem::is_regular_file(source, ec)) base = std::filesystem::path(source).parent_path();
  const InputRecord record;
  Scene scene = reader::parse_with_base(text, source, base);
  scene.input_files = record.files();
  return scene;
}

Scene parse_scene_text(const std::string& text, const std::string& source, const std::string& base,
                       std::vector<SceneRobot>& robots) {
  return parse_scene_text(text, source, base, robots, ReadOptions{});
}

Scene parse_scene_text(const std::string& text, const std::string& source, const std::string& base,
                       std::vector<SceneRobot>& robots, const ReadOptions& options) {
  const reader::Tree tree = reader::parse_json(text, source);
  const InputRecord record;
  reader::SceneReader scene_reader(source, base, tree, options);
  scene_reader.robots_out_ = &robots;
  Scene scene = scene_reader.read();
  scene.input_files = record.files();
  return scene;
}

Scene parse_scene_document(const nlohmann::ordered_json& document, const std::string& source, const std::string& base,
                           std::vector<SceneRobot>& robots) {
  const reader::Tree tree = reader::tree_of(document, source);
  const InputRecord record;
  reader::SceneReader scene_reader(source, base, tree);
  scene_reader.robots_out_ = &robots;
  Scene scene = scene_reader.read();
  scene.input_files = record.files();
  return scene;
}

void parse_request_line(const std::string& text, const std::string& source, const std::string& base,
                        RequestLine& out) {
  const reader::Tree tree = reader::parse_json(text, source);
  reader::SceneReader scene_reader(source, base, tree);
  scene_reader.read_request(out);
  out.notes = scene_reader.take_notes();
  out.warnings = scene_reader.take_warnings();
}

Scene parse_scene_file(const std::string& path, const ReadOptions& options, std::vector<SceneRobot>* robots) {
  return reader::read_scene_file(path, robots, options);
}

Scene parse_scene_file(const std::string& path) { return reader::read_scene_file(path, nullptr); }

Scene parse_scene_file(const std::string& path, std::vector<SceneRobot>& robots) {
  return reader::read_scene_file(path, &robots);
}

}  // namespace tmcert
