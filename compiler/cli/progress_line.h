// What the batch commands (the compile, `matc bake`) print while they run: a progress line on a
// terminal, with the batch's other messages printed above it.
#pragma once

#include <cstddef>
#include <functional>
#include <mutex>
#include <string>
#include <string_view>

#include "matc/api/batch.h"

namespace matc::cli {

// "[12/1000] gold" on one terminal line, redrawn as items finish; nothing when disabled (not a
// TTY, or -q).
class ProgressLine {
 public:
  explicit ProgressLine(bool enabled) : enabled_(enabled) {}
  void update(std::size_t done, std::size_t total, std::string_view last);
  // Runs `print` (which writes whole lines to standard error) with the line cleared first, so
  // that messages printed while workers run are not drawn over.
  void print_above(const std::function<void()>& print);
  void clear();

 private:
  void draw();  // "[done/total] last", at the cursor (the mutex held)

  std::mutex mutex_;
  std::size_t total_ = 0;
  std::size_t done_ = 0;
  std::string last_;
  bool enabled_;
};

// The events of a batch as the commands print them: diagnostics and the batch's own errors on
// standard error above `progress`, which follows the batch.
api::BatchEvents printed_events(ProgressLine& progress);

// Whether standard error is a terminal (progress lines are drawn only there).
bool stderr_is_terminal();

}  // namespace matc::cli
