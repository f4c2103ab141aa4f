// The scene reader's JSON tree with exact numbers (internal to src/io/).
//
// The JSON text becomes a small tree of our own through nlohmann's SAX
// interface: unlike its DOM, SAX hands us the raw text of every number, so
// 0.1 stays the decimal 1/10 instead of the nearest double.  JsonReader
// reads typed values out of the tree (objects, arrays, exact numbers,
// points, affine maps); every error it throws names the JSON path of the
// offending value: "<source>: <path>: <what>".
#pragma once

#include "src/model/model.h"

#include <nlohmann/json_fwd.hpp>

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace tmcert {

// A user string made safe for a one-line message (declared in parse.h too).
std::string quote_text(const std::string& s);

namespace reader {

// Limits that turn absurd input into an InputError instead of exhausting
// memory or time.  A real scene is far below each of them.
constexpr std::size_t kMaxNesting = 64;         // scenes need 7 levels
constexpr std::size_t kMaxValues = 10'000'000;  // JSON values in a document

// Replaces line breaks and other control characters so a message stays on one line.
std::string one_line(std::string s);

// JSON paths in the style "bodies[1].motion.weights[2]".
std::string member_path(const std::string& parent, const std::string& key);
std::string index_path(const std::string& parent, std::size_t index);
// "<source>: <path>: <what>" ("document" for the empty path).
std::string located(const std::string& source, const std::string& path, const std::string& what);

// A JSON path kept as a chain of steps on the call stack (the document, its
// member "bodies", element 1 of that, ...) and spelled out by member_path
// and index_path only for a message: reading a scene passes one to every
// number it reads.  A step refers to the path it extends and must not
// outlive it: make steps as arguments, or as variables in the scope of
// the path they extend.
class Path {
 public:
  Path() = default;  // the document itself

  Path member(std::string_view key) const { return Path(this, key, 0, false); }
  Path index(std::size_t i) const { return Path(this, {}, i, true); }

  std::string str() const {
    if (!parent_) return {};
    const std::string parent = parent_->str();
    return is_index_ ? index_path(parent, index_) : member_path(parent, std::string(key_));
  }

 private:
  Path(const Path* parent, std::string_view key, std::size_t index, bool is_index)
      : parent_(parent), key_(key), index_(index), is_index_(is_index) {}

  const Path* parent_ = nullptr;  // null for the document
  std::string_view key_;          // a member's key
  std::size_t index_ = 0;         // an element's index
  bool is_index_ = false;
};

// A value of a Tree.  Counts and indices fit in 32 bits: a document has at
// most kMaxValues values.
struct Node {
  enum class Kind : std::uint8_t { Null, Boolean, Number, String, Array, Object };
  Kind kind = Kind::Null;
  bool boolean = false;
  std::uint32_t size = 0;       // a container's items are Tree::nodes[first, first + size)
  std::uint32_t first = 0;
  std::uint32_t first_key = 0;  // an object's keys are Tree::keys[first_key, first_key + size)
  std::size_t text = 0;         // a number as written, or a string's value:
  std::size_t text_size = 0;    // Tree::text[text, text + text_size)
};
static_assert(kMaxValues <= std::numeric_limits<std::uint32_t>::max());

// A whole document.  Every value but the root lives in one array, the items
// of each container next to each other; every object key in another,
// parallel to its object's items; and the text of every number and string
// in one string: a scene of many bodies has millions of small containers
// and numbers, which would otherwise each need an allocation.
struct Tree {
  Node root;
  std::vector<Node> nodes;
  std::vector<std::string> keys;
  std::string text;

  std::string_view text_of(const Node& node) const { return std::string_view(text).substr(node.text, node.text_size); }
};

// "null", "a boolean", "a number", ... for messages.
const char* kind_name(Node::Kind kind);

// A JSON number such as 1e400 (or a 400-digit integer) is valid JSON and
// means an exact rational, but nlohmann's reader converts every number to
// double on the way and stops at an overflow: such tokens are marked (see
// json_tree.cpp) so that they stay numbers with their exact text.  Returns
// false, leaving `out` alone, when nothing needs it.
bool quote_overflowing_numbers(const std::string& text, std::string& out);

// Parses a JSON document into a Tree.  Throws InputError "<source>:
// invalid JSON at byte N: ..." or "<source>: <path>: <what>" (duplicate
// key, nesting, value count, binary value, a number too large).
Tree parse_json(const std::string& text, const std::string& source);

// The tree of a document held as a JSON value (SceneBuilder's): the same
// tree, limits and messages as parse_json(value.dump(), source), without
// writing or parsing any text.  Numbers the value holds as integers keep
// their decimal text; strings stay strings (the reader reads numbers
// written as strings exactly).  A string that is not valid UTF-8 throws
// nlohmann's type_error, as dump() does.
Tree tree_of(const nlohmann::ordered_json& value, const std::string& source);

// Typed reading of a Tree; every error names the source and the JSON path.
class JsonReader {
 public:
  JsonReader(std::string source, const Tree& tree) : source_(std::move(source)), tree_(tree) {}

  // An object's keys and member values, side by side.
  struct Members {
    std::span<const std::string> keys;
    std::span<const Node> values;
  };

  [[noreturn]] void fail(const Path& path, const std::string& what) const;

  std::string_view text(const Node& node) const { return tree_.text_of(node); }

  // A value for a message: a string quoted, anything else by its kind.
  std::string describe(const Node& node) const;

  // A value as compact JSON, numbers exactly as written (an id echoed in
  // results: the same bytes for the same input).
  std::string compact(const Node& node) const;

  static const Node* find(const Members& object, std::string_view key) {
    for (std::size_t i = 0; i < object.keys.size(); ++i)
      if (object.keys[i] == key) return &object.values[i];
    return nullptr;
  }

  // Keys starting with "_" and "comment" are free for annotations.
  static bool is_annotation(const std::string& key) { return key == "comment" || (!key.empty() && key[0] == '_'); }

  void reject_unknown_keys(const Members& object, const Path& path, std::initializer_list<std::string_view> known) const;

  Members object(const Node& node, const Path& path) const;

  // An array's items.
  std::span<const Node> array(const Node& node, const Path& path) const;

  // A JSON number (exactly the decimal it spells) or a string holding an
  // integer, "p/q" or a decimal.
  Exact number(const Node& node, const Path& path) const;

  // A number >= 0.
  Exact non_negative(const Node& node, const Path& path) const;

  // [x, y, z], and a list of them.
  Vec3E point(const Node& node, const Path& path) const;
  std::vector<Vec3E> points(const Node& node, const Path& path) const;

  // A 3x4 affine matrix [A | a] written as 3 rows of 4 numbers.
  Mat34E affine(const Node& node, const Path& path) const;

  // `count` weights, each > 0 (one per point / control point).
  std::vector<Exact> positive_weights(const Node& node, const Path& path, std::size_t count,
                                      const std::string& per) const;

 protected:
  std::string source_;
  const Tree& tree_;
};

}  // namespace reader
}  // namespace tmcert
