#include "src/motion/chain.h"

#include <stdexcept>

namespace tmcert {

namespace {

const Mat34E kIdentityE = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};

template <class T>
std::array<T, 12> compose(const std::array<T, 12>& a, const std::array<T, 12>& b) {
  std::array<T, 12> out;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 4; ++c) {
      T sum = a[4 * r] * b[c] + a[4 * r + 1] * b[4 + c] + a[4 * r + 2] * b[8 + c];
      if (c == 3) sum = sum + a[4 * r + 3];
      out[4 * r + c] = sum;
    }
  }
  return out;
}

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

// sin and cos of a jet with one evaluation of each validated function.
void sincos(const Jet& a, Jet& s, Jet& one_minus_c) {
  const Interval sv = validated::sin(a.v), cv = validated::cos(a.v);
  const Interval d2 = CGAL::square(a.d);
  s = Jet(sv, cv * a.d, cv * a.dd - sv * d2);
  // (1 - cos)' = sin a', (1 - cos)'' = sin a'' + cos a'^2.
  one_minus_c = Jet(Interval(1) - cv, sv * a.d, sv * a.dd + cv * d2);
}

}  // namespace

LinkChain::LinkChain(std::vector<std::vector<Pose>> constants, std::vector<ChainJoint> joints)
    : ChainDescription(constants, joints) {
  if (constants.size() != joints.size() + 1) throw std::invalid_argument("LinkChain: constants.size() != joints + 1");
  RoundingGuard guard;
  for (const std::vector<Pose>& list : constants) {
    Constant c;
    Mat34E exact = kIdentityE;
    bool is_exact = true;
    PoseInterval enclosed;
    for (int e = 0; e < 12; ++e) enclosed[e] = to_interval(kIdentityE[e]);
    for (const Pose& p : list) {
      const std::optional<Mat34E> m = tmcert::exact_pose(p);
      if (m && is_exact) exact = compose(exact, *m);
      else is_exact = false;
      enclosed = compose(enclosed, interval_pose(p));
    }
    if (is_exact) {
      c.exact = exact;
      c.identity = exact == kIdentityE;
      for (int e = 0; e < 12; ++e) enclosed[e] = to_interval(exact[e]);  // tightest
    }
    c.enclosed = enclosed;
    constants_.push_back(std::move(c));
  }
  for (const ChainJoint& j : joints) {
    Prepared p;
    p.joint = j;
    const Vec3E& k = j.axis;
    const Exact n2 = k[0] * k[0] + k[1] * k[1] + k[2] * k[2];
    if (n2 == 0) throw std::invalid_argument("LinkChain: zero joint axis");
    if (const std::optional<Exact> n = rational_sqrt(n2)) {
      p.unit_exact = Vec3E{k[0] / *n, k[1] / *n, k[2] / *n};
      for (int i = 0; i < 3; ++i) p.unit[i] = to_interval((*p.unit_exact)[i]);
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

std::optional<Mat34E> LinkChain::exact_pose(const std::vector<Exact>& q) const {
  if (!constants_[0].exact) return std::nullopt;
  Mat34E m = *constants_[0].exact;
  for (std::size_t j = 0; j < joints_.size(); ++j) {
    const Prepared& p = joints_[j];
    if (p.joint.kind == ChainJoint::Kind::Revolute) {
      if (q[j] != 0) return std::nullopt;  // sin and cos of a nonzero rational are irrational
    } else if (q[j] != 0) {
      if (!p.unit_exact) return std::nullopt;
      Mat34E t = kIdentityE;
      for (int i = 0; i < 3; ++i) t[4 * i + 3] = (*p.unit_exact)[i] * q[j];
      m = compose(m, t);
    }
    const Constant& c = constants_[j + 1];
    if (!c.exact) return std::nullopt;
    if (!c.identity) m = compose(m, *c.exact);
  }
  return m;
}

bool LinkChain::rational_between(const std::vector<Exact>& from, const std::vector<Exact>& to) const {
  for (const Constant& c : constants_)
    if (!c.exact) return false;
  for (std::size_t j = 0; j < joints_.size(); ++j) {
    const Prepared& p = joints_[j];
    if (p.joint.kind == ChainJoint::Kind::Revolute) {
      if (from[j] != 0 || to[j] != 0) return false;
    } else if (!p.unit_exact && (from[j] != 0 || to[j] != 0)) {
      return false;  // a translation along an irrational direction
    }
  }
  return true;
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
  explicit LinkModel(const LinkMotion& m) : motion_(m), chain_(prepared(m.chain)) {
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
    return chain_->exact_pose(q);
  }

 private:
  // The chain with its enclosures: the verifier's chains are prepared once
  // (PlacedRobot); any other description is prepared here.
 public:
  static std::shared_ptr<const LinkChain> prepared(const std::shared_ptr<const ChainDescription>& d) {
    if (auto chain = std::dynamic_pointer_cast<const LinkChain>(d)) return chain;
    std::vector<ChainJoint> joints;
    for (std::size_t j = 0; j < d->joint_count(); ++j) joints.push_back(d->joint(j));
    return std::make_shared<const LinkChain>(d->constant_poses(), std::move(joints));
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
  explicit HermiteLinkModel(const LinkMotion& m) : motion_(m), chain_(LinkModel::prepared(m.chain)) {
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
    return chain_->exact_pose(q);
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
