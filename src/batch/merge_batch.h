// `tmcert batch-merge` (docs/scene-format.md "Batch runs"): the result
// files of the shards of one batch run merged into the bytes an unsharded
// run writes.
#pragma once

#include <string>
#include <vector>

namespace tmcert {

// Merges result files (each in increasing "index" order, as `tmcert batch`
// writes them) by index into `output` (empty: standard output), copying
// every line byte for byte.  Everything is checked before anything is
// written: every line is a JSON object with a non-negative integer
// "index", a file's indices increase, and together the files hold every
// index from 0 to the largest exactly once.  Throws InputError naming the
// file and line otherwise (exit 3, nothing written), or when `output`
// cannot be written or is one of the files to merge (src/scene/
// output_file.h); OutputError (exit 4) when a write fails.  Returns the
// number of lines merged.
std::size_t merge_batch(const std::vector<std::string>& shards, const std::string& output);

}  // namespace tmcert
