#include "src/certificate/algebraic_witness.h"

namespace tmcert::certificate {

std::string root_claim_error(const ClaimedRoot& root, const Exact& t0, const Exact& t1) {
  if (!(root.lo < root.hi)) return "the interval is empty (needs lo < hi)";
  if (root.lo < t0 || root.hi > t1) return "the interval is not inside the check's interval";
  const PolyZ p = primitive(root.root_of);
  if (degree(p) < 1) return "root_of is a constant";
  PolyZ d;
  for (int i = 1; i <= degree(p); ++i) d.push_back(p[i] * i);
  if (degree(gcd(p, d)) > 0) return "root_of is not square-free";
  if (sign_at(p, root.lo) == CGAL::ZERO || sign_at(p, root.hi) == CGAL::ZERO)
    return "root_of vanishes at an end of the interval";
  if (real_roots(p, root.lo, root.hi).size() != 1) return "root_of has not exactly one root in the interval";
  return {};
}

RealRoot check_parameter_root(const ClaimedRoot& root, const Exact& t0, const Exact& t1) {
  const Exact length = t1 - t0;
  return RealRoot{compose_affine(primitive(root.root_of), t0, length), (root.lo - t0) / length, (root.hi - t0) / length};
}

namespace {

// A body's motion in s in [0, 1] (power basis): 12 numerator entries and the
// weight; a fixed body its constant pose with weight 1.
void motion_polys(const Motion* motion, std::vector<PolyQ>& numerator, PolyQ& weight) {
  numerator.assign(12, PolyQ{});
  if (!motion) {
    const Exact id[12] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
    for (int e = 0; e < 12; ++e) numerator[e] = id[e] == 0 ? PolyQ{} : PolyQ{id[e]};
    weight = {Exact(1)};
    return;
  }
  const Motion& m = *motion;
  const int n = m.degree();
  // B_k(s) = C(n,k) s^k (1-s)^(n-k) in the power basis.
  std::vector<PolyQ> basis(n + 1);
  Exact binom(1);
  for (int k = 0; k <= n; ++k) {
    PolyQ p{binom};
    for (int i = 0; i < k; ++i) p = mul(p, PolyQ{Exact(0), Exact(1)});
    for (int i = 0; i < n - k; ++i) p = mul(p, PolyQ{Exact(1), Exact(-1)});
    basis[k] = p;
    binom = binom * (n - k) / (k + 1);
  }
  weight.clear();
  for (int k = 0; k <= n; ++k) {
    PolyQ wk = basis[k];
    for (Exact& c : wk) c *= m.weights[k];
    weight = add(weight, wk);
    for (int e = 0; e < 12; ++e) {
      PolyQ term = wk;
      for (Exact& c : term) c *= m.control_points[k][e];
      numerator[e] = add(numerator[e], term);
    }
  }
}

}  // namespace

CheckMotions::CheckMotions(const Body& a, const Body& b) {
  motion_polys(a.motion ? &*a.motion : nullptr, numerator_[0], weight_[0]);
  motion_polys(b.motion ? &*b.motion : nullptr, numerator_[1], weight_[1]);
}

CheckMotions::CheckMotions(const Motion& a, const Motion& b) {
  motion_polys(&a, numerator_[0], weight_[0]);
  motion_polys(&b, numerator_[1], weight_[1]);
}

MovingPoint CheckMotions::place(int side, const Vec3E& x) const {
  const std::vector<PolyQ>& n = numerator_[side];
  MovingPoint out;
  for (int i = 0; i < 3; ++i) {
    PolyQ acc = n[4 * i + 3];
    for (int j = 0; j < 3; ++j) {
      PolyQ term = n[4 * i + j];
      for (Exact& c : term) c *= x[j];
      acc = add(acc, term);
    }
    out.x[i] = mul(acc, weight_[1 - side]);  // over the common weight w_a w_b
  }
  return out;
}

std::vector<std::vector<int>> sub_features(std::size_t vertices) {
  std::vector<std::vector<int>> out;
  const int n = static_cast<int>(vertices);
  for (int i = 0; i < n; ++i) out.push_back({i});
  if (n == 2) out.push_back({0, 1});
  if (n >= 3) {
    for (int i = 0; i < n; ++i) out.push_back({i, (i + 1) % n});
    std::vector<int> all(n);
    for (int i = 0; i < n; ++i) all[i] = i;
    out.push_back(all);
  }
  return out;
}

}  // namespace tmcert::certificate
