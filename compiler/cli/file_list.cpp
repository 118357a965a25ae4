#include "file_list.h"

#include <fstream>
#include <iostream>

namespace matc::cli {

std::optional<std::vector<std::string>> read_file_list(const std::string& path) {
  std::ifstream file;
  if (path != "-") {
    file.open(path);
    if (!file) return std::nullopt;
  }
  std::istream& in = path == "-" ? std::cin : file;
  std::vector<std::string> paths;
  for (std::string line; std::getline(in, line);) {
    while (!line.empty() && (line.back() == '\r' || line.back() == ' '))
      line.pop_back();
    if (!line.empty()) paths.push_back(std::move(line));
  }
  if (in.bad()) return std::nullopt;
  return paths;
}

}  // namespace matc::cli
