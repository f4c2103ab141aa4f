#include "src/motion/bezier.h"

#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace tmcert {

HomogeneousCurve<Exact, 1> homogeneous_curve(const Motion& motion) {
  // Copy-constructed entries (a default Gmpq allocates a value of its own),
  // and no product for the usual weight 1.
  HomogeneousCurve<Exact, 1> c;
  c.reserve(motion.control_points.size());
  for (std::size_t k = 0; k < motion.control_points.size(); ++k) {
    const Exact& w = motion.weights[k];
    const Mat34E& p = motion.control_points[k];
    const bool one = w == 1;
    c.push_back([&]<std::size_t... I>(std::index_sequence<I...>) {
      return HomogeneousPoint<Exact, 1>{(I < 12 ? (one ? p[I % 12] : Exact(w * p[I % 12])) : w)...};
    }(std::make_index_sequence<13>{}));
  }
  return c;
}

namespace {

// Binomial coefficients as exact integers (Pascal's triangle, no division).
std::vector<std::vector<CGAL::Gmpz>> binomials(int n) {
  std::vector<std::vector<CGAL::Gmpz>> c(n + 1);
  for (int i = 0; i <= n; ++i) {
    c[i].assign(i + 1, CGAL::Gmpz(1));
    for (int k = 1; k < i; ++k) c[i][k] = c[i - 1][k - 1] + c[i - 1][k];
  }
  return c;
}

// Bernstein coefficients of the product of two polynomials given by their
// Bernstein coefficients (degrees n and m):
//   c_k = sum_{i+j=k} C(n,i) C(m,j) / C(n+m,k) a_i b_j.
// A positive combination: positive inputs give positive outputs.  A factor
// of degree 0 is a plain scaling.
std::vector<Exact> bernstein_product(const std::vector<Exact>& a, const std::vector<Exact>& b,
                                     const std::vector<std::vector<CGAL::Gmpz>>& binom) {
  const int n = static_cast<int>(a.size()) - 1, m = static_cast<int>(b.size()) - 1;
  if (m == 0) {
    if (b[0] == 1) return a;
    std::vector<Exact> c(a);
    for (Exact& x : c) x *= b[0];
    return c;
  }
  std::vector<Exact> c(n + m + 1, Exact(0));
  for (int i = 0; i <= n; ++i) {
    if (a[i] == 0) continue;
    for (int j = 0; j <= m; ++j) c[i + j] += Exact(binom[n][i] * binom[m][j]) * a[i] * b[j];
  }
  for (int k = 0; k <= n + m; ++k) c[k] /= Exact(binom[n + m][k]);
  return c;
}

bool constant_weights(const Motion& m) {
  return std::all_of(m.weights.begin(), m.weights.end(), [&](const Exact& w) { return w == m.weights[0]; });
}

}  // namespace

HomogeneousCurve<Exact, 2> joint_curve(const Motion& first, const Motion& second) {
  const Motion* motions[2] = {&first, &second};
  const bool polynomial = constant_weights(first) && constant_weights(second);
  const int n1 = first.degree(), n2 = second.degree();
  if (polynomial && n1 == n2) {
    // Same degree, constant weights: the affine control points as they are
    // (the common case of two linear per-vertex motions).
    // Copy-constructed entries: a default Gmpq allocates a value of its own.
    const Exact one(1);
    HomogeneousCurve<Exact, 2> c;
    c.reserve(n1 + 1);
    for (int k = 0; k <= n1; ++k)
      c.push_back([&]<std::size_t... I>(std::index_sequence<I...>) {
        return HomogeneousPoint<Exact, 2>{
            (I < 24 ? motions[I / 12]->control_points[k][I % 12] : one)...};
      }(std::make_index_sequence<25>{}));
    return c;
  }
  const auto binom = binomials(n1 + n2);
  // Per block: the polynomial each coordinate's numerator is multiplied by,
  // and the common weight.
  std::vector<Exact> weight;
  std::array<std::vector<Exact>, 2> factor;
  if (polynomial) {
    // c_b(t) = sum B_k P_k exactly (equal weights cancel): elevate the
    // affine control points to the common degree, weights all 1.
    const int n = std::max(n1, n2);
    weight.assign(n + 1, Exact(1));
    factor[0].assign(n - n1 + 1, Exact(1));
    factor[1].assign(n - n2 + 1, Exact(1));
  } else {
    weight = bernstein_product(first.weights, second.weights, binom);
    factor[0] = second.weights;
    factor[1] = first.weights;
  }
  HomogeneousCurve<Exact, 2> c(weight.size());
  for (int b = 0; b < 2; ++b) {
    const Motion& m = *motions[b];
    for (int e = 0; e < 12; ++e) {
      std::vector<Exact> numerator(m.control_points.size());
      for (std::size_t k = 0; k < numerator.size(); ++k)
        numerator[k] = polynomial ? m.control_points[k][e] : m.weights[k] * m.control_points[k][e];
      const std::vector<Exact> product = bernstein_product(numerator, factor[b], binom);
      for (std::size_t k = 0; k < c.size(); ++k) c[k][12 * b + e] = product[k];
    }
  }
  for (std::size_t k = 0; k < c.size(); ++k) c[k][24] = weight[k];
  return c;
}

template <int B>
Mat34E evaluate(const HomogeneousCurve<Exact, B>& curve, const Exact& u, int block) {
  // The Bernstein sum with integer weights: for u = p/q in lowest terms,
  // q^n B_k(u) = C(n, k) p^k (q - p)^(n - k) is an integer, and the common
  // factor q^n cancels in numerator / weight.  Each entry is one sum over a
  // running denominator (ExactSum): no gcd per term, unlike de Casteljau.
  const std::size_t w = kHomogeneousSize<B> - 1;
  const std::size_t n = curve.size() - 1;
  if (CGAL::is_zero(u) || u == 1) {  // an end: its control point, as it is
    const auto& h = curve[CGAL::is_zero(u) ? 0 : n];
    Mat34E m;
    for (int e = 0; e < 12; ++e) m[e] = h[w] == 1 ? h[12 * block + e] : h[12 * block + e] / h[w];
    return m;
  }
  mpz_srcptr p = mpq_numref(u.mpq()), q = mpq_denref(u.mpq());
  CGAL::Gmpz r;
  mpz_sub(r.mpz(), q, p);
  std::vector<CGAL::Gmpz> c(n + 1);
  for (std::size_t k = 0; k <= n; ++k) {
    CGAL::Gmpz t, a;
    mpz_bin_uiui(c[k].mpz(), n, k);
    mpz_pow_ui(t.mpz(), p, k);
    mpz_pow_ui(a.mpz(), r.mpz(), n - k);
    mpz_mul(c[k].mpz(), c[k].mpz(), t.mpz());
    mpz_mul(c[k].mpz(), c[k].mpz(), a.mpz());
  }
  std::array<ExactSum, 13> sums;  // the block's 12 entries, then the weight
  CGAL::Gmpz term;
  for (std::size_t k = 0; k <= n; ++k) {
    if (mpz_sgn(c[k].mpz()) == 0) continue;
    for (int e = 0; e < 13; ++e) {
      const Exact& h = curve[k][e < 12 ? 12 * block + e : w];
      mpz_mul(term.mpz(), mpq_numref(h.mpq()), c[k].mpz());
      CGAL::Gmpz den;
      mpz_set(den.mpz(), mpq_denref(h.mpq()));
      sums[e].add(term, den);
    }
  }
  const Exact weight = sums[12].value();
  Mat34E m;
  for (int e = 0; e < 12; ++e) m[e] = sums[e].value() / weight;
  return m;
}

MetricData metric_data_of(const Metric& metric) {
  MetricData d;
  for (int i = 0; i < 16; ++i) {
    d.g_interval[i] = to_interval(metric.moment()[i]);
    d.g_double[i] = CGAL::to_double(metric.moment()[i]);
  }
  d.exact = [&metric]() -> const Metric& { return metric; };
  return d;
}

namespace {

template <int B>
using Affine = std::array<double, 12 * B>;

template <int B>
double metric_distance2(const Affine<B>& p, const Affine<B>& q, const Metrics<B>& metrics) {
  double s = 0;
  for (int b = 0; b < B; ++b) {
    const std::array<double, 16>& g = metrics[b]->g_double;
    for (int row = 0; row < 3; ++row) {
      double d[4];
      for (int c = 0; c < 4; ++c) d[c] = p[12 * b + 4 * row + c] - q[12 * b + 4 * row + c];
      for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) s += d[r] * g[4 * r + c] * d[c];
    }
  }
  return s;
}

// A good (not optimal: only R must be rigorous) center for the points: the
// better of their centroid and the midpoint of their farthest pair.
template <int B>
Affine<B> choose_center(const std::vector<Affine<B>>& pts, const Metrics<B>& metrics) {
  if (pts.size() <= 2) {  // a segment (or point): its midpoint is the best center
    Affine<B> c;
    for (int e = 0; e < 12 * B; ++e) c[e] = 0.5 * (pts.front()[e] + pts.back()[e]);
    return c;
  }
  Affine<B> centroid{};
  for (const Affine<B>& p : pts)
    for (int e = 0; e < 12 * B; ++e) centroid[e] += p[e] / static_cast<double>(pts.size());
  std::size_t fi = 0, fj = 0;
  double far = -1;
  for (std::size_t i = 0; i < pts.size(); ++i)
    for (std::size_t j = i + 1; j < pts.size(); ++j) {
      const double d = metric_distance2<B>(pts[i], pts[j], metrics);
      if (d > far) { far = d; fi = i; fj = j; }
    }
  Affine<B> mid;
  for (int e = 0; e < 12 * B; ++e) mid[e] = 0.5 * (pts[fi][e] + pts[fj][e]);
  auto radius2 = [&](const Affine<B>& c) {
    double r = 0;
    for (const Affine<B>& p : pts) r = std::max(r, metric_distance2<B>(p, c, metrics));
    return r;
  };
  return radius2(mid) < radius2(centroid) ? mid : centroid;
}

template <std::size_t N>
bool all_finite(const std::array<double, N>& a) {
  return std::all_of(a.begin(), a.end(), [](double x) { return std::isfinite(x); });
}

}  // namespace

template <int B>
BallD<B> bounding_ball(const HomogeneousCurve<Interval, B>& piece, const Metrics<B>& metrics) {
  constexpr int W = 12 * B;  // index of the weight
  BallD<B> ball;
  // Approximate affine control points (round to nearest; only a center).
  std::vector<Affine<B>> approx(piece.size());
  for (std::size_t k = 0; k < piece.size(); ++k)
    for (int e = 0; e < W; ++e) approx[k][e] = CGAL::to_double(piece[k][e]) / CGAL::to_double(piece[k][W]);
  ball.center = choose_center<B>(approx, metrics);
  if (!all_finite(ball.center)) return ball;  // valid = false: clears nothing

  // R^2 = max_k ||P_k - g||^2, each P_k = N_k / w_k enclosed by intervals.
  // Upward rounding makes the interval sup an upper bound of the exact value.
  RoundingGuard guard;
  // G with its off-diagonal entries doubled (exact: times 2), per body.
  std::array<std::array<Interval, 16>, B> g2;
  for (int b = 0; b < B; ++b)
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) g2[b][4 * r + c] = r == c ? metrics[b]->g_interval[4 * r + c] : Interval(2) * metrics[b]->g_interval[4 * r + c];
  double r2 = 0;
  for (const HomogeneousPoint<Interval, B>& h : piece) {
    Interval s(0);
    // Encloses 1/w: P = N * (1/w) is enclosed.  A weight of exactly 1 (every
    // polynomial motion) needs no product.
    const bool unit = h[W].inf() == 1 && h[W].sup() == 1;
    const Interval inv_w = unit ? Interval(1) : Interval(1) / h[W];
    for (int b = 0; b < B; ++b) {
      const std::array<Interval, 16>& g = g2[b];
      for (int row = 0; row < 3; ++row) {
        Interval d[4];
        for (int c = 0; c < 4; ++c) {
          const int e = 12 * b + 4 * row + c;
          d[c] = (unit ? h[e] : h[e] * inv_w) - Interval(ball.center[e]);
        }
        // d^T G d with G symmetric: diagonal plus twice the upper triangle.
        for (int r = 0; r < 4; ++r) {
          Interval t = g[5 * r] * d[r];
          for (int c = r + 1; c < 4; ++c) t += g[4 * r + c] * d[c];
          s += d[r] * t;
        }
      }
    }
    const double sup = s.sup();
    if (!(sup >= 0) || !std::isfinite(sup)) return ball;  // NaN or infinite: invalid
    r2 = std::max(r2, sup);
  }
  ball.r2 = r2;
  ball.valid = true;
  return ball;
}

template <int B>
BallE<B> bounding_ball(const HomogeneousCurve<Exact, B>& piece, const Metrics<B>& metrics) {
  constexpr int W = 12 * B;
  std::vector<Affine<B>> approx(piece.size());
  std::vector<std::array<Exact, 12 * B>> exact_points(piece.size());
  for (std::size_t k = 0; k < piece.size(); ++k)
    for (int e = 0; e < W; ++e) {
      exact_points[k][e] = piece[k][e] / piece[k][W];
      approx[k][e] = CGAL::to_double(exact_points[k][e]);
    }
  const Affine<B> c = choose_center<B>(approx, metrics);
  BallE<B> ball;
  for (int e = 0; e < W; ++e) ball.center[e] = std::isfinite(c[e]) ? Exact(c[e]) : exact_points[0][e];
  ball.r2 = 0;
  for (const auto& p : exact_points) {
    Exact n2 = 0;
    for (int b = 0; b < B; ++b) {
      Mat34E d;
      for (int e = 0; e < 12; ++e) d[e] = p[12 * b + e] - ball.center[12 * b + e];
      n2 += metrics[b]->exact().norm2(d);
    }
    if (n2 > ball.r2) ball.r2 = n2;
  }
  return ball;
}

template <int B>
BallD<B> bounding_ball(const HomogeneousCurve<double, B>& piece, const Metrics<B>& metrics) {
  constexpr int W = 12 * B;
  BallD<B> ball;
  std::vector<Affine<B>> pts(piece.size());
  for (std::size_t k = 0; k < piece.size(); ++k)
    for (int e = 0; e < W; ++e) pts[k][e] = piece[k][e] / piece[k][W];
  ball.center = choose_center<B>(pts, metrics);
  double r2 = 0;
  for (const Affine<B>& p : pts) r2 = std::max(r2, metric_distance2<B>(p, ball.center, metrics));
  ball.r2 = r2;
  ball.valid = std::isfinite(r2) && all_finite(ball.center);
  return ball;
}

template Mat34E evaluate<1>(const HomogeneousCurve<Exact, 1>&, const Exact&, int);
template Mat34E evaluate<2>(const HomogeneousCurve<Exact, 2>&, const Exact&, int);
template BallD<1> bounding_ball<1>(const HomogeneousCurve<Interval, 1>&, const Metrics<1>&);
template BallD<2> bounding_ball<2>(const HomogeneousCurve<Interval, 2>&, const Metrics<2>&);
template BallE<1> bounding_ball<1>(const HomogeneousCurve<Exact, 1>&, const Metrics<1>&);
template BallE<2> bounding_ball<2>(const HomogeneousCurve<Exact, 2>&, const Metrics<2>&);
template BallD<1> bounding_ball<1>(const HomogeneousCurve<double, 1>&, const Metrics<1>&);
template BallD<2> bounding_ball<2>(const HomogeneousCurve<double, 2>&, const Metrics<2>&);

}  // namespace tmcert
