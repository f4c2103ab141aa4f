// Printing results: the tmcert-result/1 JSON document and a human summary.
#pragma once

#include "src/verify/verify.h"

#include <string>

namespace tmcert {

std::string result_json(const Scene& scene, const SceneResult& result);
std::string result_summary(const Scene& scene, const SceneResult& result);
// One element of the result document's "checks" (its bodies index `scene`).
std::string check_json(const Scene& scene, const CheckResult& check);

}  // namespace tmcert
