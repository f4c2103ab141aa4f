// The certificate checker's document reading (check_document.h): the file
// and text readers with the size and nesting limits, and the JSON helpers.
#include "src/certificate/check_document.h"
#include "src/io/read_file.h"

#include <algorithm>

namespace tmcert::certificate {

namespace check_internal {

const char* describe(const json& v) {
  switch (v.type()) {
    case json::value_t::null: return "null";
    case json::value_t::boolean: return "a boolean";
    case json::value_t::number_integer:
    case json::value_t::number_unsigned: return "an integer";
    case json::value_t::number_float: return "a number with a fraction or exponent";
    case json::value_t::string: return "a string";
    case json::value_t::array: return "an array";
    case json::value_t::object: return "an object";
    default: return "a binary value";
  }
}

std::size_t nesting(const std::string& text) {
  std::size_t depth = 0, deepest = 0;
  bool in_string = false, escaped = false;
  for (const char c : text) {
    if (in_string) {
      if (escaped) escaped = false;
      else if (c == '\\') escaped = true;
      else if (c == '"') in_string = false;
      continue;
    }
    if (c == '"') in_string = true;
    else if (c == '[' || c == '{') deepest = std::max(deepest, ++depth);
    else if ((c == ']' || c == '}') && depth > 0) --depth;
  }
  return deepest;
}

}  // namespace check_internal

using namespace check_internal;

nlohmann::json parse_certificate_text(const std::string& text, const std::string& source) {
  if (nesting(text) > kMaxJsonNesting)
    throw InputError(source + ": document: nested deeper than " + std::to_string(kMaxJsonNesting) + " levels");
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    std::string what = e.what();
    const std::size_t bracket = what.find("] ");  // drop "[json.exception.parse_error.101] "
    if (what.rfind("[json.exception", 0) == 0 && bracket != std::string::npos) what.erase(0, bracket + 2);
    for (char& ch : what)
      if (static_cast<unsigned char>(ch) < 0x20) ch = ' ';
    throw InputError(source + ": not JSON: " + what);
  }
}

nlohmann::json read_certificate_file(const std::string& path) {
  // Only a regular file, and at most kMaxFileBytes of it.
  const std::string text = read_regular_file(path, kMaxFileBytes);
  return parse_certificate_text(text, path);
}

}  // namespace tmcert::certificate
