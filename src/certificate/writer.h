// Writing certificates (docs/certificate-format.md): after a certified
// verification, every piece the search cleared is given a proof made of
// separating planes between the swept control points of groups of elements,
// found in double precision and confirmed with interval arithmetic on
// enclosures of the exact control points, or, for two elements no plane
// separates, an exact "no contact" claim (exact_claims.h); a piece whose
// proof fails is bisected.  The checker (check.h) re-verifies the document exactly.
#pragma once

#include "src/certificate/scope.h"
#include "src/model/model.h"
#include "src/verify/verify.h"

#include <cstddef>
#include <string>

namespace tmcert::certificate {

struct WriteStats {
  std::size_t pieces = 0;       // pieces written
  std::size_t separations = 0;  // separation claims written
  std::size_t exact_separations = 0;  // of which found in exact arithmetic (clearance below doubles)
  std::size_t exact_claims = 0;  // exact "no contact" claims (where no separating plane was found)
  std::size_t bisections = 0;   // cleared pieces that needed smaller pieces
  double seconds = 0;
};

// The tmcert-certificate/2 document of `result`, which verify_scene computed
// for `scene` with VerifyOptions::record_cover and a certified kernel.
// Throws InputError for a result of the fast kernel and ResourceLimit when a
// cleared piece cannot be proven within the bisection limit.
std::string certificate_json(const Scene& scene, const SceneResult& result, WriteStats* stats = nullptr);

}  // namespace tmcert::certificate
