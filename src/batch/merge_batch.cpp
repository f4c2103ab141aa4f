#include "src/batch/merge_batch.h"

#include "src/model/model.h"
#include "src/io/output_file.h"
#include "src/io/parse.h"

#include <nlohmann/json.hpp>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <queue>
#include <random>
#include <sys/stat.h>
#include <unistd.h>
#include <utility>

namespace tmcert {

namespace {

std::string reason(int error) { return error ? std::string(": ") + std::strerror(error) : std::string(); }

bool json_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

}  // namespace

bool result_line_index(const char* line, std::size_t size, std::size_t& index) {
  const char* p = line;
  const char* const end = line + size;
  auto skip = [&] {
    while (p != end && json_space(*p)) ++p;
  };
  auto literal = [&](const char* text) {
    const std::size_t n = std::strlen(text);
    if (static_cast<std::size_t>(end - p) < n || std::memcmp(p, text, n) != 0) return false;
    p += n;
    return true;
  };
  skip();
  if (!literal("{")) return false;
  skip();
  if (!literal("\"index\"")) return false;
  skip();
  if (!literal(":")) return false;
  skip();
  if (p == end || *p < '0' || *p > '9') return false;
  std::size_t value = 0;
  if (*p == '0') {
    ++p;  // a leading zero is not JSON (and the fallback says so)
  } else {
    for (; p != end && *p >= '0' && *p <= '9'; ++p) {
      const std::size_t digit = static_cast<std::size_t>(*p - '0');
      if (value > (std::numeric_limits<std::size_t>::max() - digit) / 10) return false;  // too large: the fallback
      value = value * 10 + digit;
    }
  }
  skip();
  if (p == end || (*p != ',' && *p != '}')) return false;  // 1.5, 1e3, 01, ...: the fallback decides
  // The object closes at the end of the line (a line cut short does not).
  const char* last = end;
  while (last != p && json_space(last[-1])) --last;
  if (last == p || last[-1] != '}') return false;
  if (*p == '}' && last != p + 1) return false;
  index = value;
  return true;
}

namespace {

struct FileCloser {
  void operator()(std::FILE* f) const {
    if (f) std::fclose(f);
  }
};

// One shard's file, read line by line: only the current line is held.
struct ShardFile {
  std::string name;
  std::unique_ptr<std::FILE, FileCloser> in;
  char* line = nullptr;     // the current line, without its line break
  std::size_t size = 0;     // of `line`
  std::size_t capacity = 0;
  std::size_t line_number = 0;
  std::size_t index = 0;  // of `line`

  ~ShardFile() { std::free(line); }

  // The next line and its index; false at the end of the file.
  bool next() {
    errno = 0;
    const ssize_t got = ::getline(&line, &capacity, in.get());
    if (got < 0) {
      if (std::ferror(in.get())) throw InputError(name + ": reading failed" + reason(errno));
      return false;
    }
    ++line_number;
    size = static_cast<std::size_t>(got);
    const bool complete = size > 0 && line[size - 1] == '\n';
    if (complete) --size;
    const std::size_t previous = index;
    // A line as `tmcert batch` writes it gives its index without being
    // parsed; any other line (and a last line without its line break: a
    // file cut short) is parsed whole.
    if (!complete || !result_line_index(line, size, index)) {
      const std::string where = name + " line " + std::to_string(line_number) + ": ";
      nlohmann::json doc = nlohmann::json::parse(line, line + size, nullptr, false);
      if (doc.is_discarded() || !doc.is_object())
        throw InputError(where + "not a result line (expected one JSON object per line)");
      const auto it = doc.find("index");
      if (it == doc.end() || !it->is_number_unsigned())
        throw InputError(where + "index: missing, or not a non-negative integer");
      index = it->get<std::size_t>();
    }
    if (line_number > 1 && index <= previous)
      throw InputError(name + " line " + std::to_string(line_number) + ": index: " + std::to_string(index) +
                       " after " + std::to_string(previous) + " (a shard's results are in increasing index order)");
    return true;
  }
};

constexpr std::size_t kBuffer = 1 << 20;

std::vector<std::unique_ptr<ShardFile>> open_all(const std::vector<std::string>& names) {
  std::vector<std::unique_ptr<ShardFile>> files;
  for (const std::string& name : names) {
    std::error_code ec;
    if (std::filesystem::is_directory(name, ec)) throw InputError(name + ": is a directory, not a result file");
    auto f = std::make_unique<ShardFile>();
    f->name = name;
    errno = 0;
    f->in.reset(std::fopen(name.c_str(), "rb"));
    if (!f->in) throw InputError(name + ": cannot open the result file" + reason(errno));
    std::setvbuf(f->in.get(), nullptr, _IOFBF, kBuffer / 4);
    files.push_back(std::move(f));
  }
  return files;
}

// Visits the lines of all files in index order (a k-way merge: a heap of
// each file's current line), checking that the indices are 0, 1, 2, ...
// with no gap and no repetition.  Returns the number of lines.
std::size_t merge_lines(std::vector<std::unique_ptr<ShardFile>>& files,
                        const std::function<void(const char*, std::size_t)>& emit) {
  using Head = std::pair<std::size_t, std::size_t>;  // (index, file)
  std::priority_queue<Head, std::vector<Head>, std::greater<Head>> heads;
  for (std::size_t f = 0; f < files.size(); ++f)
    if (files[f]->next()) heads.push({files[f]->index, f});
  std::size_t expected = 0;
  while (!heads.empty()) {
    const auto [index, f] = heads.top();
    heads.pop();
    ShardFile& file = *files[f];
    if (index != expected) {
      const std::string where = file.name + " line " + std::to_string(file.line_number) + ": index: ";
      if (index < expected) throw InputError(where + std::to_string(index) + " is also in another file");
      throw InputError(where + std::to_string(index) + ", but no file holds index " + std::to_string(expected) +
                       " (a shard missing or incomplete)");
    }
    emit(file.line, file.size);
    ++expected;
    if (file.next()) heads.push({file.index, f});
  }
  return expected;
}

// Writes the merged lines to `out`; throws InputError naming `what` when
// writing fails.
std::size_t merge_into(const std::vector<std::string>& shards, std::FILE* out, const std::string& what) {
  auto files = open_all(shards);
  bool failed = false;
  const std::size_t lines = merge_lines(files, [&](const char* line, std::size_t size) {
    failed |= std::fwrite(line, 1, size, out) != size || std::fputc('\n', out) == EOF;
  });
  errno = 0;
  if (failed || std::fflush(out) != 0 || std::ferror(out)) throw OutputError(what + reason(errno));
  return lines;
}

// A regular file written beside the output and renamed onto it once every
// line is written: the output is never left holding part of a merge.
class Replacement {
 public:
  explicit Replacement(const std::filesystem::path& target) : target_(target) {
    struct stat info;
    const bool exists = ::stat(target_.c_str(), &info) == 0;
    const std::filesystem::path dir = target_.parent_path().empty() ? "." : target_.parent_path();
    std::random_device random;
    for (int attempt = 0; attempt < 100 && fd_ < 0; ++attempt) {
      char tag[32];
      std::snprintf(tag, sizeof tag, ".%08x.%ld.tmp", static_cast<unsigned>(random()), static_cast<long>(::getpid()));
      std::string name = ".";
      name += target_.filename().string();
      name += tag;
      path_ = dir / name;
      errno = 0;
      fd_ = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);  // the umask applies
      if (fd_ < 0 && errno != EEXIST) break;
    }
    if (fd_ < 0) throw InputError("-o: cannot write " + quote_text(target_.string()) + reason(errno));
    if (exists) ::fchmod(fd_, info.st_mode & 07777);  // the output keeps its permissions
    out_.reset(::fdopen(fd_, "wb"));
    if (!out_) {
      ::close(fd_);
      ::unlink(path_.c_str());
      throw InputError("-o: cannot write " + quote_text(target_.string()));
    }
    std::setvbuf(out_.get(), nullptr, _IOFBF, kBuffer);
  }
  ~Replacement() {
    if (!done_) ::unlink(path_.c_str());
  }
  Replacement(const Replacement&) = delete;
  Replacement& operator=(const Replacement&) = delete;

  std::FILE* file() { return out_.get(); }

  void commit() {
    errno = 0;
    const int closed = std::fclose(out_.release());
    if (closed != 0 || std::rename(path_.c_str(), target_.c_str()) != 0)
      throw OutputError("-o: cannot write " + quote_text(target_.string()) + reason(errno));
    done_ = true;
  }

 private:
  std::filesystem::path target_, path_;
  int fd_ = -1;
  std::unique_ptr<std::FILE, FileCloser> out_;
  bool done_ = false;
};

}  // namespace

std::size_t merge_batch(const std::vector<std::string>& shards, const std::string& output) {
  if (shards.empty()) throw InputError("batch-merge: at least one result file is required");
  // The output is checked before any work (src/io/output_file.h): none
  // of the result files to merge, nor the standard output's file; it is
  // written (truncated) only after the check of every line.
  std::optional<OutputFile> file_out;
  if (!output.empty()) {
    file_out.emplace("-o", output);
    std::vector<FileIdentity> inputs;
    for (const std::string& shard : shards)
      if (std::optional<FileIdentity> f = file_identity(shard)) inputs.push_back(*f);
    require_distinct({&*file_out}, inputs);
  }
  // A new or plain file: one pass into a replacement.
  if (!output.empty()) {
    std::filesystem::path target = output;
    std::error_code ec;
    if (std::filesystem::is_symlink(target, ec)) target = std::filesystem::weakly_canonical(target, ec);
    if (ec) target = output;
    struct stat info;
    const bool exists = ::stat(target.c_str(), &info) == 0;
    if (!exists || (S_ISREG(info.st_mode) && info.st_nlink == 1)) {
      if (exists) {  // a file the user may not write is not replaced
        errno = 0;
        const int fd = ::open(target.c_str(), O_WRONLY | O_CLOEXEC | O_NONBLOCK);
        if (fd < 0) throw InputError("-o: cannot write " + quote_text(output) + reason(errno));
        ::close(fd);
      }
      Replacement replacement(target);
      const std::size_t lines = merge_into(shards, replacement.file(), "-o: cannot write " + quote_text(output));
      replacement.commit();
      return lines;
    }
  }
  // Standard output, or a device, a FIFO, a file with other links: first
  // every line checked, nothing written; then the merge written.
  {
    auto files = open_all(shards);
    merge_lines(files, [](const char*, std::size_t) {});
  }
  auto files = open_all(shards);
  std::string buffer;
  auto flush = [&] {
    if (file_out) file_out->append(buffer);
    else write_stdout(buffer);
    buffer.clear();
  };
  if (file_out) file_out->begin();
  const std::size_t lines = merge_lines(files, [&](const char* line, std::size_t size) {
    buffer.append(line, size);
    buffer += '\n';
    if (buffer.size() >= (1u << 16)) flush();
  });
  flush();
  if (file_out) file_out->finish();
  return lines;
}

}  // namespace tmcert
