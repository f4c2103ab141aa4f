// Building a scene in code, without JSON: bodies from vertex and index
// arrays (or exact numbers, or mesh files), motions of every type, robots
// from URDF, checks and the scene's settings.
//
//   tmcert::SceneBuilder b;
//   b.add_body("table").triangles(table_xyz, table_indices);
//   b.add_body("box").triangles(box_xyz, box_indices)
//       .motion(tmcert::Motion::translation({0, 0, 2}, {0, 0, "-1/2"}));
//   const tmcert::Scene scene = b.build();   // throws tmcert::InputError
//
// Coordinates given as doubles are taken exactly as their binary values (no
// rounding: 0.1 is the double nearest to 1/10, not 1/10); give a Number
// ("1/10", "0.1") for an exact decimal or fraction.  Nothing is checked
// until build(), which runs the scene reader's own validation, so an error
// names the field exactly as it would in a tmcert-scene/1 document
// ("SceneBuilder: bodies[1].polygons[3]: polygon is not planar (body
// \"box\")"); bodies and robots are numbered in the order they were added.
#pragma once

#include "tmcert/export.h"
#include "tmcert/motion.h"
#include "tmcert/numbers.h"
#include "tmcert/scene.h"

#include <cstddef>
#include <deque>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace tmcert::api {

// One body of a SceneBuilder (SceneBuilder::add_body).  Every call adds to
// the body and returns it, for chaining.  Features accumulate: polygons,
// triangles and mesh faces are numbered in the order they were added.
class TMCERT_API BodyBuilder {
 public:
  // Polygons from a flat vertex array `xyz` (x, y, z per vertex: 3n
  // doubles, exact) and `faces`, each a list of vertex indices in order
  // (planar, simple, >= 3 vertices; convex or not).
  BodyBuilder& polygons(std::span<const double> xyz, const std::vector<std::vector<std::size_t>>& faces);
  // The same with the faces flat: `sizes[k]` indices per polygon, all of
  // them one after the other in `indices`.
  BodyBuilder& polygons(std::span<const double> xyz, std::span<const std::size_t> indices,
                        std::span<const std::size_t> sizes);
  // Exact vertices.
  BodyBuilder& polygons(std::span<const Point> vertices, const std::vector<std::vector<std::size_t>>& faces);
  // One polygon, its vertices in order.
  BodyBuilder& polygon(const std::vector<Point>& vertices);
  // Triangles: three vertex indices per triangle in `indices`.
  BodyBuilder& triangles(std::span<const double> xyz, std::span<const std::size_t> indices);
  BodyBuilder& triangles(std::span<const Point> vertices, std::span<const std::size_t> indices);
  // Segments: two points (6 doubles) per segment; endpoints distinct.
  BodyBuilder& segments(std::span<const double> xyz);
  BodyBuilder& segment(const Point& a, const Point& b);
  // Points: 3 doubles per point.
  BodyBuilder& points(std::span<const double> xyz);
  BodyBuilder& point(const Point& p);
  // A mesh file (OFF, OBJ or STL, read exactly), relative to the current
  // directory at the time of the call.  Its faces come after the polygons
  // added by the other calls, whenever it is called.  One per body.
  BodyBuilder& mesh(const std::string& path);
  // A closed surface whose inside counts as part of the body (its polygons
  // must form closed shells).
  BodyBuilder& solid(bool value = true);
  // The mass distribution of the body's metric: points and positive
  // weights, not coplanar (default: the body's vertices, equal weights).
  BodyBuilder& mass(const std::vector<Point>& points, const std::vector<Number>& weights);
  // The paper's toleranced motion: every pose within `r` of the nominal one
  // in the body's metric is possible (default 0).
  BodyBuilder& tolerance(Number r);
  // The body's motion (default: fixed at the identity).  Replaces an
  // earlier one.
  BodyBuilder& motion(Motion m);

  // A continuous-collision primitive whose vertices move linearly from
  // `start` to `end` (one vertex: a point; two: a segment; three: a
  // triangle) over the parameters [t0, t1] (README "Linear per-vertex
  // motion"): adds the canonical point (0,0,0), segment (0,0,0)-(1,0,0) or
  // triangle (0,0,0),(1,0,0),(0,1,0) and sets the motion to the degree-1
  // curve of the maps [v1 - v0, v2 - v0, 0 | v0] at both ends (they may be
  // singular).  Give the body no other features: they would move with the
  // same maps.  Throws InputError at once when start and end differ in
  // size, the size is not 1 to 3, or a coordinate is not a number.
  BodyBuilder& linear_primitive(const std::vector<Point>& start, const std::vector<Point>& end, Number t0 = 0,
                                Number t1 = 1);

  const std::string& name() const { return name_; }

  // Internal (SceneBuilder::add_body).
  explicit BodyBuilder(std::string name) : name_(std::move(name)) {}

 private:
  friend class SceneBuilder;
  std::string name_;
  std::vector<std::vector<Point>> polygons_;
  std::vector<std::pair<Point, Point>> segments_;
  std::vector<Point> points_;
  std::optional<std::string> mesh_;
  std::optional<bool> solid_;
  std::optional<std::pair<std::vector<Point>, std::vector<Number>>> mass_;
  std::optional<Number> tolerance_;
  std::optional<Motion> motion_;
};

// A robot from a URDF file moving in joint space (SceneBuilder::add_robot):
// a body "<robot>/<link>" per link with collision geometry.
class TMCERT_API RobotBuilder {
 public:
  // Where the robot's root link is placed (default: the identity).
  RobotBuilder& base(Pose pose);
  // The joint-space path, linear between waypoints: `joints` names every
  // moving joint (the column order of `positions`), `times` strictly
  // increasing, one row of positions per time, within the joints' limits.
  RobotBuilder& path(std::vector<std::string> joints, std::vector<Number> times,
                     std::vector<std::vector<Number>> positions);
  // The path as the controller executes a time-parameterised trajectory
  // (ros_control's joint_trajectory_controller): "cubic" splines in time
  // through the positions with these `velocities` (dq/dt), or "quintic"
  // with also `accelerations`, each one row per time like `positions`;
  // "linear" (the default) takes neither.  Limits hold on the whole
  // polynomial (docs/scene-format.md "Robots from URDF").
  RobotBuilder& interpolation(std::string how, std::vector<std::vector<Number>> velocities = {},
                              std::vector<std::vector<Number>> accelerations = {});
  // Check pairs of its own links (not parent and child, not allowed).
  RobotBuilder& self_collision(bool value = true);
  // A pair of links never checked against each other.
  RobotBuilder& allow(std::string link_a, std::string link_b);
  // Every <disable_collisions link1 link2> of a MoveIt SRDF file (relative
  // to the current directory at the time of the call) as allowed pairs.
  RobotBuilder& srdf(std::string file);

  const std::string& name() const { return name_; }

  // Internal (SceneBuilder::add_robot).
  RobotBuilder(std::string name, std::string urdf) : name_(std::move(name)), urdf_(std::move(urdf)) {}

 private:
  friend class SceneBuilder;
  std::string name_, urdf_;
  std::optional<Pose> base_;
  std::vector<std::string> joints_;
  std::vector<Number> times_;
  std::vector<std::vector<Number>> positions_;
  std::optional<std::string> interpolation_;
  std::vector<std::vector<Number>> velocities_, accelerations_;
  std::optional<bool> self_collision_;
  std::vector<std::pair<std::string, std::string>> allowed_;
  std::optional<std::string> srdf_;
};

class TMCERT_API SceneBuilder {
 public:
  SceneBuilder() = default;

  // A new body with a unique, non-empty name.  The reference stays valid
  // as long as the builder.
  BodyBuilder& add_body(std::string name);
  // A robot from `urdf` (relative to the current directory at the time of
  // the call); its links' bodies are named "<name>/<link>".
  RobotBuilder& add_robot(std::string name, std::string urdf);

  // A pair to check (by body or link name).  Without any, the default:
  // every moving body against every other body, and the robot rules.
  SceneBuilder& check(std::string body_a, std::string body_b);
  // With a minimum separation for this pair: safe means the bodies stay
  // farther apart than `clearance`.
  SceneBuilder& check(std::string body_a, std::string body_b, Number clearance);

  // Termination tolerance, a length (default: 1/1000 of the scene diagonal).
  SceneBuilder& epsilon(Number e);
  // Subdivision depth limit, 1 to 200 (default 40).
  SceneBuilder& max_depth(int depth);
  // Minimum separation of every check without its own (default 0).
  SceneBuilder& clearance(Number d);
  // A folder searched for package://NAME/... mesh URIs of the robots' URDFs
  // (relative to the current directory at the time of the call), in order,
  // before ROS_PACKAGE_PATH; each with its subfolders up to four levels.
  SceneBuilder& package_path(std::string folder);

  // Validates everything and returns the scene; the builder is unchanged
  // and can build again.  Throws InputError.
  Scene build() const;
  // The scene as a tmcert-scene/1 document (numbers as exact strings, file
  // names absolute): what build() validates.
  std::string to_json() const;

 private:
  // The document of to_json() as a JSON value (defined and instantiated in
  // src/api/scene_builder.cpp alone).
  template <typename Document>
  Document document() const;

  struct Check {
    std::string a, b;
    std::optional<Number> clearance;
  };
  std::deque<BodyBuilder> bodies_;  // deque: add_body's references stay valid
  std::deque<RobotBuilder> robots_;
  std::vector<Check> checks_;
  std::optional<Number> epsilon_;
  std::optional<int> max_depth_;
  std::optional<Number> clearance_;
  std::vector<std::string> package_paths_;
};

}  // namespace tmcert::api

namespace tmcert {
using namespace api;
}
