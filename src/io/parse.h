// Reading tmcert-scene/1 documents (SCENE_FORMAT.md) into the exact model.
#pragma once

#include "src/model/model.h"
#include "src/model/solid.h"

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace tmcert {

class PlacedRobot;
enum class JointInterpolation;  // src/io/robot.h

// A robot of a scene ("robots"), kept so that it can be moved along other
// paths (batch runs, docs/scene-format.md "Batch runs").
struct SceneRobot {
  std::shared_ptr<const PlacedRobot> robot;
  std::vector<std::string> joints;  // the path's column order, as written
  std::vector<int> bodies;          // its link bodies (indices into Scene::bodies)
  bool self_collision = false;
  std::vector<std::pair<std::string, std::string>> allowed_pairs;  // link names
};

// How a scene reads what it refers to (SCENE_FORMAT.md "Real robots as they
// ship"): package folders searched for package:// URIs before the scene's
// own "package_paths" and ROS_PACKAGE_PATH (`tmcert verify --package-path`).
struct ReadOptions {
  std::vector<std::string> package_paths;
};

// Reads and validates a scene file.  Every number is read exactly from its
// JSON text.  Throws InputError with a one-line message naming the file and
// the JSON path (e.g. "scene.json: bodies[1].motion.weights[2]: weight must
// be positive") on any malformed input.
Scene parse_scene_file(const std::string& path);
// The same, and the scene's robots into `robots`.
Scene parse_scene_file(const std::string& path, std::vector<SceneRobot>& robots);
// The same with read options (robots may be null).
Scene parse_scene_file(const std::string& path, const ReadOptions& options, std::vector<SceneRobot>* robots = nullptr);

// A user string made safe for a one-line message: quoted, control
// characters escaped, strings longer than 60 characters shortened.
std::string quote_text(const std::string& s);

// Validates one polygon as the scene reader does (planar, simple, at least
// 3 non-collinear vertices) and returns its cleaned vertices and its convex
// pieces, tagged with polygon index `index`.  Throws InputError without a
// location.
std::pair<std::vector<Vec3E>, std::vector<ConvexPiece>> split_scene_polygon(const std::vector<Vec3E>& vertices,
                                                                            int index);

// The same for a document held in memory; `source` names it in messages.
Scene parse_scene_text(const std::string& text, const std::string& source);

// The same, with mesh and URDF files relative to the directory `base`, and
// the scene's robots into `robots`.
Scene parse_scene_text(const std::string& text, const std::string& source, const std::string& base,
                       std::vector<SceneRobot>& robots);
Scene parse_scene_text(const std::string& text, const std::string& source, const std::string& base,
                       std::vector<SceneRobot>& robots, const ReadOptions& options);

// One request of a batch run (docs/scene-format.md "Batch runs"), read as
// scenes are: exact numbers, the same motion objects and messages.
struct RequestLine {
  std::string id = "null";   // the "id" value as compact JSON, numbers as written
  std::string body;          // the moved body's name (empty for a robot)
  // A robot's path segment: the robot's name, and its path in the column
  // order of the environment's "joints" (else empty).
  std::string robot;
  std::vector<Exact> path_times;
  std::vector<std::vector<Exact>> path_positions;
  // Its interpolation, velocities and accelerations (JointPath).
  JointInterpolation path_interpolation{};  // linear
  std::vector<std::vector<Exact>> path_velocities, path_accelerations;
  std::optional<Body> inline_body;  // the body itself, when the request gives it
  // A body's motion, as Body::motion and Body::trajectory hold one (it moves).
  std::optional<Motion> motion;
  std::optional<Trajectory> trajectory;
  std::vector<std::string> checks;  // bodies to check against; empty: every other body
  std::optional<Exact> clearance;
  // As Scene::notes and Scene::warnings, for what the line itself gives
  // (an inline body's mesh, a motion's rpy angles).
  std::vector<std::string> notes;
  std::vector<std::string> warnings;
};

// Reads a request line into `out` (its id first: a request rejected later
// keeps it).  Throws InputError "<source>: <JSON path>: <what>".
void parse_request_line(const std::string& text, const std::string& source, const std::string& base,
                        RequestLine& out);

}  // namespace tmcert
