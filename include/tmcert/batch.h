// Batch runs (`tmcert batch`, `tmcert batch-merge`; docs/scene-format.md,
// "Batch runs"): an environment read once, one request per line of a JSON
// Lines file, one result line per request in input order.
#pragma once

#include "tmcert/export.h"
#include "tmcert/numbers.h"
#include "tmcert/result.h"

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace tmcert::api {

// What BatchOptions::progress is given while batch() runs.
struct BatchProgress {
  std::size_t requests_read = 0;     // of the shard, read so far (the file is streamed)
  std::size_t requests_written = 0;  // their result lines written
  std::string activity;              // for people; not an interface
  double seconds = 0;                // since batch() started
};

// The options of `tmcert batch` (tmcert batch --help).
struct BatchOptions {
  std::string requests;  // the requests file (JSON Lines); "-" for standard input
  std::string scene;     // the environment scene file; empty: the first line of `requests`
  std::string output;    // the results file; empty: standard output
  std::string shard;     // "i/n": only the requests whose index is i modulo n; empty: all
  Kernel kernel = Kernel::Filtered;
  std::optional<Number> epsilon;  // none: the environment's, else its default refined; "auto": refined
  std::optional<int> max_depth;   // 1 to 200; none: the environment's
  std::optional<double> time_limit;  // seconds per check (none: 30 s when refined, else none)
  int threads = 1;                // requests run in parallel (the output is the same)
  bool stats = false;             // each check's stats (seconds included: not reproducible)
  // As VerifyOptions::progress: called about every progress_interval
  // seconds from a thread of batch()'s own; false (or an exception)
  // cancels the run: no further line is written (the output ends after
  // the last complete one) and batch() throws Cancelled (or rethrows).
  std::function<bool(const BatchProgress&)> progress;
  double progress_interval = 0.5;
};

// What a batch run did.
struct BatchSummary {
  std::size_t requests = 0;  // every request of the file, in every shard
  std::size_t safe = 0, collision = 0, undecided = 0, errors = 0;  // of this shard's (errors: bad lines)
  // tmcert batch's exit code: 1 when a request collides, else 2 when one is
  // undecided or bad, else 0.
  int exit_code = 0;
};

// Runs a batch (tmcert batch without its summary line on stderr).  Throws
// InputError for a bad environment, a bad option or a file that cannot be
// read or written (before any result is written), ResourceLimit, Cancelled.
TMCERT_API BatchSummary batch(const BatchOptions& options);

// Merges the result files of the shards of one run into the bytes of the
// unsharded run (tmcert batch-merge); empty `output`: standard output.
// Returns the number of result lines.  Throws InputError when the files do
// not make up one run or cannot be read or written.
TMCERT_API std::size_t batch_merge(const std::vector<std::string>& shards, const std::string& output = "");

}  // namespace tmcert::api

namespace tmcert {
using namespace api;
}
