// Reading tmcert-scene/1 documents (SCENE_FORMAT.md) into the exact model.
#pragma once

#include "src/scene/model.h"
#include "src/scene/solid.h"

#include <string>
#include <utility>
#include <vector>

namespace tmcert {

// Reads and validates a scene file.  Every number is read exactly from its
// JSON text.  Throws InputError with a one-line message naming the file and
// the JSON path (e.g. "scene.json: bodies[1].motion.weights[2]: weight must
// be positive") on any malformed input.
Scene parse_scene_file(const std::string& path);

// A user string made safe for a one-line message: quoted, control
// characters escaped, strings longer than 60 characters shortened.
std::string quote_text(const std::string& s);

// Validates one polygon as the scene reader does (planar, simple, at least
// 3 non-collinear vertices) and returns its cleaned vertices and its convex
// pieces, tagged with polygon index `index`.  Throws InputError without a
// location.
std::pair<std::vector<Vec3E>, std::vector<ConvexPiece>> split_scene_polygon(const std::vector<Vec3E>& vertices,
                                                                            int index);

// The same for a document held in memory; `source` names it in messages.
Scene parse_scene_text(const std::string& text, const std::string& source);

}  // namespace tmcert
