// An output file named on the command line (`--certificate OUT`, and any
// other option that writes a file): opened when the command starts, so that
// a path that cannot be written is bad input (exit 3) before a long
// verification runs, and no verdict is ever printed without the file.
#pragma once

#include <string>

namespace tmcert {

class OutputFile {
 public:
  // Makes sure `path` can be written (opening it for appending, which
  // creates it when missing and leaves an existing file as it is); throws
  // InputError naming `option` and the path, with the system's reason, when
  // it cannot.
  OutputFile(std::string option, std::string path);
  // A file that this object created but never wrote (the run failed before
  // its result) is removed again; an existing file keeps its old content.
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  // Replaces the file's content and closes it; throws InputError naming the
  // option when writing fails (a full disk, a lost device).
  void write(const std::string& content);

  const std::string& path() const { return path_; }

 private:
  std::string option_, path_;
  bool existed_ = false;
  bool written_ = false;
};

}  // namespace tmcert
