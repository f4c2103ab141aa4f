// Rational Bezier motions in the space of affine maps: homogeneous control
// points, exact evaluation, enclosed subdivision and certified bounding
// balls (DESIGN.md sections 3 and 5, proofs/bounding-balls.md).
//
// A curve has B blocks of 12 affine coordinates: B = 1 for one body's motion
// in R^12, B = 2 for the joint curve of two moving bodies in R^24 with the
// product metric.  A homogeneous control point holds w * P (12 B entries)
// followed by the weight w.
#pragma once

#include "kernels/number_types.h"
#include "src/metric/metric.h"
#include "src/model/model.h"

#include <array>
#include <functional>
#include <vector>

namespace tmcert {

template <int B>
constexpr std::size_t kHomogeneousSize = 12 * B + 1;

template <class NT, int B = 1>
using HomogeneousPoint = std::array<NT, kHomogeneousSize<B>>;

template <class NT, int B = 1>
using HomogeneousCurve = std::vector<HomogeneousPoint<NT, B>>;

// One body's motion, exactly.
HomogeneousCurve<Exact, 1> homogeneous_curve(const Motion& motion);

// The joint curve of two motions over the same parameter: one rational
// Bezier curve in R^24 whose blocks are the two motions, exactly.  Motions
// with constant weights are only degree-elevated to the larger degree;
// otherwise both are brought to the common weight w1 w2 (degree n1 + n2).
HomogeneousCurve<Exact, 2> joint_curve(const Motion& first, const Motion& second);

template <class NT, std::size_t N>
std::vector<std::array<Interval, N>> enclose(const std::vector<std::array<NT, N>>& curve) {
  std::vector<std::array<Interval, N>> c(curve.size());
  for (std::size_t k = 0; k < c.size(); ++k)
    for (std::size_t e = 0; e < N; ++e) c[k][e] = to_interval(curve[k][e]);
  return c;
}

template <std::size_t N>
std::vector<std::array<double, N>> approximate(const std::vector<std::array<Exact, N>>& curve) {
  std::vector<std::array<double, N>> c(curve.size());
  for (std::size_t k = 0; k < c.size(); ++k)
    for (std::size_t e = 0; e < N; ++e) c[k][e] = CGAL::to_double(curve[k][e]);
  return c;
}

// De Casteljau at u = 1/2: the control points of the two halves.  Over
// Interval (call under RoundingGuard) the results enclose the exact halves'
// control points; over Exact they are exact.
template <class NT, std::size_t N>
void split_half(const std::vector<std::array<NT, N>>& c, std::vector<std::array<NT, N>>& left,
                std::vector<std::array<NT, N>>& right) {
  // In place on `right`: after level L its entries 0..n-2-L hold the L+1-th
  // de Casteljau column and entry n-1-L is final.
  const std::size_t n = c.size();
  right = c;
  left.resize(n);
  const NT half(0.5);
  for (std::size_t level = 0; level < n; ++level) {
    left[level] = right[0];
    for (std::size_t k = 0; k + 1 < n - level; ++k)
      for (std::size_t e = 0; e < N; ++e) right[k][e] = (right[k][e] + right[k + 1][e]) * half;
  }
}

// The affine map(s) c(u) at a rational parameter u in [0, 1], exactly:
// block b of the curve.
template <int B>
Mat34E evaluate(const HomogeneousCurve<Exact, B>& curve, const Exact& u, int block = 0);

// Metric data prepared once per body for the ball computations: the moment
// matrix enclosed by intervals and rounded to doubles, and a way to the exact
// metric (built lazily by its owner: exact arithmetic is rarely needed).
struct MetricData {
  std::array<Interval, 16> g_interval;
  std::array<double, 16> g_double;
  std::function<const Metric&()> exact;
};

// A ball of affine maps (product metric for B = 2) containing a curve piece:
// center blocks and squared radius.  For the certified kernels r2 is an
// upper bound computed with upward rounding; `valid` is false when no finite
// bound was obtained (the piece then clears nothing).
template <int B>
struct BallD {
  std::array<double, 12 * B> center{};
  double r2 = 0;
  bool valid = false;
};

template <int B>
struct BallE {
  std::array<Exact, 12 * B> center;
  Exact r2;
};

// Metric data of an exact metric that outlives it.
MetricData metric_data_of(const Metric& metric);

template <int B>
using Metrics = std::array<const MetricData*, B>;

// Certified: control points enclosed by intervals; call outside any guard.
template <int B>
BallD<B> bounding_ball(const HomogeneousCurve<Interval, B>& piece, const Metrics<B>& metrics);
// Exact reference: exact control points, exact radius.
template <int B>
BallE<B> bounding_ball(const HomogeneousCurve<Exact, B>& piece, const Metrics<B>& metrics);
// Fast, uncertified: everything in double.
template <int B>
BallD<B> bounding_ball(const HomogeneousCurve<double, B>& piece, const Metrics<B>& metrics);

}  // namespace tmcert
