// The certificate checker's Bernstein arithmetic (check_bernstein.h): our
// own small routines (independent of src/motion): products of Bernstein
// polynomials, degree elevation as a product with the constant 1, and de
// Casteljau subdivision, all in exact rationals.
#include "src/certificate/check_bernstein.h"
#include "src/certificate/check.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace tmcert::certificate {

namespace check_internal {

std::vector<Exact> binomials(int n) {
  std::vector<Exact> c(n + 1);
  c[0] = Exact(1);
  for (int k = 0; k < n; ++k) c[k + 1] = c[k] * Exact(n - k) / Exact(k + 1);
  return c;
}

// Coefficients of p q in the Bernstein basis of degree n + m, for p of
// degree n and q of degree m:
//   c_k = sum_{i+j=k} C(n,i) C(m,j) / C(n+m,k) p_i q_j.
std::vector<Exact> bernstein_product(const std::vector<Exact>& p, const std::vector<Exact>& q) {
  const int n = static_cast<int>(p.size()) - 1, m = static_cast<int>(q.size()) - 1;
  const std::vector<Exact> cn = binomials(n), cm = binomials(m), cnm = binomials(n + m);
  std::vector<Exact> c(n + m + 1, Exact(0));
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= m; ++j) c[i + j] += cn[i] * cm[j] * p[i] * q[j];
  for (int k = 0; k <= n + m; ++k) c[k] /= cnm[k];
  return c;
}

HomogeneousMotion motion_of(const Body& b) {
  if (!b.motion) return {{identity_pose()}, {Exact(1)}};
  return {b.motion->control_points, b.motion->weights};
}

bool constant_weights(const std::vector<Exact>& w) {
  return std::all_of(w.begin(), w.end(), [&](const Exact& x) { return x == w.front(); });
}

std::vector<CP> joint_curve(const HomogeneousMotion& ma, const HomogeneousMotion& mb) {
  const int na = static_cast<int>(ma.affine.size()) - 1, nb = static_cast<int>(mb.affine.size()) - 1;
  const bool polynomial = constant_weights(ma.weights) && constant_weights(mb.weights);
  const HomogeneousMotion* m[2] = {&ma, &mb};
  // Each block's numerator is multiplied by `factor` (the other motion's
  // weights, or the constant 1 of the elevation degree).
  std::vector<Exact> factor[2];
  std::vector<Exact> weight;
  if (polynomial) {
    const int n = std::max(na, nb);
    factor[0].assign(n - na + 1, Exact(1));
    factor[1].assign(n - nb + 1, Exact(1));
    weight.assign(n + 1, Exact(1));
  } else {
    factor[0] = mb.weights;
    factor[1] = ma.weights;
    weight = bernstein_product(ma.weights, mb.weights);
  }
  std::vector<CP> c(weight.size());
  for (int blk = 0; blk < 2; ++blk) {
    const HomogeneousMotion& mo = *m[blk];
    for (int e = 0; e < 12; ++e) {
      std::vector<Exact> numerator(mo.affine.size());
      for (std::size_t k = 0; k < numerator.size(); ++k)
        numerator[k] = polynomial ? mo.affine[k][e] : mo.weights[k] * mo.affine[k][e];
      const std::vector<Exact> product = bernstein_product(numerator, factor[blk]);
      for (std::size_t k = 0; k < c.size(); ++k) c[k][12 * blk + e] = product[k];
    }
  }
  for (std::size_t k = 0; k < c.size(); ++k) c[k][24] = weight[k];
  return c;
}

std::vector<CP> joint_curve(const Body& a, const Body& b) { return joint_curve(motion_of(a), motion_of(b)); }

// de Casteljau at s: the control points of [0, s] (left) or [s, 1] (right).
std::vector<CP> split(std::vector<CP> p, const Exact& s, bool keep_left) {
  return split_controls(std::move(p), s, keep_left);
}

// The curve restricted exactly to [ua, ub] within [0, 1] (0 <= ua < ub <= 1).
std::vector<CP> restrict_curve(const std::vector<CP>& c, const Exact& ua, const Exact& ub) {
  std::vector<CP> left = ub == 1 ? c : split(c, ub, true);
  if (sgn(ua) == 0) return left;
  return split(std::move(left), ua / ub, false);
}

}  // namespace check_internal

using namespace check_internal;

Mat34E pose_at(const Body& body, const Exact& t) {
  if (!body.motion) return identity_pose();
  const Motion& m = *body.motion;
  const int n = m.degree();
  const Exact u = (t - m.t0) / (m.t1 - m.t0);
  const Exact v = Exact(1) - u;
  const std::vector<Exact> c = binomials(n);
  // B_k(u) = C(n,k) u^k (1-u)^(n-k)
  std::vector<Exact> upow(n + 1), vpow(n + 1);
  upow[0] = vpow[0] = Exact(1);
  for (int k = 1; k <= n; ++k) {
    upow[k] = upow[k - 1] * u;
    vpow[k] = vpow[k - 1] * v;
  }
  Mat34E numerator;
  for (Exact& x : numerator) x = Exact(0);
  Exact weight(0);
  for (int k = 0; k <= n; ++k) {
    const Exact b = c[k] * upow[k] * vpow[n - k] * m.weights[k];
    for (int e = 0; e < 12; ++e) numerator[e] += b * m.control_points[k][e];
    weight += b;
  }
  if (sgn(weight) == 0) throw std::domain_error("pose_at: the motion's weight vanishes at t = " + str(t));
  for (Exact& x : numerator) x /= weight;
  return numerator;
}

namespace detail {

std::vector<std::array<Exact, 25>> joint_control_points(const Body& a, const Body& b, const Exact& ua,
                                                        const Exact& ub) {
  if (!(sgn(ua) >= 0 && ua < ub && ub <= 1)) throw std::invalid_argument("joint_control_points: need 0 <= ua < ub <= 1");
  return restrict_curve(joint_curve(a, b), ua, ub);
}

}  // namespace detail

}  // namespace tmcert::certificate
