// The check every batch makes before writing: no output may overwrite one of its inputs.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace matc {

// The inputs that lie in the output directory (the only ones an output can overwrite), by file
// name, so that a batch of 100,000 keeps no more than those.
class InputsInOutputDirectory {
 public:
  explicit InputsInOutputDirectory(const std::filesystem::path& output_directory);
  // `as_given` is how the user named it (what the error quotes); `path` where it lies.
  void add(const std::filesystem::path& path, const std::string& as_given);
  // "output 'DIR/x.json' would overwrite the input x.json" for the first of `outputs` that would.
  std::optional<std::string> overwrite_problem(
      const std::vector<std::filesystem::path>& outputs) const;

 private:
  // The input (as given) that writing `output`, a file in the output directory, would replace.
  std::optional<std::string> overwritten_by(const std::filesystem::path& output) const;

  std::filesystem::path directory_identity_;
  std::map<std::string, std::string> inputs_;  // file name -> as given
};

// What the overwrite error asks for.
inline constexpr const char* kOutputDirectoryRule =
    "an output directory (-o) that holds no input file";

}  // namespace matc
