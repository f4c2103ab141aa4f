#include "src/batch/shard.h"

#include "src/io/parse.h"

#include <algorithm>
#include <cctype>

namespace tmcert {

namespace {

// A decimal number of at most 7 digits (kMaxShards has 7), else nothing.
bool small_number(const std::string& s, std::size_t& out) {
  if (s.empty() || s.size() > 7 ||
      !std::all_of(s.begin(), s.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); }))
    return false;
  out = std::stoul(s);
  return true;
}

}  // namespace

Shard Shard::parse(const std::string& text) {
  const std::size_t slash = text.find('/');
  Shard s;
  if (slash == std::string::npos || !small_number(text.substr(0, slash), s.index) ||
      !small_number(text.substr(slash + 1), s.count) || s.count < 1 || s.count > kMaxShards || s.index >= s.count)
    throw InputError("--shard: expected i/n with 0 <= i < n <= " + std::to_string(kMaxShards) + ", got " + quote_text(text));
  return s;
}

}  // namespace tmcert
