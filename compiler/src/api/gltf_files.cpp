#include <filesystem>
#include <fstream>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "base/echoed_text.h"
#include "matc/api/gltf.h"
#include "material/gltf_asset.h"
#include "material/gltf_import.h"
#include "pipeline/atomic_file.h"

namespace matc::api {
namespace {

namespace fs = std::filesystem;

fs::path folder_of(const fs::path& path) {
  return path.parent_path().empty() ? fs::path(".") : path.parent_path();
}

// The files a .gltf names beside it, as relative paths (each URI decoded, once each). The import
// checked every one to stay inside the asset's folder.
std::vector<std::string> external_files(const GltfAsset& asset) {
  std::vector<std::string> files;
  std::set<std::string> seen;
  for (const std::string& uri : asset.external_uris) {
    std::string file = percent_decoded(uri);
    if (seen.insert(matc::path_identity(file)).second) files.push_back(std::move(file));
  }
  return files;
}

// Why a copy of `source` may not go to `target`: something else is there (a file with other
// bytes, a link, a folder: another asset's, maybe, which matc did not write). Empty when nothing
// is there, or the same bytes are.
std::string copy_target_problem(const fs::path& source, const fs::path& target) {
  std::error_code error;
  const fs::file_status status = fs::symlink_status(target, error);
  if (error || status.type() == fs::file_type::not_found) return {};
  if (status.type() != fs::file_type::regular) return "exists and is not a plain file";
  return same_file_contents(source, target) ? std::string() : "exists with other bytes";
}

// Why the asset may not be written to `output` (nothing written then); empty when it may.
std::string output_problem(const fs::path& input, const fs::path& output,
                           const std::vector<std::string>& files, bool copies) {
  const std::string written = matc::path_identity(output);
  std::set<std::string> inputs = {matc::path_identity(input)};
  for (const std::string& file : files)
    inputs.insert(matc::path_identity(folder_of(input) / file));
  if (written == matc::path_identity(input))
    return fmt::format("output '{}' would overwrite its input", echoed(output.string(), 128));
  if (inputs.contains(written))
    return fmt::format("output '{}' would overwrite a file the asset names",
                       echoed(output.string(), 128));
  if (!copies) return {};
  for (const std::string& file : files) {
    const fs::path target = folder_of(output) / file;
    if (inputs.contains(matc::path_identity(target)))
      return fmt::format(
          "copying '{}' beside the output would overwrite '{}', a file the asset names",
          echoed(file, 128), echoed(target.string(), 128));
    std::error_code error;
    const fs::path source = folder_of(input) / file;
    if (const std::string problem = copy_target_problem(source, target); !problem.empty())
      return fmt::format(
          "cannot copy '{}' beside the output: '{}' {}; matc replaces no file it "
          "may not have written (write the asset elsewhere, or remove that file)",
          echoed(file, 128), echoed(target.string(), 128), problem);
    if (!fs::is_regular_file(source, error))
      return fmt::format("cannot copy '{}', which the asset names: '{}' is not a file",
                         echoed(file, 128), echoed(source.string(), 128));
    const std::uintmax_t size = fs::file_size(source, error);
    if (error || size > kMaxGltfFileBytes)
      return fmt::format("cannot copy '{}', which the asset names: {}", echoed(file, 128),
                         error ? error.message() : fmt::format("{} bytes, over 256 MiB", size));
  }
  return {};
}

// Copies `source` to `target` as matc writes its outputs, a block at a time.
matc::WriteOutcome copy_beside_output(const fs::path& source, const fs::path& target) {
  std::error_code error;
  fs::create_directories(target.parent_path(), error);
  if (error)
    throw std::runtime_error(fmt::format(
        "cannot create '{}': {}", echoed(target.parent_path().string(), 128), error.message()));
  return write_file_atomically(target, [&](std::ostream& out) {
    std::ifstream in(source, std::ios::binary);
    if (!in)
      throw std::runtime_error(fmt::format("cannot read '{}'", echoed(source.string(), 128)));
    out << in.rdbuf();
  });
}

}  // namespace

GltfFilesCopied write_gltf(const GltfAsset& asset, std::string_view input,
                           std::string_view output) {
  const fs::path input_path(input);
  const fs::path output_path(output);
  const std::vector<std::string> files = external_files(asset);
  const bool copies = !files.empty() && matc::path_identity(folder_of(output_path)) !=
                                            matc::path_identity(folder_of(input_path));
  if (const std::string problem = output_problem(input_path, output_path, files, copies);
      !problem.empty())
    throw std::invalid_argument(problem);
  GltfFilesCopied copied;
  if (!output_path.parent_path().empty()) fs::create_directories(output_path.parent_path());
  if (copies) {
    for (const std::string& file : files) {
      // A file already there holds the same bytes (output_problem compared it): not read again.
      const fs::path target = folder_of(output_path) / file;
      std::error_code error;
      const bool there = fs::symlink_status(target, error).type() == fs::file_type::regular;
      const bool written = !there && copy_beside_output(folder_of(input_path) / file, target) ==
                                         matc::WriteOutcome::written;
      (written ? copied.written : copied.unchanged).push_back(file);
    }
  }
  write_file_atomically(output_path, asset.bytes);
  return copied;
}

}  // namespace matc::api
