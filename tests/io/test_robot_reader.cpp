// The scene reader's robots (src/io/robot_reader.cpp): joint-path values
// read exactly, package folders relative to the scene, a robot placed from
// a committed URDF with its link bodies and default checks, and the
// messages that name the field.
#include "src/io/scene_reader.h"

#include <boost/test/unit_test.hpp>

#include <string>

using tmcert::Exact;
using tmcert::InputError;
namespace reader = tmcert::reader;

BOOST_AUTO_TEST_SUITE(robot_reader)

BOOST_AUTO_TEST_CASE(joint_path_values_are_exact) {
  const reader::Tree tree = reader::parse_json(R"({"times": [0, "1/3"], "positions": [[0.1, 0], [1, 2]]})", "r.json");
  const reader::SceneReader r("r.json", "", tree);
  tmcert::JointPath jp;
  r.joint_path_values(tree.root, reader::Path().member("path"), jp);
  BOOST_REQUIRE(jp.times.size() == 2u);
  BOOST_TEST(jp.times[1] == Exact(1) / Exact(3));
  BOOST_REQUIRE(jp.positions.size() == 2u);
  BOOST_TEST(jp.positions[0][0] == Exact(1) / Exact(10));
  const reader::Tree bad = reader::parse_json(R"({"times": [0, 1]})", "r.json");
  try {
    reader::SceneReader("r.json", "", bad).joint_path_values(bad.root, reader::Path().member("path"), jp);
    BOOST_FAIL("no error");
  } catch (const InputError& e) {
    BOOST_TEST(std::string(e.what()) == "r.json: path.positions: missing required field");
  }
}

BOOST_AUTO_TEST_CASE(package_paths_are_relative_to_the_scene_and_come_after_the_given_ones) {
  const reader::Tree tree = reader::parse_json(R"(["pkgs", "more"])", "r.json");
  tmcert::ReadOptions options;
  options.package_paths = {"/given"};
  reader::SceneReader r("r.json", "/scenes", tree, options);
  r.package_paths(tree.root, reader::Path().member("package_paths"));
  const tmcert::UrdfOptions urdf = r.urdf_options();
  BOOST_REQUIRE(urdf.package_paths.size() >= 3u);
  BOOST_TEST(urdf.package_paths[0] == "/given");
  BOOST_TEST(urdf.package_paths[1] == "/scenes/pkgs");
  BOOST_TEST(urdf.package_paths[2] == "/scenes/more");
}

BOOST_AUTO_TEST_CASE(robot_links_become_bodies_with_default_checks) {
  const std::string data = TMCERT_TEST_DATA;
  const reader::Tree tree = reader::parse_json(
      R"([{"name": "arm", "urdf": "chain.urdf", "joints": ["j1", "j2", "j3", "j4"],
           "path": {"times": [0, 1], "positions": [[0, 0, 0, 0], [0.1, 0, 0, 0]]}, "self_collision": true}])",
      "r.json");
  const reader::SceneReader r("r.json", data + "/robots", tree);
  tmcert::Scene scene;
  std::unordered_map<std::string, std::size_t> names;
  const auto robots = r.robots(scene, tree.root, reader::Path().member("robots"), names);
  BOOST_REQUIRE(robots.size() == 1u);
  BOOST_TEST(robots[0].joints.size() == 4u);
  BOOST_TEST(robots[0].self_collision);
  BOOST_TEST(scene.bodies.size() >= 6u);  // every link has collision geometry
  for (const tmcert::Body& b : scene.bodies) BOOST_TEST(b.name.rfind("arm/", 0) == 0);
  BOOST_TEST(names.size() == scene.bodies.size());
  BOOST_TEST(!reader::SceneReader::default_checks_with_robots(scene, 0, robots).empty());  // self-collision pairs
  // Without robots the default checks are the general rule.
  tmcert::Scene plain;
  plain.bodies.resize(3);
  plain.bodies[1].motion = tmcert::Motion{};
  BOOST_TEST((reader::SceneReader::default_checks_with_robots(plain, 3, {}) ==
              std::vector<std::pair<int, int>>{{0, 1}, {1, 2}}));
  BOOST_TEST((reader::SceneReader::default_checks(plain) == reader::SceneReader::default_checks_with_robots(plain, 3, {})));
}

BOOST_AUTO_TEST_CASE(unknown_robot_fields_and_files_are_named) {
  const reader::Tree tree = reader::parse_json(R"([{"name": "arm", "urdf": "missing.urdf", "joints": [],
                                                    "path": {"times": [0], "positions": [[]]}}])",
                                               "r.json");
  const reader::SceneReader r("r.json", "/nonexistent-folder", tree);
  tmcert::Scene scene;
  std::unordered_map<std::string, std::size_t> names;
  try {
    r.robots(scene, tree.root, reader::Path().member("robots"), names);
    BOOST_FAIL("no error");
  } catch (const InputError& e) {
    BOOST_TEST(std::string(e.what()).rfind("r.json: robots[0].urdf: ", 0) == 0);
  }
}

BOOST_AUTO_TEST_SUITE_END()
