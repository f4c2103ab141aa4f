// The scene reader's robots (src/io/scene_reader.h): "robots" from URDF
// moving along joint-space paths (SCENE_FORMAT.md "Robots from URDF,
// moving in joint space"), their package folders, allowed pairs and SRDF,
// and the default checks of a scene with robots.
#include "src/io/scene_reader.h"

#include <algorithm>
#include <set>

namespace tmcert::reader {

// "package_paths": folders relative to the scene file, searched for
// package:// URIs after the given ones (ReadOptions) and before
// ROS_PACKAGE_PATH.
void SceneReader::package_paths(const Node& node, const Path& path) {
  const std::span<const Node> list = array(node, path);
  for (std::size_t k = 0; k < list.size(); ++k) {
    if (list[k].kind != Node::Kind::String || text(list[k]).empty())
      fail(path.index(k), "expected a folder name (a non-empty string)");
    const std::string name(text(list[k]));
    if (name.find('\0') != std::string::npos) fail(path.index(k), "folder name contains a NUL character");
    scene_packages_.push_back((base_ / std::filesystem::path(name)).string());
  }
}

// The package folders in their order: given, the scene's, ROS_PACKAGE_PATH.
UrdfOptions SceneReader::urdf_options() const {
  UrdfOptions out;
  out.package_paths = options_.package_paths;
  out.package_paths.insert(out.package_paths.end(), scene_packages_.begin(), scene_packages_.end());
  for (const std::string& f : ros_package_path()) out.package_paths.push_back(f);
  return out;
}

// A joint-space path's "times", "positions", "interpolation",
// "velocities" and "accelerations" (exact numbers; their meaning is checked
// by validate_joint_path).  Velocities belong to cubic and quintic paths,
// accelerations to quintic ones: a missing one is "missing required field",
// one the interpolation does not use is refused.
void SceneReader::joint_path_values(const Node& node, const Path& path, JointPath& jp) const {
  const Members pobj = object(node, path);
  reject_unknown_keys(pobj, path, {"times", "positions", "interpolation", "velocities", "accelerations"});
  if (const Node* how = find(pobj, "interpolation")) {
    const Path hpath = path.member("interpolation");
    const std::string_view name = how->kind == Node::Kind::String ? text(*how) : std::string_view();
    if (name == "linear") jp.interpolation = JointInterpolation::Linear;
    else if (name == "cubic") jp.interpolation = JointInterpolation::Cubic;
    else if (name == "quintic") jp.interpolation = JointInterpolation::Quintic;
    else fail(hpath, "expected \"linear\", \"cubic\" or \"quintic\"");
  }
  auto rows_of = [&](const char* key, std::vector<std::vector<Exact>>& out, bool used) {
    const Path rpath = path.member(key);
    const Node* n = find(pobj, key);
    if (!used) {
      if (n)
        fail(rpath, std::string("not used by \"") + interpolation_name(jp.interpolation) +
                        "\" interpolation (velocities: cubic or quintic; accelerations: quintic)");
      return;
    }
    if (!n) fail(rpath, std::string("missing required field (\"") + interpolation_name(jp.interpolation) + "\" interpolation)");
    const std::span<const Node> rows = array(*n, rpath);
    for (std::size_t k = 0; k < rows.size(); ++k) {
      const Path row_path = rpath.index(k);
      std::vector<Exact> row;
      for (std::size_t c = 0; const Node& v : array(rows[k], row_path)) row.push_back(number(v, row_path.index(c++)));
      out.push_back(std::move(row));
    }
  };
  rows_of("velocities", jp.velocities, jp.interpolation != JointInterpolation::Linear);
  rows_of("accelerations", jp.accelerations, jp.interpolation == JointInterpolation::Quintic);
  const Path tpath = path.member("times"), qpath = path.member("positions");
  const Node* times_node = find(pobj, "times");
  if (!times_node) fail(tpath, "missing required field");
  for (std::size_t k = 0; const Node& t : array(*times_node, tpath)) jp.times.push_back(number(t, tpath.index(k++)));
  const Node* positions = find(pobj, "positions");
  if (!positions) fail(qpath, "missing required field");
  const std::span<const Node> rows = array(*positions, qpath);
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const Path row_path = qpath.index(k);
    std::vector<Exact> row;
    for (std::size_t c = 0; const Node& v : array(rows[k], row_path)) row.push_back(number(v, row_path.index(c++)));
    jp.positions.push_back(std::move(row));
  }
}

// "robots" (SCENE_FORMAT.md "Robots from URDF, moving in joint space"):
// each adds a body "<robot>/<link>" per link with collision geometry.
std::vector<SceneReader::RobotInScene> SceneReader::robots(Scene& scene, const Node& node, const Path& path,
                                 std::unordered_map<std::string, std::size_t>& names) const {
  const std::span<const Node> list = array(node, path);
  std::vector<RobotInScene> out;
  std::map<std::string, std::shared_ptr<const RobotModel>> loaded;  // by file
  std::set<std::string> robot_names;
  for (std::size_t r = 0; r < list.size(); ++r) {
    const Path rpath = path.index(r);
    const Members obj = object(list[r], rpath);
    reject_unknown_keys(obj, rpath, {"name", "urdf", "base", "joints", "path", "self_collision", "allowed_pairs", "srdf"});
    auto string_field = [&](const char* key) {
      const Node* n = find(obj, key);
      if (!n) fail(rpath.member(key), "missing required field");
      if (n->kind != Node::Kind::String || text(*n).empty()) fail(rpath.member(key), "expected a non-empty string");
      return std::string(text(*n));
    };
    const std::string name = string_field("name");
    for (char c : name)
      if (static_cast<unsigned char>(c) < 0x20 || c == 0x7F)
        fail(rpath.member("name"), "a robot name cannot contain control characters");
    if (!robot_names.insert(name).second) fail(rpath.member("name"), "duplicate robot name " + quote_text(name));
    const std::string urdf = string_field("urdf");
    if (urdf.find('\0') != std::string::npos) fail(rpath.member("urdf"), "file name contains a NUL character");
    const std::string file = (base_ / std::filesystem::path(urdf)).string();
    std::shared_ptr<const RobotModel>& model = loaded[file];
    if (!model) {
      try {
        model = load_urdf(file, urdf_options());
      } catch (const InputError& e) {
        fail(rpath.member("urdf"), one_line(e.what()));
      }
      notes_.insert(notes_.end(), model->notes.begin(), model->notes.end());
    }
    Pose base;
    if (const Node* b = find(obj, "base")) base = pose(*b, rpath.member("base"));
    JointPath jp;
    const Path jpath = rpath.member("joints");
    const Node* joints = find(obj, "joints");
    if (!joints) fail(jpath, "missing required field");
    const std::span<const Node> jlist = array(*joints, jpath);
    for (std::size_t c = 0; c < jlist.size(); ++c) {
      if (jlist[c].kind != Node::Kind::String) fail(jpath.index(c), "expected a joint name (a string)");
      jp.joints.emplace_back(text(jlist[c]));
    }
    const Path ppath = rpath.member("path");
    const Node* pnode = find(obj, "path");
    if (!pnode) fail(ppath, "missing required field");
    joint_path_values(*pnode, ppath, jp);
    const Path tpath = ppath.member("times"), qpath = ppath.member("positions");
    RobotInScene placed;
    placed.joints = jp.joints;
    placed.robot = std::make_shared<const PlacedRobot>(model, name, base);
    try {
      placed.bodies = add_robot(scene, *placed.robot, jp);
    } catch (const JointPathError& e) {
      const Path field = e.field == "joints"          ? jpath
                         : e.field == "times"         ? tpath
                         : e.field == "path"          ? ppath
                         : e.field == "velocities"    ? ppath.member("velocities")
                         : e.field == "accelerations" ? ppath.member("accelerations")
                                                      : qpath;
      if (e.index.empty()) fail(field, e.what());
      const Path first = field.index(e.index[0]);
      if (e.index.size() == 1) fail(first, e.what());
      fail(first.index(e.index[1]), e.what());
    }
    for (const std::vector<int>& parts : placed.bodies.parts) {
      for (int b : parts) {
        const std::string& body_name = scene.bodies[b].name;
        if (auto [it, fresh] = names.emplace(body_name, static_cast<std::size_t>(b)); !fresh)
          fail(rpath.member("name"), "the link body " + quote_text(body_name) + " has the name of another body");
      }
      if (parts.size() > 1) link_parts_[parts.front()] = parts;
    }
    if (const Node* sc = find(obj, "self_collision")) {
      if (sc->kind != Node::Kind::Boolean) fail(rpath.member("self_collision"), "expected true or false");
      placed.self_collision = sc->boolean;
    }
    if (const Node* ap = find(obj, "allowed_pairs")) {
      const Path apath = rpath.member("allowed_pairs");
      const std::span<const Node> pairs = array(*ap, apath);
      for (std::size_t k = 0; k < pairs.size(); ++k) {
        const Path pair_path = apath.index(k);
        const std::span<const Node> pair = array(pairs[k], pair_path);
        if (pair.size() != 2) fail(pair_path, "an allowed pair names exactly 2 links, got " + std::to_string(pair.size()));
        std::string links[2];
        for (std::size_t s = 0; s < 2; ++s) {
          if (pair[s].kind != Node::Kind::String) fail(pair_path.index(s), "expected a link name (a string)");
          links[s] = std::string(text(pair[s]));
          if (model->link_index(links[s]) < 0)
            fail(pair_path.index(s), "unknown link " + quote_text(links[s]) + " (not in " + model->source + ")");
        }
        placed.allowed.emplace_back(links[0], links[1]);
      }
    }
    if (const Node* sr = find(obj, "srdf")) {
      // MoveIt's allowed self-collisions: every <disable_collisions>.
      const Path spath = rpath.member("srdf");
      if (sr->kind != Node::Kind::String || text(*sr).empty()) fail(spath, "expected a non-empty string (an SRDF file)");
      const std::string srdf(text(*sr));
      if (srdf.find('\0') != std::string::npos) fail(spath, "file name contains a NUL character");
      try {
        for (auto& pair : read_srdf((base_ / std::filesystem::path(srdf)).string(), *model)) placed.allowed.push_back(pair);
      } catch (const InputError& e) {
        fail(spath, one_line(e.what()));
      }
    }
    out.push_back(std::move(placed));
  }
  return out;
}

// The default checks with robots: the general rule among the bodies
// that are not links, then each robot's rule (every link against every
// body not of that robot; self-collision pairs), each pair once.
std::vector<std::pair<int, int>> SceneReader::default_checks_with_robots(const Scene& scene, std::size_t plain_bodies,
    const std::vector<RobotInScene>& robots) {
  Scene plain;
  plain.bodies.assign(scene.bodies.begin(), scene.bodies.begin() + static_cast<std::ptrdiff_t>(plain_bodies));
  std::vector<std::pair<int, int>> out = default_checks(plain);
  if (robots.empty()) return out;
  std::set<std::pair<int, int>> seen;
  for (const auto& [a, b] : out) seen.insert(std::minmax(a, b));
  for (const RobotInScene& r : robots) {
    std::set<int> own;
    for (const std::vector<int>& parts : r.bodies.parts) own.insert(parts.begin(), parts.end());
    std::vector<int> environment;
    for (int b = 0; b < static_cast<int>(scene.bodies.size()); ++b)
      if (!own.count(b)) environment.push_back(b);
    for (const auto& [a, b] : robot_default_checks(*r.robot, r.bodies, environment, r.self_collision, r.allowed))
      if (seen.insert(std::minmax(a, b)).second) out.emplace_back(a, b);
  }
  return out;
}

}  // namespace tmcert::reader
