// The certificate checker's document reading: JSON access with messages
// naming the JSON path (every malformed value is an InputError naming the
// certificate file and the path), exact rationals with the limits of
// docs/certificate-format.md "Limits", and the rejection of a claim that
// does not hold.
#pragma once

#include "src/certificate/check.h"
#include "src/certificate/check_numbers.h"
#include "src/io/parse.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdint>
#include <string>
#include <utility>

namespace tmcert::certificate::check_internal {

using json = nlohmann::json;

// The format written (docs/certificate-format.md); the checker also reads
// kFormatV1, whose documents are /2 documents without shared proof nodes.
inline constexpr const char* kFormat = "tmcert-certificate/2";
inline constexpr const char* kFormatV1 = "tmcert-certificate/1";

// "null", "a boolean", "an integer", ...: a JSON value's type in messages.
const char* describe(const json& v);

// Deepest nesting of arrays and objects in a JSON text (outside strings).
std::size_t nesting(const std::string& text);

// "parent[i]" and "parent.key": JSON paths in messages.
inline std::string idx(const std::string& parent, std::size_t i) { return parent + "[" + std::to_string(i) + "]"; }
inline std::string mem(const std::string& parent, const char* key) { return parent.empty() ? key : parent + "." + key; }

// A claim that does not hold: the message, without the source prefix.
struct Rejected {
  std::string message;
};

// JSON access with messages naming the path; every malformed value is an
// InputError.
class Reader {
 public:
  explicit Reader(std::string source) : source_(std::move(source)) {}
  const std::string& source() const { return source_; }

  [[noreturn]] void bad(const std::string& path, const std::string& what) const {
    throw InputError(source_ + ": " + (path.empty() ? std::string("document") : path) + ": " + what);
  }

  const json& object(const json& v, const std::string& path) const {
    if (!v.is_object()) bad(path, std::string("expected an object, got ") + describe(v));
    return v;
  }
  const json& array(const json& v, const std::string& path) const {
    if (!v.is_array()) bad(path, std::string("expected an array, got ") + describe(v));
    return v;
  }
  const json& array(const json& v, const std::string& path, std::size_t size) const {
    array(v, path);
    if (v.size() != size)
      bad(path, "expected " + std::to_string(size) + " entries, got " + std::to_string(v.size()));
    return v;
  }
  const json* find(const json& obj, const char* key) const {
    const auto it = obj.find(key);
    return it == obj.end() ? nullptr : &*it;
  }
  const json& member(const json& obj, const char* key, const std::string& path) const {
    const json* v = find(obj, key);
    if (!v) bad(mem(path, key), "missing required field");
    return *v;
  }
  const std::string& string(const json& v, const std::string& path) const {
    if (!v.is_string()) bad(path, std::string("expected a string, got ") + describe(v));
    return v.get_ref<const std::string&>();
  }
  std::size_t index(const json& v, const std::string& path, std::size_t limit, const std::string& what) const {
    return index_at(v, [&] { return path; }, limit, what);
  }
  // The same with the path built only for a message (hot loops).
  template <class PathFn>
  std::size_t index_at(const json& v, const PathFn& path, std::size_t limit, const char* what) const {
    if (!v.is_number_integer()) bad(path(), std::string("expected a non-negative integer, got ") + describe(v));
    if (v.is_number_unsigned()) {
      const std::uint64_t x = v.get<std::uint64_t>();
      if (x < limit) return static_cast<std::size_t>(x);
    } else {
      const std::int64_t x = v.get<std::int64_t>();
      if (x >= 0 && static_cast<std::uint64_t>(x) < limit) return static_cast<std::size_t>(x);
    }
    bad(path(), v.dump() + " is out of range (" + what + ")");
  }
  template <class PathFn>
  std::size_t index_at(const json& v, const PathFn& path, std::size_t limit, const std::string& what) const {
    return index_at(v, path, limit, what.c_str());
  }
  Exact rational(const json& v, const std::string& path) const {
    return rational_at(v, [&] { return path; });
  }
  // The same with the path built only for a message (hot loops).
  template <class PathFn>
  Exact rational_at(const json& v, const PathFn& path) const {
    if (v.is_number_unsigned()) return Exact(static_cast<unsigned long long>(v.get<std::uint64_t>()));
    if (v.is_number_integer()) return Exact(static_cast<long long>(v.get<std::int64_t>()));
    if (!v.is_string())
      bad(path(), std::string("expected a rational (a string \"p/q\", an integer or a decimal, or a JSON "
                            "integer), got ") + describe(v));
    const std::string& s = v.get_ref<const std::string&>();
    if (s.size() > kMaxNumberChars)
      bad(path(), "number of " + std::to_string(s.size()) + " characters (at most " +
                    std::to_string(kMaxNumberChars) + ")");
    if (s.find('/') == std::string::npos) {
      const std::size_t e = s.find_first_of("eE");
      if (e != std::string::npos) {
        std::size_t i = e + 1;
        if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
        const std::string digits = s.substr(i);
        const bool ok = !digits.empty() && digits.size() <= 6 &&
                        std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; });
        if (ok && std::stol(digits) > kMaxDecimalExponent)
          bad(path(), "decimal exponent beyond " + std::to_string(kMaxDecimalExponent) + " in magnitude");
        if (!ok) bad(path(), "not a rational: " + quote_text(s));
      }
    }
    Exact out;
    if (!parse_exact(s, out)) bad(path(), "not a rational: " + quote_text(s));
    return out;
  }
  Vec3E vec3(const json& v, const std::string& path) const {
    array(v, path, 3);
    return {rational(v[0], idx(path, 0)), rational(v[1], idx(path, 1)), rational(v[2], idx(path, 2))};
  }
  std::pair<Exact, Exact> pair(const json& v, const std::string& path) const {
    array(v, path, 2);
    return {rational(v[0], idx(path, 0)), rational(v[1], idx(path, 1))};
  }

 private:
  std::string source_;
};

}  // namespace tmcert::certificate::check_internal
