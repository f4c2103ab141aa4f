// src/verify/options.h: the one options path.  The epsilon rule (a number
// fixed; else the scene's, fixed; else, and for "auto", the default,
// refined: per check or the whole scene's), the ranges and their messages
// in both spellings, and build_options.
#include "src/io/parse.h"
#include "src/verify/options.h"

#include <boost/test/unit_test.hpp>

#include <string>

using namespace tmcert;

namespace {

const std::string kScene = std::string(TMCERT_TEST_DATA) + "/scenes/far-triangle-keeps-check-epsilon.json";

std::string message_of(const WrittenOptions& w, OptionSpelling spelling) {
  try {
    check_options(w, spelling);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string epsilon_message(const std::string& text, OptionSpelling spelling) {
  try {
    parse_epsilon(text, spelling);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

BOOST_AUTO_TEST_SUITE(options)

BOOST_AUTO_TEST_CASE(resolve_epsilon_follows_the_one_rule) {
  Scene scene = parse_scene_file(kScene);
  BOOST_REQUIRE(!scene.epsilon);
  const Exact whole = default_epsilon(scene);
  const EpsilonChoice absent, automatic{true, std::nullopt}, given{false, Exact(1, 7)};
  for (EpsilonScope scope : {EpsilonScope::PerCheck, EpsilonScope::WholeScene}) {
    const bool per_check = scope == EpsilonScope::PerCheck;
    VerifyOptions o;
    resolve_epsilon(o, given, scene, scope);
    BOOST_TEST((o.epsilon && *o.epsilon == Exact(1, 7)));
    BOOST_TEST(!o.refine);
    // No epsilon anywhere: the default, refined.
    resolve_epsilon(o, absent, scene, scope);
    BOOST_TEST(o.refine);
    BOOST_TEST((per_check ? !o.epsilon : (o.epsilon && *o.epsilon == whole)));
    resolve_epsilon(o, automatic, scene, scope);
    BOOST_TEST(o.refine);
    BOOST_TEST((per_check ? !o.epsilon : (o.epsilon && *o.epsilon == whole)));
  }
  scene.epsilon = Exact(1, 3);  // the scene's: fixed, unless "auto" or a number is given
  for (EpsilonScope scope : {EpsilonScope::PerCheck, EpsilonScope::WholeScene}) {
    VerifyOptions o;
    resolve_epsilon(o, absent, scene, scope);
    BOOST_TEST((o.epsilon && *o.epsilon == Exact(1, 3)));
    BOOST_TEST(!o.refine);
    resolve_epsilon(o, given, scene, scope);
    BOOST_TEST((o.epsilon && *o.epsilon == Exact(1, 7)));
    BOOST_TEST(!o.refine);
    resolve_epsilon(o, automatic, scene, scope);
    BOOST_TEST(o.refine);
    const bool expected = scope == EpsilonScope::PerCheck ? !o.epsilon : (o.epsilon && *o.epsilon == default_epsilon(scene));
    BOOST_TEST(expected);
  }
}

BOOST_AUTO_TEST_CASE(epsilon_text_in_both_spellings) {
  BOOST_TEST(parse_epsilon("auto", OptionSpelling::Library).automatic);
  const EpsilonChoice c = parse_epsilon("3/1000", OptionSpelling::CommandLine);
  BOOST_TEST((!c.automatic && c.value && *c.value == Exact(3, 1000)));
  BOOST_TEST(epsilon_message("-1", OptionSpelling::CommandLine) ==
             "--epsilon: must be a positive number (decimal or p/q), got '-1'");
  BOOST_TEST(epsilon_message("0", OptionSpelling::Library) ==
             "epsilon: must be a positive number (decimal or p/q), got \"0\"");
}

BOOST_AUTO_TEST_CASE(ranges_and_their_messages) {
  WrittenOptions w;
  BOOST_TEST(message_of(w, OptionSpelling::Library).empty());
  w.max_depth = 201;
  BOOST_TEST(message_of(w, OptionSpelling::Library) == "max_depth: must be between 1 and 200, got 201");
  BOOST_TEST(message_of(w, OptionSpelling::CommandLine) == "--max-depth: must be between 1 and 200, got 201");
  w.max_depth = 200;
  w.threads = 0;
  BOOST_TEST(message_of(w, OptionSpelling::Library) == "threads: must be between 1 and 256, got 0");
  w.threads = 256;
  w.time_limit = 0.0;
  BOOST_TEST(message_of(w, OptionSpelling::Library) == "time_limit: must be a number of seconds, > 0 and at most 1e9");
  BOOST_TEST(!valid_time_limit(1e9 * 1.0000001));
  BOOST_TEST(valid_time_limit(1e9));
  w.time_limit = 1e9;
  w.certificate = true;
  w.kernel = KernelKind::Fast;
  BOOST_TEST(message_of(w, OptionSpelling::Library) ==
             "certificate: the fast kernel is not certified; use the filtered or the exact kernel");
  BOOST_TEST(message_of(w, OptionSpelling::CommandLine) ==
             "--certificate: the fast kernel is not certified; use --kernel filtered or exact");
}

BOOST_AUTO_TEST_CASE(build_options_takes_the_scenes_defaults) {
  Scene scene = parse_scene_file(kScene);
  scene.max_depth = 33;
  WrittenOptions w;
  w.threads = 4;
  w.all_pairs = true;
  w.certificate = true;
  w.time_limit = 2.5;
  VerifyOptions o = build_options(w, scene, EpsilonScope::PerCheck, OptionSpelling::Library);
  BOOST_TEST(o.max_depth == 33);
  BOOST_TEST(o.threads == 4);
  BOOST_TEST(!o.hierarchy);
  BOOST_TEST(o.record_cover);
  BOOST_TEST(o.time_limit == 2.5);
  BOOST_TEST((!o.epsilon && o.refine));
  w.max_depth = 12;
  o = build_options(w, scene, EpsilonScope::WholeScene, OptionSpelling::Library);
  BOOST_TEST(o.max_depth == 12);
  BOOST_TEST((o.epsilon && *o.epsilon == default_epsilon(scene) && o.refine));
}

BOOST_AUTO_TEST_SUITE_END()
