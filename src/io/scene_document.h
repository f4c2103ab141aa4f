// A tmcert-scene/1 document held as a JSON value (SceneBuilder's,
// src/api/scene_builder.cpp), read without writing or parsing its text.
#pragma once

#include "src/io/parse.h"

#include <nlohmann/json_fwd.hpp>

#include <string>
#include <vector>

namespace tmcert {

// As parse_scene_text(document.dump(), source, base, robots): the same
// tree (src/io/json_tree.h tree_of), checks and messages.
Scene parse_scene_document(const nlohmann::ordered_json& document, const std::string& source, const std::string& base,
                           std::vector<SceneRobot>& robots);

}  // namespace tmcert
