#include "src/batch/merge_batch.h"

#include "src/model/model.h"
#include "src/io/parse.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <queue>
#include <utility>

namespace tmcert {

namespace {

// One shard's file, read line by line.
struct ShardFile {
  std::string name;
  std::ifstream in;
  std::string line;
  std::size_t line_number = 0;
  std::size_t index = 0;  // of `line`

  // The next line and its index; false at the end of the file.
  bool next() {
    if (!std::getline(in, line)) {
      if (in.bad()) throw InputError(name + ": reading failed");
      return false;
    }
    ++line_number;
    const std::string where = name + " line " + std::to_string(line_number) + ": ";
    nlohmann::json doc = nlohmann::json::parse(line, nullptr, false);
    if (doc.is_discarded() || !doc.is_object())
      throw InputError(where + "not a result line (expected one JSON object per line)");
    const auto it = doc.find("index");
    if (it == doc.end() || !it->is_number_unsigned())
      throw InputError(where + "index: missing, or not a non-negative integer");
    const std::size_t previous = index;
    index = it->get<std::size_t>();
    if (line_number > 1 && index <= previous)
      throw InputError(where + "index: " + std::to_string(index) + " after " + std::to_string(previous) +
                       " (a shard's results are in increasing index order)");
    return true;
  }
};

std::vector<std::unique_ptr<ShardFile>> open_all(const std::vector<std::string>& names) {
  std::vector<std::unique_ptr<ShardFile>> files;
  for (const std::string& name : names) {
    std::error_code ec;
    if (std::filesystem::is_directory(name, ec)) throw InputError(name + ": is a directory, not a result file");
    auto f = std::make_unique<ShardFile>();
    f->name = name;
    f->in.open(name, std::ios::binary);
    if (!f->in) throw InputError(name + ": cannot open the result file");
    files.push_back(std::move(f));
  }
  return files;
}

// Visits the lines of all files in index order, checking that the
// indices are 0, 1, 2, ... with no gap and no repetition.
void merge_lines(std::vector<std::unique_ptr<ShardFile>>& files, const std::function<void(const std::string&)>& emit) {
  using Head = std::pair<std::size_t, std::size_t>;  // (index, file)
  std::priority_queue<Head, std::vector<Head>, std::greater<Head>> heads;
  for (std::size_t f = 0; f < files.size(); ++f)
    if (files[f]->next()) heads.push({files[f]->index, f});
  std::size_t expected = 0;
  while (!heads.empty()) {
    const auto [index, f] = heads.top();
    heads.pop();
    ShardFile& file = *files[f];
    const std::string where = file.name + " line " + std::to_string(file.line_number) + ": index: ";
    if (index < expected) throw InputError(where + std::to_string(index) + " is also in another file");
    if (index > expected)
      throw InputError(where + std::to_string(index) + ", but no file holds index " + std::to_string(expected) +
                       " (a shard missing or incomplete)");
    emit(file.line);
    ++expected;
    if (file.next()) heads.push({file.index, f});
  }
}

}  // namespace

std::size_t merge_batch(const std::vector<std::string>& shards, const std::string& output) {
  if (shards.empty()) throw InputError("batch-merge: at least one result file is required");
  std::ofstream file_out;
  if (!output.empty()) {
    // Checked before any work; opened for writing only after the check.
    std::ofstream probe(output, std::ios::binary | std::ios::app);
    if (!probe) throw InputError("-o: cannot write " + quote_text(output));
  }
  for (const std::string& shard : shards) {
    std::error_code ec;
    if (!output.empty() && std::filesystem::equivalent(shard, output, ec))
      throw InputError("-o: " + quote_text(output) + " is also a result file to merge");
  }
  // First pass: everything checked, nothing written.
  {
    auto files = open_all(shards);
    merge_lines(files, [](const std::string&) {});
  }
  if (!output.empty()) {
    file_out.open(output, std::ios::binary | std::ios::trunc);
    if (!file_out) throw InputError("-o: cannot write " + quote_text(output));
  }
  std::ostream& out = output.empty() ? std::cout : file_out;
  auto files = open_all(shards);
  std::size_t lines = 0;
  merge_lines(files, [&](const std::string& line) {
    out << line << '\n';
    ++lines;
  });
  out.flush();
  if (!out) throw InputError(output.empty() ? std::string("cannot write to standard output")
                                            : "-o: cannot write " + quote_text(output));
  return lines;
}

}  // namespace tmcert
