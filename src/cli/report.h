// Printing results: the tmcert-result/1 JSON document and a human summary.
#pragma once

#include "src/verify/verify.h"

#include <string>

namespace tmcert {

std::string result_json(const Scene& scene, const SceneResult& result);
std::string result_summary(const Scene& scene, const SceneResult& result);

}  // namespace tmcert
