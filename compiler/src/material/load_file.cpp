#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include <fmt/format.h>

#include "material/parse.h"

namespace matc {

LoadedFile load_file(const std::filesystem::path& path, std::uintmax_t max_bytes) {
  // A path from an input ("file": "x.csv\u0000...") would end at the NUL: another file is read.
  if (path.native().find('\0') != std::string::npos)
    return {std::nullopt, "the path holds a NUL byte, which no file name can"};
  // One open and one fstat (a batch reads thousands of inputs); O_NONBLOCK so that a FIFO or a
  // device is refused below instead of blocking the open.
  const int descriptor = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY);
  if (descriptor < 0) {
    if (errno == ENOENT || errno == ENOTDIR) return {std::nullopt, "no such file"};
    return {std::nullopt, std::strerror(errno)};
  }
  const auto close_after = [descriptor](LoadedFile result) {
    ::close(descriptor);
    return result;
  };
  struct stat status {};
  if (::fstat(descriptor, &status) != 0) return close_after({std::nullopt, std::strerror(errno)});
  if (S_ISDIR(status.st_mode)) return close_after({std::nullopt, "is a directory, not a file"});
  if (!S_ISREG(status.st_mode)) return close_after({std::nullopt, "is not a regular file"});
  const auto size = static_cast<std::uintmax_t>(status.st_size);
  if (size > max_bytes) {
    return close_after(
        {std::nullopt, fmt::format("is {} bytes, over the {}-byte limit", size, max_bytes)});
  }
  std::string bytes;
  bytes.reserve(static_cast<std::size_t>(size));
  // Reads to the end, in case the file changed since it was measured, but never past the limit.
  char chunk[1 << 16];
  for (;;) {
    const ssize_t read = ::read(descriptor, chunk, sizeof chunk);
    if (read < 0 && errno == EINTR) continue;
    if (read < 0) return close_after({std::nullopt, std::strerror(errno)});
    if (read == 0) break;
    bytes.append(chunk, static_cast<std::size_t>(read));
    if (bytes.size() > max_bytes) {
      return close_after({std::nullopt, fmt::format("is over the {}-byte limit", max_bytes)});
    }
  }
  return close_after({std::move(bytes), {}});
}

}  // namespace matc
