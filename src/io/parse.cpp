// Reading tmcert-scene/1 documents (SCENE_FORMAT.md).
//
// Two stages.  First the JSON text becomes a small tree of our own through
// nlohmann's SAX interface: unlike its DOM, SAX hands us the raw text of
// every number, so 0.1 stays the decimal 1/10 instead of the nearest double.
// Then the tree is validated and turned into the exact model; every error
// names the JSON path of the offending value.  Polygons are checked
// (planar, simple) and split into convex pieces with exact arithmetic.
// Mesh files (src/io/mesh.h) are read relative to the scene file, and
// every face goes through the same polygon checks.
#include "src/io/parse.h"

#include "kernels/decimal.h"

#include "src/motion/segment.h"

#include "src/metric/metric.h"
#include "src/io/mesh.h"
#include "src/io/read_file.h"
#include "src/model/solid.h"
#include "src/io/robot.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_triangulation_face_base_2.h>
#include <CGAL/Filtered_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <cstring>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <climits>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <span>
#include <sstream>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <utility>

namespace tmcert {

namespace {

// Limits that turn absurd input into an InputError instead of exhausting
// memory or time.  A real scene is far below each of them.
constexpr std::size_t kMaxNesting = 64;             // scenes need 7 levels
constexpr std::size_t kMaxValues = 10'000'000;      // JSON values in a document
constexpr std::uintmax_t kMaxFileBytes = 1ull << 30;
constexpr std::size_t kMaxPolygonVertices = 100'000;

constexpr const char* kFormat = "tmcert-scene/1";

// ---------------------------------------------------------------- messages


// Replaces line breaks and other control characters so a message stays on one line.
std::string one_line(std::string s) {
  for (char& c : s)
    if (static_cast<unsigned char>(c) < 0x20) c = ' ';
  return s;
}

bool is_identifier(const std::string& key) {
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

// ---------------------------------------------------------------- JSON tree

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

// ---------------------------------------------------------------- exact geometry

using Vec2E = std::array<Exact, 2>;

int sign(const Exact& x) { return x > 0 ? 1 : (x < 0 ? -1 : 0); }

Vec3E sub(const Vec3E& a, const Vec3E& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3E cross(const Vec3E& a, const Vec3E& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Exact dot(const Vec3E& a, const Vec3E& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
bool is_zero(const Vec3E& a) { return a[0] == 0 && a[1] == 0 && a[2] == 0; }

// Twice the signed area of triangle abc: > 0 for a left turn.
Exact orient(const Vec2E& a, const Vec2E& b, const Vec2E& c) {
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

// A cheap enclosure of a rational: mpq_get_d truncates toward zero, so the
// value lies between that double and its neighbour away from zero.  False
// when the double is not finite (then only exact arithmetic decides).
bool cheap_interval(const Exact& q, Interval& out) {
  const double d = mpq_get_d(q.mpq());
  if (!std::isfinite(d)) return false;
  const int s = mpq_sgn(q.mpq());
  const double away = std::nextafter(d, s >= 0 ? std::numeric_limits<double>::infinity()
                                               : -std::numeric_limits<double>::infinity());
  if (!std::isfinite(away)) return false;
  out = s == 0 ? Interval(0) : Interval(std::min(d, away), std::max(d, away));
  return true;
}

// The sign of orient(a, b, c): an interval filter first, exact when the
// filter cannot decide (the filtered-predicate pattern of DESIGN.md).
int orient_sign(const Vec2E& a, const Vec2E& b, const Vec2E& c) {
  Interval x[6];
  const Exact* q[6] = {&a[0], &a[1], &b[0], &b[1], &c[0], &c[1]};
  bool ok = true;
  for (int i = 0; i < 6 && ok; ++i) ok = cheap_interval(*q[i], x[i]);
  if (ok) {
    RoundingGuard guard;
    const Interval det = (x[2] - x[0]) * (x[5] - x[1]) - (x[3] - x[1]) * (x[4] - x[0]);
    if (det.inf() > 0) return 1;
    if (det.sup() < 0) return -1;
  }
  return sign(orient(a, b, c));
}

// Given that p is collinear with a and b: is it on the closed segment ab?
bool within_box(const Vec2E& a, const Vec2E& b, const Vec2E& p) {
  return std::min(a[0], b[0]) <= p[0] && p[0] <= std::max(a[0], b[0]) &&
         std::min(a[1], b[1]) <= p[1] && p[1] <= std::max(a[1], b[1]);
}

// Do the closed segments ab and cd share a point?
bool segments_meet(const Vec2E& a, const Vec2E& b, const Vec2E& c, const Vec2E& d) {
  const int o1 = orient_sign(a, b, c), o2 = orient_sign(a, b, d);
  const int o3 = orient_sign(c, d, a), o4 = orient_sign(c, d, b);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return (o1 == 0 && within_box(a, b, c)) || (o2 == 0 && within_box(a, b, d)) ||
         (o3 == 0 && within_box(c, d, a)) || (o4 == 0 && within_box(c, d, b));
}

// Position of a direction in counterclockwise order starting at +x.
bool angle_less(const Vec2E& a, const Vec2E& b) {
  auto half = [](const Vec2E& d) { return (d[1] < 0 || (d[1] == 0 && d[0] < 0)) ? 1 : 0; };
  if (half(a) != half(b)) return half(a) < half(b);
  return a[0] * b[1] - a[1] * b[0] > 0;
}

// A polygon after validation, in original 3D coordinates and in the
// injective 2D projection, with each vertex's index in the input.
struct CleanPolygon {
  std::vector<Vec3E> points;
  std::vector<Vec2E> flat;
  std::vector<std::size_t> original;
};

std::string vertex_name(std::size_t i) { return "vertex " + std::to_string(i); }

// Throws InputError (message without location; the caller adds the path)
// unless the polygon is planar, has no repeated vertex and not all vertices
// are collinear.  Projects it onto the coordinate plane that drops the
// largest component of its normal, which is injective on its plane.
CleanPolygon project_polygon(const std::vector<Vec3E>& v) {
  const std::size_t n = v.size();
  // Repeated vertices, in O(n log n): sort, then compare neighbours.
  std::vector<std::size_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return v[a] < v[b] || (v[a] == v[b] && a < b);
  });
  for (std::size_t k = 1; k < n; ++k)
    if (v[order[k]] == v[order[k - 1]])
      throw InputError(vertex_name(order[k - 1]) + " and " + vertex_name(order[k]) +
                       " are equal (a polygon must be simple)");

  // A non-collinear triple 0, 1, j gives the plane.
  const Vec3E e1 = sub(v[1], v[0]);
  Vec3E normal{0, 0, 0};
  std::size_t j = 2;
  for (; j < n; ++j) {
    normal = cross(e1, sub(v[j], v[0]));
    if (!is_zero(normal)) break;
  }
  if (j == n) throw InputError("polygon vertices are collinear");
  for (std::size_t i = 2; i < n; ++i)
    if (dot(normal, sub(v[i], v[0])) != 0)
      throw InputError("polygon is not planar: " + vertex_name(i) + " is off the plane of vertices 0, 1 and " +
                       std::to_string(j));

  int drop = 0;
  for (int a = 1; a < 3; ++a)
    if (CGAL::abs(normal[a]) > CGAL::abs(normal[drop])) drop = a;
  const int u = drop == 0 ? 1 : 0, w = drop == 2 ? 1 : 2;
  CleanPolygon p;
  p.points = v;
  p.original.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    p.flat.push_back({v[i][u], v[i][w]});
    p.original[i] = i;
  }
  return p;
}

// Removes, repeatedly, every vertex that lies strictly between its two
// neighbours on their line: the boundary stays the same point set.  A vertex
// collinear with its neighbours but not between them is a spike where the
// two edges overlap: the polygon is not simple.
CleanPolygon remove_collinear(const CleanPolygon& in) {
  const std::size_t n = in.flat.size();
  std::vector<std::size_t> prev(n), next(n);
  std::vector<bool> alive(n, true);
  for (std::size_t i = 0; i < n; ++i) {
    prev[i] = (i + n - 1) % n;
    next[i] = (i + 1) % n;
  }
  std::vector<std::size_t> work(n);
  for (std::size_t i = 0; i < n; ++i) work[i] = n - 1 - i;
  std::size_t count = n;
  while (!work.empty()) {
    const std::size_t i = work.back();
    work.pop_back();
    if (!alive[i]) continue;
    const Vec2E &a = in.flat[prev[i]], &b = in.flat[i], &c = in.flat[next[i]];
    if (orient_sign(a, b, c) != 0) continue;
    const Exact along = (a[0] - b[0]) * (c[0] - b[0]) + (a[1] - b[1]) * (c[1] - b[1]);
    if (along > 0)
      throw InputError("adjacent edges overlap at " + vertex_name(in.original[i]) + " (a polygon must be simple)");
    // Only a fully collinear polygon could shrink below 3; that was rejected before.
    if (count <= 3) throw InputError("polygon vertices are collinear");
    alive[i] = false;
    --count;
    next[prev[i]] = next[i];
    prev[next[i]] = prev[i];
    work.push_back(prev[i]);
    work.push_back(next[i]);
  }
  CleanPolygon out;
  for (std::size_t i = 0; i < n; ++i)
    if (alive[i]) {
      out.points.push_back(in.points[i]);
      out.flat.push_back(in.flat[i]);
      out.original.push_back(in.original[i]);
    }
  return out;
}

// True iff the cleaned polygon (no zero turns) turns the same way at every
// vertex and winds around exactly once, i.e. is convex and simple.  The
// winding is counted as how often the edge direction passes the +x direction.
bool is_convex(const CleanPolygon& p) {
  const std::size_t n = p.flat.size();
  int turn = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const int s = orient_sign(p.flat[(i + n - 1) % n], p.flat[i], p.flat[(i + 1) % n]);
    if (turn == 0) turn = s;
    if (s != turn) return false;
  }
  std::vector<Vec2E> dir(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2E &a = p.flat[i], &b = p.flat[(i + 1) % n];
    dir[i] = {b[0] - a[0], b[1] - a[1]};
  }
  int wraps = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2E &d = dir[i], &e = dir[(i + 1) % n];
    if (turn > 0 ? angle_less(e, d) : angle_less(d, e)) ++wraps;
  }
  return wraps == 1;
}

// Throws unless no two non-adjacent edges share a point (adjacent edges
// meet only at their common vertex once zero turns are gone).  Edges are
// swept in order of their smallest x so only overlapping ones are compared.
void require_simple(const CleanPolygon& p) {
  const std::size_t n = p.flat.size();
  std::vector<Exact> lo(n), hi(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2E &a = p.flat[i], &b = p.flat[(i + 1) % n];
    lo[i] = std::min(a[0], b[0]);
    hi[i] = std::max(a[0], b[0]);
  }
  std::vector<std::size_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return lo[a] < lo[b]; });
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = order[k];
    for (std::size_t m = k + 1; m < n && lo[order[m]] <= hi[i]; ++m) {
      const std::size_t j = order[m];
      if ((i + 1) % n == j || (j + 1) % n == i) continue;  // adjacent
      if (segments_meet(p.flat[i], p.flat[(i + 1) % n], p.flat[j], p.flat[(j + 1) % n])) {
        auto edge = [&](std::size_t e) {
          return "edge " + std::to_string(p.original[e]) + "-" + std::to_string(p.original[(e + 1) % n]);
        };
        const std::size_t first = std::min(i, j), second = std::max(i, j);
        throw InputError("polygon is self-intersecting: " + edge(first) + " and " + edge(second) + " meet");
      }
    }
  }
}

// Triangulation of a polygon (no repeated vertex, no zero turn) by CGAL's
// constrained Delaunay triangulation of its exact 2D projection, on a
// filtered exact kernel: O(n log n) expected, where ear clipping and the
// pairwise simplicity test were quadratic or worse (52 s for 10 000
// vertices).  The polygon's edges are the constraints.  The polygon is
// simple iff no two constraints cross or overlap (CGAL throws) and every
// edge is an edge of the triangulation (else a vertex lies on it); then no
// point is added, every triangle has three polygon vertices, and the
// triangles inside are those reached from the outside across an odd number
// of constraints.  Each is returned in the polygon's orientation.  Nothing
// when the polygon is not simple (require_simple then says why).
std::optional<std::vector<std::array<std::size_t, 3>>> triangulate(const CleanPolygon& p) {
  using K = CGAL::Filtered_kernel<CGAL::Simple_cartesian<Exact>>;
  using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::size_t, K>;
  using Fbi = CGAL::Triangulation_face_base_with_info_2<int, K>;  // constraints crossed from outside
  using Fb = CGAL::Constrained_triangulation_face_base_2<K, Fbi>;
  using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
  using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::No_constraint_intersection_tag>;
  const std::size_t n = p.flat.size();
  Exact twice_area = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2E &a = p.flat[i], &b = p.flat[(i + 1) % n];
    twice_area += a[0] * b[1] - a[1] * b[0];
  }
  const int orientation = sign(twice_area);  // nonzero for a simple polygon
  std::vector<std::pair<K::Point_2, std::size_t>> points;
  points.reserve(n);
  for (std::size_t i = 0; i < n; ++i) points.emplace_back(K::Point_2(p.flat[i][0], p.flat[i][1]), i);
  Cdt cdt;
  cdt.insert(points.begin(), points.end());  // spatially sorted
  if (cdt.number_of_vertices() != n) return std::nullopt;
  std::vector<Cdt::Vertex_handle> handle(n);
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) handle[v->info()] = v;
  try {
    for (std::size_t i = 0; i < n; ++i) cdt.insert_constraint(handle[i], handle[(i + 1) % n]);
  } catch (const Cdt::Intersection_of_constraints_exception&) {
    return std::nullopt;
  }
  if (cdt.number_of_vertices() != n) return std::nullopt;
  for (std::size_t i = 0; i < n; ++i)
    if (!cdt.is_edge(handle[i], handle[(i + 1) % n])) return std::nullopt;
  // Each face's count of constraints crossed from the infinite face: flood
  // fill across unconstrained edges, one more across a constrained one.
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info() = -1;
  std::vector<Cdt::Edge> border;
  auto fill = [&](Cdt::Face_handle start, int level) {
    if (start->info() != -1) return;
    start->info() = level;
    std::vector<Cdt::Face_handle> queue{start};
    while (!queue.empty()) {
      const Cdt::Face_handle f = queue.back();
      queue.pop_back();
      for (int e = 0; e < 3; ++e) {
        const Cdt::Face_handle g = f->neighbor(e);
        if (g->info() != -1) continue;
        if (cdt.is_constrained(Cdt::Edge(f, e))) {
          border.push_back(Cdt::Edge(f, e));
        } else {
          g->info() = level;
          queue.push_back(g);
        }
      }
    }
  };
  fill(cdt.infinite_face(), 0);
  for (std::size_t k = 0; k < border.size(); ++k) {  // border grows while filling: breadth first
    const Cdt::Edge e = border[k];
    fill(e.first->neighbor(e.second), e.first->info() + 1);
  }
  std::vector<std::array<std::size_t, 3>> triangles;
  triangles.reserve(n - 2);
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (f->info() % 2 == 0) continue;
    // CGAL's faces are counterclockwise in the projection.
    std::array<std::size_t, 3> t{f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()};
    if (orientation < 0) std::swap(t[1], t[2]);
    triangles.push_back(t);
  }
  if (triangles.size() != n - 2) return std::nullopt;
  return triangles;
}

// Validates one input polygon and returns its cleaned vertices plus its
// convex pieces (tagged with `index`).  Errors carry no location.
std::pair<std::vector<Vec3E>, std::vector<ConvexPiece>> split_polygon(const std::vector<Vec3E>& vertices,
                                                                      int index) {
  // A triangle with distinct, non-collinear vertices is its own convex
  // piece (anything else goes through the general checks and their messages).
  if (vertices.size() == 3 && vertices[0] != vertices[1] && vertices[1] != vertices[2] && vertices[0] != vertices[2] &&
      !is_zero(cross(sub(vertices[1], vertices[0]), sub(vertices[2], vertices[0]))))
    return {vertices, {ConvexPiece{index, vertices}}};
  const CleanPolygon clean = remove_collinear(project_polygon(vertices));
  std::vector<ConvexPiece> pieces;
  if (is_convex(clean)) {
    pieces.push_back(ConvexPiece{index, clean.points});
  } else {
    const auto triangles = triangulate(clean);
    if (!triangles) {
      require_simple(clean);  // says why (quadratic, but only for a bad polygon)
      throw InputError("polygon could not be triangulated (is it simple?)");
    }
    for (const auto& t : *triangles)
      pieces.push_back(ConvexPiece{index, {clean.points[t[0]], clean.points[t[1]], clean.points[t[2]]}});
  }
  return {clean.points, std::move(pieces)};
}

// ---------------------------------------------------------------- scene reader

// Walks the tree, validating as it goes.  Every error is thrown as
// "<source>: <path>: <what>".
class SceneReader {
 public:
  // `base` is the directory mesh file names are relative to ("" for the
  // current directory).
  SceneReader(std::string source, std::filesystem::path base, const Tree& tree, ReadOptions options = {})
      : source_(std::move(source)), base_(std::move(base)), tree_(tree), options_(std::move(options)) {}

  Scene read() {
    Scene scene;
    scene.source = source_;
    const Path document;
    const Members doc = object(tree_.root, document);

    const Node* format = find(doc, "format");
    if (!format) fail(document.member("format"), std::string("missing required field (expected \"") + kFormat + "\")");
    if (format->kind != Node::Kind::String || text(*format) != kFormat)
      fail(document.member("format"), "unknown format version " + describe(*format) + ", expected \"" + kFormat + "\"");
    reject_unknown_keys(doc, document,
                        {"format", "epsilon", "max_depth", "bodies", "checks", "clearance", "robots", "package_paths"});
    if (const Node* pp = find(doc, "package_paths")) package_paths(*pp, document.member("package_paths"));
    if (const Node* c = find(doc, "clearance")) scene.clearance = non_negative(*c, document.member("clearance"));

    if (const Node* eps = find(doc, "epsilon")) {
      const Path eps_path = document.member("epsilon");
      scene.epsilon = number(*eps, eps_path);
      if (!(*scene.epsilon > 0)) fail(eps_path, "must be positive");
    }
    if (const Node* depth = find(doc, "max_depth")) scene.max_depth = max_depth(*depth, document.member("max_depth"));

    const Path bodies_path = document.member("bodies");
    const Node* bodies = find(doc, "bodies");
    const Node* robots_node = find(doc, "robots");
    // A scene of robots alone (self-collision) needs no other body.
    if (!bodies && !robots_node) fail(bodies_path, "missing required field");
    const std::span<const Node> list = bodies ? array(*bodies, bodies_path) : std::span<const Node>();
    if (list.empty() && !robots_node) fail(bodies_path, "at least one body is required");
    std::unordered_map<std::string, std::size_t> names;
    names.reserve(list.size());
    scene.bodies.reserve(list.size());
    for (std::size_t i = 0; i < list.size(); ++i) {
      const Path path = bodies_path.index(i);
      scene.bodies.push_back(body(list[i], path));
      const std::string& name = scene.bodies.back().name;
      if (auto [it, fresh] = names.emplace(name, i); !fresh)
        fail(path.member("name"),
             "duplicate body name " + quote_text(name) + " (also " + index_path("bodies", it->second) + ")");
    }
    assign_masses(scene, bodies_path);
    const std::size_t plain_bodies = scene.bodies.size();
    std::vector<RobotInScene> placed;
    if (robots_node) placed = robots(scene, *robots_node, document.member("robots"), names);
    if (robots_out_)
      for (const RobotInScene& r : placed) {
        SceneRobot kept{r.robot, r.joints, {}, r.self_collision, r.allowed};
        for (const std::vector<int>& parts : r.bodies.parts)
          kept.bodies.insert(kept.bodies.end(), parts.begin(), parts.end());
        robots_out_->push_back(std::move(kept));
      }
    if (scene.bodies.empty()) fail(bodies_path, "at least one body is required (the robots have no collision geometry)");

    if (const Node* checks = find(doc, "checks"))
      scene.checks = explicit_checks(*checks, document.member("checks"), names, scene.check_clearance);
    else
      scene.checks = default_checks_with_robots(scene, plain_bodies, placed);
    scene.notes = std::move(notes_);
    scene.warnings = std::move(warnings_);
    return scene;
  }

  // A rational above 2 pi (2 pi < 6.283185307179587): an rpy angle beyond
  // it is most likely in degrees.
  static const Exact& two_pi_above() {
    static const Exact bound = [] {
      Exact e;
      parse_exact("6.283185307179587", e);
      return e;
    }();
    return bound;
  }

  std::string rpy_warning(const Path& path, const Exact& angle) const {
    const double degrees = CGAL::to_double(angle);
    char radians[64];
    const auto r = std::to_chars(radians, radians + sizeof radians, degrees * 3.141592653589793 / 180);
    return located(source_, path.str(), "the angle " + to_decimal(angle).text + " is more than 2 pi: it is read as " +
                                            "radians; if it is in degrees, write " + std::string(radians, r.ptr) +
                                            " (its radians) instead");
  }

  // "; the nearest rotation is the unit quaternion ...: write ... instead"
  // with its components as decimals, which the reader takes exactly (a
  // quaternion of any norm is a rotation): the rotation factor of the
  // matrix's polar decomposition, in double precision.  When the matrix is
  // not a rotation up to float noise (singular values off 1 by more than
  // 1e-3: a scaling, a shear), the hint says so.  Empty when no rotation
  // is near (a polar factor with determinant -1: a reflection) or the
  // matrix is beyond the doubles.
  static std::string nearest_quaternion_hint(const std::array<Exact, 9>& m) {
    Eigen::Matrix3d a;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) {
        a(r, c) = CGAL::to_double(m[3 * r + c]);
        if (!std::isfinite(a(r, c))) return {};
      }
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd(a, Eigen::ComputeFullU | Eigen::ComputeFullV);
    const Eigen::Vector3d sigma = svd.singularValues();
    const Eigen::Matrix3d nearest = svd.matrixU() * svd.matrixV().transpose();
    if (!(nearest.determinant() > 0)) return {};
    Eigen::Quaterniond q(nearest);
    q.normalize();
    if (q.w() < 0) q.coeffs() = -q.coeffs();
    std::string list;
    for (const double x : {q.w(), q.x(), q.y(), q.z()}) {
      char buffer[64];
      const auto r = std::to_chars(buffer, buffer + sizeof buffer, x == 0 ? 0.0 : x);
      list += (list.empty() ? "" : ", ") + std::string(buffer, r.ptr);
    }
    std::string far;
    if ((sigma.array() - 1).abs().maxCoeff() > 1e-3) {
      std::ostringstream values;
      values.precision(6);
      values << sigma(0) << ", " << sigma(1) << ", " << sigma(2);
      far = " (but the matrix is not a rotation up to rounding: it scales by " + values.str() + ")";
    }
    return "; the nearest rotation is the unit quaternion [w, x, y, z] = [" + list + "]" + far + ": write " +
           "\"rotation\": {\"quaternion\": [" + list + "]} instead (its decimals are read exactly; a quaternion " +
           "of any norm is a rotation)";
  }

  // "package_paths": folders relative to the scene file, searched for
  // package:// URIs after the given ones (ReadOptions) and before
  // ROS_PACKAGE_PATH.
  void package_paths(const Node& node, const Path& path) {
    const std::span<const Node> list = array(node, path);
    for (std::size_t k = 0; k < list.size(); ++k) {
      if (list[k].kind != Node::Kind::String || text(list[k]).empty())
        fail(path.index(k), "expected a folder name (a non-empty string)");
      const std::string name(text(list[k]));
      if (name.find('\0') != std::string::npos) fail(path.index(k), "folder name contains a NUL character");
      scene_packages_.push_back((base_ / std::filesystem::path(name)).string());
    }
  }

  // The package folders in their order: given, the scene's, ROS_PACKAGE_PATH.
  UrdfOptions urdf_options() const {
    UrdfOptions out;
    out.package_paths = options_.package_paths;
    out.package_paths.insert(out.package_paths.end(), scene_packages_.begin(), scene_packages_.end());
    for (const std::string& f : ros_package_path()) out.package_paths.push_back(f);
    return out;
  }

  // A request line of a batch run (docs/scene-format.md "Batch runs"):
  // {"id", "body", "motion" or "robot", "path"; "checks", "clearance"}.  `out.id` is set first,
  // so that a request rejected later is still reported under its id.
  void read_request(RequestLine& out) const {
    const Path document;
    const Members doc = object(tree_.root, document);
    if (const Node* id = find(doc, "id")) out.id = compact(*id);
    reject_unknown_keys(doc, document, {"id", "body", "motion", "robot", "path", "checks", "clearance"});
    const Path body_path = document.member("body");
    const Node* b = find(doc, "body");
    if (const Node* r = find(doc, "robot")) {
      // A robot's path segment: {"robot": name, "path": {"times", "positions"}}.
      const Path robot_path = document.member("robot");
      if (b) fail(body_path, "a request moves a body or a robot, not both");
      if (find(doc, "motion")) fail(document.member("motion"), "a robot moves along its \"path\", not a motion");
      if (r->kind != Node::Kind::String || text(*r).empty()) fail(robot_path, "expected a robot name (a string)");
      out.robot = text(*r);
      const Path path_path = document.member("path");
      const Node* p = find(doc, "path");
      if (!p) fail(path_path, "missing required field");
      JointPath jp;
      joint_path_values(*p, path_path, jp);
      out.path_times = std::move(jp.times);
      out.path_positions = std::move(jp.positions);
      read_request_checks(out);
      return;
    }
    if (find(doc, "path")) fail(document.member("path"), "a path moves a robot (give \"robot\")");
    if (!b) fail(body_path, "missing required field (a body name of the environment, or a body; or a robot)");
    if (b->kind == Node::Kind::String) {
      out.body = text(*b);
      if (out.body.empty()) fail(body_path, "a body name must be a non-empty string");
    } else if (b->kind == Node::Kind::Object) {
      Scene alone;  // its default mass from its own vertices
      alone.bodies.push_back(body(*b, body_path));
      if (alone.bodies[0].motion || alone.bodies[0].trajectory)
        fail(body_path.member("motion"), "the request's motion goes in its \"motion\" field");
      assign_masses(alone, body_path);
      out.body = alone.bodies[0].name;
      out.inline_body = std::move(alone.bodies[0]);
    } else {
      fail(body_path, std::string("expected a body name or a body object, got ") + kind_name(b->kind));
    }
    const Path motion_path = document.member("motion");
    const Node* m = find(doc, "motion");
    if (!m) fail(motion_path, "missing required field");
    Body moved;
    motion(moved, *m, motion_path);
    if (!moved.moves()) fail(motion_path, "the motion must move (a one-pose motion is not a request)");
    out.motion = std::move(moved.motion);
    out.trajectory = std::move(moved.trajectory);
    read_request_checks(out);
  }

  // A request's "checks" and "clearance".
  void read_request_checks(RequestLine& out) const {
    const Path document;
    const Members doc = object(tree_.root, document);
    if (const Node* c = find(doc, "checks")) {
      const Path checks_path = document.member("checks");
      const std::span<const Node> list = array(*c, checks_path);
      if (list.empty()) fail(checks_path, "at least one body name is required (omit the field for every other body)");
      for (std::size_t k = 0; k < list.size(); ++k) {
        if (list[k].kind != Node::Kind::String)
          fail(checks_path.index(k), std::string("expected a body name, got ") + kind_name(list[k].kind));
        std::string name(text(list[k]));
        if (std::find(out.checks.begin(), out.checks.end(), name) != out.checks.end())
          fail(checks_path.index(k), "duplicate body " + quote_text(name));
        out.checks.push_back(std::move(name));
      }
    }
    if (const Node* c = find(doc, "clearance")) out.clearance = non_negative(*c, document.member("clearance"));
  }

 private:
  [[noreturn]] void fail(const Path& path, const std::string& what) const {
    throw InputError(located(source_, path.str(), what));
  }

  std::string_view text(const Node& node) const { return tree_.text_of(node); }

  // A value for a message: a string quoted, anything else by its kind.
  std::string describe(const Node& node) const {
    return node.kind == Node::Kind::String ? quote_text(std::string(text(node)))
                                           : std::string("(") + kind_name(node.kind) + ")";
  }

  // A value as compact JSON, numbers exactly as written (an id echoed in
  // results: the same bytes for the same input).
  std::string compact(const Node& node) const {
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

  // An object's keys and member values, side by side.
  struct Members {
    std::span<const std::string> keys;
    std::span<const Node> values;
  };

  static const Node* find(const Members& object, std::string_view key) {
    for (std::size_t i = 0; i < object.keys.size(); ++i)
      if (object.keys[i] == key) return &object.values[i];
    return nullptr;
  }

  // Keys starting with "_" and "comment" are free for annotations.
  static bool is_annotation(const std::string& key) { return key == "comment" || (!key.empty() && key[0] == '_'); }

  void reject_unknown_keys(const Members& object, const Path& path,
                           std::initializer_list<std::string_view> known) const {
    for (const std::string& key : object.keys)
      if (!is_annotation(key) && std::find(known.begin(), known.end(), key) == known.end())
        fail(path.member(key), "unknown field " + quote_text(key));
  }

  Members object(const Node& node, const Path& path) const {
    if (node.kind != Node::Kind::Object) fail(path, std::string("expected an object, got ") + kind_name(node.kind));
    return {std::span(tree_.keys).subspan(node.first_key, node.size),
            std::span(tree_.nodes).subspan(node.first, node.size)};
  }

  // An array's items.
  std::span<const Node> array(const Node& node, const Path& path) const {
    if (node.kind != Node::Kind::Array) fail(path, std::string("expected an array, got ") + kind_name(node.kind));
    return std::span(tree_.nodes).subspan(node.first, node.size);
  }

  // A JSON number (exactly the decimal it spells) or a string holding an
  // integer, "p/q" or a decimal.
  Exact number(const Node& node, const Path& path) const {
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

  int max_depth(const Node& node, const Path& path) const {
    const Exact value = number(node, path);
    if (value.denominator() != 1) fail(path, "must be an integer");
    if (value < 1 || value > 200) fail(path, "must be between 1 and 200");
    return static_cast<int>(CGAL::to_double(value));
  }

  Vec3E point(const Node& node, const Path& path) const {
    const std::span<const Node> coords = array(node, path);
    if (coords.size() != 3)
      fail(path, "a point needs exactly 3 coordinates, got " + std::to_string(coords.size()));
    return {number(coords[0], path.index(0)), number(coords[1], path.index(1)),
            number(coords[2], path.index(2))};
  }

  std::vector<Vec3E> points(const Node& node, const Path& path) const {
    const std::span<const Node> list = array(node, path);
    std::vector<Vec3E> out;
    out.reserve(list.size());
    for (std::size_t i = 0; i < list.size(); ++i) out.push_back(point(list[i], path.index(i)));
    return out;
  }

  // A 3x4 affine matrix [A | a] written as 3 rows of 4 numbers.
  Mat34E affine(const Node& node, const Path& path) const {
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

  Body body(const Node& node, const Path& path) const {
    const Members obj = object(node, path);
    reject_unknown_keys(obj, path,
                        {"name", "polygons", "segments", "points", "mass", "motion", "solid", "mesh", "tolerance"});
    Body b;

    const Node* name = find(obj, "name");
    if (!name) fail(path.member("name"), "missing required field");
    if (name->kind != Node::Kind::String || text(*name).empty())
      fail(path.member("name"), "a body name must be a non-empty string");
    b.name = text(*name);
    // Names are printed in results and messages: no control characters
    // (C0, DEL, or C1 as UTF-8 C2 80..9F), which would print raw.
    for (std::size_t k = 0; k < b.name.size(); ++k) {
      const auto c = static_cast<unsigned char>(b.name[k]);
      const bool c1 = c == 0xC2 && k + 1 < b.name.size() && static_cast<unsigned char>(b.name[k + 1]) >= 0x80 &&
                      static_cast<unsigned char>(b.name[k + 1]) <= 0x9F;
      if (c < 0x20 || c == 0x7F || c1)
        fail(path.member("name"), "a body name cannot contain control characters, got " + quote_text(b.name));
    }

    if (const Node* polygons = find(obj, "polygons")) {
      const Path list_path = path.member("polygons");
      const std::span<const Node> list = array(*polygons, list_path);
      for (std::size_t i = 0; i < list.size(); ++i) polygon(b, list[i], list_path.index(i));
    }
    if (const Node* segments = find(obj, "segments")) {
      const Path list_path = path.member("segments");
      const std::span<const Node> list = array(*segments, list_path);
      for (std::size_t i = 0; i < list.size(); ++i) {
        const Path seg_path = list_path.index(i);
        const std::vector<Vec3E> ends = points(list[i], seg_path);
        if (ends.size() != 2) fail(seg_path, "a segment needs exactly 2 points, got " + std::to_string(ends.size()));
        if (ends[0] == ends[1]) fail(seg_path, "segment endpoints are equal");
        b.segments.push_back({ends[0], ends[1]});
      }
    }
    if (const Node* pts = find(obj, "points")) b.points = points(*pts, path.member("points"));
    // Mesh faces come after the explicit polygons (polygon indices go on).
    if (const Node* file = find(obj, "mesh")) mesh(b, *file, path.member("mesh"));
    if (b.polygons.empty() && b.segments.empty() && b.points.empty())
      fail(path, "body has no features (needs at least one of polygons, segments, points, mesh)");

    if (const Node* solid = find(obj, "solid")) {
      const Path solid_path = path.member("solid");
      if (solid->kind != Node::Kind::Boolean) fail(solid_path, "expected true or false");
      // The inside of a solid counts as contact, and "inside" is only
      // defined for a closed surface (proofs/containment.md).
      if (solid->boolean) require_closed(b, solid_path);
      b.solid = solid->boolean;
    }
    if (const Node* mass = find(obj, "mass")) {
      b.mass = explicit_mass(*mass, path.member("mass"));
      b.mass_is_default = false;
    }
    if (const Node* m = find(obj, "motion")) motion(b, *m, path.member("motion"));
    if (const Node* t = find(obj, "tolerance")) b.tolerance = non_negative(*t, path.member("tolerance"));
    if (!b.mass_is_default) normalise_mass_scale(b);
    return b;
  }

  // Mass weights far outside the double range (1e400, 1e-400) would
  // overflow or vanish in every enclosure of the body's metric.  The
  // metric's norm scales with the square root of the weights, so weights
  // multiplied by 100^-m and the tolerance (a length in that metric) by
  // 10^-m give the same set of admissible motions, the same distances and
  // the same verdicts, exactly (proofs/input-exactness.md); a clearance is
  // turned into the metric from the weights as they are then.  Weights
  // whose largest is within (2^-32, 2^32) stay as written.
  static void normalise_mass_scale(Body& b) {
    long top = LONG_MIN;
    for (const Exact& w : b.mass.weights)
      top = std::max(top, static_cast<long>(mpz_sizeinbase(mpq_numref(w.mpq()), 2)) -
                              static_cast<long>(mpz_sizeinbase(mpq_denref(w.mpq()), 2)));
    if (top == LONG_MIN || (top > -32 && top < 32)) return;
    const long m = std::lround(static_cast<double>(top) * 0.30102999566398120 / 2);  // 100^m ~ 2^top
    CGAL::Gmpz ten;
    mpz_ui_pow_ui(ten.mpz(), 10, static_cast<unsigned long>(m < 0 ? -m : m));
    const Exact length = m > 0 ? Exact(CGAL::Gmpz(1), ten) : Exact(ten);  // 10^-m
    const Exact weight = length * length;                                 // 100^-m
    for (Exact& w : b.mass.weights) w *= weight;
    b.tolerance *= length;
  }

  Exact non_negative(const Node& node, const Path& path) const {
    const Exact value = number(node, path);
    if (value < 0) fail(path, "must not be negative");
    return value;
  }

  void polygon(Body& b, const Node& node, const Path& path) const {
    const std::span<const Node> list = array(node, path);
    if (list.size() < 3)
      fail(path, "a polygon needs at least 3 vertices, got " + std::to_string(list.size()));
    if (list.size() > kMaxPolygonVertices)
      fail(path, "polygon has more than " + std::to_string(kMaxPolygonVertices) + " vertices");
    const std::vector<Vec3E> vertices = points(node, path);
    try {
      auto [clean, pieces] = split_polygon(vertices, static_cast<int>(b.polygons.size()));
      b.polygons.push_back(std::move(clean));
      for (ConvexPiece& piece : pieces) b.pieces.push_back(std::move(piece));
    } catch (const InputError& e) {
      fail(path, e.what());
    }
  }

  // "mesh": a file name relative to the scene file's directory.  Each face
  // becomes a polygon through the same checks as explicit polygons; an
  // error names the file and the face.
  void mesh(Body& b, const Node& node, const Path& path) const {
    const std::string name(text(node));
    if (node.kind != Node::Kind::String || name.empty())
      fail(path, std::string("expected a mesh file name (a non-empty string), got ") +
                     (node.kind == Node::Kind::String ? "an empty string" : kind_name(node.kind)));
    if (name.find('\0') != std::string::npos) fail(path, "file name contains a NUL character");
    const std::string file = (base_ / std::filesystem::path(name)).string();
    MeshData data;
    try {
      data = read_mesh(file);
    } catch (const InputError& e) {
      fail(path, one_line(e.what()));
    }
    if (data.faces.empty()) fail(path, file + ": mesh has no faces");
    if (data.from_floats)
      notes_.push_back(source_ + ": " + path.str() + ": mesh " + file + " (" + data.format +
                       ") is read from its single-precision floats: its coordinates are their exact values");
    std::vector<Vec3E> vertices;
    MeshFaceCounts counts;
    for (std::size_t f = 0; f < data.faces.size(); ++f) {
      const std::vector<std::size_t>& face = data.faces[f];
      vertices.clear();
      for (std::size_t index : face) vertices.push_back(data.vertices[index]);
      try {
        add_mesh_face(b, vertices, f, counts);
      } catch (const InputError& e) {
        fail(path, file + ": face " + std::to_string(f) + ": " + e.what());
      }
    }
    const std::string where = located(source_, path.str(), file + ": ");
    if (counts.fans > 0)
      notes_.push_back(where + count_text(counts.fans, "face is", "faces are") + " not exactly planar (" +
                       faces_text(counts.fan_faces, counts.fans) + "): each is split into the triangles of a fan from its " +
                       "first vertex, " + count_text(counts.fan_triangles, "triangle", "triangles") + " in all" +
                       (counts.fan_degenerate > 0 ? " (" + std::to_string(counts.fan_degenerate) + " of zero area, read as segments)" : "") +
                       "; the body is these triangles");
    if (counts.degenerate > 0)
      notes_.push_back(where + count_text(counts.degenerate, "face has", "faces have") + " zero area (" +
                       faces_text(counts.degenerate_faces, counts.degenerate) + "): " +
                       (counts.degenerate == 1 ? "it is" : "each is") + " read as the segment (or point) it covers");
  }

  // What add_mesh_face did beyond plain polygons, for the body's notes.
  struct MeshFaceCounts {
    std::size_t fans = 0, fan_triangles = 0, fan_degenerate = 0, degenerate = 0;
    std::vector<std::size_t> fan_faces, degenerate_faces;  // the first few face numbers
  };
  static constexpr std::size_t kFacesNamed = 5;

  static std::string count_text(std::size_t n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
  }
  static std::string faces_text(const std::vector<std::size_t>& faces, std::size_t total) {
    std::string out = total == 1 ? "face " : "faces ";
    for (std::size_t k = 0; k < faces.size(); ++k) out += (k ? ", " : "") + std::to_string(faces[k]);
    if (total > faces.size()) out += ", ...";
    return out;
  }

  // A face of a mesh file (docs/scene-format.md, "Data from real
  // pipelines"; proofs/mesh-faces.md):
  //  * all vertices collinear (zero area; a triangle with a repeated
  //    vertex too): the segment between its two extreme vertices, which is
  //    exactly the face's point set (a point when all are equal);
  //  * not exactly planar: the triangles (v0, v_k, v_k+1) of the fan from
  //    its first vertex, each as a polygon (or, when of zero area, as its
  //    segment); the fan's boundary is the face's boundary loop;
  //  * otherwise the polygon checks of inline polygons (split_polygon).
  void add_mesh_face(Body& b, const std::vector<Vec3E>& v, std::size_t face, MeshFaceCounts& counts) const {
    const std::size_t n = v.size();
    std::size_t i = 1;
    while (i < n && v[i] == v[0]) ++i;
    Vec3E normal{0, 0, 0};
    if (i < n) {
      const Vec3E d = sub(v[i], v[0]);
      for (std::size_t j = i + 1; j < n && is_zero(normal); ++j) normal = cross(d, sub(v[j], v[0]));
    }
    if (is_zero(normal)) {  // collinear (or a single point)
      add_degenerate(b, v);
      if (counts.degenerate++ < kFacesNamed) counts.degenerate_faces.push_back(face);
      return;
    }
    bool planar = true;
    for (std::size_t k = 1; k < n && planar; ++k) planar = dot(normal, sub(v[k], v[0])) == 0;
    if (planar) {
      auto [clean, pieces] = split_polygon(v, static_cast<int>(b.polygons.size()));
      b.polygons.push_back(std::move(clean));
      for (ConvexPiece& piece : pieces) b.pieces.push_back(std::move(piece));
      return;
    }
    if (counts.fans++ < kFacesNamed) counts.fan_faces.push_back(face);
    for (std::size_t k = 1; k + 1 < n; ++k) {
      const std::vector<Vec3E> triangle = {v[0], v[k], v[k + 1]};
      ++counts.fan_triangles;
      if (is_zero(cross(sub(v[k], v[0]), sub(v[k + 1], v[0])))) {
        add_degenerate(b, triangle);
        ++counts.fan_degenerate;
        continue;
      }
      auto [clean, pieces] = split_polygon(triangle, static_cast<int>(b.polygons.size()));
      b.polygons.push_back(std::move(clean));
      for (ConvexPiece& piece : pieces) b.pieces.push_back(std::move(piece));
    }
  }

  // Collinear points: the segment between the two extreme ones along their
  // line (their convex hull, exactly), or the point when all are equal.
  static void add_degenerate(Body& b, const std::vector<Vec3E>& v) {
    std::size_t i = 1;
    while (i < v.size() && v[i] == v[0]) ++i;
    if (i == v.size()) {
      b.points.push_back(v[0]);
      return;
    }
    const Vec3E d = sub(v[i], v[0]);
    std::size_t lo = 0, hi = 0;
    Exact s_lo = 0, s_hi = 0;
    for (std::size_t k = 1; k < v.size(); ++k) {
      const Exact s = dot(d, sub(v[k], v[0]));
      if (s < s_lo) s_lo = s, lo = k;
      if (s > s_hi) s_hi = s, hi = k;
    }
    b.segments.push_back({v[lo], v[hi]});
  }

  void require_closed(const Body& b, const Path& path) const {
    std::string problem = solid_problem(b);
    if (problem.empty()) problem = shell_intersection_problem(b);
    if (!problem.empty()) fail(path, problem);
  }

  MassDistribution explicit_mass(const Node& node, const Path& path) const {
    const Members obj = object(node, path);
    reject_unknown_keys(obj, path, {"points", "weights"});
    const Node* pts = find(obj, "points");
    if (!pts) fail(path.member("points"), "missing required field");
    const Node* weights = find(obj, "weights");
    if (!weights) fail(path.member("weights"), "missing required field");
    MassDistribution mass;
    mass.points = points(*pts, path.member("points"));
    if (mass.points.empty()) fail(path.member("points"), "at least one mass point is required");
    mass.weights = positive_weights(*weights, path.member("weights"), mass.points.size(), "mass point");
    try {
      Metric::require_positive_definite(mass);
    } catch (const InputError& e) {
      fail(path, e.what());
    }
    return mass;
  }

  // `count` weights, each > 0 (one per point / control point).
  std::vector<Exact> positive_weights(const Node& node, const Path& path, std::size_t count,
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
  // when keyframes or pieces reduce to one exactly), anything else becomes
  // a trajectory of segments.
  void motion(Body& b, const Node& node, const Path& path) const {
    std::vector<MotionSegment> segments;
    std::optional<Motion> single = motion_segments(node, path, segments);
    if (single) {
      b.motion = std::move(single);
      return;
    }
    if (segments.size() == 1 && segments[0].rational) {
      b.motion = segments[0].rational;
      return;
    }
    b.trajectory = Trajectory{std::move(segments)};
  }

  // Appends the segments of a motion; returns a motionless or one-curve
  // rational_bezier motion instead, as it is.
  std::optional<Motion> motion_segments(const Node& node, const Path& path, std::vector<MotionSegment>& out) const {
    const Members obj = object(node, path);
    const Path type_path = path.member("type");
    const Node* type = find(obj, "type");
    if (!type) fail(type_path, "missing required field (e.g. \"rational_bezier\")");
    const std::string kind = type->kind == Node::Kind::String ? std::string(text(*type)) : std::string();
    if (kind == "keyframes") {
      keyframes(obj, path, out);
      return std::nullopt;
    }
    if (kind == "piecewise") {
      piecewise(obj, path, out);
      return std::nullopt;
    }
    if (kind != "rational_bezier")
      fail(type_path, "unknown motion type " + describe(*type) +
                          " (supported: \"rational_bezier\", \"keyframes\", \"piecewise\")");
    Motion m = rational_bezier(obj, path);
    if (m.degree() >= 1) {
      MotionSegment seg;
      seg.t0 = m.t0;
      seg.t1 = m.t1;
      seg.rational = m;
      out.push_back(std::move(seg));
    }
    return m;
  }

  // {"translation": [x, y, z], "rotation": {...}} (SCENE_FORMAT.md "Rigid poses").
  Pose pose(const Node& node, const Path& path) const {
    const Members obj = object(node, path);
    reject_unknown_keys(obj, path, {"translation", "rotation"});
    Pose p;
    if (const Node* t = find(obj, "translation")) p.translation = point(*t, path.member("translation"));
    if (const Node* r = find(obj, "rotation")) {
      const Path rpath = path.member("rotation");
      const Members rot = object(*r, rpath);
      reject_unknown_keys(rot, rpath, {"quaternion", "rpy", "matrix"});
      const Node* q = find(rot, "quaternion");
      const Node* e = find(rot, "rpy");
      const Node* m = find(rot, "matrix");
      if ((q ? 1 : 0) + (e ? 1 : 0) + (m ? 1 : 0) != 1)
        fail(rpath, "a rotation is exactly one of \"quaternion\", \"rpy\" or \"matrix\"");
      if (q) {
        const Path qpath = rpath.member("quaternion");
        const std::span<const Node> items = array(*q, qpath);
        if (items.size() != 4) fail(qpath, "a quaternion is [w, x, y, z]: expected 4 numbers, got " + std::to_string(items.size()));
        p.rotation.kind = Rotation::Kind::Quaternion;
        for (int i = 0; i < 4; ++i) p.rotation.quaternion[i] = number(items[i], qpath.index(i));
        if (std::all_of(p.rotation.quaternion.begin(), p.rotation.quaternion.end(), [](const Exact& x) { return x == 0; }))
          fail(qpath, "the quaternion is zero (it has no rotation)");
      } else if (e) {
        const Path epath = rpath.member("rpy");
        const std::span<const Node> items = array(*e, epath);
        if (items.size() != 3) fail(epath, "rpy is [roll, pitch, yaw] in radians: expected 3 numbers, got " + std::to_string(items.size()));
        p.rotation.kind = Rotation::Kind::Rpy;
        for (int i = 0; i < 3; ++i) {
          p.rotation.rpy[i] = number(items[i], epath.index(i));
          // Far beyond any angle: the enclosures of sin and cos would be [-1, 1].
          if (CGAL::abs(p.rotation.rpy[i]) > 1000000) fail(epath.index(i), "angle out of range (at most 10^6 radians)");
          // Above 2 pi: likely degrees.  Read as radians, as documented, and said.
          if (CGAL::abs(p.rotation.rpy[i]) > two_pi_above()) warnings_.push_back(rpy_warning(epath.index(i), p.rotation.rpy[i]));
        }
      } else {
        const Path mpath = rpath.member("matrix");
        const std::span<const Node> rows = array(*m, mpath);
        if (rows.size() != 3) fail(mpath, "a rotation matrix has 3 rows, got " + std::to_string(rows.size()));
        p.rotation.kind = Rotation::Kind::Matrix;
        for (std::size_t r = 0; r < 3; ++r) {
          const Path row_path = mpath.index(r);
          const std::span<const Node> row = array(rows[r], row_path);
          if (row.size() != 3) fail(row_path, "a rotation matrix row has 3 numbers, got " + std::to_string(row.size()));
          for (std::size_t c = 0; c < 3; ++c) p.rotation.matrix[3 * r + c] = number(row[c], row_path.index(c));
        }
        if (const std::string problem = rotation_matrix_problem(p.rotation.matrix); !problem.empty())
          fail(mpath, "not a rotation: " + problem + nearest_quaternion_hint(p.rotation.matrix));
      }
    }
    return p;
  }

  // Strictly increasing parameter values, `count` of them.
  std::vector<Exact> times(const Node& node, const Path& path, std::size_t count, const std::string& per) const {
    const std::span<const Node> list = array(node, path);
    if (list.size() != count)
      fail(path, "expected " + std::to_string(count) + " times (one per " + per + "), got " + std::to_string(list.size()));
    std::vector<Exact> out;
    for (std::size_t i = 0; i < count; ++i) {
      out.push_back(number(list[i], path.index(i)));
      if (i > 0 && !(out[i - 1] < out[i])) fail(path.index(i), "times must be strictly increasing");
    }
    return out;
  }

  void keyframes(const Members& obj, const Path& path, std::vector<MotionSegment>& out) const {
    reject_unknown_keys(obj, path, {"type", "interpolation", "times", "poses"});
    Interpolation how = Interpolation::Slerp;
    if (const Node* i = find(obj, "interpolation")) {
      const Path ipath = path.member("interpolation");
      const std::string name = i->kind == Node::Kind::String ? std::string(text(*i)) : std::string();
      if (name == "slerp") how = Interpolation::Slerp;
      else if (name == "screw") how = Interpolation::Screw;
      else if (name == "nlerp") how = Interpolation::Nlerp;
      else fail(ipath, "unknown interpolation " + describe(*i) + " (supported: \"slerp\", \"screw\", \"nlerp\")");
    }
    const Path ppath = path.member("poses");
    const Node* poses_node = find(obj, "poses");
    if (!poses_node) fail(ppath, "missing required field");
    const std::span<const Node> list = array(*poses_node, ppath);
    if (list.size() < 2) fail(ppath, "keyframes need at least 2 poses, got " + std::to_string(list.size()));
    std::vector<Pose> poses;
    for (std::size_t k = 0; k < list.size(); ++k) poses.push_back(pose(list[k], ppath.index(k)));
    std::vector<Exact> t;
    if (const Node* tn = find(obj, "times")) {
      t = times(*tn, path.member("times"), poses.size(), "pose");
    } else {
      for (std::size_t k = 0; k < poses.size(); ++k) t.push_back(Exact(static_cast<long>(k)) / Exact(static_cast<long>(poses.size() - 1)));
    }
    for (std::size_t k = 0; k + 1 < poses.size(); ++k) {
      try {
        require_interpolable(poses[k], poses[k + 1], how);
      } catch (const InputError& e) {
        fail(ppath.index(k + 1), std::string(e.what()) + " (from poses[" + std::to_string(k) + "])");
      }
      MotionSegment seg;
      seg.t0 = t[k];
      seg.t1 = t[k + 1];
      seg.from = poses[k];
      seg.to = poses[k + 1];
      seg.interpolation = how;
      seg.rational = rational_keyframe_segment(poses[k], poses[k + 1], how, t[k], t[k + 1]);
      out.push_back(std::move(seg));
    }
  }

  void piecewise(const Members& obj, const Path& path, std::vector<MotionSegment>& out) const {
    reject_unknown_keys(obj, path, {"type", "pieces"});
    const Path ppath = path.member("pieces");
    const Node* pieces = find(obj, "pieces");
    if (!pieces) fail(ppath, "missing required field");
    const std::span<const Node> list = array(*pieces, ppath);
    if (list.empty()) fail(ppath, "at least one piece is required");
    for (std::size_t k = 0; k < list.size(); ++k) {
      const Path piece_path = ppath.index(k);
      std::vector<MotionSegment> segs;
      const std::optional<Motion> still = motion_segments(list[k], piece_path, segs);
      if (segs.empty()) fail(piece_path, "a piece must move over an interval (one control point is a pose, not a motion)");
      (void)still;
      if (!out.empty()) {
        const MotionSegment& prev = out.back();
        const MotionSegment& next = segs.front();
        const std::string join = "join with pieces[" + std::to_string(k - 1) + "]";
        if (prev.t1 != next.t0)
          fail(piece_path, join + ": the intervals do not abut (the previous piece ends at " + to_string(prev.t1) +
                               ", this one starts at " + to_string(next.t0) + ")");
        const std::optional<Mat34E> end = segment_end(prev, true), start = segment_end(next, false);
        if (end && start) {
          if (*end != *start) fail(piece_path, join + ": the poses differ at t = " + to_string(next.t0) + " (a jump)");
        } else if (!(!prev.rational && !next.rational && same_pose(prev.to, next.from))) {
          fail(piece_path, join + ": the poses at t = " + to_string(next.t0) +
                               " cannot be proven equal (an rpy pose must be written the same way on both sides)");
        }
      }
      for (MotionSegment& seg : segs) out.push_back(std::move(seg));
    }
  }

  static bool same_pose(const Pose& a, const Pose& b) {
    if (a.translation != b.translation || a.rotation.kind != b.rotation.kind) return false;
    return a.rotation.kind != Rotation::Kind::Rpy || a.rotation.rpy == b.rotation.rpy;
  }

  // The exact pose at a segment's end (`last`) or start, when it is exact.
  static std::optional<Mat34E> segment_end(const MotionSegment& seg, bool last) {
    if (seg.rational) return motion_pose(*seg.rational, last ? seg.t1 : seg.t0);
    return exact_pose(last ? seg.to : seg.from);
  }

  Motion rational_bezier(const Members& obj, const Path& path) const {
    reject_unknown_keys(obj, path, {"type", "interval", "control_points", "weights"});

    Motion m;
    if (const Node* interval = find(obj, "interval")) {
      const Path interval_path = path.member("interval");
      const std::span<const Node> ends = array(*interval, interval_path);
      if (ends.size() != 2)
        fail(interval_path, "expected [t0, t1], got " + std::to_string(ends.size()) + " values");
      m.t0 = number(ends[0], interval_path.index(0));
      m.t1 = number(ends[1], interval_path.index(1));
      if (!(m.t0 < m.t1)) fail(interval_path, "interval start must be less than its end");
    }
    const Path cp_path = path.member("control_points");
    const Node* cps = find(obj, "control_points");
    if (!cps) fail(cp_path, "missing required field");
    const std::span<const Node> list = array(*cps, cp_path);
    if (list.empty()) fail(cp_path, "at least one control point is required");
    m.control_points.reserve(list.size());
    for (std::size_t k = 0; k < list.size(); ++k)
      m.control_points.push_back(affine(list[k], cp_path.index(k)));
    if (const Node* weights = find(obj, "weights"))
      m.weights = positive_weights(*weights, path.member("weights"), list.size(), "control point");
    else
      m.weights.assign(list.size(), Exact(1));
    normalise_weights(m);  // the same curve; weights of 1e400 would overflow every enclosure
    return m;
  }

  // Default masses need the size of the whole scene, so they come after all
  // bodies are read.  Every mass, default or not, must give a metric.
  void assign_masses(Scene& scene, const Path& bodies_path) const {
    auto vertices_of = [](const Body& b) {
      std::vector<Vec3E> v;
      for (const auto& polygon : b.polygons) v.insert(v.end(), polygon.begin(), polygon.end());
      for (const auto& segment : b.segments) v.insert(v.end(), segment.begin(), segment.end());
      v.insert(v.end(), b.points.begin(), b.points.end());
      return v;
    };
    const Exact size = default_mass_fallback_size(scene.bodies);

    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
      Body& b = scene.bodies[i];
      if (!b.mass_is_default) continue;
      b.mass = default_mass(vertices_of(b), size);
      try {
        Metric::require_positive_definite(b.mass);
      } catch (const InputError& e) {  // default_mass promises this cannot happen
        fail(bodies_path.index(i), std::string("default mass: ") + e.what());
      }
    }
  }

  std::vector<std::pair<int, int>> explicit_checks(const Node& node, const Path& checks_path,
                                                   const std::unordered_map<std::string, std::size_t>& names,
                                                   std::vector<std::optional<Exact>>& clearances) const {
    const std::span<const Node> list = array(node, checks_path);
    std::vector<std::pair<int, int>> out;
    std::map<std::pair<int, int>, std::size_t> seen;  // unordered pair -> where it was written
    std::set<std::pair<int, int>> expanded;           // the pairs checked
    for (std::size_t k = 0; k < list.size(); ++k) {
      const Path item_path = checks_path.index(k);
      const Path bodies_path = item_path.member("bodies");
      const Path* where = &item_path;
      const Node* pair_node = &list[k];
      clearances.emplace_back();
      if (list[k].kind == Node::Kind::Object) {
        // {"bodies": ["a", "b"], "clearance": d}
        const Members obj = object(list[k], item_path);
        reject_unknown_keys(obj, item_path, {"bodies", "clearance"});
        if (const Node* c = find(obj, "clearance")) clearances.back() = non_negative(*c, item_path.member("clearance"));
        pair_node = find(obj, "bodies");
        if (!pair_node) fail(bodies_path, "missing required field");
        where = &bodies_path;
      }
      const Path& path = *where;
      const std::span<const Node> pair = array(*pair_node, path);
      if (pair.size() != 2)
        fail(path, "a check names exactly 2 bodies, got " + std::to_string(pair.size()));
      int idx[2];
      for (std::size_t s = 0; s < 2; ++s) {
        const Path side = path.index(s);
        const Node& name = pair[s];
        if (name.kind != Node::Kind::String) fail(side, std::string("expected a body name, got ") + kind_name(name.kind));
        const std::string written(text(name));
        const auto it = names.find(written);
        if (it == names.end()) fail(side, "unknown body " + quote_text(written));
        idx[s] = static_cast<int>(it->second);
      }
      if (idx[0] == idx[1]) fail(path, "a body cannot be checked against itself");
      const auto key = std::minmax(idx[0], idx[1]);
      if (auto [it, fresh] = seen.emplace(key, k); !fresh)
        fail(path, "duplicate check (same pair as " + index_path("checks", it->second) + ")");
      // A robot link of several bodies (robot.h LinkPart) named by its
      // first: every part of it, each pair once.
      const std::optional<Exact> clearance = clearances.back();
      clearances.pop_back();
      auto parts = [&](int b) {
        const auto it = link_parts_.find(b);
        return it == link_parts_.end() ? std::vector<int>{b} : it->second;
      };
      for (int a : parts(idx[0]))
        for (int b : parts(idx[1])) {
          if (a == b || !expanded.insert(std::minmax(a, b)).second) continue;
          out.emplace_back(a, b);
          clearances.push_back(clearance);
        }
    }
    return out;
  }

  // A joint-space path's "times" and "positions" (exact numbers; their
  // meaning is checked by validate_joint_path).
  void joint_path_values(const Node& node, const Path& path, JointPath& jp) const {
    const Members pobj = object(node, path);
    reject_unknown_keys(pobj, path, {"times", "positions"});
    const Path tpath = path.member("times"), qpath = path.member("positions");
    const Node* times_node = find(pobj, "times");
    if (!times_node) fail(tpath, "missing required field");
    for (std::size_t k = 0; const Node& t : array(*times_node, tpath)) jp.times.push_back(number(t, tpath.index(k++)));
    const Node* positions = find(pobj, "positions");
    if (!positions) fail(qpath, "missing required field");
    const std::span<const Node> rows = array(*positions, qpath);
    for (std::size_t k = 0; k < rows.size(); ++k) {
      const Path row_path = qpath.index(k);
      std::vector<Exact> row;
      for (std::size_t c = 0; const Node& v : array(rows[k], row_path)) row.push_back(number(v, row_path.index(c++)));
      jp.positions.push_back(std::move(row));
    }
  }

  // A robot of the scene after its links were added (for default checks).
  struct RobotInScene {
    std::shared_ptr<const PlacedRobot> robot;
    RobotBodies bodies;
    std::vector<std::string> joints;
    bool self_collision = false;
    std::vector<std::pair<std::string, std::string>> allowed;
  };

  // "robots" (SCENE_FORMAT.md "Robots from URDF, moving in joint space"):
  // each adds a body "<robot>/<link>" per link with collision geometry.
  std::vector<RobotInScene> robots(Scene& scene, const Node& node, const Path& path,
                                   std::unordered_map<std::string, std::size_t>& names) const {
    const std::span<const Node> list = array(node, path);
    std::vector<RobotInScene> out;
    std::map<std::string, std::shared_ptr<const RobotModel>> loaded;  // by file
    std::set<std::string> robot_names;
    for (std::size_t r = 0; r < list.size(); ++r) {
      const Path rpath = path.index(r);
      const Members obj = object(list[r], rpath);
      reject_unknown_keys(obj, rpath, {"name", "urdf", "base", "joints", "path", "self_collision", "allowed_pairs", "srdf"});
      auto string_field = [&](const char* key) {
        const Node* n = find(obj, key);
        if (!n) fail(rpath.member(key), "missing required field");
        if (n->kind != Node::Kind::String || text(*n).empty()) fail(rpath.member(key), "expected a non-empty string");
        return std::string(text(*n));
      };
      const std::string name = string_field("name");
      for (char c : name)
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7F)
          fail(rpath.member("name"), "a robot name cannot contain control characters");
      if (!robot_names.insert(name).second) fail(rpath.member("name"), "duplicate robot name " + quote_text(name));
      const std::string urdf = string_field("urdf");
      if (urdf.find('\0') != std::string::npos) fail(rpath.member("urdf"), "file name contains a NUL character");
      const std::string file = (base_ / std::filesystem::path(urdf)).string();
      std::shared_ptr<const RobotModel>& model = loaded[file];
      if (!model) {
        try {
          model = load_urdf(file, urdf_options());
        } catch (const InputError& e) {
          fail(rpath.member("urdf"), one_line(e.what()));
        }
        notes_.insert(notes_.end(), model->notes.begin(), model->notes.end());
      }
      Pose base;
      if (const Node* b = find(obj, "base")) base = pose(*b, rpath.member("base"));
      JointPath jp;
      const Path jpath = rpath.member("joints");
      const Node* joints = find(obj, "joints");
      if (!joints) fail(jpath, "missing required field");
      const std::span<const Node> jlist = array(*joints, jpath);
      for (std::size_t c = 0; c < jlist.size(); ++c) {
        if (jlist[c].kind != Node::Kind::String) fail(jpath.index(c), "expected a joint name (a string)");
        jp.joints.emplace_back(text(jlist[c]));
      }
      const Path ppath = rpath.member("path");
      const Node* pnode = find(obj, "path");
      if (!pnode) fail(ppath, "missing required field");
      joint_path_values(*pnode, ppath, jp);
      const Path tpath = ppath.member("times"), qpath = ppath.member("positions");
      RobotInScene placed;
      placed.joints = jp.joints;
      placed.robot = std::make_shared<const PlacedRobot>(model, name, base);
      try {
        placed.bodies = add_robot(scene, *placed.robot, jp);
      } catch (const JointPathError& e) {
        const Path& field = e.field == "joints" ? jpath : e.field == "times" ? tpath : qpath;
        if (e.index.empty()) fail(field, e.what());
        const Path first = field.index(e.index[0]);
        if (e.index.size() == 1) fail(first, e.what());
        fail(first.index(e.index[1]), e.what());
      }
      for (const std::vector<int>& parts : placed.bodies.parts) {
        for (int b : parts) {
          const std::string& body_name = scene.bodies[b].name;
          if (auto [it, fresh] = names.emplace(body_name, static_cast<std::size_t>(b)); !fresh)
            fail(rpath.member("name"), "the link body " + quote_text(body_name) + " has the name of another body");
        }
        if (parts.size() > 1) link_parts_[parts.front()] = parts;
      }
      if (const Node* sc = find(obj, "self_collision")) {
        if (sc->kind != Node::Kind::Boolean) fail(rpath.member("self_collision"), "expected true or false");
        placed.self_collision = sc->boolean;
      }
      if (const Node* ap = find(obj, "allowed_pairs")) {
        const Path apath = rpath.member("allowed_pairs");
        const std::span<const Node> pairs = array(*ap, apath);
        for (std::size_t k = 0; k < pairs.size(); ++k) {
          const Path pair_path = apath.index(k);
          const std::span<const Node> pair = array(pairs[k], pair_path);
          if (pair.size() != 2) fail(pair_path, "an allowed pair names exactly 2 links, got " + std::to_string(pair.size()));
          std::string links[2];
          for (std::size_t s = 0; s < 2; ++s) {
            if (pair[s].kind != Node::Kind::String) fail(pair_path.index(s), "expected a link name (a string)");
            links[s] = std::string(text(pair[s]));
            if (model->link_index(links[s]) < 0)
              fail(pair_path.index(s), "unknown link " + quote_text(links[s]) + " (not in " + model->source + ")");
          }
          placed.allowed.emplace_back(links[0], links[1]);
        }
      }
      if (const Node* sr = find(obj, "srdf")) {
        // MoveIt's allowed self-collisions: every <disable_collisions>.
        const Path spath = rpath.member("srdf");
        if (sr->kind != Node::Kind::String || text(*sr).empty()) fail(spath, "expected a non-empty string (an SRDF file)");
        const std::string srdf(text(*sr));
        if (srdf.find('\0') != std::string::npos) fail(spath, "file name contains a NUL character");
        try {
          for (auto& pair : read_srdf((base_ / std::filesystem::path(srdf)).string(), *model)) placed.allowed.push_back(pair);
        } catch (const InputError& e) {
          fail(spath, one_line(e.what()));
        }
      }
      out.push_back(std::move(placed));
    }
    return out;
  }

  // The default checks with robots: the general rule among the bodies
  // that are not links, then each robot's rule (every link against every
  // body not of that robot; self-collision pairs), each pair once.
  static std::vector<std::pair<int, int>> default_checks_with_robots(const Scene& scene, std::size_t plain_bodies,
                                                                     const std::vector<RobotInScene>& robots) {
    Scene plain;
    plain.bodies.assign(scene.bodies.begin(), scene.bodies.begin() + static_cast<std::ptrdiff_t>(plain_bodies));
    std::vector<std::pair<int, int>> out = default_checks(plain);
    if (robots.empty()) return out;
    std::set<std::pair<int, int>> seen;
    for (const auto& [a, b] : out) seen.insert(std::minmax(a, b));
    for (const RobotInScene& r : robots) {
      std::set<int> own;
      for (const std::vector<int>& parts : r.bodies.parts) own.insert(parts.begin(), parts.end());
      std::vector<int> environment;
      for (int b = 0; b < static_cast<int>(scene.bodies.size()); ++b)
        if (!own.count(b)) environment.push_back(b);
      for (const auto& [a, b] : robot_default_checks(*r.robot, r.bodies, environment, r.self_collision, r.allowed))
        if (seen.insert(std::minmax(a, b)).second) out.emplace_back(a, b);
    }
    return out;
  }

  // Every pair with at least one moving body, once, in body order.
  static std::vector<std::pair<int, int>> default_checks(const Scene& scene) {
    std::vector<std::pair<int, int>> out;
    const int n = static_cast<int>(scene.bodies.size());
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j)
        if (scene.bodies[i].motion || scene.bodies[i].trajectory || scene.bodies[j].motion || scene.bodies[j].trajectory)
          out.emplace_back(i, j);
    return out;
  }

  std::string source_;
  std::filesystem::path base_;
  const Tree& tree_;
  ReadOptions options_;
  std::vector<std::string> scene_packages_;        // "package_paths", resolved
  mutable std::map<int, std::vector<int>> link_parts_;  // a link's first body -> all its bodies
  mutable std::vector<std::string> notes_, warnings_;  // Scene::notes, Scene::warnings

 public:
  std::vector<std::string> take_notes() { return std::move(notes_); }
  std::vector<std::string> take_warnings() { return std::move(warnings_); }
  // Where read() puts the scene's robots (none: nowhere).
  std::vector<SceneRobot>* robots_out_ = nullptr;
};

Scene parse_with_base(const std::string& text, const std::string& source, const std::filesystem::path& base) {
  const Tree tree = parse_json(text, source);
  return SceneReader(source, base, tree).read();
}

}  // namespace

std::pair<std::vector<Vec3E>, std::vector<ConvexPiece>> split_scene_polygon(const std::vector<Vec3E>& vertices,
                                                                            int index) {
  return split_polygon(vertices, index);
}

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

// Mesh files are relative to the directory of `source` when it names an
// existing file, otherwise to the current directory.
Scene parse_scene_text(const std::string& text, const std::string& source) {
  std::error_code ec;
  std::filesystem::path base;
  if (!source.empty() && std::filesystem::is_regular_file(source, ec)) base = std::filesystem::path(source).parent_path();
  const InputRecord record;
  Scene scene = parse_with_base(text, source, base);
  scene.input_files = record.files();
  return scene;
}

Scene parse_scene_text(const std::string& text, const std::string& source, const std::string& base,
                       std::vector<SceneRobot>& robots) {
  return parse_scene_text(text, source, base, robots, ReadOptions{});
}

Scene parse_scene_text(const std::string& text, const std::string& source, const std::string& base,
                       std::vector<SceneRobot>& robots, const ReadOptions& options) {
  const Tree tree = parse_json(text, source);
  const InputRecord record;
  SceneReader reader(source, base, tree, options);
  reader.robots_out_ = &robots;
  Scene scene = reader.read();
  scene.input_files = record.files();
  return scene;
}

void parse_request_line(const std::string& text, const std::string& source, const std::string& base,
                        RequestLine& out) {
  const Tree tree = parse_json(text, source);
  SceneReader reader(source, base, tree);
  reader.read_request(out);
  out.notes = reader.take_notes();
  out.warnings = reader.take_warnings();
}

namespace {

Scene read_scene_file(const std::string& path, std::vector<SceneRobot>* robots, const ReadOptions& options = {}) {
  const InputRecord record;  // the scene's files (Scene::input_files)
  // Only a regular file, and at most kMaxFileBytes of it (docs/scene-format.md).
  std::string text = read_regular_file(path, kMaxFileBytes);
  // The text goes once it is parsed: for a large scene it is a good part of
  // the memory that reading the scene takes.
  const Tree tree = parse_json(text, path);
  std::string().swap(text);
  SceneReader reader(path, std::filesystem::path(path).parent_path(), tree, options);
  reader.robots_out_ = robots;
  Scene scene = reader.read();
  scene.input_files = record.files();
  return scene;
}

}  // namespace

Scene parse_scene_file(const std::string& path, const ReadOptions& options, std::vector<SceneRobot>* robots) {
  return read_scene_file(path, robots, options);
}

Scene parse_scene_file(const std::string& path) { return read_scene_file(path, nullptr); }

Scene parse_scene_file(const std::string& path, std::vector<SceneRobot>& robots) {
  return read_scene_file(path, &robots);
}

}  // namespace tmcert
