// Reading URDF (robot.h): urdfdom checks the structure (one root, a tree,
// every joint's links exist, limits where required) and gives the tree;
// every number is read again from the XML text (TinyXML, the parser urdfdom
// itself uses) with the exact decimal reader, because urdfdom stores
// doubles.
#include "src/io/robot.h"

#include "kernels/decimal.h"
#include "src/metric/metric.h"
#include "src/motion/segment.h"
#include "src/io/primitives.h"
#include "src/io/mesh.h"
#include "src/io/parse.h"
#include "src/io/read_file.h"
#include "src/model/solid.h"

#include <console_bridge/console.h>
#include <tinyxml.h>
#include <urdf_parser/urdf_parser.h>

#include <cmath>
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
  UrdfReader(std::string source, std::filesystem::path directory)
      : source_(std::move(source)), directory_(std::move(directory)) {}

  std::shared_ptr<const RobotModel> read(const std::string& text) {
    // xacro (URDF with macros: a .xacro file, or xacro: elements and
    // namespace) is expanded by the xacro tool, not here.
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
      if (j->FirstChildElement("mimic")) fail("joint " + quote_text(name) + ": <mimic> joints are not supported");
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
    return model;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const { throw InputError(source_ + ": " + what); }

  bool is_xacro(const std::string& text) const {
    return source_.ends_with(".xacro") || text.find("xmlns:xacro") != std::string::npos ||
           text.find("<xacro:") != std::string::npos;
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

  // A mesh file name as the URDF writes it, resolved against the URDF's
  // directory.
  std::string mesh_file(const std::string& name, const std::string& where) const {
    std::string file = name;
    if (file.rfind("package://", 0) == 0)
      fail(where + ": mesh " + quote_text(name) + ": package:// URIs are not resolved; write a path relative to the URDF");
    if (file.rfind("file://", 0) == 0) file = file.substr(7);
    if (file.empty()) fail(where + ": mesh: empty filename");
    const std::filesystem::path p(file);
    return (p.is_absolute() ? p : directory_ / p).string();
  }

  // One <collision> element's polygons, in the link frame's axes about the
  // element's origin (not yet translated).
  PolygonList shape(const TiXmlElement* geometry, const std::string& where, std::vector<std::string>& enlarged,
                    std::string& kind_out, Exact& radius_out, Exact& length_out) const {
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
      enlarged.push_back("cylinder");
      radius_out = r;
      length_out = len;
      return cylinder_polyhedron(r, len);
    }
    if (kind == "sphere") {
      const Exact r = positive(number(g, "radius", where + ": sphere", std::nullopt), "sphere radius");
      enlarged.push_back("sphere");
      radius_out = r;
      return sphere_polyhedron(r);
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

  void geometry(const TiXmlElement* e, RobotLink& link) const {
    const std::string where = "link " + quote_text(link.name);
    struct Element {
      Pose origin;
      PolygonList polygons;
      std::string kind;          // box, cylinder, sphere, mesh
      Exact radius, length;      // cylinder, sphere
      std::string where;
    };
    std::vector<Element> elements;
    std::vector<std::string> enlarged;
    int index = 0;
    for (const TiXmlElement* c = e->FirstChildElement("collision"); c; c = c->NextSiblingElement("collision"), ++index) {
      Element el;
      el.where = where + ": collision[" + std::to_string(index) + "]";
      el.origin = origin(c, el.where);
      mesh_files_.clear();
      el.polygons = shape(c->FirstChildElement("geometry"), el.where, enlarged, el.kind, el.radius, el.length);
      if (!mesh_files_.empty()) el.where += " (" + mesh_files_.back() + ")";
      elements.push_back(std::move(el));
    }
    if (elements.empty()) return;
    // Where the body frame sits (proofs/robot-links.md section 2).  Elements
    // with one common origin: that origin (applied exactly as a translation
    // of the vertices when it has no rotation).  Otherwise the boxes and
    // meshes decide: rotated ones must share one origin, which becomes the
    // body frame, else the body frame is the link frame and their origins'
    // translations move the vertices exactly.  Cylinders and spheres whose
    // origin is not exact in that frame are circumscribed there with a
    // rational rotation and centre and a radius enlarged by the proven
    // error (section 3); a sphere needs its centre only.
    auto same = [](const Pose& a, const Pose& b) {
      return a.translation == b.translation && a.rotation.kind == b.rotation.kind && a.rotation.rpy == b.rotation.rpy;
    };
    auto rotated = [](const Pose& p) { return p.rotation.kind != Rotation::Kind::Identity; };
    bool same_origin = true;
    for (const Element& el : elements) same_origin = same_origin && same(el.origin, elements[0].origin);
    std::optional<Pose> frame;  // the body frame in the link frame; none: the link frame
    if (same_origin) {
      if (rotated(elements[0].origin)) frame = elements[0].origin;
    } else {
      for (const Element& el : elements) {
        if (el.kind != "box" && el.kind != "mesh") continue;
        if (!rotated(el.origin)) continue;
        if (frame && !same(*frame, el.origin))
          fail(el.where + ": boxes and meshes with different rotated origins (rpy) cannot be placed exactly in one "
                          "body; give them the same origin, or rpy 0 0 0");
        frame = el.origin;
      }
      if (frame)
        for (const Element& el : elements)
          if ((el.kind == "box" || el.kind == "mesh") && !same(*frame, el.origin))
            fail(el.where + ": a box or mesh whose origin differs from the rotated origin of another cannot be "
                            "placed exactly in one body; give them the same origin, or rpy 0 0 0");
    }
    if (frame) link.body_frame = {*frame};
    Body body;
    for (Element& el : elements) {
      // The element's placement in the body frame: exact, or circumscribed.
      std::optional<Vec3E> offset;
      if (frame && same(*frame, el.origin)) offset = Vec3E{Exact(0), Exact(0), Exact(0)};
      else if (!frame && (!rotated(el.origin) || el.kind == "sphere")) offset = el.origin.translation;
      if (!offset) el.polygons = circumscribed_in_frame(el.kind, el.radius, el.length, frame ? *frame : Pose{}, el.origin, el.where);
      std::size_t f = 0;
      for (const std::vector<Vec3E>& polygon : el.polygons) {
        std::vector<Vec3E> moved;
        for (const Vec3E& v : polygon)
          moved.push_back(offset ? Vec3E{v[0] + (*offset)[0], v[1] + (*offset)[1], v[2] + (*offset)[2]} : v);
        add_polygon(body, moved, el.where + ": face " + std::to_string(f++));
      }
    }
    std::vector<Vec3E> vertices;
    for (const auto& p : body.polygons) vertices.insert(vertices.end(), p.begin(), p.end());
    for (const auto& s : body.segments) vertices.insert(vertices.end(), s.begin(), s.end());
    vertices.insert(vertices.end(), body.points.begin(), body.points.end());
    body.mass = default_mass(vertices, size_of(vertices));
    body.mass_is_default = true;
    body.solid = solid_problem(body).empty() && shell_intersection_problem(body).empty();
    body.enlarged = enlarged;
    link.geometry = std::move(body);
  }

  // A cylinder or sphere at `origin` (link frame), circumscribed in the body
  // frame `frame` (link frame): the relative pose F^-1 O is enclosed; a
  // rational rotation R~ (from a rational quaternion: exactly orthogonal)
  // and a rational centre c~ near it, with |R - R~|_F <= eps and
  // |c - c~| <= gamma proven in intervals, place the shape's polyhedron
  // with radius (and half-length) enlarged by
  // delta = eps sqrt(r^2 + h^2) + gamma: every point R x + c of the shape
  // is R~ x + c~ + e with |e| <= delta (proofs/robot-links.md section 3).
  PolygonList circumscribed_in_frame(const std::string& kind, const Exact& r, const Exact& length, const Pose& frame,
                                     const Pose& origin, const std::string& where) const {
    std::array<Exact, 9> rot;
    Vec3E centre;
    Exact delta;
    {
      RoundingGuard guard;
      const PoseInterval f = interval_pose(frame), o = interval_pose(origin);
      std::array<Interval, 9> rel;
      std::array<Interval, 3> c;
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) rel[3 * i + j] = f[i] * o[j] + f[4 + i] * o[4 + j] + f[8 + i] * o[8 + j];
        c[i] = f[i] * (o[3] - f[3]) + f[4 + i] * (o[7] - f[7]) + f[8 + i] * (o[11] - f[11]);
      }
      // A quaternion of the midpoint matrix (any approximation will do:
      // the error is bounded below), on a grid of 2^-20.
      std::array<double, 9> m;
      for (int i = 0; i < 9; ++i) m[i] = CGAL::to_double(rel[i]);
      std::array<double, 4> q;
      const double tr = m[0] + m[4] + m[8];
      if (tr > 0) q = {1 + tr, m[7] - m[5], m[2] - m[6], m[3] - m[1]};
      else if (m[0] >= m[4] && m[0] >= m[8]) q = {m[7] - m[5], 1 + m[0] - m[4] - m[8], m[1] + m[3], m[2] + m[6]};
      else if (m[4] >= m[8]) q = {m[2] - m[6], m[1] + m[3], 1 - m[0] + m[4] - m[8], m[5] + m[7]};
      else q = {m[3] - m[1], m[2] + m[6], m[5] + m[7], 1 - m[0] - m[4] + m[8]};
      const double qn = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
      std::array<Exact, 4> qe;
      for (int i = 0; i < 4; ++i) qe[i] = Exact(static_cast<long>(std::llround(q[i] / qn * 1048576.0)), 1048576L);
      const Exact n2 = qe[0] * qe[0] + qe[1] * qe[1] + qe[2] * qe[2] + qe[3] * qe[3];
      if (n2 == 0) fail(where + ": cannot place the shape (degenerate rotation)");
      const Exact &w = qe[0], &x = qe[1], &y = qe[2], &z = qe[3];
      rot = {(w * w + x * x - y * y - z * z) / n2, 2 * (x * y - w * z) / n2, 2 * (x * z + w * y) / n2,
             2 * (x * y + w * z) / n2, (w * w - x * x + y * y - z * z) / n2, 2 * (y * z - w * x) / n2,
             2 * (x * z - w * y) / n2, 2 * (y * z + w * x) / n2, (w * w - x * x - y * y + z * z) / n2};
      Interval eps2(0), gamma2(0);
      for (int i = 0; i < 9; ++i) eps2 += CGAL::square(rel[i] - to_interval(rot[i]));
      for (int i = 0; i < 3; ++i) {
        centre[i] = Exact(CGAL::to_double(c[i]));
        gamma2 += CGAL::square(c[i] - to_interval(centre[i]));
      }
      const Interval half = to_interval(length) / Interval(2), radius = to_interval(r);
      const Interval reach = kind == "sphere" ? Interval(0) : CGAL::sqrt(CGAL::square(radius) + CGAL::square(half));
      const Interval d = CGAL::sqrt(eps2) * reach + CGAL::sqrt(gamma2);
      if (!std::isfinite(d.sup())) fail(where + ": cannot place the shape (its origin is not finite)");
      delta = Exact(d.sup());
    }
    if (kind == "sphere") {
      PolygonList out = sphere_polyhedron(r + delta);
      for (auto& poly : out)
        for (Vec3E& v : poly) v = {v[0] + centre[0], v[1] + centre[1], v[2] + centre[2]};
      return out;
    }
    PolygonList out = cylinder_polyhedron(r + delta, length + 2 * delta);
    for (auto& poly : out)
      for (Vec3E& v : poly) {
        Vec3E t;
        for (int i = 0; i < 3; ++i) t[i] = rot[3 * i] * v[0] + rot[3 * i + 1] * v[1] + rot[3 * i + 2] * v[2] + centre[i];
        v = t;
      }
    return out;
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
  mutable std::vector<std::string> mesh_files_;
};

}  // namespace

std::shared_ptr<const RobotModel> load_urdf_text(const std::string& text, const std::string& source,
                                                 const std::string& directory) {
  UrdfReader reader(source, directory);
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

std::shared_ptr<const RobotModel> load_urdf(const std::string& file) {
  const std::string text = read_regular_file(file, kMaxUrdfBytes);
  const std::filesystem::path dir = std::filesystem::path(file).parent_path();
  return load_urdf_text(text, file, dir.string());
}

}  // namespace tmcert
