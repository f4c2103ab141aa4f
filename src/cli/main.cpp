// tmcert command line (SCENE_FORMAT.md): exit 0 safe, 1 collision,
// 2 undecided, 3 bad input or usage, 4 internal error or resource limit.
#include "kernels/allocation.h"
#include "src/batch/merge_batch.h"
#include "src/batch/run_batch.h"
#include "src/certificate/check.h"
#include "src/certificate/writer.h"
#include "src/report/report.h"
#include "src/html/report_html.h"
#include "src/io/output_file.h"
#include "src/io/parse.h"
#include "src/verify/options.h"
#include "src/verify/progress.h"
#include "src/verify/verify.h"

#include <CLI/CLI.hpp>

#include <sys/ioctl.h>
#include <unistd.h>

#include <csignal>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <memory>
#include <mutex>
#include <new>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

// The scene of `verify`, kept to the end of the process (run_verify).  A
// global with external linkage, so that the store is not optimised away and
// leak checkers see the scene as reachable, not leaked.
tmcert::Scene* g_kept_scene = nullptr;

namespace {

constexpr int kExitBadInput = 3;
constexpr int kExitInternal = 4;

int exit_code(tmcert::Verdict v) {
  switch (v) {
    case tmcert::Verdict::Safe: return 0;
    case tmcert::Verdict::Collision: return 1;
    case tmcert::Verdict::Undecided: return 2;
  }
  return 2;
}

struct VerifyArgs {
  std::string scene;
  std::string epsilon;
  int max_depth = -1;
  std::string kernel = "filtered";
  bool json = false;
  std::string certificate;
  int threads = 1;
  bool all_pairs = false;
  std::string time_limit;  // seconds per check; empty: none
  std::string report;      // --report: HTML page; empty: none
  std::vector<std::string> package_paths;  // --package-path, in order
};

// Progress on stderr when it is a terminal, from about two seconds into a
// run on: one line, rewritten in place a few times a second, erased before
// the result is printed.  It names what the run does (reading the scene,
// the check and its step, writing the certificate) and, while checks run,
// the share of their work done (src/verify/progress.h: below 100% until
// every check is done), so no phase of a long run is silent.
class TerminalProgress {
 public:
  static constexpr double kFirstAfter = 2.0;  // seconds
  static constexpr double kInterval = 0.25;   // seconds

  explicit TerminalProgress(tmcert::RunProgress& run)
      : first_after_(first_after()), watcher_(run, [this](const tmcert::ProgressReport& r) { return show(r); }, kInterval) {}
  ~TerminalProgress() {
    std::lock_guard<std::mutex> lock(mutex_);
    stopped_ = true;
    if (shown_) std::fputs("\r\033[K", stderr);
    std::fflush(stderr);
  }

  // The line for a report (without the carriage return), at most `width` bytes.
  static std::string line(const tmcert::ProgressReport& r, std::size_t width) {
    std::string text = "tmcert: ";
    char buffer[96];
    if (r.checks > 0 && r.checks_done < r.checks) {
      // Rounded down: never "100%" while a check is left.
      std::snprintf(buffer, sizeof buffer, "%d%% of %zu check%s, ", static_cast<int>(std::floor(100 * r.fraction)),
                    r.checks, r.checks == 1 ? "" : "s");
      text += buffer;
    } else if (r.checks > 0) {
      if (r.checks == 1) std::snprintf(buffer, sizeof buffer, "the check is done, ");
      else std::snprintf(buffer, sizeof buffer, "all %zu checks done, ", r.checks);
      text += buffer;
    }
    std::snprintf(buffer, sizeof buffer, "%.0f s", r.seconds);
    text += buffer;
    if (!r.activity.empty()) text += ": " + r.activity;
    if (width > 0 && text.size() > width) text.resize(width > 3 ? width - 3 : width), text += "...";
    return text;
  }

 private:
  // TMCERT_PROGRESS_AFTER=SECONDS replaces the two seconds (0: from the
  // start; tests/regression/progress_tty.py).
  static double first_after() {
    const char* text = std::getenv("TMCERT_PROGRESS_AFTER");
    if (!text || !*text) return kFirstAfter;
    char* end = nullptr;
    const double seconds = std::strtod(text, &end);
    return end && *end == '\0' && std::isfinite(seconds) && seconds >= 0 ? seconds : kFirstAfter;
  }

  bool show(const tmcert::ProgressReport& r) {
    if (r.seconds < first_after_) return true;
    struct winsize size {};
    const std::size_t columns = ioctl(STDERR_FILENO, TIOCGWINSZ, &size) == 0 && size.ws_col > 0 ? size.ws_col : 80;
    const std::string text = line(r, columns - 1);  // the last column would wrap on some terminals
    std::lock_guard<std::mutex> lock(mutex_);
    if (stopped_) return true;
    shown_ = true;
    std::fprintf(stderr, "\r%s\033[K", text.c_str());
    std::fflush(stderr);
    return true;
  }

  std::mutex mutex_;
  bool shown_ = false, stopped_ = false;
  double first_after_;
  tmcert::ProgressWatcher watcher_;  // last: stopped first
};

// --kernel (CLI11 admits only these three names).
tmcert::KernelKind kernel_option(const std::string& name) {
  return name == "exact" ? tmcert::KernelKind::Exact
         : name == "fast" ? tmcert::KernelKind::Fast
                          : tmcert::KernelKind::Filtered;
}

// --time-limit: a positive, finite number of seconds, at most 10^9 (about 31 years).
double time_limit_option(const std::string& option) {
  const char* text = option.c_str();
  char* end = nullptr;
  errno = 0;
  const double seconds = std::strtod(text, &end);
  if (end == text || *end != '\0' || errno == ERANGE || !tmcert::valid_time_limit(seconds))
    throw tmcert::InputError("--time-limit: must be a number of seconds, > 0 and at most 1e9, got '" + option + "'");
  return seconds;
}

// The reader's warnings (an rpy angle above 2 pi read as radians, ...)
// on stderr as soon as the scene is read; they are in the result too.
void print_warnings(const tmcert::Scene& scene) {
  for (const std::string& warning : scene.warnings) std::cerr << "tmcert: warning: " << warning << "\n";
}

int run_verify(const VerifyArgs& args) {
  using namespace tmcert;
  // Output paths are checked first (src/io/output_file.h): a path that
  // cannot be written is bad input (exit 3), never a verdict without its
  // file.  Nothing is created or changed before the result is written; a
  // FIFO is opened here once, so that its reader gets an end of file (not
  // a wait for ever) when the run fails before writing.  After the scene is
  // read, each must be none of its files, of the other output and of the
  // standard output's file.
  std::optional<OutputFile> certificate_file;
  if (!args.certificate.empty()) certificate_file.emplace("--certificate", args.certificate);
  std::optional<OutputFile> report_file;
  if (!args.report.empty()) report_file.emplace("--report", args.report);
  RunProgress run;
  std::optional<TerminalProgress> progress;
  if (isatty(STDERR_FILENO)) progress.emplace(run);
  run.set_activity("reading " + args.scene);
  auto owned = std::make_unique<Scene>(parse_scene_file(args.scene, ReadOptions{args.package_paths}));
  Scene& scene = *owned;
  if (progress) {
    // Warnings go before the progress line, which is erased and comes back.
    progress.reset();
    print_warnings(scene);
    progress.emplace(run);
  } else {
    print_warnings(scene);
  }
  // The options by the library's rules (src/verify/options.h), in the
  // command line's words.
  WrittenOptions written;
  written.kernel = kernel_option(args.kernel);
  if (!args.epsilon.empty()) written.epsilon = parse_epsilon(args.epsilon, OptionSpelling::CommandLine);
  if (args.max_depth >= 0) written.max_depth = args.max_depth;
  if (!args.time_limit.empty()) written.time_limit = time_limit_option(args.time_limit);
  written.threads = args.threads;
  written.all_pairs = args.all_pairs;
  written.certificate = !args.certificate.empty();
  VerifyOptions options = build_options(written, scene, EpsilonScope::PerCheck, OptionSpelling::CommandLine);
  require_supported(scene);
  if (!args.certificate.empty())
    if (const std::string why = certificate::uncertifiable(scene); !why.empty())
      throw InputError("--certificate: certificates do not cover this scene: " + why);
  std::vector<const OutputFile*> outputs;
  if (certificate_file) outputs.push_back(&*certificate_file);
  if (report_file) outputs.push_back(&*report_file);
  require_distinct(outputs, scene.input_files);
  options.run = &run;
  // As before the options were built in one place: the command line's
  // --threads spreads the checks, not the parts of one check (the library
  // spreads both; the result is the same).
  options.threads = 1;
  const SceneResult result = verify_scene(scene, options, args.threads);
  // Every document is built before anything is written, and the files
  // before the verdict is printed: running out of memory on the way leaves
  // no file and prints no verdict (exit 4), and a write that fails is exit
  // 4 naming the path (OutputError), never a verdict without its file.
  certificate::WriteStats stats;
  std::string certificate_text, report_text;
  if (certificate_file) {
    run.set_activity("writing the certificate " + args.certificate);
    certificate_text = certificate::certificate_json(scene, result, &stats);
  }
  if (report_file) {
    run.set_activity("writing the report " + args.report);
    report_text = report_html(scene, result);
  }
  const std::string printed = args.json ? result_json(scene, result) : result_summary(scene, result);
  progress.reset();  // erases the progress line before anything is printed
  if (certificate_file) {
    certificate_file->write(certificate_text);
    std::string().swap(certificate_text);
    std::cerr << "tmcert: certificate written to " << args.certificate << " (" << stats.pieces << " pieces, "
              << stats.separations << " separations, " << stats.seconds << " s)\n";
  }
  if (report_file) {
    report_file->write(report_text);
    std::cerr << "tmcert: report written to " << args.report << "\n";
  }
  write_stdout(printed);
  // The process ends now: freeing a scene of many bodies number by number
  // (every coordinate a GMP rational) took longer than verifying it, so the
  // scene is kept, reachable, for the system to reclaim.
  g_kept_scene = owned.release();
  return exit_code(result.verdict);
}

// `tmcert check CERTIFICATE SCENE`: 0 every claim holds, 1 rejected (one
// line on stderr naming the claim), 3 bad input, 4 internal error.
int run_certificate_check(const std::string& certificate_file, const std::string& scene_file,
                          const std::vector<std::string>& package_paths) {
  using namespace tmcert;
  const Scene scene = parse_scene_file(scene_file, ReadOptions{package_paths});
  print_warnings(scene);
  const nlohmann::json doc = certificate::read_certificate_file(certificate_file);
  const certificate::CheckOutcome outcome = certificate::check_certificate(scene, doc, certificate_file);
  if (!outcome.ok) {
    std::cerr << "tmcert: rejected: " << outcome.message << "\n";
    return 1;
  }
  std::string printed = "tmcert: certificate holds: every claim is proven\n";
  for (const std::string& line : outcome.proven) printed += "  " + line + "\n";
  write_stdout(printed);
  return 0;
}

// `tmcert batch` options as written, checked in run_batch_command.
struct BatchArgs {
  tmcert::BatchOptions options;
  std::optional<std::string> shard;
  std::string epsilon, kernel = "filtered", time_limit;
  int max_depth = -1;
};

int run_batch_command(BatchArgs& args) {
  using namespace tmcert;
  BatchOptions& o = args.options;
  if (args.shard) o.shard = Shard::parse(*args.shard);
  o.verify.kernel = kernel_option(args.kernel);
  if (!args.epsilon.empty()) o.verify.epsilon = parse_epsilon(args.epsilon, OptionSpelling::CommandLine);
  if (args.max_depth >= 0) o.verify.max_depth = args.max_depth;
  if (!args.time_limit.empty()) o.verify.time_limit = time_limit_option(args.time_limit);
  o.spelling = OptionSpelling::CommandLine;
  return run_batch(o);
}

// Edit distance (insertions, deletions, substitutions, transpositions of
// neighbours) between a and b, for suggestions.
std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i)
    for (std::size_t j = 1; j <= b.size(); ++j) {
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}

// A first argument that is neither an option nor a command: "unknown
// command 'verfy' (did you mean 'verify'?)" (CLI11 alone would say that
// a subcommand is required).  Empty when `word` is a command.
std::string unknown_command(const std::string& word, const std::vector<std::string>& commands) {
  if (std::find(commands.begin(), commands.end(), word) != commands.end()) return "";
  std::string best;
  std::size_t best_distance = 3;  // suggest within two edits, or a prefix
  for (const std::string& c : commands) {
    const std::size_t d = c.rfind(word, 0) == 0 && word.size() >= 2 ? 1 : edit_distance(word, c);
    if (d < best_distance) best_distance = d, best = c;
  }
  std::string message = "unknown command '" + word + "'";
  if (!best.empty()) message += " (did you mean '" + best + "'?)";
  std::string list;
  for (const std::string& c : commands) list += (list.empty() ? "" : ", ") + c;
  return message + "; the commands are " + list + " (tmcert --help)";
}

}  // namespace

int main(int argc, char** argv) {
  tmcert::install_allocation_failure_handlers();
  // A reader that goes away (a closed pipe, a FIFO's reader) makes the
  // write fail with EPIPE, reported as a failed write (exit 4) naming the
  // output, instead of killing the process without a word.
  std::signal(SIGPIPE, SIG_IGN);
  CLI::App app{"tmcert: certified collision checks of moving polyhedra"};
  app.set_version_flag("--version", "tmcert 0.1.0");
  app.require_subcommand(1);
  VerifyArgs args;
  CLI::App* verify = app.add_subcommand("verify", "check every requested body pair over the whole motion");
  verify->add_option("scene", args.scene, "scene file (tmcert-scene/1)")->required();
  verify->add_option("--epsilon", args.epsilon, "termination tolerance, a length, for every check, fixed (overrides the scene); "
                     "'auto' or absent (and none in the scene): per check, 1/1000 of the diagonal of its two bodies' "
                     "box, its undecided parts searched again at epsilon/10, ... down to 1e-9 of that diagonal");
  verify->add_option("--max-depth", args.max_depth, "subdivision depth limit (overrides the scene)")
      ->check(CLI::Range(tmcert::kMinDepth, tmcert::kMaxDepth));  // as the scene's max_depth
  verify->add_option("--kernel", args.kernel, "filtered (default, certified), exact (certified), fast (not certified)")
      ->check(CLI::IsMember({"filtered", "exact", "fast"}));
  verify->add_flag("--json", args.json, "print the tmcert-result/1 document");
  CLI::Option* certificate_option = verify->add_option("--certificate", args.certificate, "write a certificate of the verdict to this file (tmcert-certificate/2; re-check it with tmcert check)");
  CLI::Option* report_option = verify->add_option("--report", args.report, "write a visual report of the result to this file (one self-contained HTML page)");
  verify->add_option("--threads", args.threads, "worker threads")->check(CLI::Range(tmcert::kMinThreads, tmcert::kMaxThreads));
  verify->add_option("--time-limit", args.time_limit,
                     "seconds per check; when a check runs past it, the rest of its interval is undecided "
                     "(reason limit), never safe; default: 30 with refinement (no --epsilon, or --epsilon auto: its first "
                     "search and refinement together), none with a given epsilon");
  const char* package_help = "a folder searched for package://NAME/... (repeatable; before the scene's \"package_paths\" "
                             "and ROS_PACKAGE_PATH; each with its subfolders up to four levels)";
  verify->add_option("--package-path", args.package_paths, package_help)->allow_extra_args(false);
  verify->add_flag("--all-pairs", args.all_pairs,
                   "carry every feature pair from the start instead of the bounding-volume hierarchies "
                   "(the reference the hierarchy is tested against; slow for large bodies)");
  CLI::App* check = app.add_subcommand("check", "re-verify a certificate in exact arithmetic "
                                                "(0 every claim holds, 1 rejected, 3 bad input)");
  std::string cert_file, cert_scene;
  check->add_option("certificate", cert_file, "certificate file (tmcert-certificate/2, or /1)")->required();
  check->add_option("scene", cert_scene, "the scene it certifies (tmcert-scene/1)")->required();
  std::vector<std::string> check_packages;
  check->add_option("--package-path", check_packages, package_help)->allow_extra_args(false);
  BatchArgs batch_args;
  CLI::App* batch = app.add_subcommand("batch", "certify many motions against one environment: JSON Lines "
                                                "requests in, one result line per request out (in input order)");
  batch->add_option("requests", batch_args.options.requests,
                    "requests file (JSON Lines; - for standard input); its first line is the environment "
                    "unless --scene is given")->required();
  CLI::Option* batch_scene_option = batch->add_option("--scene", batch_args.options.scene, "the environment scene (tmcert-scene/1, fixed bodies)");
  CLI::Option* batch_output_option = batch->add_option("-o,--output", batch_args.options.output, "results file (default: standard output)");
  batch->add_option("--shard", batch_args.shard, "i/n: run only the requests whose index is i modulo n");
  batch->add_option("--epsilon", batch_args.epsilon, "termination tolerance, a length, fixed (overrides the environment); 'auto' or absent (and none in the "
                    "environment): the environment's default, undecided parts searched again at epsilon/10, ... down to "
                    "epsilon/10^6");
  batch->add_option("--max-depth", batch_args.max_depth, "subdivision depth limit (overrides the environment)")
      ->check(CLI::Range(tmcert::kMinDepth, tmcert::kMaxDepth));
  batch->add_option("--kernel", batch_args.kernel, "filtered (default, certified), exact (certified), fast (not certified)")
      ->check(CLI::IsMember({"filtered", "exact", "fast"}));
  batch->add_option("--time-limit", batch_args.time_limit, "seconds per check (the rest of a check past it is undecided; default: 30 with "
                                                      "refinement, none with a given epsilon)");
  batch->add_option("--threads", batch_args.options.verify.threads, "requests run in parallel (the output is the same)")
      ->check(CLI::Range(tmcert::kMinThreads, tmcert::kMaxThreads));
  batch->add_option("--package-path", batch_args.options.package_paths, package_help)->allow_extra_args(false);
  batch->add_flag("--stats", batch_args.options.stats,
                  "give each check its stats, wall-clock seconds included (output not reproducible)");
  std::vector<std::string> merge_files;
  std::string merge_output;
  CLI::App* merge = app.add_subcommand("batch-merge", "merge the result files of the shards of a batch run "
                                                      "(the bytes of the unsharded run)");
  merge->add_option("results", merge_files, "result files of the shards (any order)")->required();
  CLI::Option* merge_output_option = merge->add_option("-o,--output", merge_output, "merged file (default: standard output)");
  unsigned long long memory_limit = 0;
  for (CLI::App* sub : {verify, check, batch})
    sub->add_option("--memory-limit", memory_limit,
                    "address space of the process in MiB; beyond it: out of memory, exit 4, no verdict")
        ->check(CLI::Range(1ull, 1ull << 40));

  if (argc >= 2 && argv[1][0] != '-') {
    std::vector<std::string> commands;
    for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) commands.push_back(sub->get_name());
    if (const std::string unknown = unknown_command(argv[1], commands); !unknown.empty()) {
      std::cerr << "tmcert: " << unknown << "\n";
      return kExitBadInput;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    const int code = app.exit(e);  // --help, --version
    try {
      tmcert::flush_stdout();
    } catch (const tmcert::OutputError& error) {
      std::cerr << "tmcert: " << error.what() << "\n";
      return kExitInternal;
    }
    return code;
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return kExitBadInput;
  }

  // A file option given an empty name is refused, not taken as absent.
  for (const auto& [option, value, name] :
       {std::tuple{certificate_option, &args.certificate, "--certificate"}, {report_option, &args.report, "--report"},
        {batch_scene_option, &batch_args.options.scene, "--scene"}, {batch_output_option, &batch_args.options.output, "-o"},
        {merge_output_option, &merge_output, "-o"}})
    if (option->count() > 0 && value->empty()) {
      std::cerr << "tmcert: " << name << ": the file name is empty\n";
      return kExitBadInput;
    }
  if (memory_limit && !tmcert::limit_address_space(memory_limit)) {
    std::cerr << "tmcert: --memory-limit: the system refuses a limit of " << memory_limit << " MiB\n";
    return kExitBadInput;
  }
  try {
    if (check->parsed()) return run_certificate_check(cert_file, cert_scene, check_packages);
    if (batch->parsed()) return run_batch_command(batch_args);
    if (merge->parsed()) {
      const std::size_t lines = tmcert::merge_batch(merge_files, merge_output);
      std::cerr << "tmcert batch-merge: " << lines << " results from " << merge_files.size() << " files\n";
      return 0;
    }
    return run_verify(args);
  } catch (const tmcert::InputError& e) {
    std::cerr << "tmcert: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const tmcert::OutputError& e) {
    std::cerr << "tmcert: " << e.what() << "\n";
    return kExitInternal;
  } catch (const tmcert::ResourceLimit& e) {
    std::cerr << "tmcert: resource limit: " << e.what() << "\n";
    return kExitInternal;
  } catch (const std::bad_alloc&) {
    std::cerr << "tmcert: out of memory\n";
    return kExitInternal;
  } catch (const std::exception& e) {
    std::cerr << "tmcert: internal error: " << e.what() << "\n";
    return kExitInternal;
  } catch (...) {
    std::cerr << "tmcert: internal error\n";
    return kExitInternal;
  }
}
