// Reading an input file whole, safely: only a regular file (a FIFO, a
// device such as /dev/zero, a socket or a directory would block or never
// end), and at most a given number of bytes.
#pragma once

#include <cstdint>
#include <string>

namespace tmcert {

// The contents of the regular file `path` (symbolic links followed).
// Throws InputError "<path>: <what>" when it cannot be opened, is not a
// regular file, cannot be read, or holds more than `max_bytes` bytes (also
// when it grows beyond that while being read).  Never blocks on opening:
// the file is opened non-blocking and checked before anything is read.
std::string read_regular_file(const std::string& path, std::uintmax_t max_bytes);

}  // namespace tmcert
