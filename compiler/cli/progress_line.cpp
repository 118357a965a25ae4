#include "progress_line.h"

#include <unistd.h>

#include <cstdio>

#include <fmt/core.h>

#include "print_diagnostics.h"

namespace matc::cli {

void ProgressLine::update(std::size_t done, std::size_t total, std::string_view last) {
  if (!enabled_) return;
  const std::lock_guard lock(mutex_);
  done_ = done;
  total_ = total;
  last_ = last;
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

api::BatchEvents printed_events(ProgressLine& progress) {
  api::BatchEvents events;
  events.diagnostics = [&progress](const std::vector<api::Diagnostic>& diagnostics) {
    progress.print_above([&] { print_diagnostics(diagnostics); });
  };
  events.progress = [&progress](const api::BatchProgress& done) {
    progress.update(done.done, done.total, done.name);
  };
  events.error = [&progress](const std::string& where, const std::string& message) {
    progress.print_above([&] { fmt::print(stderr, "{}: error: {}\n", where, message); });
  };
  return events;
}

bool stderr_is_terminal() {
  return isatty(fileno(stderr)) != 0;
}

}  // namespace matc::cli
