// --files-from: the paths of a list file, one per line (for more files than a command line holds).
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace matc::cli {

// The non-empty lines of `path` ("-": standard input), trailing '\r' and spaces removed; nothing
// when the file cannot be read.
std::optional<std::vector<std::string>> read_file_list(const std::string& path);

}  // namespace matc::cli
