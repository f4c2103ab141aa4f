// The options of a run as a user wrote them, and the one place that turns
// them into VerifyOptions for a scene: every entry point (tmcert verify,
// tmcert batch, the library's verify() and batch(), the OMPL validator)
// goes through build_options, and the epsilon a run uses is chosen by
// resolve_epsilon alone (SCENE_FORMAT.md "Decisive by default").  The
// rules are written once; each entry point keeps its own spelling of the
// messages (OptionSpelling).
#pragma once

#include "src/verify/verify.h"

#include <optional>
#include <string>

namespace tmcert {

// How an entry point names its options in messages: `--epsilon`, `'x'`
// (the command line) or `epsilon`, `"x"` (the library, Python).
enum class OptionSpelling { CommandLine, Library };

// The ranges of the options (the scene's "max_depth" has the same).
constexpr int kMinDepth = 1, kMaxDepth = 200;
constexpr int kMinThreads = 1, kMaxThreads = 256;
constexpr double kMaxTimeLimit = 1e9;  // seconds, about 31 years
bool valid_time_limit(double seconds);  // finite, > 0, at most kMaxTimeLimit

// An epsilon as written: none, "auto", or a positive exact number.
struct EpsilonChoice {
  bool automatic = false;      // "auto": the default, refined, whatever the scene gives
  std::optional<Exact> value;  // a number: fixed for every check, no refinement
};

// "auto", or a positive number (decimal or p/q) read exactly; otherwise
// InputError naming the option in `spelling`.
EpsilonChoice parse_epsilon(const std::string& text, OptionSpelling spelling);

// Without a fixed epsilon, whether each check takes the default of its
// own two bodies (verify), or one default serves every check of the scene
// (batch requests and OMPL edges against one prepared environment).
enum class EpsilonScope { PerCheck, WholeScene };

// The epsilon rule: a number given is used, fixed; else the scene's
// "epsilon", fixed; else (and for "auto", whatever the scene gives) the
// default, refined: for PerCheck left absent here (Verifier::check takes
// default_epsilon of the check's two bodies), for WholeScene
// default_epsilon(scene).  Sets options.epsilon and options.refine.
void resolve_epsilon(VerifyOptions& options, const EpsilonChoice& choice, const Scene& scene, EpsilonScope scope);

// The options of a run as written, before the scene's defaults.
struct WrittenOptions {
  KernelKind kernel = KernelKind::Filtered;
  EpsilonChoice epsilon;
  std::optional<int> max_depth;      // none: the scene's
  std::optional<double> time_limit;  // seconds per check; none: no limit
  int threads = 1;
  bool all_pairs = false;
  bool certificate = false;          // record what a certificate needs
};

// The ranges and combinations, without the scene (InputError in
// `spelling`): max_depth, threads, time_limit, a certificate of the fast
// kernel.
void check_options(const WrittenOptions& written, OptionSpelling spelling);

// VerifyOptions for `scene`: the written options checked (check_options),
// the epsilon by resolve_epsilon, max_depth the written one else the
// scene's.
VerifyOptions build_options(const WrittenOptions& written, const Scene& scene, EpsilonScope scope,
                            OptionSpelling spelling);

}  // namespace tmcert
