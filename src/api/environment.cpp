// Environment (include/tmcert/environment.h): obstacles and movers
// prepared once (src/verify/fixed_environment.h) in a pool of copies
// (src/api/shared_environment.h), motions certified against them from any
// number of threads; the certified OMPL validator (src/ompl/) certifies its
// edges through the same pool.  The obstacles' rules and the
// options are the OMPL adapter's (src/ompl/public_ompl.cpp uses the
// helpers here), in each one's words.
#include "kernels/vec3.h"
#include "src/io/parse.h"
#include "src/verify/fixed_environment.h"
#include "src/verify/options.h"
#include "src/api/shared_environment.h"

#include "src/api/internal.h"
#include "tmcert/environment.h"

#include <mutex>
#include <vector>

namespace tmcert::api {

namespace {

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
    const auto at = [&](const tmcert::Vec3E& x) { return posed ? tmcert::vec3::apply(pose, x) : x; };  // exactly
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

// An Environment is its pool of prepared copies.
struct Environment::Impl {
  Impl(tmcert::Body obstacles, std::vector<tmcert::Body> movers, std::vector<std::pair<int, int>> pairs,
       const tmcert::VerifyOptions& options)
      : pool(std::move(obstacles), std::move(movers), std::move(pairs), options) {}
  tmcert::EnvironmentPool pool;
};

}  // namespace tmcert::api

const tmcert::EnvironmentPool& tmcert::pool_of(const tmcert::api::Environment& environment) {
  return environment.impl().pool;
}

std::shared_ptr<const tmcert::api::Environment> tmcert::shared_environment(
    tmcert::Body obstacles, std::vector<tmcert::Body> movers, std::vector<std::pair<int, int>> mover_pairs,
    const tmcert::VerifyOptions& options) {
  return std::make_shared<const tmcert::api::Environment>(std::make_unique<tmcert::api::Environment::Impl>(
      std::move(obstacles), std::move(movers), std::move(mover_pairs), options));
}

namespace tmcert::api {

// ---------------------------------------------------------------- Environment

Environment::Environment(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

Environment::Environment(const Scene& scene, const std::string& moving_body, const VerifyOptions& options) {
  impl_ = public_errors([&] {
    const tmcert::Scene& s = *scene.impl().scene;
    require_no_clearance(s, kEnvironment);
    const MoverAndObstacles split = split_mover(s, moving_body, kEnvironment);
    return std::make_unique<Impl>(obstacle_body(s, split.obstacles, kEnvironment),
                                  std::vector<tmcert::Body>{s.bodies[split.mover]}, std::vector<std::pair<int, int>>{},
                                  environment_options(s, options, kEnvironment));
  });
}

Environment::~Environment() = default;
Environment::Environment(Environment&&) noexcept = default;
Environment& Environment::operator=(Environment&&) noexcept = default;

std::size_t Environment::prepared_copies() const { return impl_->pool.copies(); }

MotionResult Environment::certify(const Motion& motion, const CertifyOptions& certify_options) const {
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
    const tmcert::MotionCheck check = impl_->pool.check({trajectory}, certify_options.decide);
    MotionResult out;
    out.verdict = static_cast<Verdict>(static_cast<int>(check.verdict));  // same order (src/api/verify.cpp)
    if (check.safe_until) out.safe_until = to_rational(*check.safe_until);
    if (check.first_contact)
      out.first_contact = std::array{to_rational(check.first_contact->first), to_rational(check.first_contact->second)};
    if (check.witness) {
      const std::vector<tmcert::Body>& bodies = impl_->pool.labels();  // 0 the obstacles, 1 the moving body
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
