// Where a batch's files go: a directory (each file written atomically, an unchanged file left
// untouched so build systems see no change) or memory (an asset server, a test, a Python script).
// Batches write from several threads at once: every sink is thread-safe.
#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <mutex>
#include <ostream>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "pipeline/atomic_file.h"

namespace matc {

class OutputSink {
 public:
  virtual ~OutputSink() = default;
  // Stores `bytes` as the file `name` (a plain file name, no folders). Throws std::runtime_error
  // with a readable reason when it cannot.
  virtual WriteOutcome write(const std::string& name, std::string_view bytes) = 0;
  // The same for a file too large to hold in memory at once: `produce` writes its bytes.
  virtual WriteOutcome write(const std::string& name,
                             const std::function<void(std::ostream&)>& produce) = 0;
  // All of a material's files, or none of them: a failure leaves none of `files` changed.
  // Outcomes in the order of `files`.
  virtual std::vector<WriteOutcome> write_all(std::span<const OutputFile> files);
  // The folder the files land in, when they land on disk: a batch then checks that no output
  // overwrites an input, spools its manifest there and can write a depfile. Null for memory.
  virtual const std::filesystem::path* directory() const { return nullptr; }
};

// Files in `directory` (created on the first write), written by write_file_atomically.
class DirectoryOutput final : public OutputSink {
 public:
  explicit DirectoryOutput(std::filesystem::path directory) : directory_(std::move(directory)) {}
  WriteOutcome write(const std::string& name, std::string_view bytes) override;
  WriteOutcome write(const std::string& name,
                     const std::function<void(std::ostream&)>& produce) override;
  std::vector<WriteOutcome> write_all(std::span<const OutputFile> files) override;
  const std::filesystem::path* directory() const override { return &directory_; }

 private:
  void create_directory_once();

  std::filesystem::path directory_;
  std::once_flag created_;
};

// Files kept in memory, by name; a file written again with the same bytes is "unchanged".
class MemoryOutput final : public OutputSink {
 public:
  WriteOutcome write(const std::string& name, std::string_view bytes) override;
  WriteOutcome write(const std::string& name,
                     const std::function<void(std::ostream&)>& produce) override;
  // What was written, by file name (call once the batch has returned).
  const std::map<std::string, std::string>& files() const { return files_; }

 private:
  std::mutex mutex_;
  std::map<std::string, std::string> files_;
};

}  // namespace matc
