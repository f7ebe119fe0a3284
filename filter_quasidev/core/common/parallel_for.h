// Runs work(i) for every i in [0, n) on up to `threads` threads, the caller's among them; each
// index runs once, on whichever thread is free. After all have finished, rethrows the exception
// of the lowest index that threw, if any, so errors do not depend on the scheduling. The
// helper threads run OpenMP regions serially, as SerialLibraries makes the caller's.
#pragma once

#include <algorithm>
#include <atomic>
#include <exception>
#include <thread>
#include <vector>

#include "common/serial_libraries.h"

namespace qd::common {

// The indices [0, n), each handed out once to whichever thread asks, and each index's exception,
// so that the lowest can be rethrown once all have finished: errors do not depend on the
// scheduling.
template <typename Work>
class IndexQueue {
 public:
  IndexQueue(size_t n, const Work& work) : work_(work), errors_(n) {}
  // Runs the next index on this thread; false when none is left.
  bool run_next() {
    const size_t i = next_++;
    if (i >= errors_.size()) return false;
    try {
      work_(i);
    } catch (...) {
      errors_[i] = std::current_exception();
    }
    return true;
  }
  void drain() {
    while (run_next()) {
    }
  }
  size_t unclaimed() const { return errors_.size() - std::min(errors_.size(), next_.load()); }
  void rethrow_lowest() const {
    for (const std::exception_ptr& error : errors_)
      if (error) std::rethrow_exception(error);
  }

 private:
  const Work& work_;
  std::vector<std::exception_ptr> errors_;
  std::atomic<size_t> next_{0};
};

// A helper thread of the engine: OpenMP regions run serially in it, as SerialLibraries makes
// them in the caller's.
template <typename Work>
std::thread helper_thread(IndexQueue<Work>& queue) {
  return std::thread([&queue] {
    serial_openmp_in_this_thread();
    queue.drain();
  });
}

template <typename Work>
void parallel_for(size_t n, size_t threads, const Work& work) {
  IndexQueue<Work> queue(n, work);
  std::vector<std::thread> helpers;
  for (size_t t = 1; t < std::min(n, threads); ++t) helpers.push_back(helper_thread(queue));
  queue.drain();
  for (std::thread& helper : helpers) helper.join();
  queue.rethrow_lowest();
}

constexpr size_t kRangeChunk = 4096;  // indices per task of the engine's parallel loops

// Runs work(begin, end) over [0, n) cut into ranges of `chunk` indices, on up to `threads`
// threads. The cut does not depend on `threads`, so neither does any per-range result.
template <typename Work>
void parallel_ranges(size_t n, size_t threads, size_t chunk, const Work& work) {
  parallel_for((n + chunk - 1) / chunk, threads,
               [&](size_t r) { work(r * chunk, std::min(n, (r + 1) * chunk)); });
}

}  // namespace qd::common
