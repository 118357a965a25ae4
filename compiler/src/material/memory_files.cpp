#include "matc/material/memory_files.h"

#include <filesystem>

#include <fmt/format.h>

namespace matc {
namespace {

namespace fs = std::filesystem;

// `path` without "." parts and with "a/../" folded, in '/' form.
std::string normalised(const fs::path& path) {
  return path.lexically_normal().generic_string();
}

}  // namespace

std::string memory_file_name_problem(const std::string& name) {
  if (name.empty()) return "an empty name";
  if (name.find('\0') != std::string::npos) return "a name with a NUL byte";
  if (name.find('\\') != std::string::npos) return "a name with a backslash";
  if (name.front() == '/') return "an absolute path";
  if (name.find(':') != std::string::npos) return "a name with a drive or scheme";
  const std::string folded = normalised(name);
  if (folded == ".." || folded.starts_with("../")) return "a path that leaves the input's folder";
  if (folded == "." || folded.ends_with("/")) return "a folder, not a file";
  return {};
}

FileLoader memory_file_loader(const MemoryFiles& files, const std::string& input_path) {
  const std::string folder = normalised(fs::path(input_path).parent_path());
  return [&files, folder](const fs::path& path, std::uintmax_t max_bytes) -> LoadedFile {
    std::string name = normalised(path);
    if (!folder.empty() && folder != ".") {
      if (!name.starts_with(folder + "/")) return {std::nullopt, "not beside the input"};
      name.erase(0, folder.size() + 1);
    }
    for (const auto& [given, bytes] : files) {
      if (normalised(given) != name) continue;
      if (bytes.size() > max_bytes)
        return {std::nullopt, fmt::format("{} bytes; at most {}", bytes.size(), max_bytes)};
      return {bytes, {}};
    }
    return {std::nullopt, "not among the files given with the input"};
  };
}

}  // namespace matc
