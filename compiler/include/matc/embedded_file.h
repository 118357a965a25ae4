// A data file compiled into the binary by cmake/EmbedFiles.cmake.
#pragma once

#include <string_view>

namespace matc {

struct EmbeddedFile {
  std::string_view path;  // relative to the embedded folder, e.g. "ior/Au.csv"
  std::string_view bytes;
};

}  // namespace matc
