// The exact pose algebra of the scene model: rotations given exactly
// (identity, quaternion, matrix) as quaternions and 3x4 maps, the keyframe
// interpolations that are rational Bezier curves, and the checks the
// reader makes on poses and weights.  Kernels only (exact rationals,
// intervals, Arb), so that the reader (src/io/) and the certificate
// checker use it without the search's enclosures (src/motion/).
// proofs/input-exactness.md, proofs/enclosures.md.
#pragma once

#include "src/model/model.h"

#include <array>
#include <optional>
#include <string>

namespace tmcert {

// Two rotations are equal, proven exactly (false also when unknown: rpy
// angles written differently).
bool same_rotation(const Rotation& a, const Rotation& b);

// A quaternion proportional to the rotation (w, x, y, z), exactly, when the
// rotation is exact (identity, quaternion as written, matrix); nullopt for
// rpy.
std::optional<std::array<Exact, 4>> exact_quaternion(const Rotation& r);

// The unit quaternion of the rotation, enclosed (any sign).  Call under
// RoundingGuard.
std::array<Interval, 4> unit_quaternion(const Rotation& r);

// The pose as an exact 3x4 map, when its rotation is exact.
std::optional<Mat34E> exact_pose(const Pose& p);

// Why a matrix is not a rotation (not orthonormal, det != 1), or empty.
std::string rotation_matrix_problem(const std::array<Exact, 9>& m);

// The exact rational Bezier motion of the keyframe segment from `a` to
// `b` over [t0, t1], when it is one: nlerp between exact rotations (the
// quaternions as written; a degree-3 rational curve), or any interpolation
// between equal rotations (a translation).  nullopt otherwise.
std::optional<Motion> rational_keyframe_segment(const Pose& a, const Pose& b, Interpolation how, const Exact& t0,
                                                const Exact& t1);

// Throws InputError (message without a path) when the interpolation from
// `a` to `b` is not defined: slerp and screw between rotations exactly 180
// degrees apart, or whose shorter arc cannot be proven (rpy).
void require_interpolable(const Pose& a, const Pose& b, Interpolation how);

// Divides a rational Bezier motion's weights by one positive factor, which
// leaves the curve unchanged, so that they stay well inside the double
// range: weights beyond [2^-32, 2^32] (e.g. 1e400 or 1e-400, or |q|^2 of an
// nlerp quaternion of 1e300) become coprime integers (divided by the gcd of
// their numerators over the lcm of their denominators), and then, when the
// largest is still above 2^32, are divided by a power of two that brings it
// into (1/2, 2).  Weights within that range are left as they are.
// proofs/input-exactness.md.
void normalise_weights(Motion& m);

// A positive power of two f with max |q_i| f in (1/2, 2): the quaternion
// scaled by it has the same rotation and stays inside the double range
// (q nonzero).
Exact quaternion_scale(const std::array<Exact, 4>& q);

}  // namespace tmcert
