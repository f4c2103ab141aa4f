// Reading URDF (robot.h): the tree is checked here first (require_tree:
// one parent joint per link, one root, no cycle, with messages naming the
// links and joints), then urdfdom checks the structure again and gives it;
// every number is read again from the XML text (TinyXML, the parser urdfdom
// itself uses) with the exact decimal reader, because urdfdom stores
// doubles.
#include "src/io/robot.h"

#include "kernels/decimal.h"
#include "src/model/mass.h"
#include "src/io/primitives.h"
#include "src/io/mesh.h"
#include "src/io/parse.h"
#include "src/io/read_file.h"
#include "src/model/solid.h"

#include <console_bridge/console.h>
#include <tinyxml.h>
#include <urdf_parser/urdf_parser.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <mutex>
#include <sstream>

namespace tmcert {

namespace {

constexpr std::uintmax_t kMaxUrdfBytes = 64ull << 20;
// Angles beyond this are absurd (sin and cos enclosures would be [-1, 1]);
// the same bound as scene rpy angles.
const Exact kMaxAngle(1000000);

// Collects urdfdom's messages (console_bridge) instead of printing them.
class Capture : public console_bridge::OutputHandler {
 public:
  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_ERROR && first_error.empty()) first_error = text;
  }
  std::string first_error;
};

std::mutex& console_mutex() {
  static std::mutex m;
  return m;
}

std::string one_line(std::string s) {
  for (char& c : s)
    if (c == '\n' || c == '\r' || c == '\t') c = ' ';
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s;
}

class UrdfReader {
 public:
  UrdfReader(std::string source, std::filesystem::path directory, UrdfOptions options)
      : source_(std::move(source)), directory_(std::move(directory)), options_(std::move(options)) {}

  std::shared_ptr<const RobotModel> read(const std::string& text) {
    // xacro (URDF with macros: a .xacro file, or xacro: elements) is
    // expanded by the xacro tool, not here.
    if (is_xacro(text)) {
      // robot.urdf.xacro and robot.xacro become robot.urdf; another name
      // gets a new one beside it.
      std::string output = std::filesystem::path(source_).replace_extension().string();
      if (source_.ends_with(".urdf.xacro")) output = std::filesystem::path(output).replace_extension().string();
      output += source_.ends_with(".xacro") ? ".urdf" : "-expanded.urdf";
      fail("this is xacro (URDF macros), not plain URDF: run xacro first: xacro " + source_ + " > " + output);
    }
    TiXmlDocument doc;
    doc.Parse(text.c_str());
    if (doc.Error())
      fail("XML error at line " + std::to_string(doc.ErrorRow()) + ": " + one_line(doc.ErrorDesc()));
    const TiXmlElement* robot = doc.FirstChildElement("robot");
    if (!robot) fail("no <robot> element");
    // Joint types first, with our own message naming the joint.
    for (const TiXmlElement* j = robot->FirstChildElement("joint"); j; j = j->NextSiblingElement("joint")) {
      const std::string name = attribute(j, "name").value_or("");
      const std::string type = attribute(j, "type").value_or("");
      if (type != "revolute" && type != "continuous" && type != "prismatic" && type != "fixed")
        fail("joint " + quote_text(name) + ": unsupported joint type " + quote_text(type) +
             " (supported: revolute, continuous, prismatic, fixed)");
    }
    auto model = std::make_shared<RobotModel>();
    model->name = attribute(robot, "name").value_or("");
    model->source = source_;
    std::map<std::string, int> link_ids;
    for (const TiXmlElement* l = robot->FirstChildElement("link"); l; l = l->NextSiblingElement("link")) {
      RobotLink link;
      link.name = attribute(l, "name").value_or("");
      if (link_ids.count(link.name)) fail("link " + quote_text(link.name) + ": defined twice");
      link_ids[link.name] = static_cast<int>(model->links.size());
      model->links.push_back(std::move(link));
    }
    for (const TiXmlElement* j = robot->FirstChildElement("joint"); j; j = j->NextSiblingElement("joint"))
      model->joints.push_back(joint(j, link_ids));
    require_tree(*model);
    mimics(robot, *model);
    for (std::size_t j = 0; j < model->joints.size(); ++j) model->links[model->joints[j].child].parent_joint = static_cast<int>(j);
    // The structure (one root, a tree, ...) through urdfdom, after our own
    // reading so that our messages (naming the element) come first.
    urdf::ModelInterfaceSharedPtr urdf;
    Capture capture;
    {
      std::lock_guard<std::mutex> lock(console_mutex());
      console_bridge::OutputHandler* previous = console_bridge::getOutputHandler();
      console_bridge::useOutputHandler(&capture);
      try {
        urdf = urdf::parseURDF(text);
      } catch (const std::exception& e) {
        capture.first_error = e.what();
        urdf.reset();
      }
      console_bridge::useOutputHandler(previous);
    }
    if (!urdf) fail("not a valid URDF (urdfdom: " + one_line(capture.first_error.empty() ? "parse failed" : capture.first_error) + ")");

    const urdf::LinkConstSharedPtr root = urdf->getRoot();
    if (!root) fail("no root link");
    model->root = link_ids.at(root->name);
    // urdfdom has checked the tree; make sure its view and ours agree.
    for (const RobotLink& link : model->links) {
      const urdf::LinkConstSharedPtr ul = urdf->getLink(link.name);
      if (!ul) fail("link " + quote_text(link.name) + ": not in urdfdom's model");
      const bool root_link = link.parent_joint < 0;
      if (root_link != (ul->parent_joint == nullptr) ||
          (!root_link && ul->parent_joint->name != model->joints[link.parent_joint].name))
        fail("link " + quote_text(link.name) + ": inconsistent parent joint");
    }
    int l = 0;
    for (const TiXmlElement* e = robot->FirstChildElement("link"); e; e = e->NextSiblingElement("link"), ++l)
      geometry(e, model->links[l]);
    model->notes = std::move(notes_);
    return model;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const { throw InputError(source_ + ": " + what); }

  // The links and joints must form a tree (docs/scene-format.md "Robots"):
  // every joint name once, every link the child of at most one joint, one
  // link (the root) the child of none, and every link reached from the
  // root.  Checked here, naming the links and joints, rather than left to
  // urdfdom, which keeps one of two parent joints silently and does not
  // look for cycles away from the root.  Sets each link's parent joint and
  // the root.
  void require_tree(RobotModel& model) const {
    if (model.links.empty()) fail("no <link> (a robot needs at least one link)");
    std::map<std::string, std::size_t> joint_ids;
    for (std::size_t j = 0; j < model.joints.size(); ++j) {
      const RobotJoint& joint = model.joints[j];
      if (!joint_ids.emplace(joint.name, j).second) fail("joint " + quote_text(joint.name) + ": defined twice");
      if (joint.parent == joint.child)
        fail("joint " + quote_text(joint.name) + ": its parent and child are the same link " +
             quote_text(model.links[joint.child].name) + " (a URDF must be a tree)");
      RobotLink& child = model.links[joint.child];
      if (child.parent_joint >= 0)
        fail("link " + quote_text(child.name) + ": the child of two joints, " +
             quote_text(model.joints[child.parent_joint].name) + " and " + quote_text(joint.name) +
             " (a URDF must be a tree: each link has at most one parent joint)");
      child.parent_joint = static_cast<int>(j);
    }
    std::vector<std::size_t> roots;
    for (std::size_t l = 0; l < model.links.size(); ++l)
      if (model.links[l].parent_joint < 0) roots.push_back(l);
    if (roots.size() > 1)
      fail("links " + quote_text(model.links[roots[0]].name) + " and " + quote_text(model.links[roots[1]].name) +
           " are both roots (the child of no joint); a URDF must be a tree with one root, every other link "
           "connected to it by joints");
    // With one root and one parent joint per other link, a link that the
    // root does not reach lies on a cycle of joints (and so does the root's
    // absence).
    std::vector<std::vector<std::size_t>> children(model.links.size());
    for (const RobotJoint& joint : model.joints) children[joint.parent].push_back(joint.child);
    std::vector<char> reached(model.links.size(), 0);
    if (!roots.empty()) {
      std::vector<std::size_t> stack{roots[0]};
      reached[roots[0]] = 1;
      while (!stack.empty()) {
        const std::size_t l = stack.back();
        stack.pop_back();
        for (std::size_t c : children[l])
          if (!reached[c]) {
            reached[c] = 1;
            stack.push_back(c);
          }
      }
    }
    for (std::size_t l = 0; l < model.links.size(); ++l) {
      if (reached[l]) continue;
      // Up the parent joints from l until a link repeats: that is the cycle.
      std::vector<int> seen(model.links.size(), -1);
      std::vector<std::size_t> path;
      std::size_t k = l;
      while (seen[k] < 0) {
        seen[k] = static_cast<int>(path.size());
        path.push_back(k);
        k = static_cast<std::size_t>(model.joints[model.links[k].parent_joint].parent);
      }
      std::string joints;
      for (std::size_t i = static_cast<std::size_t>(seen[k]); i < path.size(); ++i)
        joints += (joints.empty() ? "" : ", ") + quote_text(model.joints[model.links[path[i]].parent_joint].name);
      fail("joints " + joints + " form a cycle through link " + quote_text(model.links[k].name) +
           " (a URDF must be a tree)");
    }
    model.root = static_cast<int>(roots[0]);
  }

  bool is_xacro(const std::string& text) const {
    // xacro's output keeps the xmlns:xacro declaration (published robots
    // do): only a .xacro name or a xacro element says the macros are left.
    return source_.ends_with(".xacro") || text.find("<xacro:") != std::string::npos;
  }

  static std::optional<std::string> attribute(const TiXmlElement* e, const char* name) {
    const char* v = e->Attribute(name);
    if (!v) return std::nullopt;
    return std::string(v);
  }

  // A list of exact numbers separated by white space.
  std::vector<Exact> numbers(const std::string& text, std::size_t count, const std::string& where) const {
    std::istringstream in(text);
    std::vector<Exact> out;
    std::string token;
    while (in >> token) {
      Exact v;
      if (!parse_exact(token, v)) fail(where + ": not a number: " + quote_text(token));
      if (!within_input_limit(v)) fail(where + ": number too large: " + token.substr(0, 60));
      out.push_back(v);
    }
    if (out.size() != count)
      fail(where + ": expected " + std::to_string(count) + " number" + (count == 1 ? "" : "s") + ", got " +
           std::to_string(out.size()) + " in " + quote_text(text));
    return out;
  }

  Exact number(const TiXmlElement* e, const char* name, const std::string& where, std::optional<Exact> fallback) const {
    const auto text = attribute(e, name);
    if (!text) {
      if (fallback) return *fallback;
      fail(where + ": missing attribute \"" + name + "\"");
    }
    return numbers(*text, 1, where + " " + name)[0];
  }

  Vec3E triple(const TiXmlElement* e, const char* name, const std::string& where, const Vec3E& fallback) const {
    const auto text = attribute(e, name);
    if (!text) return fallback;
    const std::vector<Exact> v = numbers(*text, 3, where + " " + name);
    return {v[0], v[1], v[2]};
  }

  // <origin xyz rpy>, absent: the identity.
  Pose origin(const TiXmlElement* parent, const std::string& where) const {
    Pose p;
    const TiXmlElement* o = parent->FirstChildElement("origin");
    if (!o) return p;
    const Vec3E zero{Exact(0), Exact(0), Exact(0)};
    p.translation = triple(o, "xyz", where + ": origin", zero);
    const Vec3E rpy = triple(o, "rpy", where + ": origin", zero);
    for (const Exact& a : rpy)
      if (CGAL::abs(a) > kMaxAngle) fail(where + ": origin rpy: angle out of range (at most 10^6 radians)");
    if (rpy != zero) {
      p.rotation.kind = Rotation::Kind::Rpy;
      p.rotation.rpy = rpy;
    }
    return p;
  }

  // <mimic joint="J" multiplier="m" offset="o"/> (robot.h RobotJoint::Mimic):
  // J must exist and move; a mimic on a fixed joint is ignored (it does
  // not move); cycles of mimics are refused.
  void mimics(const TiXmlElement* robot, RobotModel& model) const {
    std::size_t j = 0;
    for (const TiXmlElement* e = robot->FirstChildElement("joint"); e; e = e->NextSiblingElement("joint"), ++j) {
      const TiXmlElement* m = e->FirstChildElement("mimic");
      RobotJoint& joint = model.joints[j];
      if (!m || !joint.moves()) continue;
      const std::string where = "joint " + quote_text(joint.name) + ": mimic";
      const auto followed = attribute(m, "joint");
      if (!followed) fail(where + ": missing attribute \"joint\"");
      const int f = model.joint_index(*followed);
      if (f < 0) fail(where + ": unknown joint " + quote_text(*followed));
      if (!model.joints[f].moves()) fail(where + ": joint " + quote_text(*followed) + " is fixed");
      if (f == static_cast<int>(j)) fail(where + ": a joint cannot follow itself");
      RobotJoint::Mimic mimic;
      mimic.joint = f;
      mimic.multiplier = number(m, "multiplier", where, Exact(1));
      mimic.offset = number(m, "offset", where, Exact(0));
      joint.mimic = mimic;
    }
    for (const RobotJoint& joint : model.joints) {
      std::size_t steps = 0;
      for (const RobotJoint* k = &joint; k->mimic; k = &model.joints[k->mimic->joint])
        if (++steps > model.joints.size()) fail("joint " + quote_text(joint.name) + ": mimic: the mimic joints form a cycle");
    }
  }

  RobotJoint joint(const TiXmlElement* e, const std::map<std::string, int>& link_ids) const {
    RobotJoint j;
    j.name = attribute(e, "name").value_or("");
    const std::string where = "joint " + quote_text(j.name);
    const std::string type = attribute(e, "type").value_or("");
    j.type = type == "revolute"     ? RobotJoint::Type::Revolute
             : type == "continuous" ? RobotJoint::Type::Continuous
             : type == "prismatic"  ? RobotJoint::Type::Prismatic
                                    : RobotJoint::Type::Fixed;
    auto link_of = [&](const char* tag) {
      const TiXmlElement* x = e->FirstChildElement(tag);
      const auto name = x ? attribute(x, "link") : std::nullopt;
      if (!name) fail(where + ": missing <" + tag + " link=...>");
      const auto it = link_ids.find(*name);
      if (it == link_ids.end()) fail(where + ": unknown " + tag + " link " + quote_text(*name));
      return it->second;
    };
    j.parent = link_of("parent");
    j.child = link_of("child");
    j.origin = origin(e, where);
    if (j.moves()) {
      if (const TiXmlElement* axis = e->FirstChildElement("axis")) j.axis = triple(axis, "xyz", where + ": axis", j.axis);
      if (j.axis[0] == 0 && j.axis[1] == 0 && j.axis[2] == 0) fail(where + ": axis is zero");
    }
    if (j.type == RobotJoint::Type::Revolute || j.type == RobotJoint::Type::Prismatic) {
      const TiXmlElement* limit = e->FirstChildElement("limit");
      if (!limit) fail(where + ": missing <limit>");
      j.lower = number(limit, "lower", where + ": limit", Exact(0));
      j.upper = number(limit, "upper", where + ": limit", Exact(0));
      if (*j.lower > *j.upper) fail(where + ": limit lower " + decimal_text(*j.lower) + " is above upper " + decimal_text(*j.upper));
    }
    return j;
  }

  // A mesh file name as the URDF writes it: package://NAME/REL through the
  // package folders, file://PATH as PATH, else a path relative to the
  // URDF's directory.
  std::string mesh_file(const std::string& name, const std::string& where) const {
    std::string file = name;
    if (file.rfind("package://", 0) == 0) {
      const std::string rest = file.substr(10);
      const std::size_t slash = rest.find('/');
      if (slash == 0 || slash == std::string::npos || slash + 1 == rest.size())
        fail(where + ": mesh " + quote_text(name) + ": expected package://NAME/PATH");
      const std::string package = rest.substr(0, slash);
      auto [it, fresh] = packages_.emplace(package, std::nullopt);
      if (fresh) it->second = find_package(package, options_.package_paths);
      if (!it->second) {
        std::string folders;
        for (const std::string& f : options_.package_paths) folders += (folders.empty() ? "" : ", ") + quote_text(f);
        fail(where + ": mesh " + quote_text(name) + ": package " + quote_text(package) +
             (folders.empty() ? " not found: no package folders to search"
                              : " not found in " + folders + " (each with its subfolders up to four levels)") +
             "; give them with --package-path, the scene's \"package_paths\" or ROS_PACKAGE_PATH");
      }
      return (std::filesystem::path(*it->second) / rest.substr(slash + 1)).string();
    }
    if (file.rfind("file://", 0) == 0) file = file.substr(7);
    if (file.empty()) fail(where + ": mesh: empty filename");
    const std::filesystem::path p(file);
    return (p.is_absolute() ? p : directory_ / p).string();
  }

  // One <collision> element's polygons, in the link frame's axes about the
  // element's origin (not yet translated).
  PolygonList shape(const TiXmlElement* geometry, const std::string& where, std::string& kind_out, Exact& radius_out,
                    Exact& length_out) const {
    const TiXmlElement* g = geometry ? geometry->FirstChildElement() : nullptr;
    if (!g) fail(where + ": missing <geometry> shape");
    const std::string kind = g->Value();
    kind_out = kind;
    auto positive = [&](const Exact& v, const std::string& what) {
      if (!(v > 0)) fail(where + ": " + what + " must be positive, got " + to_string(v));
      return v;
    };
    if (kind == "box") {
      const Vec3E size = triple(g, "size", where + ": box", {Exact(0), Exact(0), Exact(0)});
      if (!attribute(g, "size")) fail(where + ": box: missing attribute \"size\"");
      for (const Exact& s : size) positive(s, "box size");
      return box_polyhedron(size);
    }
    if (kind == "cylinder") {
      const Exact r = positive(number(g, "radius", where + ": cylinder", std::nullopt), "cylinder radius");
      const Exact len = positive(number(g, "length", where + ": cylinder", std::nullopt), "cylinder length");
      radius_out = r;
      length_out = len;
      return {};  // its polyhedron: LinkParts
    }
    if (kind == "sphere") {
      const Exact r = positive(number(g, "radius", where + ": sphere", std::nullopt), "sphere radius");
      radius_out = r;
      return {};
    }
    if (kind == "mesh") {
      const auto name = attribute(g, "filename");
      if (!name) fail(where + ": mesh: missing attribute \"filename\"");
      const Vec3E scale = triple(g, "scale", where + ": mesh", {Exact(1), Exact(1), Exact(1)});
      for (const Exact& s : scale)
        if (s == 0) fail(where + ": mesh scale must be nonzero");
      const std::string file = mesh_file(*name, where);
      MeshData data;
      try {
        data = read_mesh(file);
      } catch (const InputError& e) {
        fail(where + ": mesh: " + one_line(e.what()));
      }
      if (data.faces.empty()) fail(where + ": mesh " + file + " has no faces");
      if (data.from_floats)
        notes_.push_back(source_ + ": " + where + ": mesh " + file + " (" + data.format +
                         ") is read from its single-precision floats: its coordinates are their exact values");
      PolygonList out;
      for (const auto& face : data.faces) {
        std::vector<Vec3E> f;
        for (std::size_t i : face) {
          const Vec3E& v = data.vertices[i];
          f.push_back({v[0] * scale[0], v[1] * scale[1], v[2] * scale[2]});
        }
        out.push_back(std::move(f));
      }
      mesh_files_.push_back(file);
      return out;
    }
    fail(where + ": unsupported geometry <" + kind + "> (supported: box, cylinder, sphere, mesh)");
  }

  struct Element {
    Pose origin;
    PolygonList polygons;      // boxes and meshes, about the origin (not moved)
    std::string kind;          // box, cylinder, sphere, mesh
    Exact radius, length;      // cylinder, sphere
    std::string where;
  };

  // The link's collision elements as parts (robot.h LinkPart,
  // proofs/robot-links.md section 2).
  void geometry(const TiXmlElement* e, RobotLink& link) const {
    const std::string where = "link " + quote_text(link.name);
    std::vector<Element> elements;
    int index = 0;
    for (const TiXmlElement* c = e->FirstChildElement("collision"); c; c = c->NextSiblingElement("collision"), ++index) {
      Element el;
      el.where = where + ": collision[" + std::to_string(index) + "]";
      el.origin = origin(c, el.where);
      mesh_files_.clear();
      el.polygons = shape(c->FirstChildElement("geometry"), el.where, el.kind, el.radius, el.length);
      if (!mesh_files_.empty()) el.where += " (" + mesh_files_.back() + ")";
      elements.push_back(std::move(el));
    }
    if (elements.empty()) return;
    auto same = [](const Pose& a, const Pose& b) {
      return a.translation == b.translation && a.rotation.kind == b.rotation.kind && a.rotation.rpy == b.rotation.rpy;
    };
    auto rotated = [](const Pose& p) { return p.rotation.kind != Rotation::Kind::Identity; };
    // Frames of the boxes and meshes: the link frame for those whose origin
    // has no rotation (their vertices moved by its translation exactly),
    // each rotated origin its own frame (the vertices as they are).
    struct Group {
      std::optional<Pose> frame;  // none: the link frame
      std::vector<int> elements;
    };
    std::vector<Group> groups;
    auto group_of = [&](const std::optional<Pose>& frame) -> Group& {
      for (Group& g : groups)
        if (g.frame.has_value() == frame.has_value() && (!frame || same(*g.frame, *frame))) return g;
      groups.push_back({frame, {}});
      return groups.back();
    };
    std::vector<std::pair<int, LinkPart>> parts;  // (first element, part), sorted below
    for (std::size_t k = 0; k < elements.size(); ++k) {
      const Element& el = elements[k];
      if (el.kind == "box" || el.kind == "mesh") {
        group_of(rotated(el.origin) ? std::optional<Pose>(el.origin) : std::nullopt).elements.push_back(static_cast<int>(k));
        continue;
      }
      // A cylinder or sphere: its own part, in its origin's frame (a
      // sphere's without the rotation, which does not change it).
      LinkPart part;
      part.elements = {static_cast<int>(k)};
      Pose frame = el.origin;
      if (el.kind == "sphere") frame.rotation = Rotation{};
      if (frame.translation != Vec3E{Exact(0), Exact(0), Exact(0)} || rotated(frame)) part.frame = {frame};
      Body::Primitive prim;
      prim.kind = el.kind == "sphere" ? Body::Primitive::Kind::Sphere : Body::Primitive::Kind::Cylinder;
      prim.radius = el.radius;
      prim.length = el.length;
      part.geometry = primitive_body(prim, el.where);
      parts.emplace_back(static_cast<int>(k), std::move(part));
    }
    for (const Group& g : groups) {
      // The polygons in the group's frame: exact; the element of each
      // polygon, segment and point.
      Body all;
      std::vector<int> polygon_element, other_element;
      for (int k : g.elements) {
        const Element& el = elements[k];
        const Vec3E offset = g.frame ? Vec3E{Exact(0), Exact(0), Exact(0)} : el.origin.translation;
        std::size_t f = 0;
        for (const std::vector<Vec3E>& polygon : el.polygons) {
          std::vector<Vec3E> moved;
          for (const Vec3E& v : polygon) moved.push_back({v[0] + offset[0], v[1] + offset[1], v[2] + offset[2]});
          add_polygon(all, moved, el.where + ": face " + std::to_string(f++));
          polygon_element.resize(all.polygons.size(), k);
          other_element.resize(all.segments.size() + all.points.size(), k);
        }
      }
      // Closed shells without self-intersection keep their insides; the
      // rest (open shells, segments and points of degenerate faces) are
      // surfaces.
      Body closed, open;
      std::vector<int> closed_elements, open_elements = other_element;
      split_shells(all, polygon_element, elements, closed, closed_elements, open, open_elements);
      for (Body* b : {&closed, &open}) {
        if (b->polygons.empty() && b->segments.empty() && b->points.empty()) continue;
        std::vector<int>& els = b == &closed ? closed_elements : open_elements;
        std::sort(els.begin(), els.end());
        els.erase(std::unique(els.begin(), els.end()), els.end());
        LinkPart part;
        part.elements = els;
        if (g.frame) part.frame = {*g.frame};
        b->solid = b == &closed;
        finish(*b);
        part.geometry = std::move(*b);
        // The open surfaces of an element that also has closed shells.
        if (b == &open && !closed_elements.empty() && closed_elements.front() == els.front()) part.suffix = "/open";
        parts.emplace_back(els.front(), std::move(part));
      }
    }
    // In element order (the closed shells of an element before its open
    // surfaces); the first is the link's body, the others are named by
    // their first element.
    std::stable_sort(parts.begin(), parts.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for (std::size_t p = 0; p < parts.size(); ++p) {
      LinkPart& part = parts[p].second;
      part.suffix = p == 0 ? std::string() : "/collision[" + std::to_string(parts[p].first) + "]" + part.suffix;
      link.parts.push_back(std::move(part));
    }
  }

  // The closed shells of `all` (polygon_shells: every edge of the shell in
  // exactly two of its polygons, and no self-intersection) into `closed`,
  // everything else into `open` (which has `all`'s segments and points
  // already); the elements of their polygons appended to the lists.  A
  // shell that closes but intersects itself is a surface, and the result
  // says so (a note naming its element).
  void split_shells(const Body& all, const std::vector<int>& polygon_element, const std::vector<Element>& elements,
                    Body& closed, std::vector<int>& closed_elements, Body& open, std::vector<int>& open_elements) const {
    open.segments = all.segments;
    open.points = all.points;
    if (all.polygons.empty()) return;
    const std::vector<int> shell = polygon_shells(all);
    const int shells = *std::max_element(shell.begin(), shell.end()) + 1;
    // Each shell on its own, with its convex pieces (which the
    // self-intersection test reads), renumbered to the shell's polygons.
    std::vector<Body> each(shells);
    std::vector<int> index_in_shell(all.polygons.size());
    for (std::size_t p = 0; p < all.polygons.size(); ++p) {
      index_in_shell[p] = static_cast<int>(each[shell[p]].polygons.size());
      each[shell[p]].polygons.push_back(all.polygons[p]);
    }
    for (const ConvexPiece& piece : all.pieces) {
      ConvexPiece q = piece;
      q.polygon = index_in_shell[piece.polygon];
      each[shell[piece.polygon]].pieces.push_back(std::move(q));
    }
    std::vector<int> first_polygon(shells, -1);
    for (std::size_t p = 0; p < all.polygons.size(); ++p)
      if (first_polygon[shell[p]] < 0) first_polygon[shell[p]] = static_cast<int>(p);
    std::vector<char> is_closed(shells, 0);
    for (int k = 0; k < shells; ++k) {
      if (!solid_problem(each[k]).empty()) continue;
      if (shell_intersection_problem(each[k]).empty()) {
        is_closed[k] = 1;
        continue;
      }
      notes_.push_back(source_ + ": " + elements[polygon_element[first_polygon[k]]].where + ": a closed shell of " +
                       std::to_string(each[k].polygons.size()) +
                       " polygons intersects itself: it counts as a surface (its inside is not part of the link's solid)");
    }
    std::vector<int> new_index(all.polygons.size());
    for (std::size_t p = 0; p < all.polygons.size(); ++p) {
      const bool c = is_closed[shell[p]];
      Body& to = c ? closed : open;
      new_index[p] = static_cast<int>(to.polygons.size());
      to.polygons.push_back(all.polygons[p]);
      (c ? closed_elements : open_elements).push_back(polygon_element[p]);
    }
    // The convex pieces, renumbered to the new polygon indices.
    for (const ConvexPiece& piece : all.pieces) {
      ConvexPiece q = piece;
      q.polygon = new_index[piece.polygon];
      (is_closed[shell[piece.polygon]] ? closed : open).pieces.push_back(std::move(q));
    }
  }

  // The default mass of a part's body.
  static void finish(Body& body) {
    std::vector<Vec3E> vertices;
    for (const auto& p : body.polygons) vertices.insert(vertices.end(), p.begin(), p.end());
    for (const auto& s : body.segments) vertices.insert(vertices.end(), s.begin(), s.end());
    vertices.insert(vertices.end(), body.points.begin(), body.points.end());
    body.mass = default_mass(vertices, size_of(vertices));
    body.mass_is_default = true;
  }

  // A cylinder or sphere as the body of its circumscribed polyhedron at
  // refinement level prim.level, solid, with the true shape.
  Body primitive_body(const Body::Primitive& prim, const std::string& where) const {
    Body body;
    const PolygonList polygons = prim.kind == Body::Primitive::Kind::Sphere ? sphere_polyhedron(prim.radius, prim.level)
                                                                            : cylinder_polyhedron(prim.radius, prim.length, prim.level);
    std::size_t f = 0;
    for (const std::vector<Vec3E>& polygon : polygons) add_polygon(body, polygon, where + ": face " + std::to_string(f++));
    body.solid = true;
    body.enlarged = {prim.kind == Body::Primitive::Kind::Sphere ? "sphere" : "cylinder"};
    body.primitive = prim;
    finish(body);
    return body;
  }

  static Exact size_of(const std::vector<Vec3E>& v) {
    Exact size = 0;
    for (int i = 0; i < 3; ++i) {
      Exact lo = v[0][i], hi = v[0][i];
      for (const Vec3E& p : v) {
        lo = std::min(lo, p[i]);
        hi = std::max(hi, p[i]);
      }
      size = std::max(size, hi - lo);
    }
    return size > 0 ? size : Exact(1);
  }

  // A face through the scene's polygon checks; a degenerate triangle of a
  // mesh (its vertices collinear or repeated: a segment or a point) is kept
  // as segments, which hold exactly its points.
  static void add_polygon(Body& body, const std::vector<Vec3E>& polygon, const std::string& where) {
    try {
      auto [clean, pieces] = split_scene_polygon(polygon, static_cast<int>(body.polygons.size()));
      body.polygons.push_back(std::move(clean));
      for (ConvexPiece& p : pieces) body.pieces.push_back(std::move(p));
      return;
    } catch (const InputError& e) {
      if (polygon.size() != 3) throw InputError(where + ": " + e.what());
      // Collinear or repeated vertices: the triangle is the segment between
      // its two farthest vertices (or a point).
      const Vec3E *a = &polygon[0], *b = &polygon[1];
      auto d2 = [](const Vec3E& p, const Vec3E& q) {
        Exact s = 0;
        for (int i = 0; i < 3; ++i) s += (p[i] - q[i]) * (p[i] - q[i]);
        return s;
      };
      for (int i = 0; i < 3; ++i)
        for (int j = i + 1; j < 3; ++j)
          if (d2(polygon[i], polygon[j]) > d2(*a, *b)) {
            a = &polygon[i];
            b = &polygon[j];
          }
      if (*a == *b) body.points.push_back(*a);
      else body.segments.push_back({*a, *b});
    }
  }

  std::string source_;
  std::filesystem::path directory_;
  UrdfOptions options_;
  mutable std::vector<std::string> mesh_files_;
  mutable std::vector<std::string> notes_;
  mutable std::map<std::string, std::optional<std::string>> packages_;  // package folders found
};

}  // namespace

std::shared_ptr<const RobotModel> load_urdf_text(const std::string& text, const std::string& source,
                                                 const std::string& directory, const UrdfOptions& options) {
  UrdfReader reader(source, directory, options);
  try {
    return reader.read(text);
  } catch (const InputError&) {
    throw;
  } catch (const ResourceLimit&) {
    throw;
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::exception& e) {  // never a crash: anything unexpected is bad input here
    throw InputError(source + ": " + one_line(e.what()));
  }
}

std::shared_ptr<const RobotModel> load_urdf(const std::string& file, const UrdfOptions& options) {
  const std::string text = read_regular_file(file, kMaxUrdfBytes);
  const std::filesystem::path dir = std::filesystem::path(file).parent_path();
  return load_urdf_text(text, file, dir.string(), options);
}

std::vector<std::string> ros_package_path() {
  std::vector<std::string> out;
  const char* value = std::getenv("ROS_PACKAGE_PATH");
  if (!value) return out;
  std::string item;
  for (const char* c = value;; ++c) {
    if (*c == ':' || *c == '\0') {
      if (!item.empty()) out.push_back(item);
      item.clear();
      if (*c == '\0') break;
    } else {
      item += *c;
    }
  }
  return out;
}

namespace {

// The <name> of the package.xml at `xml` (ROS package format 1 to 3), or
// "" when it has none or cannot be read.
std::string package_xml_name(const std::filesystem::path& xml) {
  std::string text;
  try {
    text = read_regular_file(xml.string(), 1u << 20);
  } catch (const std::exception&) {
    return {};
  }
  TiXmlDocument doc;
  doc.Parse(text.c_str());
  if (doc.Error()) return {};
  const TiXmlElement* package = doc.FirstChildElement("package");
  const TiXmlElement* name = package ? package->FirstChildElement("name") : nullptr;
  const char* v = name ? name->GetText() : nullptr;
  if (!v) return {};
  std::string s = v;
  const auto first = s.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return {};
  s = s.substr(first, s.find_last_not_of(" \t\r\n") - first + 1);
  return s;
}

// Visits `root` and its subfolders up to four levels below it, breadth
// first, each level's folders in name order (hidden ones skipped), until
// `found` returns true; at most kMaxFolders folders per root.
template <class F>
std::optional<std::filesystem::path> search_folders(const std::filesystem::path& root, F found) {
  constexpr int kDepth = 4;
  constexpr std::size_t kMaxFolders = 100000;
  std::error_code ec;
  if (!std::filesystem::is_directory(root, ec)) return std::nullopt;
  std::vector<std::filesystem::path> level{root};
  std::size_t visited = 0;
  for (int depth = 0; depth <= kDepth && !level.empty(); ++depth) {
    std::vector<std::filesystem::path> next;
    for (const std::filesystem::path& dir : level) {
      if (found(dir)) return dir;
      if (++visited > kMaxFolders || depth == kDepth) continue;
      std::vector<std::filesystem::path> children;
      std::filesystem::directory_iterator it(dir, std::filesystem::directory_options::skip_permission_denied, ec);
      if (ec) continue;
      for (const auto& entry : it) {
        const std::string name = entry.path().filename().string();
        if (name.empty() || name[0] == '.') continue;
        std::error_code e2;
        if (entry.is_directory(e2)) children.push_back(entry.path());
      }
      std::sort(children.begin(), children.end());
      next.insert(next.end(), children.begin(), children.end());
    }
    level = std::move(next);
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::string> find_package(const std::string& name, const std::vector<std::string>& folders) {
  for (const std::string& folder : folders)
    if (auto dir = search_folders(folder, [&](const std::filesystem::path& d) {
          std::error_code ec;
          return std::filesystem::is_regular_file(d / "package.xml", ec) && package_xml_name(d / "package.xml") == name;
        }))
      return dir->string();
  for (const std::string& folder : folders)
    if (auto dir = search_folders(folder, [&](const std::filesystem::path& d) { return d.filename() == name; }))
      return dir->string();
  return std::nullopt;
}

std::vector<std::pair<std::string, std::string>> read_srdf(const std::string& file, const RobotModel& model) {
  const std::string text = read_regular_file(file, kMaxUrdfBytes);
  auto fail = [&](const std::string& what) -> void { throw InputError(file + ": " + what); };
  TiXmlDocument doc;
  doc.Parse(text.c_str());
  if (doc.Error()) fail("XML error at line " + std::to_string(doc.ErrorRow()) + ": " + one_line(doc.ErrorDesc()));
  const TiXmlElement* robot = doc.FirstChildElement("robot");
  if (!robot) fail("no <robot> element (not an SRDF)");
  std::vector<std::pair<std::string, std::string>> out;
  int k = 0;
  for (const TiXmlElement* e = robot->FirstChildElement("disable_collisions"); e;
       e = e->NextSiblingElement("disable_collisions"), ++k) {
    const std::string where = "disable_collisions[" + std::to_string(k) + "]";
    std::string links[2];
    for (int s = 0; s < 2; ++s) {
      const char* key = s == 0 ? "link1" : "link2";
      const char* v = e->Attribute(key);
      if (!v) fail(where + ": missing attribute \"" + key + "\"");
      links[s] = v;
      if (model.link_index(links[s]) < 0)
        fail(where + ": " + key + ": unknown link " + quote_text(links[s]) + " (not in " + model.source + ")");
    }
    out.emplace_back(links[0], links[1]);
  }
  return out;
}

}  // namespace tmcert
