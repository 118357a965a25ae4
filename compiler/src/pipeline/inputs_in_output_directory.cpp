#include "pipeline/inputs_in_output_directory.h"

#include <fmt/core.h>

#include "pipeline/atomic_file.h"

namespace matc {

namespace fs = std::filesystem;

InputsInOutputDirectory::InputsInOutputDirectory(const fs::path& output_directory)
    : directory_identity_(path_identity(output_directory)) {}

void InputsInOutputDirectory::add(const fs::path& path, const std::string& as_given) {
  const fs::path identity(path_identity(path));
  if (identity.parent_path() == directory_identity_)
    inputs_.emplace(identity.filename().string(), as_given);
}

std::optional<std::string> InputsInOutputDirectory::overwritten_by(const fs::path& output) const {
  const auto input = inputs_.find(output.filename().string());
  if (input == inputs_.end()) return std::nullopt;
  return input->second;
}

std::optional<std::string> InputsInOutputDirectory::overwrite_problem(
    const std::vector<fs::path>& outputs) const {
  for (const fs::path& output : outputs) {
    if (const std::optional<std::string> input = overwritten_by(output))
      return fmt::format("output '{}' would overwrite the input {}", output.string(), *input);
  }
  return std::nullopt;
}

}  // namespace matc
