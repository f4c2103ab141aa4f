// The scene model: exact rational geometry as the user wrote it, plus the
// exact derived data (convex pieces) every later stage works on.
// Nothing here is rounded; coordinates are in the body's own frame.
#pragma once

#include "kernels/number_types.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace tmcert {

// Bad input: the message names the file, field or JSON path and what is
// wrong.  The command line turns it into exit code 3.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A resource limit that leaves no honest answer (exit code 4); a limit that
// still allows an honest "undecided" is reported as such instead.
class ResourceLimit : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A convex planar polygon with vertices in order (no three consecutive
// vertices collinear, at least 3), cut exactly from input polygon `polygon`.
struct ConvexPiece {
  int polygon = 0;            // index into Body::polygons
  std::vector<Vec3E> vertices;
};

struct MassDistribution {
  std::vector<Vec3E> points;
  std::vector<Exact> weights;  // all > 0
};

// Rational Bezier curve in the 12-dimensional space of affine maps.
// Curve parameter u in [0,1] maps to scene parameter t = t0 + u (t1 - t0).
struct Motion {
  Exact t0 = 0, t1 = 1;                 // t0 < t1
  std::vector<Mat34E> control_points;   // affine control points [A | a], >= 1
  std::vector<Exact> weights;           // > 0, same count
  // The exact curve of an nlerp keyframe segment (src/motion/segment.h):
  // its control points carry the scale of the unnormalised quaternions and
  // can lie far from its poses, so sizes (the default epsilon) are taken
  // from poses along it, never from them.
  bool nlerp = false;
  int degree() const { return static_cast<int>(control_points.size()) - 1; }
};

// A rotation as written in a pose (SCENE_FORMAT.md "Rigid poses").
struct Rotation {
  enum class Kind { Identity, Quaternion, Rpy, Matrix };
  Kind kind = Kind::Identity;
  std::array<Exact, 4> quaternion;  // Quaternion: [w, x, y, z] as written, nonzero
  std::array<Exact, 3> rpy;         // Rpy: roll, pitch, yaw in radians (R = Rz Ry Rx)
  std::array<Exact, 9> matrix;      // Matrix: rows, exactly orthonormal, det +1
  // The rotation is known exactly (everything but rpy).
  bool exact() const { return kind != Kind::Rpy; }
};

// x -> R x + translation.
struct Pose {
  Vec3E translation{Exact(0), Exact(0), Exact(0)};
  Rotation rotation;
};

enum class Interpolation { Slerp, Screw, Nlerp };

// A robot link's motion over one segment of its joint-space path
// (src/motion/chain.h): an immutable chain of joint transforms shared by
// every segment, and the joint values at the segment's two waypoints.
struct LinkMotion;

// One piece of a body's motion over the scene parameters [t0, t1]: either a
// rational Bezier curve (exact; `rational`, whose own t0/t1 are these), or
// the interpolation of two keyframe poses that is not rational (slerp and
// screw between different rotations, nlerp between rotations not given as
// exact quaternions), enclosed rigorously wherever it is evaluated
// (src/motion/segment.h, proofs/enclosures.md).  The segment parameter is
// s = (t - t0) / (t1 - t0).  A robot link's segment has `link` instead of
// two poses (its model when it is not rational; `rational` comes first).
struct MotionSegment {
  Exact t0, t1;
  std::optional<Motion> rational;
  Pose from, to;                      // when not rational and not a link
  Interpolation interpolation = Interpolation::Slerp;
  std::shared_ptr<const LinkMotion> link;  // a robot link's segment
};

// A body's motion when it is not one rational Bezier curve: keyframes with
// more than one piece or a transcendental interpolation, and piecewise
// motions.  Segments abut exactly and agree at the joins.
struct Trajectory {
  std::vector<MotionSegment> segments;  // in parameter order, >= 1
  Exact t0() const { return segments.front().t0; }
  Exact t1() const { return segments.back().t1; }
};

struct Body {
  std::string name;
  // Features as written (polygons with exactly collinear vertices removed,
  // which leaves the point set unchanged).
  std::vector<std::vector<Vec3E>> polygons;
  std::vector<std::array<Vec3E, 2>> segments;  // two distinct points
  std::vector<Vec3E> points;
  // Every polygon split exactly into convex pieces (a convex polygon is one
  // piece).  The union of a polygon's pieces is the polygon.
  std::vector<ConvexPiece> pieces;
  MassDistribution mass;            // explicit, or the documented default
  bool mass_is_default = true;
  // The motion: `motion` when it is one rational Bezier curve (every scene
  // of rational_bezier motions, and keyframes that reduce to one exactly),
  // else `trajectory`; neither: fixed at the identity.  Never both.
  std::optional<Motion> motion;
  std::optional<Trajectory> trajectory;
  bool solid = false;
  // The paper's toleranced motion: every affine map within this distance of
  // the nominal pose, in the body's metric, is possible (0: none).
  Exact tolerance = 0;
  // Shapes of the input replaced by circumscribed polyhedra (a robot link's
  // URDF cylinders and spheres): the body contains them and is larger, so
  // `safe` holds for them and a collision is one of the enlarged model.
  std::vector<std::string> enlarged;
  // A robot link's URDF cylinder or sphere (src/io/urdf.cpp), when the
  // body is one: the true shape, in the body frame (a cylinder of this
  // radius and length about the z axis, or a ball of this radius, centred
  // at the origin); the polygons are its circumscribed polyhedron at
  // refinement `level` (src/io/primitives.h).  `safe` may rest on the
  // polyhedron; a collision is reported only when proven on the true shape
  // (proofs/robot-links.md section 6).
  struct Primitive {
    enum class Kind { Cylinder, Sphere };
    Kind kind = Kind::Sphere;
    Exact radius = 0, length = 0;
    int level = 0;
  };
  std::optional<Primitive> primitive;

  // Moves over a parameter interval (a one-pose motion does not).
  bool moves() const { return trajectory || (motion && motion->degree() >= 1); }
  // The parameter interval of the motion, when there is one.
  std::optional<std::pair<Exact, Exact>> interval() const {
    if (trajectory) return std::pair{trajectory->t0(), trajectory->t1()};
    if (motion) return std::pair{motion->t0, motion->t1};
    return std::nullopt;
  }
};

// A file as the system knows it (device and inode: the same file under
// any name, through links and different spellings).
struct FileIdentity {
  std::uint64_t device = 0, inode = 0;
  std::string path;  // as it was named, for messages
  bool same(const FileIdentity& o) const { return device == o.device && inode == o.inode; }
};

struct Scene {
  std::string source;                   // file name, for messages
  // The files read for the scene (the scene file, its meshes, URDFs and
  // SRDFs): no output may be written over one of them (docs/scene-format.md
  // "Output paths").  Empty for a scene built in code or from text alone.
  std::vector<FileIdentity> input_files;
  std::vector<Body> bodies;
  std::optional<Exact> epsilon;         // absent: per check (default_epsilon of its two bodies)
  int max_depth = 40;
  std::vector<std::pair<int, int>> checks;  // indices into bodies; explicit or default
  // Minimum separation (SCENE_FORMAT.md "Tolerance and clearance"): the
  // scene's, and per check when written there (empty: the scene's for all).
  Exact clearance = 0;
  std::vector<std::optional<Exact>> check_clearance;  // parallel to checks
  // What the reader did to data from real pipelines that a user should
  // know (docs/scene-format.md, "Data from real pipelines"): mesh faces not
  // exactly planar split into fans, zero-area faces read as segments
  // (`notes`); input read in a way the user may not mean, such as an rpy
  // angle above 2 pi read as radians (`warnings`, also printed on stderr by
  // the command line).  Each names the file and the field.
  std::vector<std::string> notes;
  std::vector<std::string> warnings;
  Exact clearance_of(std::size_t check) const {
    if (check < check_clearance.size() && check_clearance[check]) return *check_clearance[check];
    return clearance;
  }
};

}  // namespace tmcert
