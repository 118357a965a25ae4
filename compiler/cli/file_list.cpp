#include "file_list.h"

#include <fstream>
#include <iostream>

#include <fmt/format.h>

namespace matc::cli {

FileList read_file_list(const std::string& path) {
  std::ifstream file;
  if (path != "-") {
    file.open(path, std::ios::binary);
    if (!file) return {{}, "cannot read the list"};
  }
  std::istream& in = path == "-" ? std::cin : file;
  FileList list;
  std::size_t number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    if (line.find('\0') != std::string::npos) {
      return {
          {},
          fmt::format("line {} holds a NUL byte; one path per line (a path holds none)", number)};
    }
    while (!line.empty() && (line.back() == '\r' || line.back() == ' '))
      line.pop_back();
    if (!line.empty()) list.paths.push_back(std::move(line));
  }
  if (in.bad()) return {{}, "cannot read the list"};
  return list;
}

}  // namespace matc::cli
