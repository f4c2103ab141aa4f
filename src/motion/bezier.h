// Rational Bezier motions in the 12-dimensional space of affine maps:
// homogeneous control points, exact evaluation, enclosed subdivision and
// certified bounding balls (DESIGN.md section 5, proofs/bounding-balls.md).
#pragma once

#include "kernels/number_types.h"
#include "src/metric/metric.h"
#include "src/scene/model.h"

#include <array>
#include <vector>

namespace tmcert {

// Homogeneous control point: entries 0..11 are w * [A | a] (row-major),
// entry 12 is the weight w.
template <class NT>
using HomogeneousPoint = std::array<NT, 13>;

template <class NT>
using HomogeneousCurve = std::vector<HomogeneousPoint<NT>>;

HomogeneousCurve<Exact> homogeneous_curve(const Motion& motion);
HomogeneousCurve<Interval> enclose(const HomogeneousCurve<Exact>& curve);
HomogeneousCurve<double> approximate(const HomogeneousCurve<Exact>& curve);

// De Casteljau at u = 1/2: the control points of the two halves.  Over
// Interval (call under RoundingGuard) the results enclose the exact halves'
// control points; over Exact they are exact.
template <class NT>
void split_half(const HomogeneousCurve<NT>& c, HomogeneousCurve<NT>& left, HomogeneousCurve<NT>& right) {
  const std::size_t n = c.size();
  std::vector<HomogeneousPoint<NT>> work(c);
  left.resize(n);
  right.resize(n);
  const NT half(0.5);
  for (std::size_t level = 0; level < n; ++level) {
    left[level] = work[0];
    right[n - 1 - level] = work[n - 1 - level];
    for (std::size_t k = 0; k + 1 < n - level; ++k)
      for (int e = 0; e < 13; ++e) work[k][e] = (work[k][e] + work[k + 1][e]) * half;
  }
}

// The affine map c(u) at a rational parameter u in [0, 1], exactly.
Mat34E evaluate(const HomogeneousCurve<Exact>& curve, const Exact& u);

// A ball B(g, R) of affine maps in the body's metric containing a curve
// piece.  For the certified kernels R^2 is an upper bound computed with
// upward rounding; `valid` is false when no finite bound was obtained (the
// piece then clears nothing).
struct BallD {
  std::array<double, 12> center{};
  double r2 = 0;
  bool valid = false;
};

struct BallE {
  std::array<Exact, 12> center;
  Exact r2;
};

// Metric data prepared once per body for the ball computations.
struct MetricData {
  std::array<Interval, 16> g_interval;
  std::array<double, 16> g_double;
  const Metric* exact = nullptr;
  explicit MetricData(const Metric& m);
};

// Certified: control points enclosed by intervals; call outside any guard.
BallD bounding_ball(const HomogeneousCurve<Interval>& piece, const MetricData& metric);
// Exact reference: exact control points, exact radius.
BallE bounding_ball(const HomogeneousCurve<Exact>& piece, const MetricData& metric);
// Fast, uncertified: everything in double.
BallD bounding_ball(const HomogeneousCurve<double>& piece, const MetricData& metric);

}  // namespace tmcert
