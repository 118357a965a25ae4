#include "progress_line.h"

#include <unistd.h>

#include <cstdio>

#include <fmt/core.h>

#include "print_diagnostics.h"

namespace matc::cli {

void ProgressLine::update(const BatchProgress& progress) {
  if (!enabled_) return;
  const std::lock_guard lock(mutex_);
  done_ = progress.done;
  total_ = progress.total;
  last_ = progress.name;
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

BatchEvents printed_events(ProgressLine& progress) {
  BatchEvents events;
  events.diagnostics = [&progress](const Diagnostics& diagnostics) {
    progress.print_above([&] { print_diagnostics(diagnostics); });
  };
  events.progress = [&progress](const BatchProgress& done) { progress.update(done); };
  events.error = [&progress](const std::string& where, const std::string& message) {
    progress.print_above([&] { fmt::print(stderr, "{}: error: {}\n", where, message); });
  };
  return events;
}

bool stderr_is_terminal() {
  return isatty(fileno(stderr)) != 0;
}

}  // namespace matc::cli
