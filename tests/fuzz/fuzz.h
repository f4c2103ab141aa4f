// Shared by the fuzz targets (tests/fuzz/README.md): each target defines
// LLVMFuzzerTestOneInput; it runs under libFuzzer (clang, -fsanitize=fuzzer)
// or under the deterministic mutation driver (driver.cpp, any compiler).
// A property a target checks and finds violated ends the run through
// fuzz_fail: the driver then saves the input, libFuzzer saves its own.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace tmcert::fuzz {

// Prints "fuzz: property violated: <what>", saves the input when the driver
// runs, and aborts.
[[noreturn]] void fail(const std::string& what);

// The directory of tests/data (compiled in).
inline std::string test_data() { return TMCERT_TEST_DATA; }

}  // namespace tmcert::fuzz
