// Mesh readers (mesh.h).  Every coordinate is exact: text tokens go through
// parse_exact (decimal forms only: "1e-3", "-0.5", "+2", ".5"; no "p/q",
// which none of the formats has), binary STL floats through their exact
// double value.  Errors name the file and the line (or triangle).
#include "src/io/mesh.h"

#include "src/io/read_file.h"

#include "src/model/model.h"

#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <map>
#include <sstream>
#include <string_view>
#include <utility>

namespace tmcert {

namespace {

// ---------------------------------------------------------------- messages

// A token from the file made safe for a one-line message.
std::string shown(std::string_view s) {
  constexpr std::size_t kShown = 40;
  std::string out = "\"";
  for (std::size_t i = 0; i < s.size() && i < kShown; ++i) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    if (c < 0x20 || c >= 0x7f) {
      static const char* hex = "0123456789abcdef";
      out += "\\x";
      out += hex[c >> 4];
      out += hex[c & 15];
    } else {
      if (c == '"' || c == '\\') out += '\\';
      out += static_cast<char>(c);
    }
  }
  if (s.size() > kShown) out += "...";
  return out + "\"";
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

class Reporter {
 public:
  explicit Reporter(std::string file) : file_(std::move(file)) {}
  [[noreturn]] void fail(const std::string& what) const { throw InputError(file_ + ": " + what); }
  [[noreturn]] void fail_line(std::size_t line, const std::string& what) const {
    throw InputError(file_ + ": line " + std::to_string(line) + ": " + what);
  }
  const std::string& file() const { return file_; }

 private:
  std::string file_;
};

// ---------------------------------------------------------------- text

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// Content lines of a text file, one at a time: split at "\n", "\r\n" or a
// lone "\r", the comment (from `comment` to the end of the line; '\0' for
// none) removed, tokenized at white space; lines without tokens are
// skipped.  With `continuation`, a line ending in a backslash goes on in
// the next one (OBJ); the joined line carries the number of its first
// line.  Tokens stay valid until the next call of next().
class LineReader {
 public:
  LineReader(const std::string& text, char comment, bool continuation)
      : text_(text), comment_(comment), continuation_(continuation) {}

  bool next() {
    tokens.clear();
    joined_.clear();
    bool joining = false;
    while (pos_ < text_.size()) {
      std::size_t end = pos_;
      while (end < text_.size() && text_[end] != '\n' && text_[end] != '\r') ++end;
      std::string_view raw(text_.data() + pos_, end - pos_);
      ++physical_;
      if (end < text_.size() && text_[end] == '\r' && end + 1 < text_.size() && text_[end + 1] == '\n') ++end;
      pos_ = end + 1;
      if (comment_) {
        const std::size_t hash = raw.find(comment_);
        if (hash != std::string_view::npos) raw = raw.substr(0, hash);
      }
      if (!joining) number = physical_;
      if (continuation_) {
        std::string_view body = raw;
        while (!body.empty() && is_space(body.back())) body.remove_suffix(1);
        if (!body.empty() && body.back() == '\\') {
          joined_.append(body.substr(0, body.size() - 1));
          joined_ += ' ';
          joining = true;
          continue;
        }
        if (joining) {
          joined_.append(raw);
          split(joined_);
          if (!tokens.empty()) return true;
          joined_.clear();
          joining = false;
          continue;
        }
      }
      split(raw);
      if (!tokens.empty()) return true;
    }
    if (joining) {  // a backslash on the last line
      split(joined_);
      if (!tokens.empty()) return true;
    }
    return false;
  }

  std::size_t number = 0;                 // line number of the current line
  std::vector<std::string_view> tokens;   // its tokens
  // Line number just past the end, for "unexpected end of file".
  std::size_t end_line() const { return physical_ + 1; }

 private:
  void split(std::string_view text) {
    std::size_t i = 0;
    while (i < text.size()) {
      while (i < text.size() && is_space(text[i])) ++i;
      const std::size_t start = i;
      while (i < text.size() && !is_space(text[i])) ++i;
      if (i > start) tokens.push_back(text.substr(start, i - start));
    }
  }

  const std::string& text_;
  char comment_;
  bool continuation_;
  std::size_t pos_ = 0, physical_ = 0;
  std::string joined_;
};

// A coordinate: a decimal as the formats write it ("1e-3", "-0.5", "+2",
// ".5"), read exactly.  No "p/q": none of the formats has it.
bool read_number(std::string_view token, Exact& out) {
  if (token.find('/') != std::string_view::npos) return false;
  return parse_exact(std::string(token), out) && within_input_limit(out);
}

// A non-negative decimal integer (an optional '+' allowed).
bool read_unsigned(std::string_view token, std::uint64_t& out) {
  if (!token.empty() && token[0] == '+') token.remove_prefix(1);
  if (token.empty() || !std::isdigit(static_cast<unsigned char>(token[0]))) return false;
  const auto [ptr, ec] = std::from_chars(token.data(), token.data() + token.size(), out);
  return ec == std::errc() && ptr == token.data() + token.size();
}

// A decimal integer with an optional sign.
bool read_signed(std::string_view token, std::int64_t& out) {
  bool negative = false;
  if (!token.empty() && (token[0] == '+' || token[0] == '-')) {
    negative = token[0] == '-';
    token.remove_prefix(1);
  }
  std::uint64_t magnitude = 0;
  if (token.empty() || !std::isdigit(static_cast<unsigned char>(token[0])) || !read_unsigned(token, magnitude))
    return false;
  if (magnitude > static_cast<std::uint64_t>(INT64_MAX)) return false;
  out = negative ? -static_cast<std::int64_t>(magnitude) : static_cast<std::int64_t>(magnitude);
  return true;
}

std::string count_text(std::uint64_t n, const char* singular, const char* plural) {
  return std::to_string(n) + " " + (n == 1 ? singular : plural);
}

// ---------------------------------------------------------------- OFF

// [ST][C][N][4][n]OFF (Geomview; the prefix letters are case-sensitive,
// N normals and n dimension, "OFF" is not).  Returns false if the token is
// not such a keyword; sets the flags for 4 and n.
bool off_keyword(std::string_view token, bool& homogeneous, bool& ndim) {
  if (token.size() < 3 || lower(std::string(token.substr(token.size() - 3))) != "off") return false;
  std::string_view prefix = token.substr(0, token.size() - 3);
  auto take = [&](std::string_view p) {
    if (prefix.substr(0, p.size()) != p) return false;
    prefix.remove_prefix(p.size());
    return true;
  };
  take("ST");
  take("C");
  take("N");
  homogeneous = take("4");
  ndim = take("n");
  return prefix.empty();
}

MeshData read_off(const std::string& text, const Reporter& r) {
  LineReader lines(text, '#', false);
  if (!lines.next()) r.fail("empty file (expected the OFF header)");
  bool homogeneous = false, ndim = false;
  if (!off_keyword(lines.tokens[0], homogeneous, ndim))
    r.fail_line(lines.number, "malformed OFF header: expected OFF (or COFF, NOFF, STOFF, 4OFF, ...), got " +
                                  shown(lines.tokens[0]));
  if (ndim) r.fail_line(lines.number, "nOFF (vertices of any dimension) is not supported");
  std::vector<std::string_view> counts(lines.tokens.begin() + 1, lines.tokens.end());
  if (!counts.empty() && lower(std::string(counts[0])) == "binary")
    r.fail_line(lines.number, "binary OFF is not supported");
  std::size_t counts_line = lines.number;
  if (counts.empty()) {
    if (!lines.next()) r.fail_line(lines.end_line(), "unexpected end of file (expected the vertex and face counts)");
    counts = lines.tokens;
    counts_line = lines.number;
  }
  if (counts.size() != 2 && counts.size() != 3)
    r.fail_line(counts_line, "malformed counts: expected \"vertices faces [edges]\", got " +
                                 count_text(counts.size(), "value", "values"));
  std::uint64_t nv = 0, nf = 0, ne = 0;
  if (!read_unsigned(counts[0], nv))
    r.fail_line(counts_line, "vertex count is not a non-negative integer: " + shown(counts[0]));
  if (!read_unsigned(counts[1], nf))
    r.fail_line(counts_line, "face count is not a non-negative integer: " + shown(counts[1]));
  if (counts.size() == 3 && !read_unsigned(counts[2], ne))
    r.fail_line(counts_line, "edge count is not a non-negative integer: " + shown(counts[2]));
  if (nv > kMaxMeshVertices)
    r.fail_line(counts_line, "too many vertices (" + std::to_string(nv) + ", at most " +
                                 std::to_string(kMaxMeshVertices) + ")");
  if (nf > kMaxMeshFaces)
    r.fail_line(counts_line,
                "too many faces (" + std::to_string(nf) + ", at most " + std::to_string(kMaxMeshFaces) + ")");

  MeshData mesh;
  mesh.vertices.reserve(nv);
  const std::size_t dim = homogeneous ? 4 : 3;
  for (std::uint64_t i = 0; i < nv; ++i) {
    const std::string vertex = "vertex " + std::to_string(i);
    if (!lines.next())
      r.fail_line(lines.end_line(), "unexpected end of file: expected " + vertex + " of " + std::to_string(nv));
    // Values after the coordinates (normals, colours, texture coordinates) are ignored.
    if (lines.tokens.size() < dim)
      r.fail_line(lines.number, vertex + " needs " + std::to_string(dim) + " coordinates, got " +
                                    std::to_string(lines.tokens.size()));
    Exact c[4];
    for (std::size_t k = 0; k < dim; ++k)
      if (!read_number(lines.tokens[k], c[k]))
        r.fail_line(lines.number, vertex + ": not a number: " + shown(lines.tokens[k]));
    if (homogeneous) {
      if (c[3] == 0) r.fail_line(lines.number, vertex + ": homogeneous coordinate w is 0");
      for (int k = 0; k < 3; ++k) c[k] /= c[3];
    }
    mesh.vertices.push_back({c[0], c[1], c[2]});
  }
  mesh.faces.reserve(nf);
  std::uint64_t total = 0;
  for (std::uint64_t f = 0; f < nf; ++f) {
    const std::string face = "face " + std::to_string(f);
    if (!lines.next())
      r.fail_line(lines.end_line(), "unexpected end of file: expected " + face + " of " + std::to_string(nf));
    std::uint64_t k = 0;
    if (!read_unsigned(lines.tokens[0], k))
      r.fail_line(lines.number, face + ": vertex count is not a non-negative integer: " + shown(lines.tokens[0]));
    if (k < 3)
      r.fail_line(lines.number, face + " has " + count_text(k, "vertex", "vertices") + " (a face needs at least 3)");
    if (k > kMaxMeshFaceVertices)
      r.fail_line(lines.number, face + " has more than " + std::to_string(kMaxMeshFaceVertices) + " vertices");
    if (lines.tokens.size() < k + 1)
      r.fail_line(lines.number, face + " announces " + std::to_string(k) + " vertices but lists " +
                                    std::to_string(lines.tokens.size() - 1));
    total += k;
    if (total > kMaxMeshFaceIndices)
      r.fail_line(lines.number,
                  "faces have more than " + std::to_string(kMaxMeshFaceIndices) + " vertex indices in all");
    std::vector<std::size_t> indices(k);
    for (std::uint64_t j = 0; j < k; ++j) {
      std::uint64_t index = 0;
      if (!read_unsigned(lines.tokens[j + 1], index))
        r.fail_line(lines.number,
                    face + ": vertex index is not a non-negative integer: " + shown(lines.tokens[j + 1]));
      if (index >= nv)
        r.fail_line(lines.number, face + ": vertex index " + std::to_string(index) + " out of range (the file has " +
                                      count_text(nv, "vertex", "vertices") + ", numbered from 0)");
      indices[j] = static_cast<std::size_t>(index);
    }
    // Values after the indices (a face colour) are ignored.
    mesh.faces.push_back(std::move(indices));
  }
  if (lines.next()) r.fail_line(lines.number, "unexpected content after the last face: " + shown(lines.tokens[0]));
  return mesh;
}

// ---------------------------------------------------------------- OBJ

bool one_of(const std::string& word, std::initializer_list<const char*> list) {
  for (const char* w : list)
    if (word == w) return true;
  return false;
}

MeshData read_obj(const std::string& text, const Reporter& r) {
  LineReader lines(text, '#', true);
  MeshData mesh;
  // Faces with positive indices may name vertices defined later; their
  // range is checked at the end, with the line they came from.
  struct Pending {
    std::size_t face, corner, line;
    std::int64_t index;  // as written, positive
  };
  std::vector<Pending> pending;
  std::uint64_t total = 0;
  while (lines.next()) {
    const std::vector<std::string_view>& t = lines.tokens;
    const std::string keyword(t[0]);
    const std::size_t values = t.size() - 1;
    if (keyword == "v") {
      // x y z, x y z w (w must be 1: OBJ's w is a weight for rational
      // free-form geometry, not a projective coordinate of polygon
      // vertices), or the common x y z r g b colour extension.
      if (values != 3 && values != 4 && values != 6)
        r.fail_line(lines.number, "a vertex needs x y z (optionally w = 1, or x y z r g b), got " +
                                      count_text(values, "value", "values"));
      if (mesh.vertices.size() >= kMaxMeshVertices)
        r.fail_line(lines.number, "too many vertices (at most " + std::to_string(kMaxMeshVertices) + ")");
      Vec3E v;
      for (int k = 0; k < 3; ++k)
        if (!read_number(t[k + 1], v[k])) r.fail_line(lines.number, "vertex: not a number: " + shown(t[k + 1]));
      if (values == 4) {
        Exact w;
        if (!read_number(t[4], w)) r.fail_line(lines.number, "vertex: not a number: " + shown(t[4]));
        if (w != 1) r.fail_line(lines.number, "vertex weight w = " + shown(t[4]) + " is not supported (must be 1)");
      } else if (values == 6) {
        for (int k = 4; k < 7; ++k) {
          Exact colour;
          if (!read_number(t[k], colour)) r.fail_line(lines.number, "vertex colour: not a number: " + shown(t[k]));
        }
      }
      mesh.vertices.push_back(std::move(v));
    } else if (keyword == "f" || keyword == "fo") {
      if (values < 3)
        r.fail_line(lines.number, "a face needs at least 3 vertices, got " + std::to_string(values));
      if (values > kMaxMeshFaceVertices)
        r.fail_line(lines.number, "face has more than " + std::to_string(kMaxMeshFaceVertices) + " vertices");
      if (mesh.faces.size() >= kMaxMeshFaces)
        r.fail_line(lines.number, "too many faces (at most " + std::to_string(kMaxMeshFaces) + ")");
      total += values;
      if (total > kMaxMeshFaceIndices)
        r.fail_line(lines.number,
                    "faces have more than " + std::to_string(kMaxMeshFaceIndices) + " vertex indices in all");
      std::vector<std::size_t> face(values);
      for (std::size_t j = 0; j < values; ++j) {
        // i, i/j, i//k or i/j/k: only the vertex index i matters; the
        // texture and normal indices must be integers where present.
        const std::string_view ref = t[j + 1];
        std::vector<std::string_view> parts;
        std::size_t start = 0;
        for (std::size_t s = 0; s <= ref.size(); ++s)
          if (s == ref.size() || ref[s] == '/') {
            parts.push_back(ref.substr(start, s - start));
            start = s + 1;
          }
        std::int64_t index = 0, other = 0;
        bool ok = parts.size() <= 3 && read_signed(parts[0], index) && index != 0;
        // "i/" is malformed; "i//k" has an empty middle part.
        for (std::size_t k = 1; ok && k < parts.size(); ++k)
          ok = parts[k].empty() ? (k == 1 && parts.size() == 3) : read_signed(parts[k], other);
        if (!ok)
          r.fail_line(lines.number, "malformed face vertex " + shown(ref) +
                                        " (expected i, i/j, i//k or i/j/k with a nonzero vertex index i)");
        if (index < 0) {
          const auto count = static_cast<std::int64_t>(mesh.vertices.size());
          if (-index > count)
            r.fail_line(lines.number, "relative vertex index " + std::to_string(index) + " out of range (" +
                                          count_text(mesh.vertices.size(), "vertex", "vertices") + " defined so far)");
          face[j] = static_cast<std::size_t>(count + index);
        } else {
          pending.push_back({mesh.faces.size(), j, lines.number, index});
        }
      }
      mesh.faces.push_back(std::move(face));
    } else if (one_of(keyword, {"vt", "vn", "vp", "g", "o", "s", "usemtl", "mtllib", "usemap", "maplib", "lod",
                                "shadow_obj", "trace_obj", "bevel", "c_interp", "d_interp", "mg"})) {
      // Texture and normal data, grouping, smoothing and display
      // attributes: no geometry.
    } else if (keyword == "l" || keyword == "p") {
      // Line and point elements are geometry too: dropping them would
      // silently leave part of the body out of every verdict.
      r.fail_line(lines.number, std::string(keyword == "l" ? "line" : "point") +
                                    " elements are not supported in meshes (only faces; write them as the body's " +
                                    (keyword == "l" ? "\"segments\"" : "\"points\"") + ")");
    } else if (one_of(keyword, {"cstype", "deg", "bmat", "step", "curv", "curv2", "surf", "parm", "trim", "hole",
                                "scrv", "sp", "end", "con", "ctech", "stech"})) {
      r.fail_line(lines.number, "free-form curves and surfaces are not supported (statement " + shown(t[0]) + ")");
    } else {
      r.fail_line(lines.number, "unknown OBJ statement " + shown(t[0]));
    }
  }
  for (const Pending& p : pending) {
    if (static_cast<std::uint64_t>(p.index) > mesh.vertices.size())
      r.fail_line(p.line, "vertex index " + std::to_string(p.index) + " out of range (the file has " +
                              count_text(mesh.vertices.size(), "vertex", "vertices") + ", numbered from 1)");
    mesh.faces[p.face][p.corner] = static_cast<std::size_t>(p.index - 1);
  }
  return mesh;
}

// ---------------------------------------------------------------- STL

// Merges vertices with exactly equal coordinates, so that faces share them.
class VertexMerger {
 public:
  explicit VertexMerger(MeshData& mesh) : mesh_(mesh) {}
  // Returns false when the vertex limit would be exceeded.
  bool add(Vec3E v, std::size_t& index) {
    const auto found = ids_.find(v);
    if (found != ids_.end()) {
      index = found->second;
      return true;
    }
    if (mesh_.vertices.size() >= kMaxMeshVertices) return false;
    index = mesh_.vertices.size();
    mesh_.vertices.push_back(v);
    ids_.emplace(std::move(v), index);
    return true;
  }

 private:
  MeshData& mesh_;
  std::map<Vec3E, std::size_t> ids_;
};

bool keyword_is(std::string_view token, const char* word) { return lower(std::string(token)) == word; }

MeshData read_stl_ascii(const std::string& text, const Reporter& r) {
  // A token stream with line numbers (statements are on separate lines by
  // convention only); keywords are case-insensitive.
  LineReader lines(text, '\0', false);
  std::vector<std::string_view> tokens;
  std::size_t next = 0, line = 0;
  bool new_line = false;  // did the last fetch() start a new line?
  auto fetch = [&]() -> bool {
    new_line = false;
    if (next < tokens.size()) return true;
    if (!lines.next()) return false;
    tokens = lines.tokens;
    line = lines.number;
    next = 0;
    new_line = true;
    return true;
  };
  auto expect = [&](const char* word) {
    if (!fetch()) r.fail_line(lines.end_line(), std::string("unexpected end of file (expected \"") + word + "\")");
    if (!keyword_is(tokens[next], word))
      r.fail_line(line, std::string("expected \"") + word + "\", got " + shown(tokens[next]));
    ++next;
  };
  auto skip_rest_of_line = [&]() { next = tokens.size(); };

  MeshData mesh;
  VertexMerger merger(mesh);
  expect("solid");
  skip_rest_of_line();  // the solid's name
  while (true) {
    if (!fetch()) r.fail_line(lines.end_line(), "unexpected end of file (expected \"facet\" or \"endsolid\")");
    const std::string_view word = tokens[next++];
    if (keyword_is(word, "endsolid")) {
      skip_rest_of_line();  // the name again
      if (!fetch()) break;
      // Several solids in one file are read as one mesh.
      if (!keyword_is(tokens[next], "solid"))
        r.fail_line(line, "unexpected content after \"endsolid\": " + shown(tokens[next]));
      ++next;
      skip_rest_of_line();
      continue;
    }
    if (!keyword_is(word, "facet")) r.fail_line(line, "expected \"facet\" or \"endsolid\", got " + shown(word));
    expect("normal");
    for (int k = 0; k < 3; ++k) {  // the normal is not used (nor checked: some writers put NaN there)
      if (!fetch()) r.fail_line(lines.end_line(), "unexpected end of file in a facet normal");
      ++next;
    }
    if (mesh.faces.size() >= kMaxMeshFaces)
      r.fail_line(line, "too many facets (at most " + std::to_string(kMaxMeshFaces) + ")");
    expect("outer");
    expect("loop");
    std::vector<std::size_t> face(3);
    for (int k = 0; k < 3; ++k) {
      expect("vertex");
      const std::size_t vertex_line = line;
      Vec3E v;
      for (int c = 0; c < 3; ++c) {
        if (!fetch() || new_line) r.fail_line(vertex_line, "a vertex needs 3 coordinates on its line");
        if (!read_number(tokens[next], v[c])) r.fail_line(line, "vertex: not a number: " + shown(tokens[next]));
        ++next;
      }
      if (!merger.add(std::move(v), face[k]))
        r.fail_line(line, "too many vertices (at most " + std::to_string(kMaxMeshVertices) + ")");
    }
    expect("endloop");
    expect("endfacet");
    mesh.faces.push_back(std::move(face));
  }
  return mesh;
}

std::uint32_t le32(const unsigned char* p) {
  return static_cast<std::uint32_t>(p[0]) | static_cast<std::uint32_t>(p[1]) << 8 |
         static_cast<std::uint32_t>(p[2]) << 16 | static_cast<std::uint32_t>(p[3]) << 24;
}

MeshData read_stl_binary(const std::string& data, const Reporter& r) {
  const auto* bytes = reinterpret_cast<const unsigned char*>(data.data());
  const std::uint64_t count = le32(bytes + 80);
  if (count > kMaxMeshFaces)
    r.fail("too many triangles (" + std::to_string(count) + ", at most " + std::to_string(kMaxMeshFaces) + ")");
  MeshData mesh;
  mesh.faces.reserve(count);
  VertexMerger merger(mesh);
  for (std::uint64_t i = 0; i < count; ++i) {
    const unsigned char* record = bytes + 84 + 50 * i;
    std::vector<std::size_t> face(3);
    for (int k = 0; k < 3; ++k) {
      Vec3E v;
      for (int c = 0; c < 3; ++c) {
        // Little-endian IEEE 754 single precision, after the 12-byte normal.
        const float f = std::bit_cast<float>(le32(record + 12 + 12 * k + 4 * c));
        if (!std::isfinite(f))
          r.fail("triangle " + std::to_string(i) + ": vertex " + std::to_string(k) + " has a " +
                 (std::isnan(f) ? "NaN" : "infinite") + " coordinate");
        v[c] = Exact(static_cast<double>(f));  // exact: a finite float is a dyadic rational
      }
      if (!merger.add(std::move(v), face[k]))
        r.fail("triangle " + std::to_string(i) + ": too many vertices (at most " +
               std::to_string(kMaxMeshVertices) + ")");
    }
    mesh.faces.push_back(std::move(face));
  }
  return mesh;
}

MeshData read_stl(const std::string& data, const Reporter& r) {
  static_assert(sizeof(float) == 4 && std::numeric_limits<float>::is_iec559, "binary STL needs IEEE floats");
  const std::size_t size = data.size();
  const auto* bytes = reinterpret_cast<const unsigned char*>(data.data());
  // Binary iff the size matches the triangle count, even when the 80-byte
  // header starts with "solid" (many writers do that).
  if (size >= 84 && 84 + 50 * static_cast<std::uint64_t>(le32(bytes + 80)) == size) return read_stl_binary(data, r);
  std::size_t i = 0;
  while (i < size && std::isspace(static_cast<unsigned char>(data[i]))) ++i;
  const bool says_solid = size - i >= 5 && lower(data.substr(i, 5)) == "solid";
  const bool has_nul = data.find('\0') != std::string::npos;  // never in ASCII STL
  if (says_solid && !has_nul) return read_stl_ascii(data, r);
  if (size < 84)
    r.fail("truncated binary STL: " + count_text(size, "byte", "bytes") + ", less than the 84-byte header" +
           (says_solid ? "" : " (and not ASCII STL, which starts with \"solid\")"));
  const std::uint64_t count = le32(bytes + 80);
  r.fail("truncated or malformed binary STL: the header announces " + count_text(count, "triangle", "triangles") +
         " (" + std::to_string(84 + 50 * count) + " bytes), the file has " + std::to_string(size) + " bytes");
}

// ---------------------------------------------------------------- COLLADA

using Mat4E = std::array<Exact, 16>;  // row major

Mat4E mat_product(const Mat4E& a, const Mat4E& b) {
  Mat4E out;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) {
      Exact sum = 0;
      for (int k = 0; k < 4; ++k)
        if (a[4 * r + k] != 0 && b[4 * k + c] != 0) sum += a[4 * r + k] * b[4 * k + c];
      out[4 * r + c] = sum;
    }
  return out;
}

// COLLADA through assimp (Debian libassimp-dev): the polygons as assimp
// triangulates them (aiProcess_Triangulate, and no other processing: no
// vertex joining by tolerance, no pre-transformed vertices), each mesh
// instance placed by the product of the node transforms from the root
// down, computed exactly from the floats assimp holds (the unit size of
// <unit meter> is in the root's; the up axis is left as written, as ROS
// tools display it), vertices merged by exact equality.  Every coordinate
// is the exact value of assimp's floats under those exact products.
MeshData read_collada(const std::string& data, const Reporter& r) {
  Assimp::Importer importer;
  importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, true);
  const aiScene* scene = importer.ReadFileFromMemory(data.data(), data.size(), aiProcess_Triangulate, "dae");
  if (!scene) r.fail(std::string("not a readable COLLADA file (assimp: ") + importer.GetErrorString() + ")");
  if (!scene->mRootNode) r.fail("COLLADA file without a scene (no root node)");
  MeshData mesh;
  mesh.from_floats = true;
  mesh.format = "COLLADA";
  VertexMerger merger(mesh);
  auto exact = [&](ai_real f, const std::string& what) {
    if (!std::isfinite(f)) r.fail(what + " is not finite");
    return Exact(static_cast<double>(f));  // exact: a finite float is a dyadic rational
  };
  std::size_t faces = 0;
  // Depth first from the root, with the exact transform of each node.
  std::vector<std::pair<const aiNode*, Mat4E>> stack;
  const Mat4E identity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  stack.emplace_back(scene->mRootNode, identity);
  std::size_t nodes = 0;
  while (!stack.empty()) {
    auto [node, parent] = std::move(stack.back());
    stack.pop_back();
    if (++nodes > kMaxMeshFaces) r.fail("too many nodes");
    const std::string where = "node " + shown(node->mName.C_Str());
    const aiMatrix4x4& t = node->mTransformation;
    const ai_real entries[16] = {t.a1, t.a2, t.a3, t.a4, t.b1, t.b2, t.b3, t.b4, t.c1, t.c2, t.c3, t.c4, t.d1, t.d2, t.d3, t.d4};
    Mat4E local;
    for (int e = 0; e < 16; ++e) local[e] = exact(entries[e], where + ": a transform entry");
    if (local[12] != 0 || local[13] != 0 || local[14] != 0 || local[15] != 1)
      r.fail(where + ": a projective transform (its last row is not 0 0 0 1)");
    const Mat4E m = mat_product(parent, local);
    for (unsigned k = 0; k < node->mNumMeshes; ++k) {
      const aiMesh* am = scene->mMeshes[node->mMeshes[k]];
      const std::string mwhere = where + ": mesh " + shown(am->mName.C_Str());
      std::vector<std::size_t> ids(am->mNumVertices);
      std::vector<char> done(am->mNumVertices, 0);
      for (unsigned f = 0; f < am->mNumFaces; ++f) {
        const aiFace& face = am->mFaces[f];
        if (face.mNumIndices < 3)
          r.fail(mwhere + ": face " + std::to_string(f) + ": " + (face.mNumIndices == 2 ? "a line" : "a point") +
                 " (only polygons are read; lines and points are refused rather than dropped)");
        if (++faces > kMaxMeshFaces) r.fail("too many faces (at most " + std::to_string(kMaxMeshFaces) + ")");
        std::vector<std::size_t> out;
        for (unsigned i = 0; i < face.mNumIndices; ++i) {
          const unsigned vi = face.mIndices[i];
          if (vi >= am->mNumVertices) r.fail(mwhere + ": face " + std::to_string(f) + ": vertex index out of range");
          if (!done[vi]) {
            const aiVector3D& v = am->mVertices[vi];
            const Exact x = exact(v.x, mwhere + ": vertex " + std::to_string(vi)), y = exact(v.y, mwhere + ": vertex"),
                        z = exact(v.z, mwhere + ": vertex");
            Vec3E p;
            for (int c = 0; c < 3; ++c) p[c] = m[4 * c] * x + m[4 * c + 1] * y + m[4 * c + 2] * z + m[4 * c + 3];
            if (!merger.add(std::move(p), ids[vi]))
              r.fail("too many vertices (at most " + std::to_string(kMaxMeshVertices) + ")");
            done[vi] = 1;
          }
          out.push_back(ids[vi]);
        }
        mesh.faces.push_back(std::move(out));
      }
    }
    for (unsigned c = node->mNumChildren; c-- > 0;) stack.emplace_back(node->mChildren[c], m);  // in file order
  }
  return mesh;
}

}  // namespace

MeshData read_mesh(const std::string& file) {
  const Reporter r(file);
  const std::string extension = lower(std::filesystem::path(file).extension().string());
  if (extension != ".off" && extension != ".obj" && extension != ".stl" && extension != ".dae")
    r.fail("unknown mesh file extension " + (extension.empty() ? std::string("(none)") : shown(extension)) +
           " (supported: .off, .obj, .stl, .dae)");
  // Only a regular file, and at most kMaxMeshFileBytes of it.
  const std::string data = read_regular_file(file, kMaxMeshFileBytes);
  if (extension == ".off") return read_off(data, r);
  if (extension == ".obj") return read_obj(data, r);
  if (extension == ".dae") return read_collada(data, r);
  return read_stl(data, r);
}

}  // namespace tmcert
