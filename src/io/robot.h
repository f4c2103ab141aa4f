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
// enclosed rigorously (src/motion/chain.h).
#pragma once

#include "src/motion/chain.h"
#include "src/model/model.h"

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace tmcert {

struct RobotJoint {
  enum class Type { Revolute, Continuous, Prismatic, Fixed };
  std::string name;
  Type type = Type::Fixed;
  int parent = -1, child = -1;       // link indices
  Pose origin;                       // child frame in the parent frame (exact xyz; rpy as written)
  Vec3E axis{Exact(1), Exact(0), Exact(0)};  // as written (URDF default 1 0 0); nonzero when moving
  std::optional<Exact> lower, upper;  // revolute and prismatic (URDF defaults 0)
  bool moves() const { return type != Type::Fixed; }
};

struct RobotLink {
  std::string name;
  int parent_joint = -1;             // -1: the root
  // The collision geometry, when the link has any: polygons and convex
  // pieces in the body frame, default mass, `solid` when it forms closed
  // shells, `enlarged` naming the cylinders and spheres replaced by
  // circumscribed polyhedra.  `name`, motion and trajectory are unset.
  std::optional<Body> geometry;
  // The body frame in the link frame (empty: the link frame itself), when
  // the collision origins could not be applied to the vertices exactly.
  std::vector<Pose> body_frame;
};

struct RobotModel {
  std::string name;                  // <robot name="...">
  std::string source;                // the URDF file, for messages
  std::vector<RobotLink> links;      // in file order
  std::vector<RobotJoint> joints;    // in file order
  int root = 0;                      // the link without a parent joint

  int link_index(const std::string& link) const;   // -1 when absent
  int joint_index(const std::string& joint) const; // -1 when absent
};

// Reads a URDF file: the structure through urdfdom, every number exactly
// from the XML text; meshes relative to the URDF's directory.  Throws
// InputError "<file>: <element>: <what>" on anything unsupported or
// malformed (joint types other than revolute, continuous, prismatic and
// fixed; mimic joints; missing or unreadable meshes; package:// URIs; ...).
std::shared_ptr<const RobotModel> load_urdf(const std::string& file);

// The same for URDF text in memory; meshes relative to `directory`.
std::shared_ptr<const RobotModel> load_urdf_text(const std::string& text, const std::string& source,
                                                 const std::string& directory);

// A joint-space path: `joints` names the columns (every moving joint of the
// robot, each once), `times` are strictly increasing (at least 2), and
// `positions` holds one row per time with one value per column.  The motion
// is linear in joint space between consecutive waypoints.
struct JointPath {
  std::vector<std::string> joints;
  std::vector<Exact> times;
  std::vector<std::vector<Exact>> positions;
};

// What is wrong with a JointPath, and where: `field` is "joints", "times"
// or "positions", `index` the element (row, then column for positions;
// empty for the field itself).  The message names the joint and waypoint.
class JointPathError : public InputError {
 public:
  JointPathError(std::string field, std::vector<std::size_t> index, const std::string& what)
      : InputError(what), field(std::move(field)), index(std::move(index)) {}
  std::string field;
  std::vector<std::size_t> index;
};

// A robot at a base pose under a name (its bodies are "<name>/<link>"),
// with the chain of every link prepared once.  Immutable; cheap to share.
class PlacedRobot {
 public:
  PlacedRobot(std::shared_ptr<const RobotModel> model, std::string name, Pose base);

  const RobotModel& model() const { return *model_; }
  const std::string& name() const { return name_; }
  const Pose& base() const { return base_; }
  // The moving joints (indices into model().joints) from the root to link
  // `link`, in chain order.
  const std::vector<int>& chain_joints(int link) const { return chain_joints_[link]; }
  const std::shared_ptr<const LinkChain>& chain(int link) const { return chains_[link]; }

 private:
  std::shared_ptr<const RobotModel> model_;
  std::string name_;
  Pose base_;
  std::vector<std::vector<int>> chain_joints_;
  std::vector<std::shared_ptr<const LinkChain>> chains_;  // null for links without geometry
};

// Throws JointPathError unless `path` fits the robot: every joint named
// exists and moves, every moving joint is named once, at least 2 strictly
// increasing times, one row per time with one value per column, and every
// value of a revolute or prismatic joint within its <limit>.
void validate_joint_path(const RobotModel& model, const JointPath& path);

// The body of every link with collision geometry, -1 for the others
// (indexed like RobotModel::links).
struct RobotBodies {
  std::vector<int> body;
};

// Validates `path` and appends a body "<name>/<link>" for every link with
// collision geometry, moving along the path over [times.front(),
// times.back()].  Checks are not touched.
RobotBodies add_robot(Scene& scene, const PlacedRobot& robot, const JointPath& path);

// The default checks of SCENE_FORMAT.md: every link body against every body
// in `environment`, and, with `self_collision`, every pair of link bodies
// that are neither parent and child (links joined by one joint) nor listed
// in `allowed_pairs` (link names, either order).  Throws InputError when an
// allowed pair names an unknown link.
std::vector<std::pair<int, int>> robot_default_checks(const PlacedRobot& robot, const RobotBodies& bodies,
                                                      const std::vector<int>& environment, bool self_collision,
                                                      const std::vector<std::pair<std::string, std::string>>& allowed_pairs);

}  // namespace tmcert
