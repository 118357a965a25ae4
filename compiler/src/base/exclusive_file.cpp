#include "base/exclusive_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <mutex>
#include <random>
#include <set>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

namespace matc {
namespace {

// The temporaries this process created and has not yet renamed or removed; an interrupted run
// removes these, and only these (remove_temporaries_in_flight).
class TemporariesInFlight {
 public:
  // Creates the file with `open` and registers it, both under the lock, so an interruption
  // sees every file that exists (none is created after it removed them). -1 with errno EINTR
  // once the run is being interrupted.
  template <typename Open>
  int create(const std::string& path, const Open& open) {
    const std::lock_guard lock(mutex_);
    if (closing_) {
      errno = EINTR;
      return -1;
    }
    const int descriptor = open();
    if (descriptor >= 0) paths_.insert(path);
    return descriptor;
  }
  void remove(const std::string& path) {
    const std::lock_guard lock(mutex_);
    paths_.erase(path);
  }
  void remove_all_and_close() {
    const std::lock_guard lock(mutex_);
    closing_ = true;
    for (const std::string& path : paths_)
      ::unlink(path.c_str());
    paths_.clear();
  }

 private:
  std::mutex mutex_;
  std::set<std::string> paths_;
  bool closing_ = false;
};

TemporariesInFlight& temporaries_in_flight() {
  static TemporariesInFlight registry;
  return registry;
}

// 64 random bits as hex: a name no other writer, and no input, can be expected to hold.
std::string unguessable_part() {
  static std::mutex mutex;
  static std::random_device device;
  const std::lock_guard lock(mutex);
  const std::uint64_t bits = (std::uint64_t{device()} << 32) | device();
  return fmt::format("{:016x}", bits);
}

// A new name ".<stem>.matc-<hex>.tmp" in `directory`, made by `make` (0 on success, -1 with errno),
// retried while it exists. Throws std::runtime_error when none can be made.
template <typename Make>
std::filesystem::path make_exclusive_name(const std::filesystem::path& directory,
                                          std::string_view stem, const Make& make) {
  const std::filesystem::path parent = directory.empty() ? "." : directory;
  for (int attempt = 0;; ++attempt) {
    const std::filesystem::path path =
        parent / fmt::format(".{}.matc-{}.tmp", stem, unguessable_part());
    if (temporaries_in_flight().create(path.string(), [&] { return make(path); }) >= 0) return path;
    const int error = errno;
    if (error == EINTR) throw std::runtime_error("interrupted: no new file is started");
    if (error != EEXIST || attempt == 16) {
      throw std::runtime_error(
          fmt::format("cannot create a file in '{}': {}", parent.string(), std::strerror(error)));
    }
  }
}

}  // namespace

ExclusiveFile create_exclusive_file(const std::filesystem::path& directory, std::string_view stem) {
  int descriptor = -1;
  const std::filesystem::path path =
      make_exclusive_name(directory, stem, [&](const std::filesystem::path& name) {
        descriptor = ::open(name.c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC | O_NOFOLLOW, 0666);
        return descriptor;
      });
  return {path, descriptor};
}

int link_open_file(int descriptor, const std::filesystem::path& name) {
  const std::string open_file = fmt::format("/proc/self/fd/{}", descriptor);
  return ::linkat(AT_FDCWD, open_file.c_str(), AT_FDCWD, name.c_str(), AT_SYMLINK_FOLLOW);
}

std::filesystem::path link_exclusive_file(int descriptor, const std::filesystem::path& directory,
                                          std::string_view stem) {
  return make_exclusive_name(directory, stem, [&](const std::filesystem::path& name) {
    return link_open_file(descriptor, name);
  });
}

void discard_exclusive_file(const std::filesystem::path& path) {
  ::unlink(path.c_str());
  forget_exclusive_file(path);
}

void forget_exclusive_file(const std::filesystem::path& path) {
  temporaries_in_flight().remove(path.string());
}

void remove_temporaries_in_flight() {
  temporaries_in_flight().remove_all_and_close();
}

}  // namespace matc
