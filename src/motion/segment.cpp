#include "src/motion/segment.h"

#include "src/motion/segment_kinds.h"

#include "src/motion/bezier.h"
#include "src/motion/chain.h"
#include "src/model/de_casteljau.h"
#include "src/model/quaternion.h"

#include <CGAL/number_utils.h>

#include <algorithm>
#include <climits>
#include <mutex>

namespace tmcert {

using quaternion::Quat;
using quaternion::qdot;
using quaternion::qmul;
using quaternion::rotation_form;

namespace {

Interval isqrt(const Interval& x) { return CGAL::sqrt(x); }

}  // namespace

// ------------------------------------------------------------------ poses

PoseInterval interval_pose(const Pose& p) {
  PoseInterval out;
  if (const auto m = exact_pose(p)) {
    for (int e = 0; e < 12; ++e) out[e] = to_interval((*m)[e]);
    return out;
  }
  const std::array<Interval, 9> R = rotation_form(unit_quaternion(p.rotation));
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) out[4 * r + c] = R[3 * r + c];
    out[4 * r + 3] = to_interval(p.translation[r]);
  }
  return out;
}

// ------------------------------------------------------------------ exact segments

Motion restrict_motion(const Motion& m, const Exact& t0, const Exact& t1) {
  if (t0 == m.t0 && t1 == m.t1) return m;
  const Exact span = m.t1 - m.t0;
  const Exact a = (t0 - m.t0) / span, b = (t1 - m.t0) / span;
  const HomogeneousCurve<Exact, 1> c = de_casteljau_restrict(homogeneous_curve(m), a, b);
  Motion out;
  out.t0 = t0;
  out.t1 = t1;
  out.nlerp = m.nlerp;
  for (const auto& p : c) {
    const Exact& w = p[12];
    Mat34E cp;
    for (int e = 0; e < 12; ++e) cp[e] = p[e] / w;
    out.control_points.push_back(cp);
    out.weights.push_back(w);
  }
  normalise_weights(out);
  return out;
}

Mat34E motion_pose(const Motion& m, const Exact& t) {
  return evaluate<1>(homogeneous_curve(m), (t - m.t0) / (m.t1 - m.t0));
}

// ------------------------------------------------------------------ models

namespace {

// A rational Bezier curve evaluated on jets: de Casteljau on the
// homogeneous control points, then the quotient by the weight.
class BezierModel final : public SegmentModel {
 public:
  explicit BezierModel(const Motion& m) : curve_(homogeneous_curve(m)) {
    RoundingGuard guard;
    enclosed_ = enclose(curve_);
  }
  PoseJet pose(const Jet& s) const override {
    const std::size_t n = enclosed_.size();
    std::vector<std::array<Jet, 13>> work(n);
    for (std::size_t k = 0; k < n; ++k)
      for (int e = 0; e < 13; ++e) work[k][e] = Jet(enclosed_[k][e]);
    const Jet one_minus = Jet(Interval(1)) - s;
    for (std::size_t level = 1; level < n; ++level)
      for (std::size_t k = 0; k + level < n; ++k)
        for (int e = 0; e < 13; ++e) work[k][e] = one_minus * work[k][e] + s * work[k + 1][e];
    PoseJet out;
    for (int e = 0; e < 12; ++e) out[e] = work[0][e] / work[0][12];
    return out;
  }
  std::optional<Mat34E> exact_pose(const Exact& s) const override { return evaluate<1>(curve_, s); }

 private:
  HomogeneousCurve<Exact, 1> curve_;
  HomogeneousCurve<Interval, 1> enclosed_;
};

// Slerp, screw and nlerp between two keyframe poses, enclosed (the
// rotations' unit quaternions and every transcendental constant are
// intervals; proofs/enclosures.md section 3).
class KeyframeModel final : public SegmentModel {
 public:
  KeyframeModel(const Pose& a, const Pose& b, Interpolation how)
      : how_(how), from_(a), to_(b) {
    RoundingGuard guard;
    // nlerp interpolates the quaternions as written (a matrix's: the
    // rational multiple exact_quaternion gives); slerp and screw the unit ones.
    // Both are multiplied by one positive power of two (the same rotations
    // at the same speed) that brings a quaternion as written into the
    // double range (1e300 or 1e-400 would overflow or vanish in |q|^2): the
    // largest factor that keeps the larger end below 2 (an rpy end is a
    // unit quaternion, factor 1).
    Exact common(1);
    if (how == Interpolation::Nlerp)
      for (const Rotation* r : {&a.rotation, &b.rotation})
        if (const auto q = exact_quaternion(*r)) common = std::min(common, quaternion_scale(*q));
    auto nlerp_quaternion = [&common](const Rotation& r) {
      if (const auto q = exact_quaternion(r)) {
        Quat<Interval> out;
        for (int i = 0; i < 4; ++i) out[i] = to_interval((*q)[i] * common);
        return out;
      }
      const Quat<Interval> u = unit_quaternion(r);
      const Interval f = to_interval(common);
      return Quat<Interval>{u[0] * f, u[1] * f, u[2] * f, u[3] * f};
    };
    p0_ = how == Interpolation::Nlerp ? nlerp_quaternion(a.rotation) : unit_quaternion(a.rotation);
    p1_ = how == Interpolation::Nlerp ? nlerp_quaternion(b.rotation) : unit_quaternion(b.rotation);
    constant_ = same_rotation(a.rotation, b.rotation);
    // The shorter arc: require_interpolable has proven the sign of p0 . p1
    // (for nlerp with exact quaternions the exact sign decides).
    const auto qa = exact_quaternion(a.rotation), qb = exact_quaternion(b.rotation);
    // With exact quaternions, the sign of their dot product from its
    // interval enclosure when that excludes 0 (proofs/enclosures.md
    // section 3c), else exactly.
    auto exact_negative = [&]() {
      Quat<Interval> ia, ib;
      for (int i = 0; i < 4; ++i) {
        ia[i] = to_interval((*qa)[i]);
        ib[i] = to_interval((*qb)[i]);
      }
      const Interval d = qdot(ia, ib);
      if (d.sup() < 0) return true;
      if (d.inf() > 0) return false;
      return qdot(*qa, *qb) < 0;
    };
    const bool negate = qa && qb ? exact_negative() : qdot(p0_, p1_).sup() < 0;
    if (negate)
      for (Interval& x : p1_) x = -x;
    for (int i = 0; i < 3; ++i) {
      t0_[i] = to_interval(a.translation[i]);
      t1_[i] = to_interval(b.translation[i]);
    }
    if (constant_) return;
    Quat<Interval> diff, sum;
    for (int i = 0; i < 4; ++i) {
      diff[i] = p0_[i] - p1_[i];
      sum[i] = p0_[i] + p1_[i];
    }
    // The angle between the unit quaternions, well conditioned for small
    // angles: |p0 - p1| = 2 sin(theta/2), |p0 + p1| = 2 cos(theta/2).
    theta_ = Interval(2) * validated::atan2(isqrt(qdot(diff, diff)), isqrt(qdot(sum, sum)));
    sinc_theta_ = sinc(Jet(theta_)).v;
    if (how_ == Interpolation::Screw) {
      // Relative rotation d = conj(p0) p1 (w >= 0: the shorter arc), its
      // angle phi; the relative translation td in the frame of the first pose.
      const Quat<Interval> conj0{p0_[0], -p0_[1], -p0_[2], -p0_[3]};
      const Quat<Interval> d = qmul(conj0, p1_);
      const Interval vnorm = isqrt(d[1] * d[1] + d[2] * d[2] + d[3] * d[3]);
      phi_ = Interval(2) * validated::atan2(vnorm, d[0]);
      const std::array<Interval, 9> R0 = rotation_form(p0_);
      for (int i = 0; i < 9; ++i) r0_[i] = R0[i];
      std::array<Interval, 3> td;  // R0^T (t1 - t0)
      for (int i = 0; i < 3; ++i) td[i] = R0[i] * (t1_[0] - t0_[0]) + R0[3 + i] * (t1_[1] - t0_[1]) + R0[6 + i] * (t1_[2] - t0_[2]);
      if (!(phi_.inf() > 0x1p-10)) {
        // A small angle, possibly 0 within rounding (rotations equal up to
        // rounding): the twist (omega, v) = log(T0^-1 T1) in forms regular
        // at phi = 0 (proofs/enclosures.md section 3): omega = phi k =
        // 2 (d1, d2, d3) / sinc(phi/2), v = V^-1 td = td - omega x td / 2 +
        // C(phi) omega x (omega x td); the translation is then
        // s v + s^2 f2(s phi) omega x v + s^3 f3(s phi) omega x (omega x v).
        small_screw_ = true;
        const Interval sinc_half = validated::factorial_series(phi_ / Interval(2), 1)[0];
        for (int i = 0; i < 3; ++i) omega_[i] = Interval(2) * d[i + 1] / sinc_half;
        const Interval c = validated::screw_inverse_coefficient(phi_);
        const std::array<Interval, 3> wt = cross(omega_, td), wwt = cross(omega_, wt);
        for (int i = 0; i < 3; ++i) v_[i] = td[i] - wt[i] / Interval(2) + c * wwt[i];
        kc_ = cross(omega_, v_);   // omega x v
        kkc_ = cross(omega_, kc_);  // omega x (omega x v)
        return;
      }
      // The unit axis k, the screw's pitch part along k and the point c
      // on its axis: c = (t_perp + cot(phi/2) k x t_perp) / 2.
      for (int i = 0; i < 3; ++i) k_[i] = d[i + 1] / vnorm;
      along_ = k_[0] * td[0] + k_[1] * td[1] + k_[2] * td[2];
      std::array<Interval, 3> perp;
      for (int i = 0; i < 3; ++i) perp[i] = td[i] - along_ * k_[i];
      const Interval cot = d[0] / vnorm;
      const std::array<Interval, 3> kp = cross(k_, perp);
      std::array<Interval, 3> c;
      for (int i = 0; i < 3; ++i) c[i] = (perp[i] + cot * kp[i]) / Interval(2);
      kc_ = cross(k_, c);
      kkc_ = cross(k_, kc_);
    }
  }

  PoseJet pose(const Jet& s) const override {
    PoseJet out;
    const Jet one(Interval(1));
    if (how_ == Interpolation::Screw && !constant_ && !small_screw_) {
      // A(s) = R(p0 (cos(s phi/2), sin(s phi/2) k)); a(s) = t0 + R0 (-sin(s phi) k x c
      //        - (1 - cos(s phi)) k x (k x c) + s along k).
      const Jet half = (phi_ / Interval(2)) * s, full = phi_ * s;
      const Jet ch = cos(half), sh = sin(half);
      const Quat<Jet> rel{ch, sh * Jet(k_[0]), sh * Jet(k_[1]), sh * Jet(k_[2])};
      const Quat<Jet> p0{Jet(p0_[0]), Jet(p0_[1]), Jet(p0_[2]), Jet(p0_[3])};
      const std::array<Jet, 9> R = rotation_form(qmul(p0, rel));
      const Jet sf = sin(full), vers = one - cos(full);
      std::array<Jet, 3> local;
      for (int i = 0; i < 3; ++i) local[i] = -(sf * Jet(kc_[i])) - vers * Jet(kkc_[i]) + (along_ * s) * Jet(k_[i]);
      for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) out[4 * r + c] = R[3 * r + c];
        out[4 * r + 3] = Jet(t0_[r]) + r0_[3 * r] * local[0] + r0_[3 * r + 1] * local[1] + r0_[3 * r + 2] * local[2];
      }
      return out;
    }
    Quat<Jet> q;
    bool unit = true;
    if (constant_) {
      for (int i = 0; i < 4; ++i) q[i] = Jet(p0_[i]);
      unit = false;  // nlerp's quaternions are as written
    } else if (how_ == Interpolation::Slerp || how_ == Interpolation::Screw) {
      // q(s) = (sin((1 - s) theta) p0 + sin(s theta) p1) / sin(theta), written
      // with sinc so that it stays enclosed when theta is tiny (keyframes
      // whose rotations differ by rounding noise):
      // sin(u theta) / sin(theta) = u sinc(u theta) / sinc(theta).
      // The sinc form only for small angles (below 2^-10, where the
      // series is accurate to about 1e-22); the sine form elsewhere, whose
      // divisor sin(theta) is a constant away from 0.
      const Jet r = one - s;
      if (theta_.inf() > 0x1p-10) {
        const Jet a = sin(theta_ * r), b = sin(theta_ * s);
        const Interval inv = Interval(1) / validated::sin(theta_);
        for (int i = 0; i < 4; ++i) q[i] = inv * (p0_[i] * a + p1_[i] * b);
      } else {
        const Jet a = r * sinc(theta_ * r), b = s * sinc(theta_ * s);
        const Interval inv = Interval(1) / sinc_theta_;
        for (int i = 0; i < 4; ++i) q[i] = inv * (p0_[i] * a + p1_[i] * b);
      }
    } else {  // nlerp: R(q) / |q|^2
      for (int i = 0; i < 4; ++i) q[i] = Jet(p0_[i]) + (p1_[i] - p0_[i]) * s;
      unit = false;
    }
    std::array<Jet, 9> R = rotation_form(q);
    if (!unit) {
      const Jet n2 = qdot(q, q);
      for (Jet& x : R) x = x / n2;
    }
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) out[4 * r + c] = R[3 * r + c];
      out[4 * r + 3] = Jet(t0_[r]) + (t1_[r] - t0_[r]) * s;
    }
    if (small_screw_) {
      // The rotation is slerp's (above, in its sinc form); the translation
      // t0 + R0 (s v + s^2 f2(s phi) omega x v + s^3 f3(s phi) omega x (omega x v)).
      const Jet x = phi_ * s, s2 = s * s, s3 = s2 * s;
      const Jet a = s2 * factorial_series(x, 2), b = s3 * factorial_series(x, 3);
      std::array<Jet, 3> local;
      for (int i = 0; i < 3; ++i) local[i] = v_[i] * s + a * Jet(kc_[i]) + b * Jet(kkc_[i]);
      for (int r = 0; r < 3; ++r)
        out[4 * r + 3] = Jet(t0_[r]) + r0_[3 * r] * local[0] + r0_[3 * r + 1] * local[1] + r0_[3 * r + 2] * local[2];
    }
    return out;
  }

  // The value parts of pose(Jet(s)) without the derivatives, for slerp
  // away from angle 0, nlerp and equal rotations: the same interval
  // operations on the values, in the same order (a constant jet's value
  // part of a * b is a.v * b.v, of sin(a) validated::sin(a.v), of a / b
  // a.v / b.v), so the same intervals bit for bit (proofs/enclosures.md
  // section 2, "Value parts").  Screw and slerp near angle 0: the jets'.
  PoseInterval pose_values(const Interval& s) const override {
    const bool slerp = how_ == Interpolation::Slerp && !constant_;
    if ((how_ == Interpolation::Screw && !constant_) || small_screw_ || (slerp && !(theta_.inf() > 0x1p-10)))
      return SegmentModel::pose_values(s);
    Quat<Interval> q;
    bool unit = true;
    if (constant_) {
      q = p0_;
      unit = false;
    } else if (slerp) {
      const Interval r = Interval(1) - s;
      const Interval a = validated::sin(theta_ * r), b = validated::sin(theta_ * s);
      const Interval inv = Interval(1) / validated::sin(theta_);
      for (int i = 0; i < 4; ++i) q[i] = inv * (p0_[i] * a + p1_[i] * b);
    } else {  // nlerp
      for (int i = 0; i < 4; ++i) q[i] = p0_[i] + (p1_[i] - p0_[i]) * s;
      unit = false;
    }
    std::array<Interval, 9> R = rotation_form(q);
    if (!unit) {
      const Interval n2 = qdot(q, q);
      for (Interval& x : R) x = x / n2;
    }
    PoseInterval out;
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) out[4 * r + c] = R[3 * r + c];
      out[4 * r + 3] = t0_[r] + (t1_[r] - t0_[r]) * s;
    }
    return out;
  }

  // The end poses exactly, computed when first asked (a planner's edge
  // often needs neither: its sampled and start tests use the enclosures
  // unless a candidate pair is left; proofs/enclosures.md section 3b).
  std::optional<Mat34E> exact_pose(const Exact& s) const override {
    if (s == 0) {
      std::call_once(from_once_, [this] { exact_from_ = tmcert::exact_pose(from_); });
      return exact_from_;
    }
    if (s == 1) {
      std::call_once(to_once_, [this] { exact_to_ = tmcert::exact_pose(to_); });
      return exact_to_;
    }
    return std::nullopt;
  }

 private:
  static std::array<Interval, 3> cross(const std::array<Interval, 3>& a, const std::array<Interval, 3>& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  }

  Interpolation how_;
  Pose from_, to_;
  mutable std::once_flag from_once_, to_once_;
  mutable std::optional<Mat34E> exact_from_, exact_to_;
  bool constant_ = false;
  Quat<Interval> p0_, p1_;
  std::array<Interval, 3> t0_, t1_;
  Interval theta_, sinc_theta_;
  // Screw only.  Away from phi = 0: the axis k, the pitch part `along`, k x c
  // and k x (k x c); near it (small_screw_): omega, v, omega x v and
  // omega x (omega x v) in kc_ and kkc_.
  Interval phi_, along_;
  bool small_screw_ = false;
  std::array<Interval, 3> k_, kc_, kkc_, omega_, v_;
  std::array<Interval, 9> r0_;
};

}  // namespace

std::unique_ptr<SegmentModel> make_bezier_model(const Motion& motion) { return std::make_unique<BezierModel>(motion); }

std::unique_ptr<SegmentModel> make_keyframe_model(const Pose& a, const Pose& b, Interpolation how) {
  return std::make_unique<KeyframeModel>(a, b, how);
}

std::unique_ptr<SegmentModel> make_segment_model(const MotionSegment& segment) {
  return verified_kind_of(segment).model(segment);
}

}  // namespace tmcert
