// The scene reader's JSON tree with exact numbers (src/io/json_tree.h).
#include "src/io/json_tree.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <unordered_set>
#include <utility>

namespace tmcert {
namespace reader {

// Replaces line breaks and other control characters so a message stays on one line.
std::string one_line(std::string s) {
  for (char& c : s)
    if (static_cast<unsigned char>(c) < 0x20) c = ' ';
  return s;
}

static bool is_identifier(const std::string& key) {
  if (key.empty() || std::isdigit(static_cast<unsigned char>(key[0]))) return false;
  return std::all_of(key.begin(), key.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
  });
}

// JSON paths in the style "bodies[1].motion.weights[2]".
std::string member_path(const std::string& parent, const std::string& key) {
  if (is_identifier(key)) return parent.empty() ? key : parent + "." + key;
  return parent + "[" + quote_text(key) + "]";
}

std::string index_path(const std::string& parent, std::size_t index) {
  return parent + "[" + std::to_string(index) + "]";
}

std::string located(const std::string& source, const std::string& path, const std::string& what) {
  return source + ": " + (path.empty() ? std::string("document") : path) + ": " + what;
}

const char* kind_name(Node::Kind kind) {
  switch (kind) {
    case Node::Kind::Null: return "null";
    case Node::Kind::Boolean: return "a boolean";
    case Node::Kind::Number: return "a number";
    case Node::Kind::String: return "a string";
    case Node::Kind::Array: return "an array";
    case Node::Kind::Object: return "an object";
  }
  return "a value";
}

namespace {

// SAX handler building the tree iteratively (nlohmann's SAX parser keeps
// its own explicit stack, and so do we), so deep nesting cannot overflow
// the call stack.  On error a callback stores the message and returns false,
// which stops the parse.
//
// An open container waits on the stack, and its finished items and keys on
// shared lists, until it closes; then they move into the tree, side by side.
constexpr char kNumberMark = '\x01';
constexpr char kStringMark = '\x02';

class TreeBuilder {
 public:
  using json = nlohmann::json;

  explicit TreeBuilder(std::string source) : source_(std::move(source)) { stack_.reserve(kMaxNesting); }

  Tree& tree() { return tree_; }
  const std::string& error() const { return error_; }

  bool null() { return add(Node{}); }
  bool boolean(bool value) {
    Node node;
    node.kind = Node::Kind::Boolean;
    node.boolean = value;
    return add(std::move(node));
  }
  // Integers arrive as machine integers; their decimal text is exact.
  bool number_integer(json::number_integer_t value) { return add_text(Node::Kind::Number, std::to_string(value)); }
  bool number_unsigned(json::number_unsigned_t value) { return add_text(Node::Kind::Number, std::to_string(value)); }
  // Everything else (fractions, exponents, integers beyond 64 bits) comes
  // with the raw token; the double is ignored.
  bool number_float(json::number_float_t, const std::string& raw) {
    // The lexer writes the C locale's decimal point into the token; the JSON
    // grammar leaves no other character it could be.
    std::string text = raw;
    for (char& c : text)
      if (!std::isdigit(static_cast<unsigned char>(c)) && c != '-' && c != '+' && c != 'e' && c != 'E')
        c = '.';
    return add_text(Node::Kind::Number, text);
  }
  bool string(std::string& value) {
    // A number token too large for the reader's double, marked by
    // quote_overflowing_numbers: still a number, with its exact text.
    if (value.size() > 1 && value[0] == kNumberMark)
      return add_text(Node::Kind::Number, std::string_view(value).substr(1));
    // A string of the document that starts with either mark, carrying
    // kStringMark in front (quote_overflowing_numbers): its own text.
    if (!value.empty() && value[0] == kStringMark) value.erase(0, 1);
    return add_text(Node::Kind::String, value);
  }
  bool binary(json::binary_t&) { return fail(pending_path(), "binary values are not allowed"); }
  bool start_object(std::size_t) { return open(Node::Kind::Object); }
  bool start_array(std::size_t) { return open(Node::Kind::Array); }
  bool key(std::string& key) {
    if (!key.empty() && key[0] == kStringMark) key.erase(0, 1);  // as for strings
    Frame& frame = stack_.back();
    if (is_duplicate(frame, key))
      return fail(member_path(container_path(), key), "duplicate key " + quote_text(key));
    pending_keys_.push_back(key);
    return true;
  }
  bool end_object() { return close(); }
  bool end_array() { return close(); }

  bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception& ex) {
    if (ex.id == 406)  // the reader's double overflowed: the number is finite, but too big for it
      return fail(pending_path(), "number too large to read as a JSON number; "
                                  "write it as a string (e.g. \"1e400\") to keep it exact");
    std::string what = ex.what();
    const std::size_t bracket = what.find("] ");  // drop "[json.exception.parse_error.101] "
    if (what.rfind("[json.exception", 0) == 0 && bracket != std::string::npos) what.erase(0, bracket + 2);
    // nlohmann counts the offending character (or the end of input) as read.
    const std::size_t offset = position > 0 ? position - 1 : 0;
    error_ = source_ + ": invalid JSON at byte " + std::to_string(offset) + ": " + one_line(what);
    return false;
  }

 private:
  // Objects with this many keys or more find duplicates through a hash set
  // (so that a huge object cannot make the search quadratic); smaller ones,
  // nearly all of them, by looking through their keys.
  static constexpr std::size_t kKeysWithoutSet = 16;

  struct Frame {
    Node::Kind kind;                          // an open array or object
    std::size_t first = 0;                    // where its finished items start in pending_
    std::size_t first_key = 0;                // where its keys start in pending_keys_
    std::unordered_set<std::string> key_set;  // its keys, once it has kKeysWithoutSet of them
  };

  bool fail(const std::string& path, const std::string& what) {
    error_ = located(source_, path, what);
    return false;
  }

  // A number or a string, its text stored in the tree's.
  bool add_text(Node::Kind kind, std::string_view text) {
    if (!count_value()) return false;
    Node node;
    node.kind = kind;
    node.text = tree_.text.size();
    node.text_size = text.size();
    tree_.text += text;
    place(std::move(node));
    return true;
  }

  // Counts a value (finished, or a container just opened) against the limit.
  bool count_value() {
    if (++values_ <= kMaxValues) return true;
    return fail(pending_path(), "document has more than " + std::to_string(kMaxValues) + " values");
  }

  // Places a finished value into the open container (or as the root).
  void place(Node&& node) {
    if (stack_.empty())
      tree_.root = std::move(node);
    else
      pending_.push_back(std::move(node));
  }

  bool add(Node&& node) {
    if (!count_value()) return false;
    place(std::move(node));
    return true;
  }

  bool open(Node::Kind kind) {
    if (stack_.size() >= kMaxNesting)
      return fail(pending_path(), "nesting deeper than " + std::to_string(kMaxNesting) + " levels");
    if (!count_value()) return false;
    Frame frame;
    frame.kind = kind;
    frame.first = pending_.size();
    frame.first_key = pending_keys_.size();
    stack_.push_back(std::move(frame));
    return true;
  }

  // The container's items (and keys) move into the tree, next to each other.
  bool close() {
    const Frame& frame = stack_.back();
    Node node;
    node.kind = frame.kind;
    node.first = static_cast<std::uint32_t>(tree_.nodes.size());
    node.size = static_cast<std::uint32_t>(pending_.size() - frame.first);
    node.first_key = static_cast<std::uint32_t>(tree_.keys.size());
    move_tail(pending_, frame.first, tree_.nodes);
    move_tail(pending_keys_, frame.first_key, tree_.keys);
    stack_.pop_back();
    place(std::move(node));
    return true;
  }

  // Moves from[start, end) to the end of `to`.
  template <typename T>
  static void move_tail(std::vector<T>& from, std::size_t start, std::vector<T>& to) {
    const auto tail = from.begin() + static_cast<std::ptrdiff_t>(start);
    to.insert(to.end(), std::make_move_iterator(tail), std::make_move_iterator(from.end()));
    from.erase(tail, from.end());
  }

  bool is_duplicate(Frame& frame, const std::string& key) const {
    const auto keys = pending_keys_.begin() + static_cast<std::ptrdiff_t>(frame.first_key);
    if (pending_keys_.end() - keys < static_cast<std::ptrdiff_t>(kKeysWithoutSet))
      return std::find(keys, pending_keys_.end(), key) != pending_keys_.end();
    if (frame.key_set.empty()) frame.key_set.insert(keys, pending_keys_.end());
    return !frame.key_set.insert(key).second;
  }

  // Finished items of the open container at stack_[level].
  std::size_t item_count(std::size_t level) const {
    const std::size_t end = level + 1 < stack_.size() ? stack_[level + 1].first : pending_.size();
    return end - stack_[level].first;
  }

  // The latest key of the open object at stack_[level].
  const std::string& last_key(std::size_t level) const {
    const std::size_t end = level + 1 < stack_.size() ? stack_[level + 1].first_key : pending_keys_.size();
    return pending_keys_[end - 1];
  }

  // Path of the innermost open container (`pending` false) or of the value
  // about to be added to it (`pending` true).  The value at each level below
  // (open, or about to be added) follows that container's finished items.
  std::string path(bool pending) const {
    std::string p;
    const std::size_t levels = pending ? stack_.size() : (stack_.empty() ? 0 : stack_.size() - 1);
    for (std::size_t i = 0; i < levels; ++i)
      p = stack_[i].kind == Node::Kind::Array ? index_path(p, item_count(i)) : member_path(p, last_key(i));
    return p;
  }
  std::string pending_path() const { return path(true); }
  std::string container_path() const { return path(false); }

  std::string source_;
  Tree tree_;
  std::vector<Frame> stack_;
  std::vector<Node> pending_;                // finished items of all open containers, innermost last
  std::vector<std::string> pending_keys_;    // their keys (of open objects), likewise
  std::size_t values_ = 0;
  std::string error_;
};

}  // namespace

// A JSON number such as 1e400 (or a 400-digit integer) is valid JSON and
// means an exact rational, but the reader converts every number to double on
// the way and stops at an overflow.  Such tokens are turned into strings
// behind a control character (U+0001, kNumberMark) before reading, and the
// tree builder turns them back into numbers with their exact text: so they
// stay numbers (a name cannot be 1e400).  A string of the document whose
// text starts with either mark (written \u0001 or \u0002: JSON allows no
// raw control character in a string) gets the escape \u0002 (kStringMark)
// in front, which the tree builder removes: so a document's own string is
// never taken for a marked number.  Returns false, leaving `out` alone,
// when nothing needs it: then the text is read as it is.
bool quote_overflowing_numbers(const std::string& text, std::string& out) {
  std::size_t copied = 0;  // text[0, copied) is in `out`
  bool changed = false;
  for (std::size_t i = 0; i < text.size();) {
    const char c = text[i];
    if (c == '"') {  // skip the string, with its escapes
      ++i;
      const std::string_view head(text.data() + i, std::min<std::size_t>(6, text.size() - i));
      if (head == "\\u0001" || head == "\\u0002") {
        if (!changed) out.reserve(text.size() + 16);
        out.append(text, copied, i - copied);
        out += "\\u0002";
        copied = i;
        changed = true;
      }
      while (i < text.size() && text[i] != '"') i += text[i] == '\\' ? 2 : 1;
      ++i;
      continue;
    }
    if (c == '-' || (c >= '0' && c <= '9')) {
      std::size_t j = i;
      while (j < text.size() && std::strchr("+-0123456789.eE", text[j]) != nullptr) ++j;
      const std::string_view token(text.data() + i, j - i);
      // Without an exponent, fewer than 309 digits stay below the largest
      // double: only other tokens need the test.
      const bool may_overflow = token.size() > 300 || token.find_first_of("eE") != std::string_view::npos;
      if (may_overflow && std::isinf(std::strtod(std::string(token).c_str(), nullptr))) {
        if (!changed) out.reserve(text.size() + 16);
        out.append(text, copied, i - copied);
        out += "\"\\u0001";
        out += token;
        out += '"';
        copied = j;
        changed = true;
      }
      i = j;
      continue;
    }
    ++i;
  }
  if (!changed) return false;
  out.append(text, copied, std::string::npos);
  return true;
}

Tree parse_json(const std::string& raw_text, const std::string& source) {
  TreeBuilder builder(source);
  bool ok = false;
  std::string quoted;
  const std::string& text = quote_overflowing_numbers(raw_text, quoted) ? quoted : raw_text;
  try {
    ok = nlohmann::json::sax_parse(text, &builder);
  } catch (const nlohmann::json::exception& ex) {  // not expected with a SAX handler; be safe
    throw InputError(source + ": invalid JSON: " + one_line(ex.what()));
  }
  if (!ok) throw InputError(builder.error().empty() ? source + ": invalid JSON" : builder.error());
  return std::move(builder.tree());
}

namespace {

// Feeds a JSON value to the tree builder as the SAX parser would feed its
// text (quote_overflowing_numbers' marks included: a string that starts
// with either mark gets kStringMark in front).  False when the builder
// stopped (its error says why).
bool feed(TreeBuilder& builder, const nlohmann::ordered_json& value) {
  using Value = nlohmann::ordered_json::value_t;
  const auto text = [](const std::string& s) {
    (void)nlohmann::ordered_json(s).dump();  // invalid UTF-8 throws, as in dump()
    std::string out;
    if (!s.empty() && (s[0] == kNumberMark || s[0] == kStringMark)) out += kStringMark;
    return out + s;
  };
  switch (value.type()) {
    case Value::null:
    case Value::discarded: return builder.null();
    case Value::boolean: return builder.boolean(value.get<bool>());
    case Value::number_integer: return builder.number_integer(value.get<std::int64_t>());
    case Value::number_unsigned: return builder.number_unsigned(value.get<std::uint64_t>());
    case Value::number_float: return builder.number_float(value.get<double>(), value.dump());
    case Value::string: {
      std::string s = text(value.get_ref<const std::string&>());
      return builder.string(s);
    }
    case Value::binary: {
      nlohmann::json::binary_t b;
      return builder.binary(b);
    }
    case Value::array:
      if (!builder.start_array(value.size())) return false;
      for (const nlohmann::ordered_json& item : value)
        if (!feed(builder, item)) return false;
      return builder.end_array();
    case Value::object:
      if (!builder.start_object(value.size())) return false;
      for (const auto& [k, item] : value.items()) {
        std::string key = text(k);
        if (!builder.key(key) || !feed(builder, item)) return false;
      }
      return builder.end_object();
  }
  return builder.null();
}

}  // namespace

Tree tree_of(const nlohmann::ordered_json& value, const std::string& source) {
  TreeBuilder builder(source);
  if (!feed(builder, value)) throw InputError(builder.error().empty() ? source + ": invalid JSON" : builder.error());
  return std::move(builder.tree());
}

// ---------------------------------------------------------------- typed reading

void JsonReader::fail(const Path& path, const std::string& what) const {
  throw InputError(located(source_, path.str(), what));
}

std::string JsonReader::describe(const Node& node) const {
  return node.kind == Node::Kind::String ? quote_text(std::string(text(node)))
                                         : std::string("(") + kind_name(node.kind) + ")";
}

std::string JsonReader::compact(const Node& node) const {
  switch (node.kind) {
    case Node::Kind::Null: return "null";
    case Node::Kind::Boolean: return node.boolean ? "true" : "false";
    case Node::Kind::Number: return std::string(text(node));
    case Node::Kind::String: return nlohmann::json(std::string(text(node))).dump();
    case Node::Kind::Array:
    case Node::Kind::Object: break;
  }
  const bool is_object = node.kind == Node::Kind::Object;
  std::string out(1, is_object ? '{' : '[');
  for (std::uint32_t i = 0; i < node.size; ++i) {
    if (i > 0) out += ',';
    if (is_object) out += nlohmann::json(tree_.keys[node.first_key + i]).dump() + ':';
    out += compact(tree_.nodes[node.first + i]);
  }
  return out + (is_object ? '}' : ']');
}


void JsonReader::reject_unknown_keys(const Members& object, const Path& path,
                                     std::initializer_list<std::string_view> known) const {
  for (const std::string& key : object.keys)
    if (!is_annotation(key) && std::find(known.begin(), known.end(), key) == known.end())
      fail(path.member(key), "unknown field " + quote_text(key));
}

JsonReader::Members JsonReader::object(const Node& node, const Path& path) const {
  if (node.kind != Node::Kind::Object) fail(path, std::string("expected an object, got ") + kind_name(node.kind));
  return {std::span(tree_.keys).subspan(node.first_key, node.size),
          std::span(tree_.nodes).subspan(node.first, node.size)};
}

std::span<const Node> JsonReader::array(const Node& node, const Path& path) const {
  if (node.kind != Node::Kind::Array) fail(path, std::string("expected an array, got ") + kind_name(node.kind));
  return std::span(tree_.nodes).subspan(node.first, node.size);
}

Exact JsonReader::number(const Node& node, const Path& path) const {
  Exact value;
  if (node.kind == Node::Kind::Number) {
    const std::string written(text(node));
    if (!parse_exact(written, value)) fail(path, "number " + written.substr(0, 60) + " is out of range");
  } else if (node.kind == Node::Kind::String) {
    const std::string written(text(node));
    if (!parse_exact(written, value))
      fail(path, "not a number: " + quote_text(written) + " (expected an integer, \"p/q\" with q > 0, or a decimal)");
  } else {
    fail(path, std::string("expected a number, got ") + kind_name(node.kind));
  }
  if (!within_input_limit(value))
    fail(path, "number too large: more than " + std::to_string(kMaxInputDigits) +
                   " digits in its numerator or denominator (docs/scene-format.md, \"Limits\")");
  return value;
}

Vec3E JsonReader::point(const Node& node, const Path& path) const {
  const std::span<const Node> coords = array(node, path);
  if (coords.size() != 3)
    fail(path, "a point needs exactly 3 coordinates, got " + std::to_string(coords.size()));
  return {number(coords[0], path.index(0)), number(coords[1], path.index(1)),
          number(coords[2], path.index(2))};
}

std::vector<Vec3E> JsonReader::points(const Node& node, const Path& path) const {
  const std::span<const Node> list = array(node, path);
  std::vector<Vec3E> out;
  out.reserve(list.size());
  for (std::size_t i = 0; i < list.size(); ++i) out.push_back(point(list[i], path.index(i)));
  return out;
}

Mat34E JsonReader::affine(const Node& node, const Path& path) const {
  const std::span<const Node> rows = array(node, path);
  if (rows.size() != 3)
    fail(path, "a control point is a 3x4 matrix: expected 3 rows, got " + std::to_string(rows.size()));
  Mat34E m;
  for (std::size_t r = 0; r < 3; ++r) {
    const Path row_path = path.index(r);
    const std::span<const Node> row = array(rows[r], row_path);
    if (row.size() != 4)
      fail(row_path, "a matrix row needs exactly 4 numbers, got " + std::to_string(row.size()));
    for (std::size_t c = 0; c < 4; ++c) m[4 * r + c] = number(row[c], row_path.index(c));
  }
  return m;
}

Exact JsonReader::non_negative(const Node& node, const Path& path) const {
  const Exact value = number(node, path);
  if (value < 0) fail(path, "must not be negative");
  return value;
}

std::vector<Exact> JsonReader::positive_weights(const Node& node, const Path& path, std::size_t count,
                                                    const std::string& per) const {
  const std::span<const Node> list = array(node, path);
  if (list.size() != count)
    fail(path, "expected " + std::to_string(count) + " weights (one per " + per + "), got " +
                   std::to_string(list.size()));
  std::vector<Exact> out;
  out.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    const Path item_path = path.index(i);
    out.push_back(number(list[i], item_path));
    if (!(out.back() > 0)) fail(item_path, "weight must be positive");
  }
  return out;
}

// A body's motion: one rational Bezier curve stays `Body::motion` (also

}  // namespace reader

// A user string made safe for a one-line message: quoted, control
// characters escaped, long strings shortened.
std::string quote_text(const std::string& s) {
  constexpr std::size_t kShown = 60;
  std::string out = "\"";
  for (std::size_t i = 0; i < s.size() && i < kShown; ++i) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += static_cast<char>(c);
    } else if (c < 0x20 || c == 0x7f) {
      static const char* hex = "0123456789abcdef";
      out += "\\u00";
      out += hex[c >> 4];
      out += hex[c & 15];
    } else {
      out += static_cast<char>(c);
    }
  }
  if (s.size() > kShown) out += "...";
  return out + "\"";
}

}  // namespace tmcert
