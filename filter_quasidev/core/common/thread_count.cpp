#include "common/thread_count.h"

#include <algorithm>
#include <thread>

namespace qd::common {

size_t thread_count(int requested) {
  if (requested > 0) return static_cast<size_t>(requested);
  return std::max(1u, std::thread::hardware_concurrency());
}

}  // namespace qd::common
