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
  last_ = name;
  fmt::print(stderr, "\r\x1b[K");
  draw();
}

void ProgressLine::print_above(const std::function<void()>& print) {
  const std::lock_guard lock(mutex_);
  if (enabled_ && done_ > 0) fmt::print(stderr, "\r\x1b[K");
  print();
  if (enabled_ && done_ > 0) draw();
  std::fflush(stderr);
}

void ProgressLine::draw() {
  fmt::print(stderr, "[{}/{}] {}", done_, total_, last_);
  std::fflush(stderr);
}

void ProgressLine::clear() {
  const std::lock_guard lock(mutex_);
  if (enabled_ && done_ > 0) fmt::print(stderr, "\r\x1b[K");
  enabled_ = false;  // for good: what is printed after the batch is not followed by the line
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
