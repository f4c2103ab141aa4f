// What certificates (tmcert-certificate/2, docs/certificate-format.md)
// cover: the one rule the writer and the checker share.
#pragma once

#include "src/model/model.h"

#include <string>
#include <utility>

namespace tmcert::certificate {

// The check's parameter interval (docs/certificate-format.md).
std::pair<Exact, Exact> check_interval(const Body& a, const Body& b);

// Why certificates (tmcert-certificate/2) cannot cover this scene: keyframe
// and piecewise motions, tolerances and clearances are not part of the
// format; empty when they can.  Both the writer and the checker refuse such
// scenes (bad input, exit 3) rather than certify a motion they do not model.
std::string uncertifiable(const Scene& scene);

}  // namespace tmcert::certificate
