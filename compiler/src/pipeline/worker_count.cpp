#include <algorithm>
#include <thread>

#include "pipeline/batch.h"

namespace matc {

unsigned worker_count(unsigned requested, std::size_t items) {
  const unsigned available = std::max(1u, std::thread::hardware_concurrency());
  const unsigned wanted = requested == 0 ? available : requested;
  return static_cast<unsigned>(std::clamp<std::size_t>(items, 1, wanted));
}

}  // namespace matc
