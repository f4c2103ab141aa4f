// Environment (include/tmcert/environment.h): obstacles and a moving body
// prepared once (src/verify/fixed_environment.h), motions certified
// against them from any number of threads.  The obstacles' rules and the
// options are the OMPL adapter's (src/ompl/public_ompl.cpp uses the
// helpers here), in each one's words.
#include "src/io/parse.h"
#include "src/verify/fixed_environment.h"
#include "src/verify/options.h"

#include "src/api/internal.h"
#include "tmcert/environment.h"

#include <mutex>
#include <vector>

namespace tmcert::api {

namespace {

// A fixed body's geometry placed by its one-pose motion, if any (x -> A x + a
// for the control point [A | a]), exactly.
tmcert::Vec3E placed(const tmcert::Mat34E& m, const tmcert::Vec3E& x) {
  tmcert::Vec3E out;
  for (int r = 0; r < 3; ++r) out[r] = m[4 * r] * x[0] + m[4 * r + 1] * x[1] + m[4 * r + 2] * x[2] + m[4 * r + 3];
  return out;
}

const ObstacleWords kEnvironment{"an Environment", "an Environment", "every body but the moving one",
                                 "an Environment certifies motions only with a certified kernel"};

}  // namespace

tmcert::Body obstacle_body(const tmcert::Scene& scene, const std::vector<std::size_t>& indices,
                           const ObstacleWords& words) {
  tmcert::Body out;
  out.name = "obstacles";
  const auto field = [&](std::size_t i) {
    return scene.source + ": bodies[" + std::to_string(i) + "] (" + tmcert::quote_text(scene.bodies[i].name) + ")";
  };
  const std::string must_be_fixed =
      std::string(".motion: the obstacles of ") + words.scene + " must be fixed (" + words.obstacles + ")";
  for (std::size_t i : indices) {
    const tmcert::Body& b = scene.bodies[i];
    if (b.moves()) throw InputError(field(i) + must_be_fixed);
    if (b.tolerance != 0)
      throw InputError(field(i) + ".tolerance: tolerances are not supported by " + words.user);
    if (b.solid && indices.size() > 1)
      throw InputError(field(i) + ".solid: a solid obstacle must be the only obstacle of " + words.scene);
    if (b.primitive)  // its collisions must be proven on its true shape, in its own frame
      throw InputError(field(i) + ": a robot link's URDF cylinder or sphere cannot be an obstacle of " + words.scene);
    const bool posed = b.motion.has_value() || b.trajectory.has_value();
    if (b.trajectory)  // a one-pose trajectory does not occur (keyframes of one pose reduce to a motion)
      throw InputError(field(i) + must_be_fixed);
    const tmcert::Mat34E pose = posed ? b.motion->control_points.front() : tmcert::Mat34E{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
    const auto at = [&](const tmcert::Vec3E& x) { return posed ? placed(pose, x) : x; };
    const int offset = static_cast<int>(out.polygons.size());
    for (const auto& polygon : b.polygons) {
      std::vector<tmcert::Vec3E> p;
      for (const tmcert::Vec3E& x : polygon) p.push_back(at(x));
      out.polygons.push_back(std::move(p));
    }
    for (const tmcert::ConvexPiece& piece : b.pieces) {
      tmcert::ConvexPiece p{offset + piece.polygon, {}};
      for (const tmcert::Vec3E& x : piece.vertices) p.vertices.push_back(at(x));
      out.pieces.push_back(std::move(p));
    }
    for (const auto& s : b.segments) out.segments.push_back({at(s[0]), at(s[1])});
    for (const tmcert::Vec3E& x : b.points) out.points.push_back(at(x));
    for (std::size_t k = 0; k < b.mass.points.size(); ++k) {
      out.mass.points.push_back(at(b.mass.points[k]));
      out.mass.weights.push_back(b.mass.weights[k]);
    }
    out.solid = b.solid;
    out.enlarged.insert(out.enlarged.end(), b.enlarged.begin(), b.enlarged.end());
  }
  return out;
}

MoverAndObstacles split_mover(const tmcert::Scene& scene, const std::string& name, const ObstacleWords& words) {
  std::optional<std::size_t> mover;
  std::vector<std::size_t> obstacles;
  for (std::size_t i = 0; i < scene.bodies.size(); ++i)
    if (scene.bodies[i].name == name) mover = i;
    else obstacles.push_back(i);
  if (!mover) throw InputError(scene.source + ": bodies: no body named " + tmcert::quote_text(name));
  if (obstacles.empty())
    throw InputError(scene.source + ": bodies: no obstacle (" + std::string(words.obstacles) + " is one)");
  return {*mover, std::move(obstacles)};
}

void require_no_clearance(const tmcert::Scene& scene, const ObstacleWords& words) {
  const std::string not_supported = std::string(": not supported by ") + words.user;
  if (scene.clearance != 0) throw InputError(scene.source + ": clearance" + not_supported);
  for (std::size_t k = 0; k < scene.check_clearance.size(); ++k)
    if (scene.check_clearance[k] && *scene.check_clearance[k] != 0)
      throw InputError(scene.source + ": checks[" + std::to_string(k) + "].clearance" + not_supported);
}

tmcert::VerifyOptions environment_options(const tmcert::Scene& scene, const VerifyOptions& o, const ObstacleWords& words) {
  if (o.kernel == Kernel::Fast) throw InputError(std::string("kernel: the fast kernel is not certified; ") + words.fast);
  // Without an epsilon (or "auto"): the whole scene's default, refined
  // (one prepared environment serves every motion).
  tmcert::VerifyOptions options = internal_options(scene, o, tmcert::EpsilonScope::WholeScene);
  options.threads = 1;           // a motion is one search; callers run motions in their own threads
  options.record_cover = false;  // no certificates of motions
  return options;
}

// ---------------------------------------------------------------- Environment

struct Environment::Impl {
  tmcert::Body obstacles, mover;
  tmcert::VerifyOptions options;
  // Prepared copies not in use; certify() takes one (or prepares one when
  // none is free) and gives it back.
  mutable std::mutex mutex;
  mutable std::vector<std::unique_ptr<tmcert::FixedEnvironment>> idle;
  mutable std::size_t copies = 0;

  std::unique_ptr<tmcert::FixedEnvironment> prepare() const {
    return std::make_unique<tmcert::FixedEnvironment>(obstacles, std::vector<tmcert::Body>{mover},
                                                      std::vector<std::pair<int, int>>{}, options);
  }
  std::unique_ptr<tmcert::FixedEnvironment> take() const {
    {
      std::lock_guard<std::mutex> lock(mutex);
      if (!idle.empty()) {
        std::unique_ptr<tmcert::FixedEnvironment> e = std::move(idle.back());
        idle.pop_back();
        return e;
      }
    }
    std::unique_ptr<tmcert::FixedEnvironment> e = prepare();  // outside the lock: others go on
    std::lock_guard<std::mutex> lock(mutex);
    ++copies;
    return e;
  }
  void give_back(std::unique_ptr<tmcert::FixedEnvironment> e) const {
    std::lock_guard<std::mutex> lock(mutex);
    idle.push_back(std::move(e));
  }
};

Environment::Environment(const Scene& scene, const std::string& moving_body, const VerifyOptions& options) {
  impl_ = public_errors([&] {
    const tmcert::Scene& s = *scene.impl().scene;
    require_no_clearance(s, kEnvironment);
    const MoverAndObstacles split = split_mover(s, moving_body, kEnvironment);
    auto impl = std::make_unique<Impl>();
    impl->obstacles = obstacle_body(s, split.obstacles, kEnvironment);
    impl->mover = s.bodies[split.mover];
    impl->options = environment_options(s, options, kEnvironment);
    impl->idle.push_back(impl->prepare());  // the first copy, which also checks the bodies
    impl->copies = 1;
    return impl;
  });
}

Environment::~Environment() = default;
Environment::Environment(Environment&&) noexcept = default;
Environment& Environment::operator=(Environment&&) noexcept = default;

std::size_t Environment::prepared_copies() const {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  return impl_->copies;
}

MotionResult Environment::certify(const Motion& motion, const CertifyOptions&) const {
  return public_errors([&] {
    // The motion read as a batch request's (the scene reader's motion
    // objects, checks and messages: "Environment: motion...").
    tmcert::RequestLine request;
    tmcert::parse_request_line("{\"body\": \"moving\", \"motion\": " + motion_json(motion) + "}", "Environment", "",
                               request);
    tmcert::Trajectory trajectory;
    if (request.trajectory) {
      trajectory = *request.trajectory;
    } else if (request.motion) {
      tmcert::MotionSegment segment;
      segment.t0 = request.motion->t0;
      segment.t1 = request.motion->t1;
      segment.rational = *request.motion;
      trajectory.segments.push_back(std::move(segment));
    } else {
      throw InputError("Environment: motion: no motion");
    }
    // A prepared copy for this call alone, given back however the call ends.
    struct Lease {
      const Impl& impl;
      std::unique_ptr<tmcert::FixedEnvironment> prepared;
      ~Lease() { impl.give_back(std::move(prepared)); }
    } lease{*impl_, impl_->take()};
    const tmcert::MotionCheck check = lease.prepared->check({trajectory});
    MotionResult out;
    out.verdict = static_cast<Verdict>(static_cast<int>(check.verdict));  // same order (src/api/verify.cpp)
    if (check.safe_until) out.safe_until = to_rational(*check.safe_until);
    if (check.first_contact)
      out.first_contact = std::array{to_rational(check.first_contact->first), to_rational(check.first_contact->second)};
    if (check.witness) {
      const std::vector<tmcert::Body>& bodies = lease.prepared->bodies();  // 0 the obstacles, 1 the moving body
      for (const tmcert::CheckResult& c : check.checks)
        if (c.verdict == tmcert::Verdict::Collision) {
          out.bodies = {bodies[c.bodies[0]].name, bodies[c.bodies[1]].name};
          out.witness = public_witness(bodies, c, *check.witness);
          break;
        }
    }
    return out;
  });
}

}  // namespace tmcert::api
