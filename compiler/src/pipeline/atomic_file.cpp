#include "matc/pipeline/atomic_file.h"

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cstring>
#include <fstream>
#include <iterator>
#include <mutex>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

namespace matc {
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

constexpr std::string_view kTemporaryMark = ".tmp";

std::filesystem::path temporary_beside(const std::filesystem::path& path) {
  return path.parent_path() /
         fmt::format(".{}{}{}", path.filename().string(), kTemporaryMark, ::getpid());
}

// The writer's process id in a name temporary_beside() made, if it is one.
std::optional<pid_t> temporary_writer(std::string_view name) {
  const std::size_t mark = name.rfind(kTemporaryMark);
  if (name.size() < 2 || name.front() != '.' || mark == std::string_view::npos || mark < 2)
    return std::nullopt;
  const std::string_view digits = name.substr(mark + kTemporaryMark.size());
  pid_t pid = 0;
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), pid);
  if (digits.empty() || error != std::errc() || end != digits.data() + digits.size() || pid <= 0)
    return std::nullopt;
  return pid;
}

// A writer killed mid-write (SIGKILL: no chance to clean up) leaves its temporary behind; the
// first write of this process into a directory removes those whose writer no longer exists (a
// concurrent matc's, alive, are left alone).
void sweep_abandoned_temporaries(const std::filesystem::path& parent) {
  static std::mutex mutex;
  static std::set<std::string> swept;
  const std::filesystem::path directory = parent.empty() ? "." : parent;
  {
    const std::lock_guard lock(mutex);
    if (!swept.insert(path_identity(directory)).second) return;
  }
  std::error_code error;
  std::filesystem::directory_iterator entries(directory, error);
  for (; !error && entries != std::filesystem::directory_iterator(); entries.increment(error)) {
    const std::optional<pid_t> writer = temporary_writer(entries->path().filename().string());
    if (!writer || *writer == ::getpid()) continue;
    if (::kill(*writer, 0) == 0 || errno != ESRCH) continue;  // alive (or not ours to probe)
    std::error_code ignored;
    std::filesystem::remove(entries->path(), ignored);
  }
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
  sweep_abandoned_temporaries(path.parent_path());
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
  sweep_abandoned_temporaries(path.parent_path());
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

}  // namespace matc
