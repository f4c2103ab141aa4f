#include "src/motion/chain.h"

#include "kernels/vec3.h"

#include <stdexcept>

namespace tmcert {

namespace {

const Mat34E kIdentityE = vec3::identity<Exact>();
using vec3::compose;

// sin and cos of a jet with one evaluation of each validated function.
void sincos(const Jet& a, Jet& s, Jet& one_minus_c) {
  const Interval sv = validated::sin(a.v), cv = validated::cos(a.v);
  const Interval d2 = CGAL::square(a.d);
  s = Jet(sv, cv * a.d, cv * a.dd - sv * d2);
  // (1 - cos)' = sin a', (1 - cos)'' = sin a'' + cos a'^2.
  one_minus_c = Jet(Interval(1) - cv, sv * a.d, sv * a.dd + cv * d2);
}

}  // namespace

LinkChain::LinkChain(const ChainDescription& description) {
  RoundingGuard guard;
  for (std::size_t k = 0; k < description.constant_poses().size(); ++k) {
    Constant c;
    if (const std::optional<Mat34E>& exact = description.exact_constant(k)) {
      c.identity = *exact == kIdentityE;
      for (int e = 0; e < 12; ++e) c.enclosed[e] = to_interval((*exact)[e]);  // tightest
    } else {
      PoseInterval enclosed;
      for (int e = 0; e < 12; ++e) enclosed[e] = to_interval(kIdentityE[e]);
      for (const Pose& p : description.constant_poses()[k]) enclosed = compose(enclosed, interval_pose(p));
      c.enclosed = enclosed;
    }
    constants_.push_back(std::move(c));
  }
  for (std::size_t j = 0; j < description.joint_count(); ++j) {
    Prepared p;
    p.joint = description.joint(j);
    const Vec3E& k = p.joint.axis;
    const Exact& n2 = description.axis_norm2(j);
    if (const std::optional<Vec3E>& unit = description.exact_unit_axis(j)) {
      for (int i = 0; i < 3; ++i) p.unit[i] = to_interval((*unit)[i]);
    } else {
      const Interval norm = validated::sqrt(n2);
      for (int i = 0; i < 3; ++i) p.unit[i] = to_interval(k[i]) / norm;
    }
    const std::array<Interval, 3>& u = p.unit;
    p.cross = {Interval(0), -u[2], u[1], u[2], Interval(0), -u[0], -u[1], u[0], Interval(0)};
    // [u]x^2 = u u^T - I with u u^T = k k^T / |k|^2 exactly.
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) p.cross2[3 * r + c] = to_interval(k[r] * k[c] / n2 - (r == c ? 1 : 0));
    joints_.push_back(std::move(p));
  }
}

std::shared_ptr<const LinkChain> LinkChain::of(const ChainDescription& description) {
  return description.prepared<LinkChain>(
      [](const ChainDescription& d) { return std::make_shared<const LinkChain>(d); });
}

PoseJet LinkChain::pose(const std::vector<Interval>& from, const std::vector<Interval>& delta, const Jet& s) const {
  std::vector<Jet> q;
  q.reserve(joints_.size());
  for (std::size_t j = 0; j < joints_.size(); ++j) q.push_back(Jet(from[j]) + delta[j] * s);
  return pose(q);
}

PoseJet LinkChain::pose(const std::vector<Jet>& values) const {
  PoseJet a;
  for (int e = 0; e < 12; ++e) a[e] = Jet(constants_[0].enclosed[e]);
  for (std::size_t j = 0; j < joints_.size(); ++j) {
    const Prepared& p = joints_[j];
    const Jet& q = values[j];
    if (p.joint.kind == ChainJoint::Kind::Revolute) {
      // A R(q) = A + sin(q) (A [u]x) + (1 - cos(q)) (A [u]x^2)  (Rodrigues).
      Jet sq, vq;
      sincos(q, sq, vq);
      std::array<Jet, 9> rot;
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) {
          Jet x1, x2;
          for (int k = 0; k < 3; ++k) {
            const Jet& ark = a[4 * r + k];
            x1 += p.cross[3 * k + c] * ark;
            x2 += p.cross2[3 * k + c] * ark;
          }
          rot[3 * r + c] = a[4 * r + c] + sq * x1 + vq * x2;
        }
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) a[4 * r + c] = rot[3 * r + c];
    } else {
      // A (translation by q u): a += A_rot u q.
      for (int r = 0; r < 3; ++r) {
        Jet au;
        for (int k = 0; k < 3; ++k) au += p.unit[k] * a[4 * r + k];
        a[4 * r + 3] += au * q;
      }
    }
    const Constant& c = constants_[j + 1];
    if (c.identity) continue;
    PoseJet next;
    for (int r = 0; r < 3; ++r)
      for (int col = 0; col < 4; ++col) {
        Jet sum = c.enclosed[col] * a[4 * r] + c.enclosed[4 + col] * a[4 * r + 1] + c.enclosed[8 + col] * a[4 * r + 2];
        if (col == 3) sum += a[4 * r + 3];
        next[4 * r + col] = sum;
      }
    a = next;
  }
  return a;
}

PoseInterval LinkChain::pose_values(const std::vector<Interval>& from, const std::vector<Interval>& delta,
                                    const Interval& s) const {
  // pose() above with every jet replaced by its value part: Jet(x).v = x,
  // (a + b).v = a.v + b.v, (a b).v = a.v b.v, (c a).v = c a.v, and sincos's
  // values sin(q.v) and 1 - cos(q.v); the same operations on the same
  // operands in the same order give the same intervals.
  PoseInterval a;
  for (int e = 0; e < 12; ++e) a[e] = constants_[0].enclosed[e];
  for (std::size_t j = 0; j < joints_.size(); ++j) {
    const Prepared& p = joints_[j];
    const Interval q = from[j] + delta[j] * s;
    if (p.joint.kind == ChainJoint::Kind::Revolute) {
      const Interval sq = validated::sin(q), vq = Interval(1) - validated::cos(q);
      std::array<Interval, 9> rot;
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) {
          Interval x1(0), x2(0);
          for (int k = 0; k < 3; ++k) {
            const Interval& ark = a[4 * r + k];
            x1 = x1 + p.cross[3 * k + c] * ark;
            x2 = x2 + p.cross2[3 * k + c] * ark;
          }
          rot[3 * r + c] = a[4 * r + c] + sq * x1 + vq * x2;
        }
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) a[4 * r + c] = rot[3 * r + c];
    } else {
      for (int r = 0; r < 3; ++r) {
        Interval au(0);
        for (int k = 0; k < 3; ++k) au = au + p.unit[k] * a[4 * r + k];
        a[4 * r + 3] = a[4 * r + 3] + au * q;
      }
    }
    const Constant& c = constants_[j + 1];
    if (c.identity) continue;
    PoseInterval next;
    for (int r = 0; r < 3; ++r)
      for (int col = 0; col < 4; ++col) {
        Interval sum = c.enclosed[col] * a[4 * r] + c.enclosed[4 + col] * a[4 * r + 1] + c.enclosed[8 + col] * a[4 * r + 2];
        if (col == 3) sum = sum + a[4 * r + 3];
        next[4 * r + col] = sum;
      }
    a = next;
  }
  return a;
}

namespace {

class LinkModel final : public SegmentModel {
 public:
  explicit LinkModel(const LinkMotion& m) : motion_(m), chain_(LinkChain::of(*m.chain)) {
    RoundingGuard guard;
    for (std::size_t j = 0; j < m.from.size(); ++j) {
      from_.push_back(to_interval(m.from[j]));
      delta_.push_back(to_interval(m.to[j] - m.from[j]));
    }
  }
  PoseJet pose(const Jet& s) const override { return chain_->pose(from_, delta_, s); }
  PoseInterval pose_values(const Interval& s) const override { return chain_->pose_values(from_, delta_, s); }
  std::optional<Mat34E> exact_pose(const Exact& s) const override {
    std::vector<Exact> q;
    q.reserve(motion_.from.size());
    for (std::size_t j = 0; j < motion_.from.size(); ++j) q.push_back(motion_.from[j] + (motion_.to[j] - motion_.from[j]) * s);
    return motion_.chain->exact_pose(q);
  }

 private:
  LinkMotion motion_;
  std::shared_ptr<const LinkChain> chain_;
  std::vector<Interval> from_, delta_;
};

// A link segment whose joints follow cubic or quintic Hermite polynomials
// (LinkMotion): each q_j(s) by Horner's rule on jets from its exact
// coefficients (hermite_coefficients) rounded outward, so that over an
// interval S of s the jet encloses q_j, q_j' and q_j'' on all of S with a
// width that shrinks with S; the pose is then the chain's, as for linear
// joints (proofs/trajectories.md section 3).
class HermiteLinkModel final : public SegmentModel {
 public:
  explicit HermiteLinkModel(const LinkMotion& m) : motion_(m), chain_(LinkChain::of(*m.chain)) {
    for (std::size_t j = 0; j < m.from.size(); ++j) exact_.push_back(link_joint_coefficients(m, j));
    RoundingGuard guard;
    for (const std::vector<Exact>& c : exact_) {
      std::vector<Interval> row;
      for (const Exact& x : c) row.push_back(to_interval(x));
      coefficients_.push_back(std::move(row));
    }
  }
  PoseJet pose(const Jet& s) const override {
    std::vector<Jet> q;
    q.reserve(coefficients_.size());
    for (const std::vector<Interval>& c : coefficients_) {
      Jet v(c.back());
      for (std::size_t k = c.size() - 1; k-- > 0;) v = v * s + Jet(c[k]);
      q.push_back(v);
    }
    return chain_->pose(q);
  }
  std::optional<Mat34E> exact_pose(const Exact& s) const override {
    std::vector<Exact> q;
    q.reserve(exact_.size());
    for (const std::vector<Exact>& c : exact_) {
      Exact v = c.back();
      for (std::size_t k = c.size() - 1; k-- > 0;) v = v * s + c[k];
      q.push_back(v);
    }
    return motion_.chain->exact_pose(q);
  }

 private:
  LinkMotion motion_;
  std::shared_ptr<const LinkChain> chain_;
  std::vector<std::vector<Exact>> exact_;
  std::vector<std::vector<Interval>> coefficients_;
};

}  // namespace

std::unique_ptr<SegmentModel> make_link_model(const LinkMotion& motion) {
  if (motion.degree() > 1) return std::make_unique<HermiteLinkModel>(motion);
  return std::make_unique<LinkModel>(motion);
}

}  // namespace tmcert
