#include "atomic_file.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

namespace matc::cli {
namespace {

bool holds_bytes(const std::filesystem::path& path, std::string_view bytes) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) return false;
  if (std::filesystem::file_size(path, error) != bytes.size() || error) return false;
  std::ifstream in(path, std::ios::binary);
  const std::string existing((std::istreambuf_iterator<char>(in)),
                             std::istreambuf_iterator<char>());
  return existing == bytes;
}

// Whether two files hold the same bytes, read a block at a time.
bool same_contents(const std::filesystem::path& a, const std::filesystem::path& b) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(b, error)) return false;
  const auto size = std::filesystem::file_size(a, error);
  if (error || std::filesystem::file_size(b, error) != size || error) return false;
  std::ifstream in_a(a, std::ios::binary);
  std::ifstream in_b(b, std::ios::binary);
  std::string block_a(1 << 16, '\0');
  std::string block_b(1 << 16, '\0');
  while (in_a && in_b) {
    in_a.read(block_a.data(), static_cast<std::streamsize>(block_a.size()));
    in_b.read(block_b.data(), static_cast<std::streamsize>(block_b.size()));
    if (in_a.gcount() != in_b.gcount() ||
        block_a.compare(0, static_cast<std::size_t>(in_a.gcount()), block_b, 0,
                        static_cast<std::size_t>(in_b.gcount())) != 0)
      return false;
  }
  return in_a.eof() && in_b.eof();
}

std::filesystem::path temporary_beside(const std::filesystem::path& path) {
  return path.parent_path() / fmt::format(".{}.tmp{}", path.filename().string(), ::getpid());
}

void write_temporary(const std::filesystem::path& temporary,
                     const std::function<void(std::ostream&)>& produce) {
  std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
  if (!out) {
    throw std::runtime_error(
        fmt::format("cannot create '{}': {}", temporary.string(), std::strerror(errno)));
  }
  try {
    produce(out);
    out.close();
  } catch (...) {
    std::filesystem::remove(temporary);
    throw;
  }
  if (!out) {
    std::filesystem::remove(temporary);
    throw std::runtime_error(fmt::format("cannot write '{}'", temporary.string()));
  }
}

void move_into_place(const std::filesystem::path& temporary, const std::filesystem::path& path) {
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) {
    std::filesystem::remove(temporary);
    throw std::runtime_error(
        fmt::format("cannot replace '{}': {}", path.string(), error.message()));
  }
}

}  // namespace

WriteOutcome write_file_atomically(const std::filesystem::path& path, std::string_view bytes) {
  if (holds_bytes(path, bytes)) return WriteOutcome::unchanged;
  const std::filesystem::path temporary = temporary_beside(path);
  write_temporary(temporary, [&](std::ostream& out) {
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  });
  move_into_place(temporary, path);
  return WriteOutcome::written;
}

WriteOutcome write_file_atomically(const std::filesystem::path& path,
                                   const std::function<void(std::ostream&)>& produce) {
  const std::filesystem::path temporary = temporary_beside(path);
  write_temporary(temporary, produce);
  if (same_contents(temporary, path)) {
    std::filesystem::remove(temporary);
    return WriteOutcome::unchanged;
  }
  move_into_place(temporary, path);
  return WriteOutcome::written;
}

std::string path_identity(const std::filesystem::path& path) {
  std::error_code error;
  const std::filesystem::path canonical = std::filesystem::weakly_canonical(path, error);
  return error ? path.lexically_normal().string() : canonical.string();
}

}  // namespace matc::cli
