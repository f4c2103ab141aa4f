#include "src/motion/bezier.h"

#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace tmcert {

HomogeneousCurve<Exact> homogeneous_curve(const Motion& motion) {
  HomogeneousCurve<Exact> c(motion.control_points.size());
  for (std::size_t k = 0; k < c.size(); ++k) {
    for (int e = 0; e < 12; ++e) c[k][e] = motion.weights[k] * motion.control_points[k][e];
    c[k][12] = motion.weights[k];
  }
  return c;
}

HomogeneousCurve<Interval> enclose(const HomogeneousCurve<Exact>& curve) {
  HomogeneousCurve<Interval> c(curve.size());
  for (std::size_t k = 0; k < c.size(); ++k)
    for (int e = 0; e < 13; ++e) c[k][e] = to_interval(curve[k][e]);
  return c;
}

HomogeneousCurve<double> approximate(const HomogeneousCurve<Exact>& curve) {
  HomogeneousCurve<double> c(curve.size());
  for (std::size_t k = 0; k < c.size(); ++k)
    for (int e = 0; e < 13; ++e) c[k][e] = CGAL::to_double(curve[k][e]);
  return c;
}

Mat34E evaluate(const HomogeneousCurve<Exact>& curve, const Exact& u) {
  // De Casteljau with exact rationals.
  std::vector<HomogeneousPoint<Exact>> work(curve);
  const Exact v = Exact(1) - u;
  for (std::size_t level = 1; level < work.size(); ++level)
    for (std::size_t k = 0; k + level < work.size(); ++k)
      for (int e = 0; e < 13; ++e) work[k][e] = v * work[k][e] + u * work[k + 1][e];
  Mat34E m;
  for (int e = 0; e < 12; ++e) m[e] = work[0][e] / work[0][12];
  return m;
}

MetricData::MetricData(const Metric& m) : exact(&m) {
  for (int i = 0; i < 16; ++i) {
    g_interval[i] = to_interval(m.moment()[i]);
    g_double[i] = CGAL::to_double(m.moment()[i]);
  }
}

namespace {

using Affine12 = std::array<double, 12>;

double metric_distance2(const Affine12& p, const Affine12& q, const std::array<double, 16>& g) {
  double s = 0;
  for (int row = 0; row < 3; ++row) {
    double d[4];
    for (int c = 0; c < 4; ++c) d[c] = p[4 * row + c] - q[4 * row + c];
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) s += d[r] * g[4 * r + c] * d[c];
  }
  return s;
}

// A good (not optimal: only R must be rigorous) center for the points: the
// better of their centroid and the midpoint of their farthest pair.
Affine12 choose_center(const std::vector<Affine12>& pts, const std::array<double, 16>& g) {
  Affine12 centroid{};
  for (const Affine12& p : pts)
    for (int e = 0; e < 12; ++e) centroid[e] += p[e] / static_cast<double>(pts.size());
  std::size_t fi = 0, fj = 0;
  double far = -1;
  for (std::size_t i = 0; i < pts.size(); ++i)
    for (std::size_t j = i + 1; j < pts.size(); ++j) {
      const double d = metric_distance2(pts[i], pts[j], g);
      if (d > far) { far = d; fi = i; fj = j; }
    }
  Affine12 mid;
  for (int e = 0; e < 12; ++e) mid[e] = 0.5 * (pts[fi][e] + pts[fj][e]);
  auto radius2 = [&](const Affine12& c) {
    double r = 0;
    for (const Affine12& p : pts) r = std::max(r, metric_distance2(p, c, g));
    return r;
  };
  return radius2(mid) < radius2(centroid) ? mid : centroid;
}

bool all_finite(const Affine12& a) {
  return std::all_of(a.begin(), a.end(), [](double x) { return std::isfinite(x); });
}

}  // namespace

BallD bounding_ball(const HomogeneousCurve<Interval>& piece, const MetricData& metric) {
  BallD ball;
  // Approximate affine control points (round to nearest; only a center).
  std::vector<Affine12> approx(piece.size());
  for (std::size_t k = 0; k < piece.size(); ++k)
    for (int e = 0; e < 12; ++e) approx[k][e] = CGAL::to_double(piece[k][e]) / CGAL::to_double(piece[k][12]);
  ball.center = choose_center(approx, metric.g_double);
  if (!all_finite(ball.center)) return ball;  // valid = false: clears nothing

  // R^2 = max_k ||P_k - g||^2, each P_k = N_k / w_k enclosed by intervals.
  // Upward rounding makes the interval sup an upper bound of the exact value.
  RoundingGuard guard;
  double r2 = 0;
  for (const HomogeneousPoint<Interval>& h : piece) {
    Interval s(0);
    for (int row = 0; row < 3; ++row) {
      Interval d[4];
      for (int c = 0; c < 4; ++c) d[c] = h[4 * row + c] / h[12] - Interval(ball.center[4 * row + c]);
      for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) s += d[r] * metric.g_interval[4 * r + c] * d[c];
    }
    const double sup = s.sup();
    if (!(sup >= 0) || !std::isfinite(sup)) return ball;  // NaN or infinite: invalid
    r2 = std::max(r2, sup);
  }
  ball.r2 = r2;
  ball.valid = true;
  return ball;
}

BallE bounding_ball(const HomogeneousCurve<Exact>& piece, const MetricData& metric) {
  std::vector<Affine12> approx(piece.size());
  std::vector<Mat34E> exact_points(piece.size());
  for (std::size_t k = 0; k < piece.size(); ++k)
    for (int e = 0; e < 12; ++e) {
      exact_points[k][e] = piece[k][e] / piece[k][12];
      approx[k][e] = CGAL::to_double(exact_points[k][e]);
    }
  const Affine12 c = choose_center(approx, metric.g_double);
  BallE ball;
  for (int e = 0; e < 12; ++e) ball.center[e] = std::isfinite(c[e]) ? Exact(c[e]) : exact_points[0][e];
  ball.r2 = 0;
  for (const Mat34E& p : exact_points) {
    Mat34E d;
    for (int e = 0; e < 12; ++e) d[e] = p[e] - ball.center[e];
    const Exact n2 = metric.exact->norm2(d);
    if (n2 > ball.r2) ball.r2 = n2;
  }
  return ball;
}

BallD bounding_ball(const HomogeneousCurve<double>& piece, const MetricData& metric) {
  BallD ball;
  std::vector<Affine12> pts(piece.size());
  for (std::size_t k = 0; k < piece.size(); ++k)
    for (int e = 0; e < 12; ++e) pts[k][e] = piece[k][e] / piece[k][12];
  ball.center = choose_center(pts, metric.g_double);
  double r2 = 0;
  for (const Affine12& p : pts) r2 = std::max(r2, metric_distance2(p, ball.center, metric.g_double));
  ball.r2 = r2;
  ball.valid = std::isfinite(r2) && all_finite(ball.center);
  return ball;
}

}  // namespace tmcert
