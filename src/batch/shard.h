// A shard of a batch run (`tmcert batch --shard i/n`): the requests whose
// 0-based index is i modulo n (docs/scene-format.md "Batch runs").
#pragma once

#include <cstddef>
#include <string>

namespace tmcert {

struct Shard {
  std::size_t index = 0;  // i, 0 <= i < count
  std::size_t count = 1;  // n, at most kMaxShards

  static constexpr std::size_t kMaxShards = 1'000'000;

  bool owns(std::size_t request) const { return request % count == index; }

  // "i/n" (decimal digits only, 0 <= i < n <= kMaxShards).  Throws
  // InputError naming --shard otherwise.
  static Shard parse(const std::string& text);
};

}  // namespace tmcert
