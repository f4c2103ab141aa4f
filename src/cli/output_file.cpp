#include "src/cli/output_file.h"

#include "src/io/parse.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace tmcert {

namespace {

std::string reason(int error) { return error ? std::string(": ") + std::strerror(error) : std::string(); }

}  // namespace

OutputFile::OutputFile(std::string option, std::string path) : option_(std::move(option)), path_(std::move(path)) {
  if (path_.empty()) throw InputError(option_ + ": the file name is empty");
  // lstat: a dangling symbolic link counts as existing, so that it is never
  // removed.  A directory is refused by name (opening it fails anyway, but
  // with a vaguer reason).
  struct stat info;
  existed_ = ::lstat(path_.c_str(), &info) == 0;
  if (existed_ && ::stat(path_.c_str(), &info) == 0 && S_ISDIR(info.st_mode))
    throw InputError(option_ + ": cannot write '" + path_ + "': it is a directory");
  // O_NONBLOCK: a FIFO without a reader fails at once instead of blocking
  // the command before it has started.  Nothing is truncated here.
  errno = 0;
  const int fd = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_CLOEXEC | O_NONBLOCK, 0666);
  if (fd < 0) throw InputError(option_ + ": cannot write '" + path_ + "'" + reason(errno));
  ::close(fd);
}

OutputFile::~OutputFile() {
  if (!written_ && !existed_) std::remove(path_.c_str());
}

void OutputFile::write(const std::string& content) {
  errno = 0;
  std::ofstream out(path_, std::ios::binary | std::ios::trunc);
  out << content;
  out.close();
  if (!out) throw InputError(option_ + ": cannot write '" + path_ + "'" + reason(errno));
  written_ = true;
}

}  // namespace tmcert
