// The scene reader's JSON tree with exact numbers (src/io/json_tree.cpp):
// the tree's layout, JSON paths, exact number tokens beyond the doubles,
// the typed reading of JsonReader and its messages.
#include "src/io/json_tree.h"

#include <boost/test/unit_test.hpp>
#include <nlohmann/json.hpp>

#include <string>

using tmcert::Exact;
using tmcert::InputError;
namespace reader = tmcert::reader;

namespace {

Exact q(const char* text) {
  Exact value;
  BOOST_REQUIRE(tmcert::parse_exact(text, value));
  return value;
}

// The message of the InputError that `f` throws, or "" if none.
template <typename F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// Two trees are the same: the same nodes, keys and text.
void same_tree(const reader::Tree& a, const reader::Tree& b) {
  auto same_node = [](const reader::Node& x, const reader::Node& y) {
    return x.kind == y.kind && x.boolean == y.boolean && x.size == y.size && x.first == y.first &&
           x.first_key == y.first_key && x.text == y.text && x.text_size == y.text_size;
  };
  BOOST_TEST(same_node(a.root, b.root));
  BOOST_REQUIRE(a.nodes.size() == b.nodes.size());
  for (std::size_t i = 0; i < a.nodes.size(); ++i) BOOST_TEST(same_node(a.nodes[i], b.nodes[i]), "node " << i);
  BOOST_TEST(a.keys == b.keys, boost::test_tools::per_element());
  BOOST_TEST(a.text == b.text);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(json_tree)

// SceneBuilder's documents are read from their JSON value (tree_of): the
// tree, and every limit's message, are those of parsing the value's text.
BOOST_AUTO_TEST_CASE(tree_of_a_value_is_the_tree_of_its_text) {
  using Json = nlohmann::ordered_json;
  Json doc = Json::object();
  doc["format"] = "tmcert-scene/1";
  doc["max_depth"] = 12;
  doc["big"] = std::uint64_t{18446744073709551615u};
  doc["neg"] = -3;
  doc["flag"] = true;
  doc["none"] = nullptr;
  // Strings that start with the number or string mark stay strings.
  doc["names"] = Json::array({"0.1", std::string("\x01") + "1e400", std::string("\x02") + "x", "", "caf\xc3\xa9"});
  doc[std::string("\x01") + "key"] = Json::array({Json::array(), Json::object()});
  same_tree(reader::tree_of(doc, "doc"), reader::parse_json(doc.dump(1), "doc"));

  // Nesting beyond the limit: the same message, naming the same path.
  Json deep = Json::array();
  for (std::size_t k = 0; k < reader::kMaxNesting + 2; ++k) deep = Json{{"pieces", Json::array({deep})}};
  const std::string from_value = error_of([&] { reader::tree_of(deep, "SceneBuilder"); });
  BOOST_TEST(from_value.find("nesting deeper than") != std::string::npos);
  BOOST_TEST(from_value == error_of([&] { reader::parse_json(deep.dump(), "SceneBuilder"); }));

  // Not UTF-8: nlohmann's type_error, as dump() throws it.
  BOOST_CHECK_THROW(reader::tree_of(Json{{"name", "\xff"}}, "doc"), nlohmann::json::type_error);
}

BOOST_AUTO_TEST_CASE(tree_keeps_number_text_and_keys_side_by_side) {
  const reader::Tree tree = reader::parse_json(R"({"a": [0.1, 2, "x"], "b": {"c": null}})", "t.json");
  BOOST_TEST((tree.root.kind == reader::Node::Kind::Object));
  BOOST_TEST(tree.root.size == 2u);
  BOOST_TEST(tree.keys[tree.root.first_key] == "a");
  BOOST_TEST(tree.keys[tree.root.first_key + 1] == "b");
  const reader::Node& a = tree.nodes[tree.root.first];
  BOOST_TEST((a.kind == reader::Node::Kind::Array));
  BOOST_TEST(a.size == 3u);
  BOOST_TEST(tree.text_of(tree.nodes[a.first]) == "0.1");  // as written, not a double
  BOOST_TEST(tree.text_of(tree.nodes[a.first + 1]) == "2");
  BOOST_TEST((tree.nodes[a.first + 2].kind == reader::Node::Kind::String));
}

BOOST_AUTO_TEST_CASE(paths_are_spelled_for_messages) {
  const reader::Path doc;
  BOOST_TEST(doc.str().empty());
  const reader::Path bodies = doc.member("bodies");
  const reader::Path first = bodies.index(1);
  BOOST_TEST(first.member("motion").member("weights").index(2).str() == "bodies[1].motion.weights[2]");
  BOOST_TEST(doc.member("odd key").str() == "[\"odd key\"]");
  BOOST_TEST(reader::located("s.json", "", "bad") == "s.json: document: bad");
  BOOST_TEST(reader::one_line("a\nb\tc") == "a b c");
}

BOOST_AUTO_TEST_CASE(overflowing_number_tokens_stay_exact_numbers) {
  std::string out;
  BOOST_TEST(!reader::quote_overflowing_numbers(R"({"a": 1e300})", out));
  BOOST_TEST(out.empty());
  BOOST_TEST(reader::quote_overflowing_numbers(R"({"a": 1e400})", out));
  const reader::Tree tree = reader::parse_json(R"({"a": 1e400, "b": "\u0001x"})", "t.json");
  const reader::Node& a = tree.nodes[tree.root.first];
  BOOST_TEST((a.kind == reader::Node::Kind::Number));
  BOOST_TEST(tree.text_of(a) == "1e400");
  const reader::Node& b = tree.nodes[tree.root.first + 1];
  BOOST_TEST((b.kind == reader::Node::Kind::String));  // a document's own string stays a string
  BOOST_TEST(tree.text_of(b) == std::string("\x01x"));
}

BOOST_AUTO_TEST_CASE(parse_errors_name_the_byte_or_the_path) {
  BOOST_TEST(error_of([] { reader::parse_json("{\"a\": [1, 2,]}", "t.json"); }).rfind("t.json: invalid JSON at byte ", 0) == 0);
  BOOST_TEST(error_of([] { reader::parse_json(R"({"a": {"k": 1, "k": 2}})", "t.json"); }) ==
             "t.json: a.k: duplicate key \"k\"");
  std::string deep;
  for (int i = 0; i < 70; ++i) deep += "[";
  BOOST_TEST(error_of([&] { reader::parse_json(deep, "t.json"); }).find("nesting deeper than 64 levels") !=
             std::string::npos);
}

BOOST_AUTO_TEST_CASE(typed_reading_is_exact_and_names_the_path) {
  const reader::Tree tree =
      reader::parse_json(R"({"n": "1/3", "p": [1, 0.5, "-2"], "m": [[1,0,0,1],[0,1,0,2],[0,0,1,3]],
                            "w": [1, 0], "s": "x", "id": {"k": [1.50, true, null]}})",
                         "t.json");
  const reader::JsonReader r("t.json", tree);
  const reader::Path doc;
  const reader::JsonReader::Members obj = r.object(tree.root, doc);
  BOOST_TEST(r.number(*r.find(obj, "n"), doc.member("n")) == q("1/3"));
  const tmcert::Vec3E p = r.point(*r.find(obj, "p"), doc.member("p"));
  BOOST_TEST(p[1] == q("1/2"));
  BOOST_TEST(p[2] == q("-2"));
  const tmcert::Mat34E m = r.affine(*r.find(obj, "m"), doc.member("m"));
  BOOST_TEST(m[11] == q("3"));
  BOOST_TEST(error_of([&] { r.positive_weights(*r.find(obj, "w"), doc.member("w"), 2, "point"); }) ==
             "t.json: w[1]: weight must be positive");
  BOOST_TEST(error_of([&] { r.number(*r.find(obj, "s"), doc.member("s")); }) ==
             "t.json: s: not a number: \"x\" (expected an integer, \"p/q\" with q > 0, or a decimal)");
  BOOST_TEST(error_of([&] { r.point(*r.find(obj, "m"), doc.member("m")); }) ==
             "t.json: m[0]: expected a number, got an array");
  BOOST_TEST(error_of([&] { r.reject_unknown_keys(obj, doc, {"n", "p", "m", "w", "s"}); }) ==
             "t.json: id: unknown field \"id\"");
  BOOST_TEST(r.compact(*r.find(obj, "id")) == R"({"k":[1.50,true,null]})");  // numbers as written
  BOOST_TEST(r.describe(*r.find(obj, "s")) == "\"x\"");
  BOOST_TEST(r.describe(*r.find(obj, "w")) == "(an array)");
}

BOOST_AUTO_TEST_SUITE_END()
