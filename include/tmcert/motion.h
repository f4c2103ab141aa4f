// Motions of a body (docs/scene-format.md, SCENE_FORMAT.md): rational
// Bezier curves of affine maps, keyframes of rigid poses, and piecewise
// motions made of either.  Values only: a SceneBuilder checks them when the
// scene is built, with the same checks and messages as the scene reader.
#pragma once

#include "tmcert/export.h"
#include "tmcert/numbers.h"

#include <optional>
#include <utility>
#include <variant>
#include <vector>

namespace tmcert::api {

// A rotation of a rigid pose.
struct Rotation {
  enum class Kind { Identity, Quaternion, Rpy, Matrix };
  Kind kind = Kind::Identity;
  std::vector<Number> values;  // 4 (w, x, y, z), 3 (roll, pitch, yaw) or 9 (rows); none for Identity

  static Rotation identity() { return {}; }
  // Any nonzero quaternion; the rotation is that of q/|q|, whose matrix is
  // rational: exact, no normalisation needed.
  static Rotation quaternion(Number w, Number x, Number y, Number z) {
    return {Kind::Quaternion, {std::move(w), std::move(x), std::move(y), std::move(z)}};
  }
  // Radians, URDF's convention R = Rz(yaw) Ry(pitch) Rx(roll); the entries
  // are transcendental and enclosed rigorously.
  static Rotation rpy(Number roll, Number pitch, Number yaw) {
    return {Kind::Rpy, {std::move(roll), std::move(pitch), std::move(yaw)}};
  }
  // Rows of an exactly orthonormal matrix with determinant +1.
  static Rotation matrix(const std::array<Number, 9>& rows) { return {Kind::Matrix, {rows.begin(), rows.end()}}; }
};

// x -> R x + translation.
struct Pose {
  Point translation{0, 0, 0};
  Rotation rotation;
};

// How keyframes are interpolated (SCENE_FORMAT.md "Motion type keyframes").
enum class Interpolation {
  Slerp,  // translation linear, rotation along the shorter great arc at constant speed
  Screw,  // FCL's constant-velocity screw motion
  Nlerp   // quaternions as written, interpolated linearly and normalised (exact, rational)
};

// A rational Bezier curve in the 12-dimensional space of affine maps:
// degree = control_points.size() - 1 (one control point: a pose at rest).
struct RationalBezier {
  std::vector<AffineMap> control_points;       // >= 1
  std::vector<Number> weights;                 // > 0, one per control point; empty: all 1
  std::pair<Number, Number> interval{0, 1};    // scene parameters, mapped onto the curve's [0, 1]
};

// Rigid poses at strictly increasing times, interpolated in between.
struct Keyframes {
  std::vector<Pose> poses;                     // >= 1
  std::vector<Number> times;                   // one per pose; empty: evenly spaced over [0, 1]
  Interpolation interpolation = Interpolation::Slerp;
};

class Motion;

// Motions whose intervals abut exactly and whose poses agree exactly at
// every join (a jump is an InputError naming the join).
struct Piecewise {
  std::vector<Motion> pieces;
};

// One of the motion types.
class TMCERT_API Motion {
 public:
  Motion(RationalBezier m) : value_(std::move(m)) {}  // NOLINT: implicit
  Motion(Keyframes m) : value_(std::move(m)) {}       // NOLINT
  Motion(Piecewise m) : value_(std::move(m)) {}       // NOLINT

  // A pure translation from `from` to `to` over [t0, t1] (a degree-1
  // rational Bezier curve with identity linear parts).
  static Motion translation(const Point& from, const Point& to, Number t0 = 0, Number t1 = 1);

  const std::variant<RationalBezier, Keyframes, Piecewise>& value() const { return value_; }

 private:
  std::variant<RationalBezier, Keyframes, Piecewise> value_;
};

}  // namespace tmcert::api

namespace tmcert {
using namespace api;
}
