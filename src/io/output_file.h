// Output files named by the user (`--certificate`, `--report`, `-o`, and
// Result::write_certificate in the library): docs/scene-format.md "Output
// paths".
//
// - Checked before any work (InputError, exit 3): a path that is empty, a
//   directory, or cannot be written; the same file (device and inode, also
//   through links and other spellings) as an input, another output or the
//   standard output's file (require_distinct).
// - Nothing is created or changed before the result is written: a run
//   that fails first (bad input, out of memory) leaves no file behind and
//   an existing file as it was.  A FIFO or another special file (a
//   terminal, /dev/null) is opened once, at the check (non-blocking, so
//   that a FIFO without a reader is refused at once instead of blocking),
//   and that descriptor is written at the end: its reader never sees an
//   early end of file.
// - A write that fails (a full disk, /dev/full, a reader gone) is
//   OutputError (exit 4) naming the option, the path and the reason; a
//   regular file being written is removed then (also when the process ends
//   through the out-of-memory handlers, kernels/allocation.h), a special
//   file is not.
#pragma once

#include "src/model/model.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace tmcert {

// A write that failed: exit 4 (a resource limit: no honest result can be
// delivered).  The message names the option (or "standard output"), the
// path and the system's reason.
class OutputError : public ResourceLimit {
 public:
  using ResourceLimit::ResourceLimit;
};

class OutputFile {
 public:
  // Checks `path` (named by `option` in messages) as above; throws
  // InputError when it cannot be written.
  OutputFile(std::string option, std::string path);
  // A file begun but not finished (the run failed while writing it) is
  // removed when it is a regular file; a kept descriptor is closed.
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  // Writes the whole content: begin(), append(), finish().
  void write(const std::string& content);
  // Streaming (batch results): begin() truncates or creates a regular file
  // (or takes the kept descriptor of a special one), append() writes, and
  // finish() closes.  Each throws OutputError when the system refuses.
  void begin();
  void append(const char* data, std::size_t size);
  void append(const std::string& text) { append(text.data(), text.size()); }
  void finish();

  const std::string& option() const { return option_; }
  const std::string& path() const { return path_; }
  // The file's identity when it exists (at the check).
  const std::optional<FileIdentity>& identity() const { return identity_; }
  // Whether this output and `other` name the same file: the same device
  // and inode, or for files that do not exist yet the same absolute path
  // once links and "." / ".." are resolved.
  bool same_file(const OutputFile& other) const;

 private:
  [[noreturn]] void failed(int error);

  std::string option_, path_;
  std::optional<FileIdentity> identity_;
  std::string resolved_;      // the absolute, resolved path (for paths not yet existing)
  int fd_ = -1;               // kept descriptor (special file), or the file being written
  bool special_ = false;      // FIFO, device, socket: written through the kept descriptor, never removed
  bool begun_ = false, finished_ = false;
  std::string remove_path_;   // the regular file being written (resolved), removed when writing fails
};

// Refuses (InputError naming both) an output that is the same file as an
// input, as another output, or as the standard output when that is a
// regular file (`> file` and `--certificate file` would overwrite each
// other).
void require_distinct(const std::vector<const OutputFile*>& outputs, const std::vector<FileIdentity>& inputs);

// The identity of an existing file (symbolic links followed); none when it
// cannot be found.
std::optional<FileIdentity> file_identity(const std::string& path);

// Writes `text` to the standard output and flushes it; throws OutputError
// ("standard output: ...") when that fails (a full disk, /dev/full, a
// closed pipe).  flush_stdout() only flushes and checks.
void write_stdout(const std::string& text);
void flush_stdout();

}  // namespace tmcert
