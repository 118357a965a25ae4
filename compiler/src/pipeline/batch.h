// What every batch (compile, bake, import) shares: its counts, the events it reports while it
// runs, cancellation, and how many threads it runs on.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>

#include "base/diagnostics.h"
#include "pipeline/atomic_file.h"

namespace matc {

// The counts a batch ends with.
struct BatchCounts {
  std::size_t done = 0;  // materials compiled, assets baked, materials imported
  std::size_t written = 0;
  std::size_t unchanged = 0;
  std::size_t failed = 0;
  std::size_t not_attempted = 0;  // after a failure without keep_going, or a cancellation

  void count(WriteOutcome outcome) { ++(outcome == WriteOutcome::written ? written : unchanged); }
};

// A batch's progress after one more item finished (compiled, failed or given up).
struct BatchProgress {
  std::size_t done = 0;
  std::size_t total = 0;  // the items the batch tries
  std::string_view name;  // the item just finished (empty when it failed before it had a name)
};

// What a batch reports as it runs. Every callback may be empty; the batch calls each one at a
// time (never two at once), from any of its threads.
struct BatchEvents {
  // Each input's diagnostics (errors, warnings, notes), in input order.
  std::function<void(const Diagnostics&)> diagnostics;
  std::function<void(const BatchProgress&)> progress;
  // A problem of the batch's own, not of one input (its output directory, manifest or depfile):
  // where it lies and what it is, as "WHERE: error: MESSAGE" would print it.
  std::function<void(const std::string& where, const std::string& message)> error;
};

// Threads for a batch of `items`: `requested` (0: one per hardware thread), never more than the
// items, at least one.
unsigned worker_count(unsigned requested, std::size_t items);

}  // namespace matc
