// batch() and batch_merge() (include/tmcert/batch.h): tmcert batch and
// tmcert batch-merge as functions, with the command line's option rules.
#include "src/batch/merge_batch.h"
#include "src/batch/run_batch.h"
#include "src/batch/shard.h"
#include "src/verify/options.h"
#include "src/verify/progress.h"

#include "src/api/internal.h"
#include "tmcert/batch.h"

#include <cmath>
#include <exception>

namespace tmcert::api {

BatchSummary batch(const BatchOptions& options) {
  return public_errors([&] {
    tmcert::BatchOptions o;
    o.requests = options.requests;
    o.scene = options.scene;
    o.output = options.output;
    if (!options.shard.empty()) o.shard = tmcert::Shard::parse(options.shard);
    o.verify = written_options(options.kernel, options.epsilon, options.max_depth, options.time_limit, options.threads);
    tmcert::check_options(o.verify, tmcert::OptionSpelling::Library);
    o.spelling = tmcert::OptionSpelling::Library;
    o.stats = options.stats;
    o.quiet = true;
    tmcert::BatchCounts counts;
    int code = 0;
    if (!options.progress) {
      code = tmcert::run_batch(o, &counts);
    } else {
      if (!std::isfinite(options.progress_interval) || !(options.progress_interval > 0) ||
          options.progress_interval > 3600)
        throw InputError("progress_interval: must be a number of seconds, > 0 and at most 3600");
      tmcert::RunProgress run;
      o.run = &run;
      std::exception_ptr callback_error;
      try {
        tmcert::ProgressWatcher watcher(
            run,
            [&](const tmcert::ProgressReport& r) {
              try {
                return options.progress(BatchProgress{r.checks, r.checks_done, r.activity, r.seconds});
              } catch (...) {
                callback_error = std::current_exception();
                return false;
              }
            },
            options.progress_interval);
        code = tmcert::run_batch(o, &counts);
      } catch (const tmcert::Cancelled&) {
        if (callback_error) std::rethrow_exception(callback_error);
        throw;
      }
      if (callback_error) std::rethrow_exception(callback_error);
    }
    BatchSummary out;
    out.requests = counts.requests;
    out.safe = counts.safe;
    out.collision = counts.collision;
    out.undecided = counts.undecided;
    out.errors = counts.error;
    out.exit_code = code;
    return out;
  });
}

std::size_t batch_merge(const std::vector<std::string>& shards, const std::string& output) {
  return public_errors([&] { return tmcert::merge_batch(shards, output); });
}

}  // namespace tmcert::api
