// Runs work(i) for every i in [0, n) on up to `threads` threads, the caller's among them; each
// index runs once, on whichever thread is free. After all have finished, rethrows the exception
// of the lowest index that threw, if any, so errors do not depend on the scheduling.
#pragma once

#include <algorithm>
#include <atomic>
#include <exception>
#include <thread>
#include <vector>

namespace qd {

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
  for (size_t t = 1; t < std::min(n, threads); ++t) helpers.emplace_back(drain);
  drain();
  for (std::thread& helper : helpers) helper.join();
  for (const std::exception_ptr& error : errors)
    if (error) std::rethrow_exception(error);
}

}  // namespace qd
