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

template <typename Work>
void parallel_for(size_t n, size_t threads, const Work& work) {
  std::vector<std::exception_ptr> errors(n);
  std::atomic<size_t> next{0};
  const auto drain = [&] {
    for (size_t i = next++; i < n; i = next++) {
      try {
        work(i);
      } catch (...) {
        errors[i] = std::current_exception();
      }
    }
  };
  std::vector<std::thread> helpers;
  for (size_t t = 1; t < std::min(n, threads); ++t)
    helpers.emplace_back([&drain] {
      serial_openmp_in_this_thread();
      drain();
    });
  drain();
  for (std::thread& helper : helpers) helper.join();
  for (const std::exception_ptr& error : errors)
    if (error) std::rethrow_exception(error);
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
