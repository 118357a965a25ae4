#include "in_order.h"

namespace matc {

void InOrder::done(std::size_t index) {
  const std::lock_guard lock(mutex_);
  done_[index] = true;
  retire_done_prefix();
}

void InOrder::finish() {
  const std::lock_guard lock(mutex_);
  while (next_ < done_.size())
    retire_(next_++);
}

void InOrder::retire_done_prefix() {
  while (next_ < done_.size() && done_[next_])
    retire_(next_++);
}

}  // namespace matc
