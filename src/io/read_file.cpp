#include "src/io/read_file.h"

#include "src/model/model.h"

#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace tmcert {

namespace {

// Closes the descriptor on every path out.
struct Descriptor {
  int fd;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

std::string kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "a special file";
}

thread_local InputRecord* t_record = nullptr;

}  // namespace

InputRecord::InputRecord() : outer_(t_record) { t_record = this; }

InputRecord::~InputRecord() {
  t_record = outer_;
  if (outer_)
    for (FileIdentity& f : files_) outer_->add(std::move(f));
}

void InputRecord::add(FileIdentity file) {
  for (const FileIdentity& f : files_)
    if (f.same(file)) return;
  files_.push_back(std::move(file));
}

std::string read_regular_file(const std::string& path, std::uintmax_t max_bytes) {
  // O_NONBLOCK: opening a FIFO for reading would otherwise wait for a writer.
  const Descriptor file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
  if (file.fd < 0) throw InputError(path + ": cannot open file");
  struct stat info {};
  if (::fstat(file.fd, &info) != 0) throw InputError(path + ": cannot read file (" + std::strerror(errno) + ")");
  if (!S_ISREG(info.st_mode))
    throw InputError(path + ": not a regular file (it is " + kind_of(info.st_mode) + "); only regular files are read");
  if (t_record)
    t_record->add({static_cast<std::uint64_t>(info.st_dev), static_cast<std::uint64_t>(info.st_ino), path});
  const std::string too_large = path + ": file too large (more than " + std::to_string(max_bytes) + " bytes)";
  if (static_cast<std::uintmax_t>(info.st_size) > max_bytes) throw InputError(too_large);
  // A regular file never blocks; reading stops at max_bytes + 1 whatever
  // the size said (a file that grows meanwhile).
  const int flags = ::fcntl(file.fd, F_GETFL);
  if (flags >= 0) ::fcntl(file.fd, F_SETFL, flags & ~O_NONBLOCK);
  std::string text;
  text.resize(static_cast<std::size_t>(info.st_size) + 1);
  std::size_t used = 0;
  for (;;) {
    if (used == text.size()) {
      if (used > max_bytes) throw InputError(too_large);
      text.resize(std::min<std::uintmax_t>(max_bytes + 1, 2 * text.size() + 4096));
    }
    const ::ssize_t got = ::read(file.fd, text.data() + used, text.size() - used);
    if (got < 0) {
      if (errno == EINTR) continue;
      throw InputError(path + ": cannot read file (" + std::strerror(errno) + ")");
    }
    if (got == 0) break;
    used += static_cast<std::size_t>(got);
  }
  if (used > max_bytes) throw InputError(too_large);
  text.resize(used);
  return text;
}

}  // namespace tmcert
