// SceneBuilder (include/tmcert/scene_builder.h): the builder holds the
// tmcert-scene/1 document of what it was given as a JSON value, every
// number as its exact text, and build() hands that value to the scene
// reader's tree (src/io/json_tree.h) directly: no JSON text is written or
// parsed on the way.  So a scene built in code is validated by exactly the
// checks of a scene file, and its errors name the same fields; there is
// no second validator.  to_json() prints the same document.
#include "kernels/number_types.h"
#include "src/io/parse.h"
#include "src/io/scene_document.h"

#include "src/api/internal.h"
#include "tmcert/scene_builder.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <regex>

namespace tmcert::api {

namespace {

using Json = nlohmann::ordered_json;

// The label of the builder's documents in messages ("SceneBuilder: bodies[1]...").
constexpr const char* kSource = "SceneBuilder";

// Array plumbing that has no place in a document (a flat array of the wrong
// length, an index out of range) is refused at once, naming the body.
[[noreturn]] void fail(const std::string& body, const std::string& field, const std::string& what) {
  throw InputError(std::string(kSource) + ": body " + tmcert::quote_text(body) + ": " + field + ": " + what);
}

Json number(const Number& n) { return n.text(); }

Json point(const Point& p) { return Json::array({number(p[0]), number(p[1]), number(p[2])}); }

Json numbers(const std::vector<Number>& list) {
  Json out = Json::array();
  for (const Number& n : list) out.push_back(number(n));
  return out;
}

// Point `i` of a flat array of coordinates (3 per point).
Point flat_point(std::span<const double> xyz, std::size_t i) { return {xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]}; }

std::vector<Point> flat_points(std::span<const double> xyz, const std::string& body, const std::string& field) {
  if (xyz.size() % 3 != 0)
    fail(body, field, "the coordinate array has " + std::to_string(xyz.size()) + " values, not 3 per vertex");
  std::vector<Point> out;
  out.reserve(xyz.size() / 3);
  for (std::size_t i = 0; i < xyz.size() / 3; ++i) out.push_back(flat_point(xyz, i));
  return out;
}

Json pose(const Pose& p) {
  Json out = Json::object();
  out["translation"] = point(p.translation);
  const Rotation& r = p.rotation;
  switch (r.kind) {
    case Rotation::Kind::Identity: break;
    case Rotation::Kind::Quaternion: out["rotation"] = Json{{"quaternion", numbers(r.values)}}; break;
    case Rotation::Kind::Rpy: out["rotation"] = Json{{"rpy", numbers(r.values)}}; break;
    case Rotation::Kind::Matrix: {
      // Rows of three; a wrong count shows as a short row, named by the reader.
      Json rows = Json::array();
      for (std::size_t i = 0; i < r.values.size(); i += 3) {
        Json row = Json::array();
        for (std::size_t k = i; k < i + 3 && k < r.values.size(); ++k) row.push_back(number(r.values[k]));
        rows.push_back(std::move(row));
      }
      out["rotation"] = Json{{"matrix", std::move(rows)}};
      break;
    }
  }
  return out;
}

const char* interpolation_name(Interpolation i) {
  switch (i) {
    case Interpolation::Slerp: return "slerp";
    case Interpolation::Screw: return "screw";
    case Interpolation::Nlerp: return "nlerp";
  }
  return "slerp";
}

Json motion(const Motion& m) {
  struct Visitor {
    Json operator()(const RationalBezier& b) const {
      Json out = Json::object();
      out["type"] = "rational_bezier";
      out["interval"] = Json::array({number(b.interval.first), number(b.interval.second)});
      Json cps = Json::array();
      for (const AffineMap& a : b.control_points) {
        Json rows = Json::array();
        for (int r = 0; r < 3; ++r)
          rows.push_back(Json::array({number(a[4 * r]), number(a[4 * r + 1]), number(a[4 * r + 2]), number(a[4 * r + 3])}));
        cps.push_back(std::move(rows));
      }
      out["control_points"] = std::move(cps);
      if (!b.weights.empty()) out["weights"] = numbers(b.weights);
      return out;
    }
    Json operator()(const Keyframes& k) const {
      Json out = Json::object();
      out["type"] = "keyframes";
      out["interpolation"] = interpolation_name(k.interpolation);
      if (!k.times.empty()) out["times"] = numbers(k.times);
      Json poses = Json::array();
      for (const Pose& p : k.poses) poses.push_back(pose(p));
      out["poses"] = std::move(poses);
      return out;
    }
    Json operator()(const Piecewise& p) const {
      Json pieces = Json::array();
      for (const Motion& piece : p.pieces) pieces.push_back(motion(piece));
      return Json{{"type", "piecewise"}, {"pieces", std::move(pieces)}};
    }
  };
  return std::visit(Visitor{}, m.value());
}

// A file name as the document holds it: absolute, so that it means the
// file it meant when it was given.
std::string absolute_file(const std::string& path) {
  if (path.empty()) return path;  // the reader names the empty field
  std::error_code ec;
  const std::filesystem::path full = std::filesystem::absolute(path, ec);
  return ec ? path : full.string();
}

}  // namespace

std::string motion_json(const Motion& m) { return motion(m).dump(); }

Motion Motion::translation(const Point& from, const Point& to, Number t0, Number t1) {
  auto pose = [](const Point& p) -> AffineMap { return {1, 0, 0, p[0], 0, 1, 0, p[1], 0, 0, 1, p[2]}; };
  return RationalBezier{{pose(from), pose(to)}, {}, {std::move(t0), std::move(t1)}};
}

// ---------------------------------------------------------------- bodies

BodyBuilder& BodyBuilder::polygons(std::span<const double> xyz, const std::vector<std::vector<std::size_t>>& faces) {
  const std::vector<Point> vertices = flat_points(xyz, name_, "polygons");
  return polygons(std::span<const Point>(vertices), faces);
}

BodyBuilder& BodyBuilder::polygons(std::span<const double> xyz, std::span<const std::size_t> indices,
                                   std::span<const std::size_t> sizes) {
  std::vector<std::vector<std::size_t>> faces;
  faces.reserve(sizes.size());
  std::size_t next = 0;
  for (std::size_t size : sizes) {
    if (size > indices.size() - next)
      fail(name_, "polygons", "the sizes add up to more than the " + std::to_string(indices.size()) + " indices");
    faces.emplace_back(indices.begin() + static_cast<std::ptrdiff_t>(next),
                       indices.begin() + static_cast<std::ptrdiff_t>(next + size));
    next += size;
  }
  if (next != indices.size())
    fail(name_, "polygons", "the sizes add up to " + std::to_string(next) + ", not to the " +
                                std::to_string(indices.size()) + " indices");
  return polygons(xyz, faces);
}

BodyBuilder& BodyBuilder::polygons(std::span<const Point> vertices, const std::vector<std::vector<std::size_t>>& faces) {
  std::vector<std::vector<Point>> added;
  added.reserve(faces.size());
  for (std::size_t f = 0; f < faces.size(); ++f) {
    std::vector<Point> polygon;
    polygon.reserve(faces[f].size());
    for (std::size_t index : faces[f]) {
      if (index >= vertices.size())
        fail(name_, "polygons", "face " + std::to_string(f) + ": vertex index " + std::to_string(index) +
                                    " is out of range (" + std::to_string(vertices.size()) + " vertices)");
      polygon.push_back(vertices[index]);
    }
    added.push_back(std::move(polygon));
  }
  for (std::vector<Point>& p : added) polygons_.push_back(std::move(p));
  return *this;
}

BodyBuilder& BodyBuilder::polygon(const std::vector<Point>& vertices) {
  polygons_.push_back(vertices);
  return *this;
}

BodyBuilder& BodyBuilder::triangles(std::span<const double> xyz, std::span<const std::size_t> indices) {
  const std::vector<Point> vertices = flat_points(xyz, name_, "triangles");
  return triangles(std::span<const Point>(vertices), indices);
}

BodyBuilder& BodyBuilder::triangles(std::span<const Point> vertices, std::span<const std::size_t> indices) {
  if (indices.size() % 3 != 0)
    fail(name_, "triangles", "the index array has " + std::to_string(indices.size()) + " values, not 3 per triangle");
  std::vector<std::vector<std::size_t>> faces;
  faces.reserve(indices.size() / 3);
  for (std::size_t i = 0; i < indices.size(); i += 3) faces.push_back({indices[i], indices[i + 1], indices[i + 2]});
  return polygons(vertices, faces);
}

BodyBuilder& BodyBuilder::segments(std::span<const double> xyz) {
  if (xyz.size() % 6 != 0)
    fail(name_, "segments", "the coordinate array has " + std::to_string(xyz.size()) + " values, not 6 per segment");
  for (std::size_t i = 0; i < xyz.size() / 6; ++i) segments_.emplace_back(flat_point(xyz, 2 * i), flat_point(xyz, 2 * i + 1));
  return *this;
}

BodyBuilder& BodyBuilder::segment(const Point& a, const Point& b) {
  segments_.emplace_back(a, b);
  return *this;
}

BodyBuilder& BodyBuilder::points(std::span<const double> xyz) {
  for (Point& p : flat_points(xyz, name_, "points")) points_.push_back(std::move(p));
  return *this;
}

BodyBuilder& BodyBuilder::point(const Point& p) {
  points_.push_back(p);
  return *this;
}

BodyBuilder& BodyBuilder::mesh(const std::string& path) {
  if (mesh_) fail(name_, "mesh", "a body has at most one mesh file (already " + tmcert::quote_text(*mesh_) + ")");
  mesh_ = absolute_file(path);
  return *this;
}

BodyBuilder& BodyBuilder::solid(bool value) {
  solid_ = value;
  return *this;
}

BodyBuilder& BodyBuilder::mass(const std::vector<Point>& points, const std::vector<Number>& weights) {
  mass_.emplace(points, weights);
  return *this;
}

BodyBuilder& BodyBuilder::tolerance(Number r) {
  tolerance_ = std::move(r);
  return *this;
}

BodyBuilder& BodyBuilder::motion(Motion m) {
  motion_ = std::move(m);
  return *this;
}

BodyBuilder& BodyBuilder::linear_primitive(const std::vector<Point>& start, const std::vector<Point>& end, Number t0,
                                           Number t1) {
  if (start.size() != end.size() || start.empty() || start.size() > 3)
    fail(name_, "linear_primitive", "expected 1 to 3 vertices at both ends, got " + std::to_string(start.size()) +
                                        " and " + std::to_string(end.size()));
  // [v1 - v0, v2 - v0, 0 | v0], columns of the vertices' differences (zero
  // where the primitive has no such vertex), exactly.
  auto map = [&](const std::vector<Point>& v, const char* which) {
    std::array<std::array<tmcert::Exact, 3>, 3> x;
    for (std::size_t i = 0; i < v.size(); ++i)
      for (int k = 0; k < 3; ++k)
        if (!tmcert::parse_exact(v[i][k].text(), x[i][k]))
          fail(name_, "linear_primitive", std::string(which) + "[" + std::to_string(i) + "][" + std::to_string(k) +
                                              "]: not a number: " + tmcert::quote_text(v[i][k].text()));
    AffineMap m;
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c)
        m[4 * r + c] = c + 1 < static_cast<int>(v.size()) ? Number(tmcert::to_string(x[c + 1][r] - x[0][r])) : Number(0);
      m[4 * r + 3] = Number(tmcert::to_string(x[0][r]));
    }
    return m;
  };
  const AffineMap from = map(start, "start"), to = map(end, "end");
  if (start.size() == 1) point({0, 0, 0});
  else if (start.size() == 2) segment({0, 0, 0}, {1, 0, 0});
  else polygon({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
  return motion(RationalBezier{{from, to}, {}, {std::move(t0), std::move(t1)}});
}

// ---------------------------------------------------------------- robots

RobotBuilder& RobotBuilder::base(Pose pose) {
  base_ = std::move(pose);
  return *this;
}

RobotBuilder& RobotBuilder::path(std::vector<std::string> joints, std::vector<Number> times,
                                 std::vector<std::vector<Number>> positions) {
  joints_ = std::move(joints);
  times_ = std::move(times);
  positions_ = std::move(positions);
  return *this;
}

RobotBuilder& RobotBuilder::interpolation(std::string how, std::vector<std::vector<Number>> velocities,
                                          std::vector<std::vector<Number>> accelerations) {
  interpolation_ = std::move(how);
  velocities_ = std::move(velocities);
  accelerations_ = std::move(accelerations);
  return *this;
}

RobotBuilder& RobotBuilder::self_collision(bool value) {
  self_collision_ = value;
  return *this;
}

RobotBuilder& RobotBuilder::allow(std::string link_a, std::string link_b) {
  allowed_.emplace_back(std::move(link_a), std::move(link_b));
  return *this;
}

RobotBuilder& RobotBuilder::srdf(std::string file) {
  srdf_ = absolute_file(file);
  return *this;
}

// ---------------------------------------------------------------- scene

BodyBuilder& SceneBuilder::add_body(std::string name) { return bodies_.emplace_back(std::move(name)); }

RobotBuilder& SceneBuilder::add_robot(std::string name, std::string urdf) {
  return robots_.emplace_back(std::move(name), absolute_file(urdf));
}

SceneBuilder& SceneBuilder::check(std::string body_a, std::string body_b) {
  checks_.push_back({std::move(body_a), std::move(body_b), std::nullopt});
  return *this;
}

SceneBuilder& SceneBuilder::check(std::string body_a, std::string body_b, Number clearance) {
  checks_.push_back({std::move(body_a), std::move(body_b), std::move(clearance)});
  return *this;
}

SceneBuilder& SceneBuilder::epsilon(Number e) {
  epsilon_ = std::move(e);
  return *this;
}

SceneBuilder& SceneBuilder::max_depth(int depth) {
  max_depth_ = depth;
  return *this;
}

SceneBuilder& SceneBuilder::clearance(Number d) {
  clearance_ = std::move(d);
  return *this;
}

SceneBuilder& SceneBuilder::package_path(std::string folder) {
  package_paths_.push_back(absolute_file(folder));
  return *this;
}

template <>
Json SceneBuilder::document<Json>() const {
  Json doc = Json::object();
  doc["format"] = "tmcert-scene/1";
  if (epsilon_) doc["epsilon"] = number(*epsilon_);
  if (max_depth_) doc["max_depth"] = *max_depth_;
  if (clearance_) doc["clearance"] = number(*clearance_);
  if (!package_paths_.empty()) doc["package_paths"] = package_paths_;
  if (!bodies_.empty() || robots_.empty()) {  // none at all: the reader says a body is required
    Json bodies = Json::array();
    for (const BodyBuilder& b : bodies_) {
      Json body = Json::object();
      body["name"] = b.name_;
      if (!b.polygons_.empty()) {
        Json list = Json::array();
        for (const std::vector<Point>& polygon : b.polygons_) {
          Json vertices = Json::array();
          for (const Point& p : polygon) vertices.push_back(point(p));
          list.push_back(std::move(vertices));
        }
        body["polygons"] = std::move(list);
      }
      if (!b.segments_.empty()) {
        Json list = Json::array();
        for (const auto& [p, q] : b.segments_) list.push_back(Json::array({point(p), point(q)}));
        body["segments"] = std::move(list);
      }
      if (!b.points_.empty()) {
        Json list = Json::array();
        for (const Point& p : b.points_) list.push_back(point(p));
        body["points"] = std::move(list);
      }
      if (b.mesh_) body["mesh"] = *b.mesh_;
      if (b.solid_) body["solid"] = *b.solid_;
      if (b.mass_) {
        Json pts = Json::array();
        for (const Point& p : b.mass_->first) pts.push_back(point(p));
        body["mass"] = Json{{"points", std::move(pts)}, {"weights", numbers(b.mass_->second)}};
      }
      if (b.tolerance_) body["tolerance"] = number(*b.tolerance_);
      if (b.motion_) body["motion"] = motion(*b.motion_);
      bodies.push_back(std::move(body));
    }
    doc["bodies"] = std::move(bodies);
  }
  if (!robots_.empty()) {
    Json robots = Json::array();
    for (const RobotBuilder& r : robots_) {
      Json robot = Json::object();
      robot["name"] = r.name_;
      robot["urdf"] = r.urdf_;
      if (r.base_) robot["base"] = pose(*r.base_);
      robot["joints"] = r.joints_;
      Json positions = Json::array();
      for (const std::vector<Number>& row : r.positions_) positions.push_back(numbers(row));
      robot["path"] = Json{{"times", numbers(r.times_)}, {"positions", std::move(positions)}};
      if (r.interpolation_) robot["path"]["interpolation"] = *r.interpolation_;
      for (const auto& [key, rows] : {std::pair{"velocities", &r.velocities_}, std::pair{"accelerations", &r.accelerations_}}) {
        if (rows->empty()) continue;
        Json list = Json::array();
        for (const std::vector<Number>& row : *rows) list.push_back(numbers(row));
        robot["path"][key] = std::move(list);
      }
      if (r.self_collision_) robot["self_collision"] = *r.self_collision_;
      if (!r.allowed_.empty()) {
        Json pairs = Json::array();
        for (const auto& [a, b] : r.allowed_) pairs.push_back(Json::array({a, b}));
        robot["allowed_pairs"] = std::move(pairs);
      }
      if (r.srdf_) robot["srdf"] = *r.srdf_;
      robots.push_back(std::move(robot));
    }
    doc["robots"] = std::move(robots);
  }
  if (!checks_.empty()) {
    Json checks = Json::array();
    for (const Check& c : checks_) {
      Json pair = Json::array({c.a, c.b});
      if (c.clearance) checks.push_back(Json{{"bodies", std::move(pair)}, {"clearance", number(*c.clearance)}});
      else checks.push_back(std::move(pair));
    }
    doc["checks"] = std::move(checks);
  }
  return doc;
}

std::string SceneBuilder::to_json() const { return document<Json>().dump(1) + "\n"; }

Scene SceneBuilder::build() const {
  const Json doc = document<Json>();
  try {
    std::vector<tmcert::SceneRobot> robots;  // URDF files are absolute (add_robot)
    tmcert::Scene scene = tmcert::parse_scene_document(doc, kSource, "", robots);
    return Scene(std::make_shared<const Scene::Impl>(
        Scene::Impl{std::make_shared<const tmcert::Scene>(std::move(scene)), std::move(robots)}));
  } catch (const tmcert::InputError& e) {
    // The reader names bodies and robots by their index; add the name.
    std::string message = e.what();
    static const std::regex located(std::string("^") + kSource + R"(: (bodies|robots)\[(\d+)\])");
    std::smatch m;
    if (std::regex_search(message, m, located)) {
      const std::size_t index = std::stoul(m[2].str());
      const bool body = m[1].str() == "bodies";
      if (index < (body ? bodies_.size() : robots_.size()))
        message += std::string(" (") + (body ? "body " : "robot ") +
                   tmcert::quote_text(body ? bodies_[index].name_ : robots_[index].name_) + ")";
    }
    throw InputError(message);
  } catch (const tmcert::ResourceLimit& e) {
    throw ResourceLimit(e.what());
  }
}

}  // namespace tmcert::api
