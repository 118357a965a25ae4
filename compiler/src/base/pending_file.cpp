#include "base/pending_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "base/exclusive_file.h"

namespace matc {
namespace {

// Whether an unnamed file can be given a name later: linkat through /proc/self/fd (the way that
// needs no capability). Asked once.
bool can_link_unnamed_files() {
  static const bool available = ::access("/proc/self/fd", X_OK) == 0;
  return available;
}

// An O_TMPFILE in `directory`, or -1 where the kernel or the file system has none.
int open_unnamed(const std::filesystem::path& directory) {
#ifdef O_TMPFILE
  if (!can_link_unnamed_files()) return -1;
  return ::open(directory.c_str(), O_TMPFILE | O_RDWR | O_CLOEXEC, 0666);
#else
  (void)directory;
  return -1;
#endif
}

}  // namespace

PendingFile PendingFile::create(const std::filesystem::path& directory, std::string_view name) {
  const std::filesystem::path parent = directory.empty() ? "." : directory;
  if (const int descriptor = open_unnamed(parent); descriptor >= 0) return {descriptor, parent, {}};
  ExclusiveFile file = create_exclusive_file(parent, name);
  return {file.descriptor, parent, std::move(file.path)};
}

PendingFile::PendingFile(PendingFile&& other) noexcept
    : descriptor_(std::exchange(other.descriptor_, -1)),
      directory_(std::move(other.directory_)),
      temporary_(std::exchange(other.temporary_, {})) {}

PendingFile& PendingFile::operator=(PendingFile&& other) noexcept {
  if (this != &other) {
    discard();
    descriptor_ = std::exchange(other.descriptor_, -1);
    directory_ = std::move(other.directory_);
    temporary_ = std::exchange(other.temporary_, {});
  }
  return *this;
}

PendingFile::~PendingFile() {
  discard();
}

void PendingFile::publish(const std::filesystem::path& target) {
  if (descriptor_ < 0) throw std::logic_error("PendingFile::publish: nothing pending");
  const auto fail = [&](const std::string& reason) {
    discard();
    throw std::runtime_error(fmt::format("cannot replace '{}': {}", target.string(), reason));
  };
  // An absent target takes the name directly; where something has it (or the link fails), the
  // file goes through a temporary name renamed over it.
  if (!named() && link_open_file(descriptor_, target) == 0) {
    discard();  // named now: closing the descriptor leaves the file
    return;
  }
  if (!named()) {
    try {
      temporary_ = link_exclusive_file(descriptor_, directory_, target.filename().string());
    } catch (const std::exception& error) {
      fail(error.what());
    }
  }
  const int closed = ::close(std::exchange(descriptor_, -1));
  const int close_error = errno;
  if (closed != 0) fail(std::strerror(close_error));
  std::error_code error;
  std::filesystem::rename(temporary_, target, error);
  if (error) fail(error.message());
  forget_exclusive_file(std::exchange(temporary_, {}));
}

void PendingFile::discard() noexcept {
  if (descriptor_ >= 0) ::close(std::exchange(descriptor_, -1));
  if (named()) discard_exclusive_file(std::exchange(temporary_, {}));
}

}  // namespace matc
