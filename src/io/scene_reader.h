// The scene reader (internal to src/io/): walks a JSON tree
// (src/io/json_tree.h), validating as it goes, into the exact model.  Every
// error is thrown as "<source>: <path>: <what>".  Its parts live in:
//   parse.cpp          scene assembly: the document, bodies, polygons and
//                      meshes, masses, checks, batch request lines
//   motion_reader.cpp  poses and motions (rational Bezier, keyframes, piecewise)
//   robot_reader.cpp   robots from URDF, joint paths, package folders,
//                      the default checks with robots
#pragma once

#include "src/io/json_tree.h"
#include "src/io/parse.h"
#include "src/io/robot.h"

#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace tmcert::reader {

class SceneReader : public JsonReader {
 public:
  // `base` is the directory mesh file names are relative to ("" for the
  // current directory).
  SceneReader(std::string source, std::filesystem::path base, const Tree& tree, ReadOptions options = {})
      : JsonReader(std::move(source), tree), base_(std::move(base)), options_(std::move(options)) {}

  // The whole document as a scene (parse.cpp).
  Scene read();

  // A request line of a batch run (docs/scene-format.md "Batch runs"):
  // {"id", "body", "motion" or "robot", "path"; "checks", "clearance"}.  `out.id` is set first,
  // so that a request rejected later is still reported under its id.
  void read_request(RequestLine& out) const;

  std::vector<std::string> take_notes() { return std::move(notes_); }
  std::vector<std::string> take_warnings() { return std::move(warnings_); }
  // Where read() puts the scene's robots (none: nowhere).
  std::vector<SceneRobot>* robots_out_ = nullptr;

  // ---- motions (motion_reader.cpp)

  // A body's motion: one rational Bezier curve stays `Body::motion` (also
  // when keyframes or pieces reduce to one exactly), anything else becomes
  // a trajectory of segments.
  void motion(Body& b, const Node& node, const Path& path) const;

  // {"translation": [x, y, z], "rotation": {...}} (SCENE_FORMAT.md "Rigid poses").
  Pose pose(const Node& node, const Path& path) const;

  // ---- robots (robot_reader.cpp)

  // A robot of the scene after its links were added (for default checks).
  struct RobotInScene {
    std::shared_ptr<const PlacedRobot> robot;
    RobotBodies bodies;
    std::vector<std::string> joints;
    bool self_collision = false;
    std::vector<std::pair<std::string, std::string>> allowed;
  };

  // "package_paths": folders relative to the scene file, searched for
  // package:// URIs after the given ones (ReadOptions) and before
  // ROS_PACKAGE_PATH.
  void package_paths(const Node& node, const Path& path);

  // The package folders in their order: given, the scene's, ROS_PACKAGE_PATH.
  UrdfOptions urdf_options() const;

  // A joint-space path's "times" and "positions" (exact numbers; their
  // meaning is checked by validate_joint_path).
  void joint_path_values(const Node& node, const Path& path, JointPath& jp) const;

  // "robots" (SCENE_FORMAT.md "Robots from URDF, moving in joint space"):
  // each adds a body "<robot>/<link>" per link with collision geometry.
  std::vector<RobotInScene> robots(Scene& scene, const Node& node, const Path& path,
                                   std::unordered_map<std::string, std::size_t>& names) const;

  // The default checks with robots: the general rule among the bodies
  // that are not links, then each robot's rule (every link against every
  // body not of that robot; self-collision pairs), each pair once.
  static std::vector<std::pair<int, int>> default_checks_with_robots(const Scene& scene, std::size_t plain_bodies,
                                                                     const std::vector<RobotInScene>& robots);

  // Every pair with at least one moving body, once, in body order.
  static std::vector<std::pair<int, int>> default_checks(const Scene& scene);

 private:
  // ---- scene assembly (parse.cpp)
  void read_request_checks(RequestLine& out) const;
  int max_depth(const Node& node, const Path& path) const;
  Body body(const Node& node, const Path& path) const;
  static void normalise_mass_scale(Body& b);
  void polygon(Body& b, const Node& node, const Path& path) const;
  void mesh(Body& b, const Node& node, const Path& path) const;
  void require_closed(const Body& b, const Path& path) const;
  MassDistribution explicit_mass(const Node& node, const Path& path) const;
  void assign_masses(Scene& scene, const Path& bodies_path) const;
  std::vector<std::pair<int, int>> explicit_checks(const Node& node, const Path& checks_path,
                                                   const std::unordered_map<std::string, std::size_t>& names,
                                                   std::vector<std::optional<Exact>>& clearances) const;

  // ---- motions (motion_reader.cpp)
  std::optional<Motion> motion_segments(const Node& node, const Path& path, std::vector<MotionSegment>& out) const;
  std::string rpy_warning(const Path& path, const Exact& angle) const;
  std::vector<Exact> times(const Node& node, const Path& path, std::size_t count, const std::string& per) const;
  // The readers of the motion types, one per JSON "type" (motion_types()
  // in motion_reader.cpp lists them): each appends the segments of the
  // motion `obj` and returns a motionless or one-curve rational_bezier
  // motion instead, as it is (nullopt for the others).
  using MotionTypeReader = std::optional<Motion> (SceneReader::*)(const Members& obj, const Path& path,
                                                                  std::vector<MotionSegment>& out) const;
  struct MotionType {
    const char* name;  // the JSON "type"
    MotionTypeReader read;
  };
  static const std::vector<MotionType>& motion_types();
  std::optional<Motion> rational_bezier(const Members& obj, const Path& path, std::vector<MotionSegment>& out) const;
  std::optional<Motion> keyframes(const Members& obj, const Path& path, std::vector<MotionSegment>& out) const;
  std::optional<Motion> piecewise(const Members& obj, const Path& path, std::vector<MotionSegment>& out) const;

  std::filesystem::path base_;
  ReadOptions options_;
  std::vector<std::string> scene_packages_;             // "package_paths", resolved
  mutable std::map<int, std::vector<int>> link_parts_;  // a link's first body -> all its bodies
  mutable std::vector<std::string> notes_, warnings_;   // Scene::notes, Scene::warnings
};

}  // namespace tmcert::reader
