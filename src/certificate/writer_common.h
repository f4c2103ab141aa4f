// The certificate writer's shared vocabulary (writer.h): the curve types,
// the limits of the proof search, exact poses and the JSON forms of
// numbers.  Internal to the writer's files.
#pragma once

#include "src/certificate/writer.h"
#include "src/motion/bezier.h"

#include <nlohmann/json.hpp>

#include <array>
#include <optional>

namespace tmcert::certificate::writer_internal {

using json = nlohmann::json;
using CurveE = HomogeneousCurve<Exact, 2>;
using CurveI = HomogeneousCurve<Interval, 2>;
constexpr std::size_t kWeight = 24;  // index of the weight in a joint control point

// Bisections of a cleared piece before giving up (each halves the piece).
constexpr int kMaxExtraDepth = 24;
// Iterations of the direction search for one group pair: many for small
// groups, few for large ones (a large pair that does not separate quickly
// is cheaper to split).
constexpr int kDirectionIterations = 48;
constexpr int kDirectionIterationsLarge = 6;
constexpr std::size_t kLargeGroup = 64;  // vertices of both groups together

// A direction rounded to about 20 significant bits: shorter numbers in the
// certificate and faster exact checks; the certification decides either way.
std::array<double, 3> rounded(const std::array<double, 3>& n);

inline const Mat34E kIdentity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};

// A body's motion, or the identity (degree 0) when it has none.
Motion motion_or_identity(const Body& b);

// A check the plain format does not describe: a keyframe or piecewise
// motion, a tolerance or a clearance (docs/certificate-format.md, "Planner
// motions, tolerances and clearances").
bool general_check(const Body& a, const Body& b, const Exact& clearance);

// m x, exactly.
Vec3E apply(const Mat34E& m, const Vec3E& x);

// The exact pose of b at scene parameter t (ResourceLimit when a planner
// motion's pose there is not exact).
Mat34E pose(const Body& b, const Exact& t);

json rational(const Exact& q);
json vec(const Vec3E& v);

}  // namespace tmcert::certificate::writer_internal
