// A collision witness at an irrational parameter (SCENE_FORMAT.md, "Exact
// contact times"; docs/certificate-format.md): written by the certificate
// writer and re-verified by `tmcert check`, both from the scene alone, in
// exact arithmetic (kernels/real_roots.h, kernels/moving_contact.h).
#pragma once

#include "kernels/moving_contact.h"
#include "src/model/model.h"

#include <optional>
#include <string>
#include <vector>

namespace tmcert::certificate {

// A real root of `root_of` (integer coefficients, constant term first) in
// the open interval (lo, hi) of the scene parameter.
struct ClaimedRoot {
  PolyZ root_of;
  Exact lo, hi;
};

// Empty when `root` is a valid claim: lo < hi inside [t0, t1], root_of
// square-free, nonzero at lo and hi, with exactly one root in (lo, hi).
// Otherwise what is wrong.
std::string root_claim_error(const ClaimedRoot& root, const Exact& t0, const Exact& t1);

// The same root in the check's parameter s = (t - t0) / (t1 - t0).
RealRoot check_parameter_root(const ClaimedRoot& root, const Exact& t0, const Exact& t1);

// The two bodies' poses as polynomials in s over their common denominator.
class CheckMotions {
 public:
  CheckMotions(const Body& a, const Body& b);
  // Two motions over one parameter interval (pieces of keyframe or
  // piecewise motions): s in [0, 1] over that interval.
  CheckMotions(const Motion& a, const Motion& b);
  // Vertex x (body frame) of body `side` (0: a, 1: b) as a moving point in
  // world coordinates over the common weight.
  MovingPoint place(int side, const Vec3E& x) const;
  // The common weight w_a(s) w_b(s) of the placed points, positive on [0, 1].
  PolyQ weight() const { return mul(weight_[0], weight_[1]); }

 private:
  std::vector<PolyQ> numerator_[2];  // 12 entries [A | a] times the body's weight
  PolyQ weight_[2];
};

// Vertex-index lists of one element's sub-features that can meet another
// element at a witness: each vertex, each edge (consecutive vertices) and
// the whole element.
std::vector<std::vector<int>> sub_features(std::size_t vertices);

}  // namespace tmcert::certificate
