// Robot arms from URDF moving in joint space (SCENE_FORMAT.md "Robots from
// URDF, moving in joint space"), as a C++ API: load a URDF once into an
// immutable RobotModel, place it at a base pose (PlacedRobot: the link
// chains prepared once), and add its links to a Scene as bodies moving
// along a joint-space path (linear between waypoints).  The scene reader
// (src/io/parse.cpp, "robots") and planners (the OMPL validator) both
// go through these functions.
//
//   auto model = tmcert::load_urdf("arm.urdf");                // InputError: exit 3
//   tmcert::PlacedRobot arm(model, "arm", base_pose);
//   tmcert::JointPath path{{"shoulder", "elbow"}, {0, 1}, {{0, 0}, {1, -1}}};
//   tmcert::RobotBodies bodies = tmcert::add_robot(scene, arm, path);
//   auto checks = tmcert::robot_default_checks(arm, bodies, environment, true, {});
//   scene.checks.insert(scene.checks.end(), checks.begin(), checks.end());
//
// Every number of the URDF is read exactly from its text; link motions are
// enclosed rigorously (src/motion/chain.h prepares each chain once).
#pragma once

#include "src/model/chain.h"
#include "src/model/model.h"

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace tmcert {

struct RobotJoint {
  enum class Type { Revolute, Continuous, Prismatic, Fixed };
  // <mimic joint="J" multiplier="m" offset="o"/> on a moving joint: its
  // value is m q_J + o exactly (m = 1, o = 0 by default).  Mimic joints are
  // not named in a JointPath; J is a moving joint, maybe a mimic joint
  // itself (no cycles).  A <mimic> on a fixed joint is ignored.
  struct Mimic {
    int joint = -1;  // the joint followed (index into RobotModel::joints)
    Exact multiplier = 1, offset = 0;
  };
  std::string name;
  Type type = Type::Fixed;
  int parent = -1, child = -1;       // link indices
  Pose origin;                       // child frame in the parent frame (exact xyz; rpy as written)
  Vec3E axis{Exact(1), Exact(0), Exact(0)};  // as written (URDF default 1 0 0); nonzero when moving
  std::optional<Exact> lower, upper;  // revolute and prismatic (URDF defaults 0)
  std::optional<Mimic> mimic;        // moving joints only
  bool moves() const { return type != Type::Fixed; }
};

// One body of a link (proofs/robot-links.md section 2): a link's collision
// elements become one body when they can be placed exactly in one frame,
// else several, all moving with the link:
//  - boxes and meshes whose origins have no rotation, together, in the link
//    frame (or, when every element of the link has the same origin, in
//    that origin's frame); those with a rotated origin in the frame of that
//    origin, one part per distinct origin;
//  - of these, the closed shells (solid, their insides count) apart from
//    the open surfaces (a part of their own, not solid);
//  - every cylinder and sphere on its own, in its origin's frame, as its
//    circumscribed polyhedron (Body::primitive holds the true shape).
// The first part is the body "<robot>/<link>", the others
// "<robot>/<link>/collision[i]" (i: the part's first collision element) with
// "/open" after the open surfaces of a frame that also has closed shells.
struct LinkPart {
  std::string suffix;      // "" for the first part, else "/collision[i]" or "/collision[i]/open"
  // Polygons in the part's frame, default mass, `solid` when closed shells,
  // `enlarged` and `primitive` for a cylinder or sphere.  `name`, motion
  // and trajectory are unset.
  Body geometry;
  // The part's frame in the link frame (empty: the link frame itself).
  std::vector<Pose> frame;
  std::vector<int> elements;  // the <collision> elements it holds (indices in the link)
};

struct RobotLink {
  std::string name;
  int parent_joint = -1;             // -1: the root
  std::vector<LinkPart> parts;       // empty: no collision geometry
  bool has_geometry() const { return !parts.empty(); }
};

struct RobotModel {
  std::string name;                  // <robot name="...">
  std::string source;                // the URDF file, for messages
  std::vector<RobotLink> links;      // in file order
  std::vector<RobotJoint> joints;    // in file order
  int root = 0;                      // the link without a parent joint
  // What the reader did that a user should know (a COLLADA mesh read from
  // its floats), one line each naming the file and the element.
  std::vector<std::string> notes;

  int link_index(const std::string& link) const;   // -1 when absent
  int joint_index(const std::string& joint) const; // -1 when absent
};

// Where `package://NAME/REL` URIs are looked up (SCENE_FORMAT.md "Real
// robots as they ship"): the folders in this order, each with its
// subfolders up to four levels; NAME is the first folder that holds a
// package.xml whose <name> is NAME, or else (none does) the first folder
// named NAME.  Relative folders are relative to the current directory.
struct UrdfOptions {
  std::vector<std::string> package_paths;
};

// The folders of the environment variable ROS_PACKAGE_PATH (colon
// separated, empty entries dropped), in order; empty when unset.
std::vector<std::string> ros_package_path();

// The folder of package NAME (UrdfOptions), or nullopt.
std::optional<std::string> find_package(const std::string& name, const std::vector<std::string>& folders);

// Reads a URDF file: the structure through urdfdom, every number exactly
// from the XML text; meshes relative to the URDF's directory, package://
// URIs through options.package_paths, file:// URIs as paths.  Throws
// InputError "<file>: <element>: <what>" on anything unsupported or
// malformed (joint types other than revolute, continuous, prismatic and
// fixed; a mimic of an unknown or fixed joint, or a cycle of mimics;
// missing or unreadable meshes; a package not found, naming the URI and
// the folders searched; ...).
std::shared_ptr<const RobotModel> load_urdf(const std::string& file, const UrdfOptions& options = {});

// The same for URDF text in memory; meshes relative to `directory`.
std::shared_ptr<const RobotModel> load_urdf_text(const std::string& text, const std::string& source,
                                                 const std::string& directory, const UrdfOptions& options = {});

// The pairs of links an SRDF file (MoveIt) allows to touch: every
// <disable_collisions link1="a" link2="b"/>, in file order; every other
// element is ignored.  Throws InputError "<file>: disable_collisions[k]:
// <what>" on malformed XML, a missing attribute, or a link `model` does not
// have.
std::vector<std::pair<std::string, std::string>> read_srdf(const std::string& file, const RobotModel& model);

// A joint-space path: `joints` names the columns (every moving joint of the
// robot but the mimic joints, each once), `times` are strictly increasing (at least 2), and
// `positions` holds one row per time with one value per column.  The motion
// is linear in joint space between consecutive waypoints, or (SCENE_FORMAT.md
// "Real robots as they ship") each joint follows the cubic Hermite
// polynomial in time through its positions and `velocities` (dq/dt), or the
// quintic one through its positions, velocities and `accelerations`
// (d^2q/dt^2), as ros_control's joint_trajectory_controller executes a
// trajectory; `velocities` and `accelerations` have the shape of
// `positions` and are empty when not used.
enum class JointInterpolation { Linear, Cubic, Quintic };

struct JointPath {
  std::vector<std::string> joints;
  std::vector<Exact> times;
  std::vector<std::vector<Exact>> positions;
  JointInterpolation interpolation = JointInterpolation::Linear;
  std::vector<std::vector<Exact>> velocities;     // cubic and quintic
  std::vector<std::vector<Exact>> accelerations;  // quintic
};

// "linear", "cubic", "quintic".
const char* interpolation_name(JointInterpolation how);

// What is wrong with a JointPath, and where: `field` is "joints", "times",
// "positions", "velocities", "accelerations" or "path" (a joint leaving its
// limits between two waypoints: the message names the segment, the joint
// and a time where it is outside), `index` the element (row, then column
// for positions; empty for the field itself).  The message names the joint
// and waypoint.
class JointPathError : public InputError {
 public:
  JointPathError(std::string field, std::vector<std::size_t> index, const std::string& what)
      : InputError(what), field(std::move(field)), index(std::move(index)) {}
  std::string field;
  std::vector<std::size_t> index;
};

// A robot at a base pose under a name (its bodies are "<name>/<link>"),
// with the chain of every link described once (the verifier prepares each
// description's enclosures once, src/motion/chain.h).  Immutable; cheap to
// share.
class PlacedRobot {
 public:
  PlacedRobot(std::shared_ptr<const RobotModel> model, std::string name, Pose base);

  const RobotModel& model() const { return *model_; }
  const std::string& name() const { return name_; }
  const Pose& base() const { return base_; }
  // The moving joints (indices into model().joints) from the root to link
  // `link`, in chain order.
  const std::vector<int>& chain_joints(int link) const { return chain_joints_[link]; }
  // The chain of part `part` of link `link` (its frame last).
  const std::shared_ptr<const ChainDescription>& chain(int link, std::size_t part = 0) const { return chains_[link][part]; }

 private:
  std::shared_ptr<const RobotModel> model_;
  std::string name_;
  Pose base_;
  std::vector<std::vector<int>> chain_joints_;
  std::vector<std::vector<std::shared_ptr<const ChainDescription>>> chains_;  // per link, per part
};

// Throws JointPathError unless `path` fits the robot: every joint named
// exists, moves and is not a mimic joint, every other moving joint is named
// once, at least 2 strictly increasing times, one row per time with one
// value per column, and every value of a revolute or prismatic joint
// within its <limit>, mimic joints included (their values are linear in
// the others', so on the linear path between waypoints too).  Cubic and
// quintic paths: velocities (and accelerations) of the shape of positions,
// none where not used, and each joint's polynomial within its limits on
// the whole of every segment, decided exactly (proofs/trajectories.md
// section 2).
void validate_joint_path(const RobotModel& model, const JointPath& path);

// The value of every joint of `model` (indexed like its joints; 0 for a
// fixed joint) at one waypoint: column c of `row` is joint columns[c]'s
// value, a mimic joint's is m q_J + o from the joint it follows.  Every
// moving joint that is not a mimic joint must have a column.
std::vector<Exact> joint_values(const RobotModel& model, const std::vector<int>& columns, const std::vector<Exact>& row);

// The bodies of every link's parts (indexed like RobotModel::links; empty
// for a link without collision geometry), and the first part's body, -1
// for none.
struct RobotBodies {
  std::vector<int> body;
  std::vector<std::vector<int>> parts;
};

// Validates `path` and appends a body per part of every link with
// collision geometry ("<name>/<link>" and "<name>/<link>/collision[i]",
// LinkPart), moving along the path over [times.front(), times.back()].
// Checks are not touched.
RobotBodies add_robot(Scene& scene, const PlacedRobot& robot, const JointPath& path);

// The default checks of SCENE_FORMAT.md: every link body against every body
// in `environment`, and, with `self_collision`, every pair of bodies of two
// links that are neither parent and child (links joined by one joint) nor
// listed in `allowed_pairs` (link names, either order); the parts of one
// link are never checked against each other.  Throws InputError when an
// allowed pair names an unknown link.
std::vector<std::pair<int, int>> robot_default_checks(const PlacedRobot& robot, const RobotBodies& bodies,
                                                      const std::vector<int>& environment, bool self_collision,
                                                      const std::vector<std::pair<std::string, std::string>>& allowed_pairs);

}  // namespace tmcert
