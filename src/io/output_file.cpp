#include "src/io/output_file.h"

#include "kernels/allocation.h"
#include "src/io/parse.h"

#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace tmcert {

namespace {

std::string reason(int error) { return error ? std::string(": ") + std::strerror(error) : std::string(); }

FileIdentity identity_of(const struct stat& info, const std::string& path) {
  return {static_cast<std::uint64_t>(info.st_dev), static_cast<std::uint64_t>(info.st_ino), path};
}

// The absolute path with links and "." / ".." resolved as far as it exists.
std::string resolved(const std::string& path) {
  std::error_code ec;
  const std::filesystem::path absolute = std::filesystem::absolute(path, ec);
  if (ec) return path;
  const std::filesystem::path canonical = std::filesystem::weakly_canonical(absolute, ec);
  return ec ? absolute.lexically_normal().string() : canonical.string();
}

}  // namespace

std::optional<FileIdentity> file_identity(const std::string& path) {
  struct stat info;
  if (path.empty() || ::stat(path.c_str(), &info) != 0) return std::nullopt;
  return identity_of(info, path);
}

OutputFile::OutputFile(std::string option, std::string path) : option_(std::move(option)), path_(std::move(path)) {
  if (path_.empty()) throw InputError(option_ + ": the file name is empty");
  if (path_.find('\0') != std::string::npos) throw InputError(option_ + ": the file name contains a NUL character");
  const std::string cannot = option_ + ": cannot write '" + path_ + "'";
  resolved_ = resolved(path_);
  struct stat info;
  if (::stat(path_.c_str(), &info) == 0) {
    identity_ = identity_of(info, path_);
    if (S_ISDIR(info.st_mode)) throw InputError(cannot + ": it is a directory");
    // O_NONBLOCK: a FIFO without a reader fails at once (ENXIO) instead of
    // blocking the command before it has started.  Nothing is truncated.
    errno = 0;
    const int fd = ::open(path_.c_str(), O_WRONLY | O_CLOEXEC | O_NONBLOCK);
    if (fd < 0) {
      const int error = errno;
      if (error == ENXIO && S_ISFIFO(info.st_mode))
        throw InputError(cannot + ": no process has this FIFO open for reading");
      throw InputError(cannot + reason(error));
    }
    if (S_ISREG(info.st_mode)) {
      ::close(fd);  // written (truncated) only at the end
      return;
    }
    // A special file: this descriptor is the one written at the end (a
    // FIFO opened twice would give its reader an end of file in between),
    // in blocking mode from now on.
    special_ = true;
    fd_ = fd;
    const int flags = ::fcntl(fd_, F_GETFL);
    if (flags >= 0) ::fcntl(fd_, F_SETFL, flags & ~O_NONBLOCK);
    return;
  }
  const int missing = errno;
  struct stat link;
  if (::lstat(path_.c_str(), &link) == 0) return;  // a dangling symbolic link: its target is created when written
  if (missing != ENOENT) throw InputError(cannot + reason(missing));
  // A new file: can it be created?  Tried and removed again at once, so
  // that nothing is left if the run fails.
  errno = 0;
  const int fd = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) throw InputError(cannot + reason(errno));
  ::close(fd);
  ::unlink(path_.c_str());
}

OutputFile::~OutputFile() {
  if (fd_ >= 0) ::close(fd_);
  if (!remove_path_.empty()) {
    if (!finished_) ::unlink(remove_path_.c_str());
    keep_on_fatal_exit(remove_path_.c_str());
  }
}

bool OutputFile::same_file(const OutputFile& other) const {
  if (identity_ && other.identity_) return identity_->same(*other.identity_);
  return resolved_ == other.resolved_;
}

void OutputFile::failed(int error) {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  if (!remove_path_.empty()) {
    ::unlink(remove_path_.c_str());
    keep_on_fatal_exit(remove_path_.c_str());
    remove_path_.clear();
  }
  finished_ = true;
  throw OutputError(option_ + ": cannot write '" + path_ + "'" + reason(error));
}

void OutputFile::begin() {
  if (begun_) return;
  begun_ = true;
  if (special_) return;
  errno = 0;
  fd_ = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd_ < 0) failed(errno);
  struct stat info;
  if (::fstat(fd_, &info) == 0 && !S_ISREG(info.st_mode)) {
    special_ = true;  // became special meanwhile: written, never removed
    return;
  }
  // The regular file now holds partial output until finish(): removed if
  // the run fails (also from the out-of-memory handlers), under its
  // resolved name (a symbolic link's target).
  char* real = ::realpath(path_.c_str(), nullptr);
  remove_path_ = real ? std::string(real) : path_;
  std::free(real);
  remove_on_fatal_exit(remove_path_.c_str());
}

void OutputFile::append(const char* data, std::size_t size) {
  if (!begun_) begin();
  if (fd_ < 0) failed(EBADF);
  while (size > 0) {
    const ::ssize_t n = ::write(fd_, data, size);
    if (n < 0) {
      if (errno == EINTR) continue;
      failed(errno);
    }
    if (n == 0) failed(EIO);
    data += n;
    size -= static_cast<std::size_t>(n);
  }
}

void OutputFile::finish() {
  if (!begun_) begin();
  if (fd_ < 0) failed(EBADF);
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0 && errno != EINTR) {
    const int error = errno;
    fd_ = -1;
    failed(error);
  }
  finished_ = true;
  if (!remove_path_.empty()) {
    keep_on_fatal_exit(remove_path_.c_str());
    remove_path_.clear();
  }
}

void OutputFile::write(const std::string& content) {
  begin();
  append(content);
  finish();
}

void require_distinct(const std::vector<const OutputFile*>& outputs, const std::vector<FileIdentity>& inputs) {
  struct stat out_info;
  std::optional<FileIdentity> standard_output;
  if (::fstat(STDOUT_FILENO, &out_info) == 0 && S_ISREG(out_info.st_mode))
    standard_output = identity_of(out_info, "standard output");
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    const OutputFile& o = *outputs[i];
    const std::string named = o.option() + ": '" + o.path() + "'";
    for (const FileIdentity& input : inputs)
      if (o.identity() && o.identity()->same(input))
        throw InputError(named + " is the input file '" + input.path + "'; it would be overwritten");
    for (std::size_t j = 0; j < i; ++j)
      if (o.same_file(*outputs[j]))
        throw InputError(named + " is the same file as " + outputs[j]->option() + " '" + outputs[j]->path() +
                         "'; give each output its own file");
    if (standard_output && o.identity() && o.identity()->same(*standard_output))
      throw InputError(named + " is the file the standard output goes to; give it another file");
  }
}

void flush_stdout() {
  errno = 0;
  std::cout.flush();
  const bool stream_failed = !std::cout;
  const int flushed = std::fflush(stdout);
  const int error = errno;
  if (stream_failed || flushed != 0 || std::ferror(stdout))
    throw OutputError("cannot write the standard output" + reason(error));
}

void write_stdout(const std::string& text) {
  std::cout << text;
  flush_stdout();
}

}  // namespace tmcert
