#include "material/memory_files.h"

#include <filesystem>
#include <map>

#include <fmt/format.h>

namespace matc {
namespace {

namespace fs = std::filesystem;

// `path` without "." parts and with "a/../" folded, in '/' form.
std::string normalised(const fs::path& path) {
  return path.lexically_normal().generic_string();
}

}  // namespace

std::string relative_file_problem(const std::string& path, std::string_view what,
                                  std::string_view folder) {
  if (path.empty()) return fmt::format("an empty {}", what);
  if (path.find('\0') != std::string::npos) return fmt::format("a {} with a NUL byte", what);
  if (path.find('\\') != std::string::npos) return fmt::format("a {} with a backslash", what);
  if (path.front() == '/') return "an absolute path";
  if (path.find(':') != std::string::npos)
    return fmt::format("a {} with a scheme or drive (not a relative file)", what);
  int depth = 0;
  for (const fs::path& part : fs::path(path)) {
    if (part == "..")
      --depth;
    else if (part != "." && !part.empty())
      ++depth;
    if (depth < 0) return fmt::format("a path that leaves {}", folder);
  }
  return {};
}

std::string memory_file_name_problem(const std::string& name) {
  if (std::string problem = relative_file_problem(name, "name", "the input's folder");
      !problem.empty())
    return problem;
  const std::string folded = normalised(name);
  if (folded == "." || folded.ends_with("/")) return "a folder, not a file";
  return {};
}

FileLoader memory_file_loader(const MemoryFiles& files, const std::string& input_path) {
  const std::string folder = normalised(fs::path(input_path).parent_path());
  // Each file by its normalised name, once (of two names for one file, the first in order).
  std::map<std::string, const std::string*> by_name;
  for (const auto& [given, bytes] : files)
    by_name.emplace(normalised(given), &bytes);
  return [by_name = std::move(by_name), folder](const fs::path& path,
                                                std::uintmax_t max_bytes) -> LoadedFile {
    std::string name = normalised(path);
    if (!folder.empty() && folder != ".") {
      if (!name.starts_with(folder + "/")) return {std::nullopt, "not beside the input"};
      name.erase(0, folder.size() + 1);
    }
    const auto found = by_name.find(name);
    if (found == by_name.end()) return {std::nullopt, "not among the files given with the input"};
    const std::string& bytes = *found->second;
    if (bytes.size() > max_bytes)
      return {std::nullopt, fmt::format("{} bytes; at most {}", bytes.size(), max_bytes)};
    return {bytes, {}};
  };
}

}  // namespace matc
