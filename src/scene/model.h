// The scene model: exact rational geometry as the user wrote it, plus the
// exact derived data (convex pieces) every later stage works on.
// Nothing here is rounded; coordinates are in the body's own frame.
#pragma once

#include "kernels/number_types.h"

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
  int degree() const { return static_cast<int>(control_points.size()) - 1; }
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
  std::optional<Motion> motion;     // absent: fixed at the identity
  bool solid = false;
};

struct Scene {
  std::string source;                   // file name, for messages
  std::vector<Body> bodies;
  std::optional<Exact> epsilon;         // absent: 1/1000 of the scene diagonal
  int max_depth = 40;
  std::vector<std::pair<int, int>> checks;  // indices into bodies; explicit or default
};

}  // namespace tmcert
