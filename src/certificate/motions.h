// The certificate checker's own view of the motions planners produce
// (keyframe and piecewise motions), and of the margins that tolerances and
// clearances add to a separation claim (docs/certificate-format.md,
// "Planner motions, tolerances and clearances"; proofs/certificates.md
// sections 6-8).
//
// Independence: like the rest of the checker this shares only the scene
// model with the verifier.  The poses of slerp, screw, nlerp and rpy
// keyframe segments are enclosed here with Arb ball arithmetic straight
// from their defining formulas (the screw through the twist's V^-1, where
// the verifier goes through a point on the screw axis), not with the
// verifier's jets and Taylor enclosures (src/motion).
#pragma once

#include "kernels/number_types.h"
#include "src/model/model.h"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace tmcert::certificate {

// A set of poses: every pose M of it has |M_e - center_e| <= radius_e for
// each of its 12 entries [A | a] (row-major).
struct PoseBox {
  Mat34E center;
  Mat34E radius;  // >= 0
};

// A body's motion on a piece [ta, tb] of a check: the exact rational Bezier
// motion restricted to the piece (over [ta, tb]; degree 0 for a body
// standing still), or a box holding its pose at every t of the piece.
struct PieceMotion {
  std::optional<Motion> exact;
  PoseBox box;  // when !exact
};

// The body's motion on [ta, tb] (ta < tb); nullopt, with `why`, when the
// piece is not inside one segment of the body's motion or the enclosure is
// not finite (e.g. a screw between rotations not provably different).
std::optional<PieceMotion> piece_motion(const Body& body, const Exact& ta, const Exact& tb, std::string& why);

// The interval around [lo, hi] (inside the check's [t0, t1]) on which both
// bodies move along one exact rational curve each: the intersection of the
// segments holding [lo, hi]; nullopt when [lo, hi] crosses a join of either
// body or a body's segment there is not rational.
std::optional<std::pair<Exact, Exact>> rational_span(const Body& a, const Body& b, const Exact& lo, const Exact& hi,
                                                     const Exact& t0, const Exact& t1);

// The exact pose at t when it is known exactly (rational motions anywhere,
// keyframe segments at their ends when the rotation there is exact).
std::optional<Mat34E> exact_pose_at(const Body& body, const Exact& t);

// The pose at t enclosed (radius 0 when exact); nullopt when not finite.
std::optional<PoseBox> pose_box_at(const Body& body, const Exact& t);

// The box of a rational motion's affine control points: its convex hull
// holds every pose of the motion (positive weights).
PoseBox control_box(const Motion& m);

// Per coordinate j < 3 the largest |x_j| over the vertices; 1 for j = 3.
std::array<Exact, 4> coordinate_bounds(const std::vector<std::vector<Vec3E>>& elements);

// An upper bound of how far any point of the body moves per unit of affine
// displacement in the body's metric: max over the vertices x of
// sqrt(x^T G^-1 x) with x = (x, 1) and G = sum_i w_i m_i m_i^T over the
// mass points (|delta x| <= ||delta||_mu sqrt(x^T G^-1 x) by Cauchy-Schwarz).
Exact displacement_bound(const Body& body, const std::vector<std::vector<Vec3E>>& elements);

// A rational upper bound of sqrt(x), x >= 0 (exact when it is a square of a double).
Exact sqrt_up(const Exact& x);

// A closed interval of rationals.
struct RInterval {
  Exact lo, hi;
};
using RBox = std::array<RInterval, 3>;

// The box of points M x for every M in the pose box.
RBox place_box(const PoseBox& pose, const Vec3E& x);

// For every choice of the five points in their boxes, the segment pq
// crosses the triangle abc at a point interior to both, transversally
// (all five orientation signs certain).
bool certain_crossing(const RBox& p, const RBox& q, const RBox& a, const RBox& b, const RBox& c);

}  // namespace tmcert::certificate
