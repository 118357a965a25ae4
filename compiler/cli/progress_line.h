// What the batch commands (the compile, `matc bake`) share: a progress line on a terminal and the
// number of worker threads for -j.
#pragma once

#include <cstddef>
#include <functional>
#include <mutex>
#include <string>

namespace matc::cli {

// "[12/1000] gold" on one terminal line, redrawn as items finish; nothing when disabled (not a
// TTY, or -q).
class ProgressLine {
 public:
  ProgressLine(std::size_t total, bool enabled) : total_(total), enabled_(enabled) {}
  void finished(const std::string& name);
  // Runs `print` (which writes whole lines to standard error) with the line cleared first, so
  // that messages printed while workers run are not drawn over.
  void print_above(const std::function<void()>& print);
  void clear();

 private:
  void draw();  // "[done/total] last", at the cursor (the mutex held)

  std::mutex mutex_;
  std::size_t total_;
  std::size_t done_ = 0;
  std::string last_;
  bool enabled_;
};

// -j: `requested` threads (0: one per hardware thread), never more than `jobs`, at least one.
unsigned worker_count(unsigned requested, std::size_t jobs);

// Whether standard error is a terminal (progress lines are drawn only there).
bool stderr_is_terminal();

}  // namespace matc::cli
