// tmcert::fuzz::fail under libFuzzer (which saves the failing input itself).
#include "tests/fuzz/fuzz.h"

#include <cstdio>
#include <cstdlib>

[[noreturn]] void tmcert::fuzz::fail(const std::string& what) {
  std::fprintf(stderr, "fuzz: property violated: %s\n", what.c_str());
  std::abort();
}
