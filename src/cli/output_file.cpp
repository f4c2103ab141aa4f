#include "src/cli/output_file.h"

#include "src/scene/parse.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sys/stat.h>

namespace tmcert {

namespace {

std::string reason(int error) { return error ? std::string(": ") + std::strerror(error) : std::string(); }

}  // namespace

OutputFile::OutputFile(std::string option, std::string path) : option_(std::move(option)), path_(std::move(path)) {
  if (path_.empty()) throw InputError(option_ + ": the file name is empty");
  // A directory or a device is refused by name (opening a directory for
  // writing fails anyway, but with a vaguer reason).
  struct stat info;
  existed_ = ::stat(path_.c_str(), &info) == 0;
  if (existed_ && S_ISDIR(info.st_mode)) throw InputError(option_ + ": cannot write '" + path_ + "': it is a directory");
  errno = 0;
  std::ofstream probe(path_, std::ios::binary | std::ios::app);
  if (!probe) throw InputError(option_ + ": cannot write '" + path_ + "'" + reason(errno));
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
