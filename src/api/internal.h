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
#include "tmcert/numbers.h"
#include "tmcert/result.h"
#include "tmcert/scene.h"
#include "tmcert/verify.h"

#include <memory>
#include <new>
#include <string>
#include <utility>

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
