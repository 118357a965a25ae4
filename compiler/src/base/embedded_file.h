// A data file compiled into the binary by cmake/EmbedFiles.cmake.
#pragma once

#include <span>
#include <string_view>

namespace matc {

struct EmbeddedFile {
  std::string_view path;  // relative to the embedded folder, e.g. "ior/Au.csv"
  std::string_view bytes;
};

// The bytes of `path` in `files`; throws std::logic_error if it was not embedded (a build bug).
std::string_view find_embedded_file(std::span<const EmbeddedFile> files, std::string_view path);

}  // namespace matc
