// matc_manifest.json, what a batch wrote: the build's description (Build::description), the
// shared files and, per material, its files with their hashes. A batch of any size formats each
// material's entry as it finishes and appends it in input order; the entries wait in an unnamed
// temporary file in the output directory (100,000 materials with every output list ~300 MB), so
// nothing is left behind even by a killed matc.
#pragma once

#include <cstddef>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <ostream>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "emit/build.h"

namespace matc {

class ManifestWriter {
 public:
  // Entries kept in `spool_directory` (the temporary is made on the first entry), or in memory
  // when it is empty.
  explicit ManifestWriter(std::filesystem::path spool_directory = {});

  // One material's entry as the manifest lists it ({name, source, inputs_hash, files}); safe to
  // call from any thread.
  static nlohmann::ordered_json entry(const MaterialOutputs& material);
  static std::string format_entry(const MaterialOutputs& material);

  // Appends a formatted entry after the others. Throws std::runtime_error when the temporary
  // cannot be made or written.
  void append(std::string_view formatted_entry);
  std::size_t entry_count() const { return count_; }

  // The manifest with every entry appended so far.
  void write(std::ostream& out, const Build& build, const std::vector<OutputFile>& shared);
  std::string text(const Build& build, const std::vector<OutputFile>& shared);

 private:
  struct Close {
    void operator()(std::FILE* file) const { std::fclose(file); }
  };
  std::filesystem::path spool_directory_;
  std::unique_ptr<std::FILE, Close> spool_;
  std::string in_memory_;
  std::size_t count_ = 0;
};

// The same manifest as one JSON tree, for batches held in memory.
nlohmann::ordered_json manifest_json(const Build& build, const std::vector<OutputFile>& shared,
                                     std::span<const MaterialOutputs> materials);

}  // namespace matc
