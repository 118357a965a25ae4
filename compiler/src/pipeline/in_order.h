// Results that finish in any order, handed on in input order as soon as every earlier one is
// done: a batch prints and releases each material's results early, so what it holds is bounded
// by how far the workers run apart, not by the batch size.
#pragma once

#include <cstddef>
#include <functional>
#include <mutex>
#include <vector>

namespace matc {

class InOrder {
 public:
  // `retire(i)` is called once per index, in increasing order, one call at a time.
  InOrder(std::size_t count, std::function<void(std::size_t)> retire)
      : done_(count, false), retire_(std::move(retire)) {}
  // Thread-safe: marks `index` done and retires the run of done indices that it completes.
  void done(std::size_t index);
  // Retires every index not yet retired, done or not (after the workers have stopped).
  void finish();

 private:
  void retire_done_prefix();

  std::mutex mutex_;
  std::vector<bool> done_;
  std::size_t next_ = 0;
  std::function<void(std::size_t)> retire_;
};

}  // namespace matc
