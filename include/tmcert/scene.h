// An immutable, validated scene: bodies with exact geometry and motions,
// and the body pairs to check.  Made by SceneBuilder (in code), or read from
// a tmcert-scene/1 document (docs/scene-format.md).
#pragma once

#include "tmcert/export.h"
#include "tmcert/numbers.h"

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace tmcert::api {

class TMCERT_API Scene {
 public:
  // Reads and validates a scene file; mesh and URDF files are relative to
  // its directory.  Throws InputError naming the file and the JSON path.
  static Scene from_file(const std::string& path);
  // The same, with folders searched for package:// URIs before the scene's
  // "package_paths" and ROS_PACKAGE_PATH (`tmcert verify --package-path`).
  static Scene from_file(const std::string& path, const std::vector<std::string>& package_paths);
  // The same for a document in memory.  `source` names it in messages;
  // mesh and URDF files are relative to the directory of `source` when it
  // names an existing file, otherwise to the current directory.
  static Scene from_json(const std::string& text, const std::string& source = "<json>");

  // Body names in scene order (robot links as "<robot>/<link>").
  std::vector<std::string> body_names() const;
  std::size_t body_count() const;
  // Does the body move (has a motion over a parameter interval)?
  // `body` is an index into body_names(); throws std::out_of_range.
  bool moves(std::size_t body) const;
  // The pairs verify() checks, by name, in order (explicit, or the default:
  // every moving body against every other body, robot rules).
  std::vector<std::pair<std::string, std::string>> checks() const;
  // The scene's epsilon as written (none: the default applies).
  std::optional<Rational> epsilon() const;
  // The epsilon a check of bodies `a` and `b` (names) uses when neither the
  // scene nor VerifyOptions gives one: 1/1000 of the diagonal of the box of
  // everything the two bodies sweep, to six significant digits.  Throws
  // std::out_of_range for an unknown name.
  Rational default_epsilon(const std::string& a, const std::string& b) const;
  int max_depth() const;
  // The file name, "SceneBuilder", or the source given to from_json.
  const std::string& source() const;
  // What the reader did to data from real pipelines (docs/scene-format.md,
  // "Data from real pipelines"): mesh faces not exactly planar split into
  // fans, zero-area faces read as segments (notes); input read in a way
  // that may not be meant, such as an rpy angle above 2 pi read as radians
  // (warnings).  One line each, naming the file and the field; also in
  // Result::notes() and Result::warnings().
  const std::vector<std::string>& notes() const;
  const std::vector<std::string>& warnings() const;

  // Internal (src/api/): the validated scene.
  struct Impl;
  explicit Scene(std::shared_ptr<const Impl> impl);
  const Impl& impl() const { return *impl_; }

 private:
  std::shared_ptr<const Impl> impl_;  // shared: copies are cheap and immutable
};

}  // namespace tmcert::api

namespace tmcert {
using namespace api;
}
