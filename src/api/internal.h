// What the public API (include/tmcert/) wraps: the internal scene and
// result behind Scene and Result, and the conversions between internal and
// public values.  Only src/api/*.cpp and the OMPL adapter
// (src/ompl/public_ompl.cpp) include this.
//
// Internal headers come first: the public headers put a using-directive
// for tmcert::api into namespace tmcert, after which an unqualified name
// such as Scene in internal code would be ambiguous.  Code here lives in
// tmcert::api, where an unqualified name finds the public type first;
// internal types are written tmcert::X.
#pragma once

#include "src/model/model.h"
#include "src/io/parse.h"
#include "src/verify/options.h"
#include "src/verify/verify.h"

#include "tmcert/errors.h"
#include "tmcert/motion.h"
#include "tmcert/numbers.h"
#include "tmcert/result.h"
#include "tmcert/scene.h"
#include "tmcert/verify.h"

#include <memory>
#include <new>
#include <string>
#include <utility>
#include <vector>

namespace tmcert::api {

struct Scene::Impl {
  std::shared_ptr<const tmcert::Scene> scene;
  std::vector<tmcert::SceneRobot> robots;  // its "robots" (for the OMPL adapter, src/ompl/public_ompl.cpp)
};

struct Result::Impl {
  std::shared_ptr<const tmcert::Scene> scene;
  tmcert::SceneResult internal;
  bool certificate = false;  // verified with VerifyOptions::certificate
  // The public view of `internal`.
  Rational epsilon;
  std::vector<CheckResult> checks;
};

// The exact value of q with its nearest double.
Rational to_rational(const tmcert::Exact& q);

// A witness as Result shows it; `bodies` are what c.bodies index.
Witness public_witness(const std::vector<tmcert::Body>& bodies, const tmcert::CheckResult& c, const tmcert::Witness& w);

// The public options as written (src/verify/options.h), the epsilon read
// in the library's words ("epsilon: ..."); the other rules are checked by
// check_options / build_options.
tmcert::WrittenOptions written_options(Kernel kernel, const std::optional<Number>& epsilon,
                                       std::optional<int> max_depth, std::optional<double> time_limit, int threads);

// The options of verify() for `scene` by the one rule set (build_options,
// the library's words): epsilon and max_depth default to the scene's
// (epsilon absent for PerCheck: each check's own default).
tmcert::VerifyOptions internal_options(const tmcert::Scene& scene, const VerifyOptions& o,
                                       tmcert::EpsilonScope scope = tmcert::EpsilonScope::PerCheck);

// The words of the refusals of an Environment or of the OMPL adapter
// (src/api/environment.cpp, src/ompl/public_ompl.cpp).
struct ObstacleWords {
  const char* scene;      // "an OMPL planning scene": the obstacles of <scene> must be fixed
  const char* user;       // "the OMPL validator": tolerances are not supported by <user>
  const char* obstacles;  // "every body but the robot"
  const char* fast;       // why the fast kernel is refused
};

// The obstacles (bodies `indices` of the scene) as one fixed body, each
// placed by its one-pose motion.  A body that moves, has a tolerance, is
// solid next to other obstacles (their union is then no longer the solid
// the containment test expects) or is a URDF cylinder or sphere is
// rejected, naming the body.
tmcert::Body obstacle_body(const tmcert::Scene& scene, const std::vector<std::size_t>& indices,
                           const ObstacleWords& words);

// The body named `name` and the others (the obstacles, in scene order);
// refused, naming the scene, when no body has the name or none is left.
struct MoverAndObstacles {
  std::size_t mover;
  std::vector<std::size_t> obstacles;
};
MoverAndObstacles split_mover(const tmcert::Scene& scene, const std::string& name, const ObstacleWords& words);

// The scene's clearances are not honoured against fixed obstacles: refused.
void require_no_clearance(const tmcert::Scene& scene, const ObstacleWords& words);

// The options of motions against prepared obstacles: the fast kernel
// refused, epsilon for the whole scene (EpsilonScope::WholeScene), one
// thread per motion, no certificates.
tmcert::VerifyOptions environment_options(const tmcert::Scene& scene, const VerifyOptions& o,
                                          const ObstacleWords& words);

// A motion as the tmcert-scene/1 object SceneBuilder writes
// (src/api/scene_builder.cpp).
std::string motion_json(const Motion& m);

// Runs f, turning the internal exceptions into the public ones (same
// messages).  std::bad_alloc and other standard exceptions pass through.
template <typename F>
auto public_errors(F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const tmcert::InputError& e) {
    throw InputError(e.what());
  } catch (const tmcert::ResourceLimit& e) {
    throw ResourceLimit(e.what());
  } catch (const tmcert::Cancelled& e) {
    throw Cancelled("cancelled by the progress callback");
  }
}

}  // namespace tmcert::api
