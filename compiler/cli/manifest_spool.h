// The manifest's "materials" list of a batch, kept in an unnamed temporary file in the output
// directory rather than in memory: 100,000 materials with every output list ~300 MB of entries.
#pragma once

#include <cstddef>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <ostream>
#include <string_view>

namespace matc::cli {

class ManifestSpool {
 public:
  explicit ManifestSpool(std::filesystem::path directory) : directory_(std::move(directory)) {}
  // Appends one formatted entry (Build::format_manifest_entry) with its separator.
  void append(std::string_view formatted_entry);
  std::size_t entry_count() const { return count_; }
  // Writes the entries appended so far, in order.
  void copy_to(std::ostream& out);

 private:
  struct Close {
    void operator()(std::FILE* file) const { std::fclose(file); }
  };
  std::filesystem::path directory_;
  std::unique_ptr<std::FILE, Close> file_;
  std::size_t count_ = 0;
};

}  // namespace matc::cli
