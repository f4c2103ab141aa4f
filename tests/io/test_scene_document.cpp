// src/io/scene_document.h: a document held as a JSON value reads as its
// text does: the same scene, the same messages.
#include "src/io/scene_document.h"

#include <boost/test/unit_test.hpp>
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace {

using Json = nlohmann::ordered_json;

Json two_bodies() {
  Json doc = Json::object();
  doc["format"] = "tmcert-scene/1";
  doc["epsilon"] = "1/100";
  doc["bodies"] = Json::array(
      {Json{{"name", "wall"}, {"polygons", Json::array({Json::array({Json::array({"3/2", -1, -1}),
                                                                     Json::array({"3/2", 1, -1}),
                                                                     Json::array({"3/2", 0, 1})})})}},
       Json{{"name", "p"}, {"points", Json::array({Json::array({0, 0, 0})})}}});
  return doc;
}

std::string message_of(const Json& doc, bool as_text) {
  try {
    std::vector<tmcert::SceneRobot> robots;
    if (as_text) tmcert::parse_scene_text(doc.dump(1), "doc", "", robots);
    else tmcert::parse_scene_document(doc, "doc", "", robots);
  } catch (const tmcert::InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

BOOST_AUTO_TEST_SUITE(scene_document)

BOOST_AUTO_TEST_CASE(a_value_reads_as_its_text) {
  const Json doc = two_bodies();
  std::vector<tmcert::SceneRobot> r1, r2;
  const tmcert::Scene a = tmcert::parse_scene_document(doc, "doc", "", r1);
  const tmcert::Scene b = tmcert::parse_scene_text(doc.dump(1), "doc", "", r2);
  BOOST_REQUIRE(a.bodies.size() == 2u);
  BOOST_REQUIRE(b.bodies.size() == 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    BOOST_TEST(a.bodies[i].name == b.bodies[i].name);
    BOOST_TEST((a.bodies[i].polygons == b.bodies[i].polygons));
    BOOST_TEST((a.bodies[i].points == b.bodies[i].points));
  }
  BOOST_TEST((a.epsilon == b.epsilon));
  BOOST_TEST((a.checks == b.checks));

  Json bad = doc;
  bad["bodies"][1]["points"][0][2] = "1/0";
  BOOST_TEST(!message_of(bad, false).empty());
  BOOST_TEST(message_of(bad, false) == message_of(bad, true));
  bad = doc;
  bad["bodies"][0]["name"] = "p";
  BOOST_TEST(message_of(bad, false).find("duplicate body name") != std::string::npos);
  BOOST_TEST(message_of(bad, false) == message_of(bad, true));
}

BOOST_AUTO_TEST_SUITE_END()
