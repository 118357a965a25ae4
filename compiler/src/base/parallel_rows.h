// Filling a table row by row on several threads (the preintegrated table, the coefficient
// table): rows are handed out one at a time, so when each row depends only on its own
// coordinates the result does not depend on the thread count.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <thread>
#include <vector>

namespace matc {

// Calls make_row_filler() once per thread, then the returned callable with each row index in
// [0, rows) on one of those threads; per-thread scratch state lives in the callable.
// requested_threads: 0 for one per hardware thread; never more threads than rows.
template <typename MakeRowFiller>
void fill_rows_in_parallel(std::size_t rows, unsigned requested_threads,
                           const MakeRowFiller& make_row_filler) {
  std::atomic<std::size_t> next_row{0};
  const auto worker = [&] {
    auto fill_row = make_row_filler();
    for (std::size_t y = next_row++; y < rows; y = next_row++)
      fill_row(y);
  };
  const unsigned hardware = std::max(1u, std::thread::hardware_concurrency());
  const unsigned threads = std::min<unsigned>(requested_threads == 0 ? hardware : requested_threads,
                                              static_cast<unsigned>(rows));
  // std::thread joined on every exit, not std::jthread: the WebAssembly build's libc++ has none.
  struct JoinedThreads {
    std::vector<std::thread> threads;
    ~JoinedThreads() {
      for (std::thread& thread : threads)
        thread.join();
    }
  } pool;
  for (unsigned t = 1; t < threads; ++t)
    pool.threads.emplace_back(worker);
  worker();
}

}  // namespace matc
