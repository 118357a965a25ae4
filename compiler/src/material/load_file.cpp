#include <cerrno>
#include <cstring>
#include <fstream>

#include <fmt/format.h>

#include "matc/material/parse.h"

namespace matc {

LoadedFile load_file(const std::filesystem::path& path, std::uintmax_t max_bytes) {
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if (status.type() == fs::file_type::not_found) return {std::nullopt, "no such file"};
  if (error) return {std::nullopt, error.message()};
  if (fs::is_directory(status)) return {std::nullopt, "is a directory, not a file"};
  if (!fs::is_regular_file(status)) return {std::nullopt, "is not a regular file"};
  const std::uintmax_t size = fs::file_size(path, error);
  if (error) return {std::nullopt, error.message()};
  if (size > max_bytes) {
    return {std::nullopt, fmt::format("is {} bytes, over the {}-byte limit", size, max_bytes)};
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) return {std::nullopt, std::strerror(errno)};
  std::string bytes;
  bytes.reserve(static_cast<std::size_t>(size));
  // Reads to the end, in case the file changed since it was measured, but never past the limit.
  char chunk[1 << 16];
  while (in.read(chunk, sizeof chunk) || in.gcount() > 0) {
    bytes.append(chunk, static_cast<std::size_t>(in.gcount()));
    if (bytes.size() > max_bytes) {
      return {std::nullopt, fmt::format("is over the {}-byte limit", max_bytes)};
    }
  }
  return {std::move(bytes), {}};
}

}  // namespace matc
