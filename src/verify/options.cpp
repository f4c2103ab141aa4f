// src/verify/options.h: the options' rules and the epsilon rule, once.
#include "src/verify/options.h"

#include "src/io/parse.h"

#include <cmath>

namespace tmcert {

namespace {

// `name` as the entry point spells it, and `text` quoted as it quotes.
std::string option_name(const char* name, OptionSpelling spelling) {
  if (spelling == OptionSpelling::Library) return name;
  std::string out = "--";
  for (const char* c = name; *c; ++c) out += *c == '_' ? '-' : *c;
  return out;
}

std::string quoted(const std::string& text, OptionSpelling spelling) {
  return spelling == OptionSpelling::Library ? quote_text(text) : "'" + text + "'";
}

}  // namespace

bool valid_time_limit(double seconds) { return std::isfinite(seconds) && seconds > 0 && seconds <= kMaxTimeLimit; }

EpsilonChoice parse_epsilon(const std::string& text, OptionSpelling spelling) {
  EpsilonChoice choice;
  if (text == "auto") {
    choice.automatic = true;
    return choice;
  }
  Exact e;
  if (!parse_exact(text, e) || !(e > 0))
    throw InputError(option_name("epsilon", spelling) + ": must be a positive number (decimal or p/q), got " +
                     quoted(text, spelling));
  choice.value = e;
  return choice;
}

void resolve_epsilon(VerifyOptions& options, const EpsilonChoice& choice, const Scene& scene, EpsilonScope scope) {
  if (choice.value) {
    options.epsilon = choice.value;  // fixed: no refinement
    options.refine = false;
  } else if (!choice.automatic && scene.epsilon) {
    options.epsilon = scene.epsilon;  // the scene's, fixed
    options.refine = false;
  } else {
    // The default, refined (SCENE_FORMAT.md "Decisive by default").
    options.epsilon = scope == EpsilonScope::WholeScene ? std::optional<Exact>(default_epsilon(scene)) : std::nullopt;
    options.refine = true;
  }
}

void check_options(const WrittenOptions& w, OptionSpelling spelling) {
  if (w.max_depth && (*w.max_depth < kMinDepth || *w.max_depth > kMaxDepth))
    throw InputError(option_name("max_depth", spelling) + ": must be between 1 and 200, got " +
                     std::to_string(*w.max_depth));
  if (w.threads < kMinThreads || w.threads > kMaxThreads)
    throw InputError(option_name("threads", spelling) + ": must be between 1 and 256, got " + std::to_string(w.threads));
  if (w.time_limit && !valid_time_limit(*w.time_limit))
    throw InputError(option_name("time_limit", spelling) + ": must be a number of seconds, > 0 and at most 1e9");
  if (w.certificate && w.kernel == KernelKind::Fast)
    throw InputError(spelling == OptionSpelling::Library
                         ? "certificate: the fast kernel is not certified; use the filtered or the exact kernel"
                         : "--certificate: the fast kernel is not certified; use --kernel filtered or exact");
}

VerifyOptions build_options(const WrittenOptions& w, const Scene& scene, EpsilonScope scope, OptionSpelling spelling) {
  check_options(w, spelling);
  VerifyOptions options;
  options.kernel = w.kernel;
  resolve_epsilon(options, w.epsilon, scene, scope);
  options.max_depth = w.max_depth ? *w.max_depth : scene.max_depth;
  options.threads = w.threads;
  if (w.time_limit) options.time_limit = *w.time_limit;
  options.hierarchy = !w.all_pairs;
  options.record_cover = w.certificate;
  return options;
}

}  // namespace tmcert
