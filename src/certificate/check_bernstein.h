// The certificate checker's Bernstein arithmetic (its own, independent of
// src/motion): binomials, products of Bernstein polynomials (degree
// elevation as a product with the constant 1), the joint curve of a check
// (docs/certificate-format.md "The curve of a check"), its exact de
// Casteljau restriction to a piece, and the exact pose of a rational motion.
#pragma once

#include "src/certificate/check_numbers.h"

#include <array>
#include <vector>

namespace tmcert::certificate::check_internal {

// C(n, k) for k = 0..n.
std::vector<Exact> binomials(int n);

// Coefficients of p q in the Bernstein basis of degree n + m, for p of
// degree n and q of degree m.
std::vector<Exact> bernstein_product(const std::vector<Exact>& p, const std::vector<Exact>& q);

// The joint curve: 25 coordinates per control point, N_a (12), N_b (12), W.
using CP = std::array<Exact, 25>;

struct HomogeneousMotion {
  std::vector<Mat34E> affine;  // A_k
  std::vector<Exact> weights;  // w_k
};

// A body's motion, or the identity (degree 0) when it has none.
HomogeneousMotion motion_of(const Body& b);

bool constant_weights(const std::vector<Exact>& w);

// The joint curve of two motions: polynomial ones (constant weights) are
// elevated to the larger degree, rational ones multiplied by the other
// motion's weights.
std::vector<CP> joint_curve(const HomogeneousMotion& ma, const HomogeneousMotion& mb);
std::vector<CP> joint_curve(const Body& a, const Body& b);

// de Casteljau at s: the control points of [0, s] (left) or [s, 1] (right).
std::vector<CP> split(std::vector<CP> p, const Exact& s, bool keep_left);

// The curve restricted exactly to [ua, ub] within [0, 1] (0 <= ua < ub <= 1).
std::vector<CP> restrict_curve(const std::vector<CP>& c, const Exact& ua, const Exact& ub);

}  // namespace tmcert::certificate::check_internal
