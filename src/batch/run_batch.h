// `tmcert batch` (docs/scene-format.md "Batch runs"): an environment read
// once, then one request per line of a JSON Lines file, one result line
// per request in input order, streamed.
#pragma once

#include "src/batch/shard.h"
#include "src/verify/options.h"
#include "src/verify/progress.h"

#include <optional>
#include <string>

namespace tmcert {

struct BatchOptions {
  std::string requests;  // a JSON Lines file, or "-" for standard input
  std::string scene;     // the environment scene; empty: the first line of `requests`
  std::string output;    // the results file; empty: standard output
  Shard shard;
  // Kernel, epsilon, max_depth, time limit as written, for verify
  // (src/verify/options.h): epsilon and max_depth default to the
  // environment scene's, epsilon by resolve_epsilon for the whole scene
  // (one prepared environment serves every request); threads: requests
  // run in parallel (output order kept), each check in one thread.
  WrittenOptions verify;
  OptionSpelling spelling = OptionSpelling::CommandLine;  // of messages
  bool stats = false;    // each check's "stats", wall-clock seconds included
  std::vector<std::string> package_paths;  // --package-path (ReadOptions)
  bool quiet = false;    // no summary line on stderr
  // Progress and cancellation: `run` (src/verify/progress.h) counts the
  // shard's requests as its items (those read so far, those written);
  // once it is cancelled, no further result line is written and run_batch
  // throws Cancelled (the output then ends after the last complete line).
  RunProgress* run = nullptr;
};

// What a run did (its summary line).
struct BatchCounts {
  std::size_t requests = 0;  // every request of the file, in every shard
  std::size_t safe = 0, collision = 0, undecided = 0, error = 0;  // of the shard's
};

// Runs the shard's requests and returns the exit code: 1 when a request
// collides, else 2 when one is undecided or bad (a bad request line is not
// certified), else 0.  A summary goes to stderr.  Throws InputError (exit
// 3) for a bad environment, a bad or unwritable file, or an output that is
// an input (the requests, the environment scene or its files), before any
// result is written; OutputError (exit 4) when writing the results fails
// (the results file is removed then, src/io/output_file.h).
int run_batch(const BatchOptions& options, BatchCounts* counts = nullptr);

}  // namespace tmcert
