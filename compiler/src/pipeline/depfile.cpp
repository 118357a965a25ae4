#include "pipeline/depfile.h"

#include <set>

#include "pipeline/atomic_file.h"

namespace matc {
namespace {

std::string escaped(const std::filesystem::path& path) {
  std::string out;
  for (const char c : std::filesystem::absolute(path).lexically_normal().string()) {
    if (c == ' ' || c == '#') out.push_back('\\');
    if (c == '$') out.push_back('$');
    out.push_back(c);
  }
  return out;
}

}  // namespace

std::string depfile_text(const std::vector<std::filesystem::path>& targets,
                         const std::vector<std::filesystem::path>& dependencies) {
  std::string text;
  for (const auto& target : targets) {
    if (!text.empty()) text.append(" \\\n ");
    text.append(escaped(target));
  }
  text.append(":");
  std::set<std::string> seen;  // each dependency once, in first-seen order
  for (const auto& dependency : dependencies) {
    std::string path = escaped(dependency);
    if (seen.insert(path).second) text.append(" \\\n ").append(path);
  }
  text.append("\n");
  return text;
}

void write_depfile(const std::filesystem::path& path,
                   const std::vector<std::filesystem::path>& targets,
                   const std::vector<std::filesystem::path>& dependencies) {
  write_file_atomically(path, depfile_text(targets, dependencies));
}

}  // namespace matc
