#include "src/ompl/certified_motion_validator.h"

#include "src/motion/segment.h"

#include <ompl/base/spaces/SE3StateSpace.h>

#include <cmath>
#include <exception>
#include <string>

namespace tmcert {

namespace ob = ompl::base;

namespace {

Exact exact_double(double x, const char* what) {
  if (!std::isfinite(x)) throw InputError(std::string("state: ") + what + " is not finite");
  return Exact(x);  // a finite double is a dyadic rational: converted exactly
}

}  // namespace

Pose SE3Motions::pose(const ob::State* s) {
  const auto* se3 = s->as<ob::SE3StateSpace::StateType>();
  const auto& q = se3->rotation();
  Pose p;
  p.translation = {exact_double(se3->getX(), "x"), exact_double(se3->getY(), "y"), exact_double(se3->getZ(), "z")};
  p.rotation.kind = Rotation::Kind::Quaternion;
  p.rotation.quaternion = {exact_double(q.w, "quaternion w"), exact_double(q.x, "quaternion x"),
                           exact_double(q.y, "quaternion y"), exact_double(q.z, "quaternion z")};
  if (p.rotation.quaternion[0] == 0 && p.rotation.quaternion[1] == 0 && p.rotation.quaternion[2] == 0 &&
      p.rotation.quaternion[3] == 0)
    throw InputError("state: the quaternion is zero");
  return p;
}

std::vector<Trajectory> SE3Motions::segment(const ob::State* s1, const ob::State* s2) const {
  MotionSegment seg;
  seg.t0 = 0;
  seg.t1 = 1;
  seg.from = pose(s1);
  seg.to = pose(s2);
  seg.interpolation = Interpolation::Slerp;
  require_interpolable(seg.from, seg.to, seg.interpolation);  // no shorter arc: InputError
  // Equal rotations: an exact translation (a rational motion).
  seg.rational = rational_keyframe_segment(seg.from, seg.to, seg.interpolation, seg.t0, seg.t1);
  return {Trajectory{{seg}}};
}

std::optional<std::vector<Mat34E>> SE3Motions::exact_poses(const ob::State* s) const {
  const std::optional<Mat34E> m = exact_pose(pose(s));
  if (!m) return std::nullopt;
  return std::vector<Mat34E>{*m};
}

// ---------------------------------------------------------------- validator

CertifiedMotionValidator::CertifiedMotionValidator(const ob::SpaceInformationPtr& si,
                                                   std::shared_ptr<const api::Environment> environment,
                                                   std::shared_ptr<const StateMotions> motions)
    : ob::MotionValidator(si),
      environment_(environment ? std::move(environment)
                               : throw InputError("CertifiedMotionValidator: environment and motions are required")),
      pool_(pool_of(*environment_)),
      motions_(std::move(motions)) {
  if (!motions_) throw InputError("CertifiedMotionValidator: environment and motions are required");
}

EdgeCertificate CertifiedMotionValidator::certify(const ob::State* s1, const ob::State* s2) const {
  return run(s1, s2, false);
}

EdgeCertificate CertifiedMotionValidator::decide(const ob::State* s1, const ob::State* s2) const {
  return run(s1, s2, true);
}

EdgeCertificate CertifiedMotionValidator::run(const ob::State* s1, const ob::State* s2, bool decide) const {
  EdgeCertificate out;
  auto not_certified = [&](const std::string& why) {
    out.problem = why;
    out.check = MotionCheck{};
    out.check.verdict = Verdict::Undecided;
    out.check.safe_until = Exact(0);
  };
  // Whatever goes wrong is "not certified", never "safe".
  try {
    const std::vector<Trajectory> motions = motions_->segment(s1, s2);
    out.check = pool_.check(motions, decide);
  } catch (const std::exception& e) {
    not_certified(e.what());
  } catch (...) {
    not_certified("unknown exception");
  }
  return out;
}

EdgeCertificate CertifiedMotionValidator::certify_state(const ob::State* s) const {
  try {
    // (With a URDF cylinder or sphere the static test sees its polyhedron:
    // the search below proves a collision on the true shape instead.)
    const std::optional<std::vector<Mat34E>> poses =
        pool_.has_primitives() ? std::nullopt : motions_->exact_poses(s);
    if (poses) {
      EdgeCertificate out;
      if (auto w = pool_.static_contact(*poses)) {
        out.check.verdict = Verdict::Collision;
        out.check.safe_until = Exact(0);
        out.check.first_contact = std::pair{Exact(0), Exact(0)};
        out.check.witness = std::move(w);
      }
      return out;
    }
  } catch (const std::exception& e) {
    EdgeCertificate out;
    out.problem = e.what();
    out.check.verdict = Verdict::Undecided;
    out.check.safe_until = Exact(0);
    return out;
  }
  return certify(s, s);
}

bool CertifiedMotionValidator::checkMotion(const ob::State* s1, const ob::State* s2) const {
  // Only "safe or not" is asked: decided at the first proof of contact.
  const bool ok = decide(s1, s2).check.verdict == Verdict::Safe;
  if (ok) ++valid_;
  else ++invalid_;
  return ok;
}

bool CertifiedMotionValidator::checkMotion(const ob::State* s1, const ob::State* s2,
                                           std::pair<ob::State*, double>& lastValid) const {
  const EdgeCertificate edge = certify(s1, s2);
  if (edge.check.verdict == Verdict::Safe) {
    ++valid_;
    return true;
  }
  ++invalid_;
  // [0, safe_until) is certified free.  The largest double strictly below
  // safe_until is a fraction inside it; OMPL interpolates its state in
  // doubles, off the certified curve by rounding, so the shorter segment
  // from s1 to that state is certified again; halve the fraction until
  // one certifies (at most a few times: the next tries are far from the
  // contact).
  const Exact until = edge.check.safe_until ? *edge.check.safe_until : Exact(0);
  double f = CGAL::to_double(until);
  while (f > 0 && !(Exact(f) < until)) f = std::nextafter(f, 0.0);
  f = std::min(f, 1.0);
  ob::State* candidate = si_->allocState();
  constexpr int kTries = 6;
  for (int k = 0; k < kTries && f > 0; ++k, f /= 2) {
    si_->getStateSpace()->interpolate(s1, s2, f, candidate);
    if (certify(s1, candidate).check.verdict == Verdict::Safe) {
      if (lastValid.first) si_->copyState(lastValid.first, candidate);
      lastValid.second = f;
      si_->freeState(candidate);
      return false;
    }
  }
  si_->freeState(candidate);
  if (lastValid.first) si_->copyState(lastValid.first, s1);
  lastValid.second = 0;
  return false;
}

CertifiedStateValidityChecker::CertifiedStateValidityChecker(const ob::SpaceInformationPtr& si,
                                                             std::shared_ptr<const CertifiedMotionValidator> validator)
    : ob::StateValidityChecker(si), validator_(std::move(validator)) {
  if (!validator_) throw InputError("CertifiedStateValidityChecker: a validator is required");
}

bool CertifiedStateValidityChecker::isValid(const ob::State* s) const {
  return validator_->certify_state(s).check.verdict == Verdict::Safe;
}

std::shared_ptr<CertifiedMotionValidator> use_certified_se3(const ob::SpaceInformationPtr& si, Body robot,
                                                            Body obstacles, const VerifyOptions& options) {
  if (!std::dynamic_pointer_cast<ob::SE3StateSpace>(si->getStateSpace()))
    throw InputError("use_certified_se3: the state space is not an ompl::base::SE3StateSpace");
  auto environment = shared_environment(std::move(obstacles), std::vector<Body>{std::move(robot)},
                                        std::vector<std::pair<int, int>>{}, options);
  auto validator = std::make_shared<CertifiedMotionValidator>(si, environment, std::make_shared<const SE3Motions>());
  si->setStateValidityChecker(std::make_shared<CertifiedStateValidityChecker>(si, validator));
  si->setMotionValidator(validator);
  return validator;
}

}  // namespace tmcert
