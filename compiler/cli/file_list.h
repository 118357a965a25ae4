// --files-from: the paths of a list file, one per line (for more files than a command line holds).
#pragma once

#include <string>
#include <vector>

namespace matc::cli {

struct FileList {
  std::vector<std::string> paths;
  std::string error;  // when not empty, why the list cannot be used ("line 3 holds a NUL byte")
};

// The non-empty lines of `path` ("-": standard input), trailing '\r' and spaces removed. A line
// holding a NUL byte is refused: the path would end there, and another file would be read.
FileList read_file_list(const std::string& path);

}  // namespace matc::cli
