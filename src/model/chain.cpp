#include "src/model/chain.h"

#include "kernels/vec3.h"
#include "src/model/pose_algebra.h"

#include <stdexcept>

namespace tmcert {

namespace {

const Mat34E kIdentityE = vec3::identity<Exact>();
using vec3::compose;

// A rational square root of q >= 0, when there is one.
std::optional<Exact> rational_sqrt(const Exact& q) {
  if (q < 0) return std::nullopt;
  mpz_srcptr num = mpq_numref(q.mpq());
  mpz_srcptr den = mpq_denref(q.mpq());
  if (!mpz_perfect_square_p(num) || !mpz_perfect_square_p(den)) return std::nullopt;
  CGAL::Gmpz n, d;
  mpz_sqrt(n.mpz(), num);
  mpz_sqrt(d.mpz(), den);
  return Exact(n, d);
}

}  // namespace

ChainDescription::ChainDescription(std::vector<std::vector<Pose>> constants, std::vector<ChainJoint> joints)
    : constant_poses_(std::move(constants)), chain_joints_(std::move(joints)) {
  if (constant_poses_.size() != chain_joints_.size() + 1)
    throw std::invalid_argument("ChainDescription: constants.size() != joints + 1");
  for (const std::vector<Pose>& list : constant_poses_) {
    std::optional<Mat34E> exact = kIdentityE;
    for (const Pose& p : list) {
      const std::optional<Mat34E> m = tmcert::exact_pose(p);
      if (!m) {
        exact.reset();
        break;
      }
      exact = compose(*exact, *m);
    }
    exact_constants_.push_back(std::move(exact));
  }
  for (const ChainJoint& j : chain_joints_) {
    const Vec3E& k = j.axis;
    const Exact n2 = k[0] * k[0] + k[1] * k[1] + k[2] * k[2];
    if (n2 == 0) throw std::invalid_argument("ChainDescription: zero joint axis");
    std::optional<Vec3E> unit;
    if (const std::optional<Exact> n = rational_sqrt(n2)) unit = Vec3E{k[0] / *n, k[1] / *n, k[2] / *n};
    unit_axes_.push_back(std::move(unit));
    axis_norms2_.push_back(n2);
  }
}

std::optional<Mat34E> ChainDescription::exact_pose(const std::vector<Exact>& q) const {
  if (!exact_constants_[0]) return std::nullopt;
  Mat34E m = *exact_constants_[0];
  for (std::size_t j = 0; j < chain_joints_.size(); ++j) {
    if (chain_joints_[j].kind == ChainJoint::Kind::Revolute) {
      if (q[j] != 0) return std::nullopt;  // sin and cos of a nonzero rational are irrational
    } else if (q[j] != 0) {
      if (!unit_axes_[j]) return std::nullopt;
      Mat34E t = kIdentityE;
      for (int i = 0; i < 3; ++i) t[4 * i + 3] = (*unit_axes_[j])[i] * q[j];
      m = compose(m, t);
    }
    const std::optional<Mat34E>& c = exact_constants_[j + 1];
    if (!c) return std::nullopt;
    if (*c != kIdentityE) m = compose(m, *c);
  }
  return m;
}

bool ChainDescription::rational_between(const std::vector<Exact>& from, const std::vector<Exact>& to) const {
  for (const std::optional<Mat34E>& c : exact_constants_)
    if (!c) return false;
  for (std::size_t j = 0; j < chain_joints_.size(); ++j) {
    if (chain_joints_[j].kind == ChainJoint::Kind::Revolute) {
      if (from[j] != 0 || to[j] != 0) return false;
    } else if (!unit_axes_[j] && (from[j] != 0 || to[j] != 0)) {
      return false;  // a translation along an irrational direction
    }
  }
  return true;
}

}  // namespace tmcert
