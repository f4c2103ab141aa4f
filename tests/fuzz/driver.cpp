// A deterministic mutation driver for the fuzz targets, for builds without
// libFuzzer (gcc; tests/fuzz/README.md).  It runs every input of the given
// corpus files and directories once, then mutates them (bit flips, byte
// edits, inserted and deleted ranges, copied ranges, dictionary tokens,
// splices of two inputs) with a seeded generator until a time or run count
// is reached.  Mutants that the target accepted without error are not fed
// back (no coverage feedback): the run depends only on the seed, the corpus
// and the number of runs.
//
//   fuzz_<target> [--seconds S] [--runs N] [--seed N] CORPUS...
//
// A violated property (tmcert::fuzz::fail) or a sanitizer report writes the
// input to ./fuzz-failure-<target>.bin and ends the run with a non-zero
// status.
#include "tests/fuzz/fuzz.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

#if defined(__has_include)
#if __has_include(<sanitizer/common_interface_defs.h>)
#include <sanitizer/common_interface_defs.h>
#define TMCERT_HAS_SANITIZER_CALLBACK 1
#endif
#endif

namespace {

const std::vector<std::uint8_t>* g_current = nullptr;
std::string g_name = "target";

void save_current() {
  if (!g_current) return;
  const std::string file = "fuzz-failure-" + g_name + ".bin";
  if (std::FILE* f = std::fopen(file.c_str(), "wb")) {
    if (!g_current->empty()) std::fwrite(g_current->data(), 1, g_current->size(), f);
    std::fclose(f);
    std::fprintf(stderr, "fuzz: input written to %s (%zu bytes)\n", file.c_str(), g_current->size());
  }
}

#ifdef TMCERT_HAS_SANITIZER_CALLBACK
extern "C" void on_sanitizer_death() { save_current(); }
#endif

// Tokens that matter to the readers: JSON structure, number spellings at
// and beyond the limits, mesh keywords.
const char* const kTokens[] = {
    "{", "}", "[", "]", ",", ":", "\"", "\\u0000", "\\u0001", "\\ud800", "null", "true", "false",
    "0", "-0", "1", "-1", "2", "1/2", "1/0", "0/0", "-1/3", "1e9999", "1e10000", "1e-9999", "1e-10000",
    "1e155", "1e-320", "1e308", "1e309", "0.1", "\"0x1p3\"", "nan", "inf", "\"1e155\"", "\"-0\"",
    "99999999999999999999999999999999", "0.000000000000000000000000000001",
    "\"format\"", "\"tmcert-scene/1\"", "\"bodies\"", "\"name\"", "\"polygons\"", "\"segments\"", "\"points\"",
    "\"motion\"", "\"type\"", "\"rational_bezier\"", "\"control_points\"", "\"weights\"", "\"interval\"",
    "\"checks\"", "\"solid\"", "\"mesh\"", "\"mass\"", "\"tolerance\"", "\"clearance\"", "\"epsilon\"",
    "\"max_depth\"", "\"keyframes\"", "\"piecewise\"", "\"times\"", "\"poses\"", "\"rpy\"", "\"quaternion\"",
    "\"verdict\"", "\"safe\"", "\"collision\"", "\"undecided\"", "\"pieces\"", "\"proof\"", "\"sep\"",
    "\"split\"", "\"parts\"", "\"children\"", "\"elements\"", "\"groups\"", "\"start\"", "\"witness\"",
    "\"t\"", "\"point\"", "\"features\"", "OFF", "COFF", "4OFF", "\nv ", "\nf ", "\nvn ", "\nl ",
    "solid ", "facet normal ", "outer loop", "vertex ", "endloop", "endfacet", "endsolid", "\n", " ", "#",
};

class Mutator {
 public:
  explicit Mutator(std::uint64_t seed) : rng_(seed) {}

  std::size_t below(std::size_t n) { return n == 0 ? 0 : std::uniform_int_distribution<std::size_t>(0, n - 1)(rng_); }

  void mutate(std::vector<std::uint8_t>& s, const std::vector<std::vector<std::uint8_t>>& corpus) {
    const int edits = 1 + static_cast<int>(below(4));
    for (int e = 0; e < edits; ++e) {
      switch (below(9)) {
        case 0:  // flip a bit
          if (!s.empty()) s[below(s.size())] ^= static_cast<std::uint8_t>(1u << below(8));
          break;
        case 1:  // set a byte
          if (!s.empty()) s[below(s.size())] = static_cast<std::uint8_t>(below(256));
          break;
        case 2:  // a digit, sign or separator where one was
          if (!s.empty()) s[below(s.size())] = static_cast<std::uint8_t>("0123456789-+.e/ ,[]{}\""[below(23)]);
          break;
        case 3: {  // insert a byte
          s.insert(s.begin() + static_cast<std::ptrdiff_t>(below(s.size() + 1)), static_cast<std::uint8_t>(below(256)));
          break;
        }
        case 4: {  // delete a range
          if (s.empty()) break;
          const std::size_t at = below(s.size()), n = 1 + below(std::min<std::size_t>(16, s.size() - at));
          s.erase(s.begin() + static_cast<std::ptrdiff_t>(at), s.begin() + static_cast<std::ptrdiff_t>(at + n));
          break;
        }
        case 5: {  // copy a range elsewhere
          if (s.empty() || s.size() > 1 << 20) break;
          const std::size_t at = below(s.size()), n = 1 + below(std::min<std::size_t>(64, s.size() - at));
          const std::vector<std::uint8_t> piece(s.begin() + static_cast<std::ptrdiff_t>(at),
                                                s.begin() + static_cast<std::ptrdiff_t>(at + n));
          s.insert(s.begin() + static_cast<std::ptrdiff_t>(below(s.size() + 1)), piece.begin(), piece.end());
          break;
        }
        case 6:
        case 7: {  // insert or overwrite with a token
          const char* token = kTokens[below(std::size(kTokens))];
          const std::size_t n = std::strlen(token);
          const std::size_t at = below(s.size() + 1);
          if (below(2) == 0 && at + n <= s.size())
            std::copy(token, token + n, s.begin() + static_cast<std::ptrdiff_t>(at));
          else
            s.insert(s.begin() + static_cast<std::ptrdiff_t>(at), token, token + n);
          break;
        }
        default: {  // splice: a prefix of this input, a suffix of another
          const auto& other = corpus[below(corpus.size())];
          if (other.empty()) break;
          const std::size_t cut = below(s.size() + 1), from = below(other.size());
          s.resize(cut);
          s.insert(s.end(), other.begin() + static_cast<std::ptrdiff_t>(from), other.end());
          break;
        }
      }
    }
  }

 private:
  std::mt19937_64 rng_;
};

std::vector<std::uint8_t> read_bytes(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

int usage() {
  std::cerr << "usage: fuzz_<target> [--seconds S] [--runs N] [--seed N] CORPUS...\n";
  return 2;
}

}  // namespace

[[noreturn]] void tmcert::fuzz::fail(const std::string& what) {
  std::fprintf(stderr, "fuzz: property violated: %s\n", what.c_str());
  save_current();
  g_current = nullptr;
  std::abort();
}

int main(int argc, char** argv) {
  g_name = std::filesystem::path(argv[0]).filename().string();
  double seconds = 10;
  std::uint64_t runs = 0, seed = 1;
  std::vector<std::filesystem::path> inputs;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if ((a == "--seconds" || a == "--runs" || a == "--seed") && i + 1 < argc) {
      const char* v = argv[++i];
      if (a == "--seconds") seconds = std::strtod(v, nullptr);
      else if (a == "--runs") runs = std::strtoull(v, nullptr, 10);
      else seed = std::strtoull(v, nullptr, 10);
    } else if (!a.empty() && a[0] == '-') {
      return usage();
    } else {
      inputs.emplace_back(a);
    }
  }
  if (inputs.empty()) return usage();
#ifdef TMCERT_HAS_SANITIZER_CALLBACK
  __sanitizer_set_death_callback(on_sanitizer_death);
#endif
  std::vector<std::vector<std::uint8_t>> corpus;
  for (const auto& p : inputs) {
    if (std::filesystem::is_directory(p)) {
      std::vector<std::filesystem::path> files;
      for (const auto& e : std::filesystem::directory_iterator(p))
        if (e.is_regular_file()) files.push_back(e.path());
      std::sort(files.begin(), files.end());  // a fixed order: a reproducible run
      for (const auto& f : files) corpus.push_back(read_bytes(f));
    } else {
      corpus.push_back(read_bytes(p));
    }
  }
  if (corpus.empty()) {
    std::cerr << g_name << ": empty corpus\n";
    return 2;
  }
  const auto start = std::chrono::steady_clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  std::uint64_t done = 0;
  for (const auto& input : corpus) {
    g_current = &input;
    LLVMFuzzerTestOneInput(input.data(), input.size());
    ++done;
  }
  Mutator mutator(seed);
  std::vector<std::uint8_t> input;
  while (runs ? done < runs : elapsed() < seconds) {
    input = corpus[mutator.below(corpus.size())];
    mutator.mutate(input, corpus);
    g_current = &input;
    LLVMFuzzerTestOneInput(input.data(), input.size());
    ++done;
  }
  g_current = nullptr;
  std::cout << g_name << ": " << done << " executions (" << corpus.size() << " corpus inputs, seed " << seed << ") in "
            << elapsed() << " s, no property violated\n";
  return 0;
}
