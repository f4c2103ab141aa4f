// Reading an input file whole, safely: only a regular file (a FIFO, a
// device such as /dev/zero, a socket or a directory would block or never
// end), and at most a given number of bytes.
#pragma once

#include "src/model/model.h"

#include <cstdint>
#include <string>
#include <vector>

namespace tmcert {

// The contents of the regular file `path` (symbolic links followed).
// Throws InputError "<path>: <what>" when it cannot be opened, is not a
// regular file, cannot be read, or holds more than `max_bytes` bytes (also
// when it grows beyond that while being read).  Never blocks on opening:
// the file is opened non-blocking and checked before anything is read.
// While an InputRecord lives on this thread, it also notes the identity
// of every file read (see InputRecord).
std::string read_regular_file(const std::string& path, std::uintmax_t max_bytes);

// Notes the files that read_regular_file reads on this thread while it
// lives (a scene file, its meshes, URDFs and SRDFs), so that outputs can be
// checked against every input.  Records nest: an inner record's files also
// go to the outer one when it ends.
class InputRecord {
 public:
  InputRecord();
  ~InputRecord();
  InputRecord(const InputRecord&) = delete;
  InputRecord& operator=(const InputRecord&) = delete;
  const std::vector<FileIdentity>& files() const { return files_; }
  void add(FileIdentity file);

 private:
  InputRecord* outer_;
  std::vector<FileIdentity> files_;
};

}  // namespace tmcert
