#include "progress_line.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <thread>

#include <fmt/core.h>

namespace matc::cli {

void ProgressLine::finished(const std::string& name) {
  if (!enabled_) return;
  const std::lock_guard lock(mutex_);
  ++done_;
  fmt::print(stderr, "\r\x1b[K[{}/{}] {}", done_, total_, name);
  std::fflush(stderr);
}

void ProgressLine::clear() {
  if (enabled_ && done_ > 0) fmt::print(stderr, "\r\x1b[K");
}

unsigned worker_count(unsigned requested, std::size_t jobs) {
  const unsigned available = std::max(1u, std::thread::hardware_concurrency());
  const unsigned wanted = requested == 0 ? available : requested;
  return static_cast<unsigned>(std::clamp<std::size_t>(jobs, 1, wanted));
}

bool stderr_is_terminal() {
  return isatty(fileno(stderr)) != 0;
}

}  // namespace matc::cli
