// Contacts proven on the true shape of a URDF cylinder or sphere
// (Body::primitive), whose body is its circumscribed polyhedron: the
// search runs on the polyhedron (so `safe` holds for the true shape), and a
// collision is reported only with a point proven to lie in both true bodies
// at one instant (SCENE_FORMAT.md "Real robots as they ship";
// proofs/robot-links.md section 6).
//
// The candidate point comes from a floating-point search (any point will
// do); the proof is exact: a rational point y on a simplex of the other
// body (exact barycentric coordinates), placed by the poses, lies in the
// cylinder {x1^2 + x2^2 <= r^2, |x3| <= l/2} or the ball {|x|^2 <= r^2} of
// the primitive's frame: with exact poses the squared distances are
// compared exactly; with enclosed poses the whole box of the placed point
// (interval arithmetic, outward rounded) must lie inside, its squared
// extents compared exactly on the box's rational corners.
#pragma once

#include "src/motion/segment.h"
#include "src/verify/prepared.h"
#include "src/verify/verify.h"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace tmcert {

// One body at one instant.  `parts` are its static parts: in world
// coordinates when `placed` (a fixed body, prepared with its pose applied),
// else in its own frame, placed by the pose.  The pose itself is needed for
// a primitive even when its parts are placed.
struct ShapeSide {
  const Body* body = nullptr;
  const std::vector<StaticPart>* parts = nullptr;
  bool placed = false;
  std::optional<Mat34E> exact;  // the body's pose, when exact
  PoseInterval enclosed;        // the body's pose, enclosed (point intervals when exact)
};

// The body's pose at its fixed position (one-pose motion or identity), as
// a ShapeSide with its prepared static parts in world coordinates.
ShapeSide fixed_side(const PreparedBody& body);

// A body's pose from an exact map (enclosed as point intervals) or an
// enclosure only.
ShapeSide moving_side(const PreparedBody& body, const std::optional<Mat34E>& exact, const PoseInterval& enclosed);

struct TrueContact {
  std::array<std::string, 2> features;  // in the order of the two sides
  std::optional<Vec3E> point;           // exact, when proven so
  std::optional<std::array<std::array<Exact, 2>, 3>> point_box;  // else a box holding the common point
  // With point_box: the point in the own frame of the side that is not
  // the primitive (`local_side`, 0 or 1 in the order of the two sides).
  std::optional<Vec3E> local_point;
  int local_side = 1;
};

// A point of both true bodies, proven, when one is found: a body with a
// primitive is that cylinder or ball; any other body is its polygons,
// segments and points (and, only with both poses exact, a primitive's
// centre inside a solid body's closed shells counts too).  nullopt: none
// was found or proven (not a proof of separation).  Needs a primitive on
// at least one side.
std::optional<TrueContact> true_contact(const ShapeSide& a, const ShapeSide& b, CheckStats& stats);

// The witness of a proven contact at scene parameter t (features swapped
// when the check names the sides in the other order).
Witness witness_of(const Exact& t, const TrueContact& c, bool swapped = false);

// A body at scene parameter t of its motion (exact where its motion is
// exact there, else enclosed).
ShapeSide side_at(const PreparedBody& body, const Exact& t);

// A check with a primitive whose collision witness was not proven on the
// true shapes (a start containment or a static test of the polyhedra, made
// without true_contact): proven now at the witness's instant, or the
// collision becomes an undecided part `enlarged_model` from that instant to
// `t_end` (everything before it keeps what the check proved).  Checks
// without a primitive, or already proven, are left alone.
void settle_enlarged(CheckResult& r, const PreparedBody& a, const PreparedBody& b, const Exact& t_end);

// The check involves a body with a primitive.
inline bool enlarged_pair(const Body& a, const Body& b) { return a.primitive.has_value() || b.primitive.has_value(); }

}  // namespace tmcert
