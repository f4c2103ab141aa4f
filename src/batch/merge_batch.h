// `tmcert batch-merge` (docs/scene-format.md "Batch runs"): the result
// files of the shards of one batch run merged into the bytes an unsharded
// run writes.
#pragma once

#include <string>
#include <cstddef>
#include <vector>

namespace tmcert {

// Merges result files (each in increasing "index" order, as `tmcert batch`
// writes them) by index into `output` (empty: standard output), copying
// every line byte for byte: a k-way merge that reads each file once, line
// by line, and holds one line per file.  Every line is a JSON object with
// a non-negative integer "index" (read by result_line_index where the line
// has tmcert's form, else parsed whole), a file's indices increase, and
// together the files hold every index from 0 to the largest exactly once.
// Throws InputError naming the file and line otherwise (exit 3), or when
// `output` cannot be written or is one of the files to merge
// (src/io/output_file.h); OutputError (exit 4) when a write fails; nothing is written then: a new or plain
// `output` file is written beside it and renamed onto it at the end (it
// keeps its permissions); standard output, or an `output` that is a
// device, a FIFO or a file with several links, is written only after a
// first pass has checked every line.  Returns the number of lines merged.
std::size_t merge_batch(const std::vector<std::string>& shards, const std::string& output);

// The "index" of a result line (without its line break) of the form
// `tmcert batch` writes: `{"index":N` (JSON whitespace allowed), N a JSON
// non-negative integer followed by ',' or '}', and the line's last
// character other than whitespace '}'.  The rest of the line is not read.
// False for any other line (which merge_batch then parses whole).
bool result_line_index(const char* line, std::size_t size, std::size_t& index);

}  // namespace tmcert
