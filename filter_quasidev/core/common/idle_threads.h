// The threads of a round of work items that no item holds: each running item holds one, and an
// item that can split a step (a race's candidates, term_race.h) borrows the idle ones for that
// step. A thread that has no item left is idle until the round ends, so a large item gets it
// without more threads running than the engine was given (a borrowed thread is back after one
// step; an item starting meanwhile oversubscribes by one, for that step at most). Measured on
// the garment family: stepping a race's candidates on every thread whatever the others do ran
// 4 threads on 2 cores and made the garments as found 15 % slower.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <thread>
#include <vector>

#include "common/parallel_for.h"

namespace qd::common {

class IdleThreads {
 public:
  explicit IdleThreads(size_t threads) : idle_(static_cast<long>(threads)) {}
  void hold() { --idle_; }                                       // an item starts
  void release(size_t n = 1) { idle_ += static_cast<long>(n); }  // it ends, or gives back
  // Takes up to `most` idle threads; returns how many it took (release them after the step).
  size_t borrow(size_t most) {
    long idle = idle_.load();
    long take = 0;
    do take = std::min(idle, static_cast<long>(most));
    while (take > 0 && !idle_.compare_exchange_weak(idle, idle - take));
    return static_cast<size_t>(std::max(take, 0L));
  }

 private:
  std::atomic<long> idle_;
};

// Runs work(i) for every i in [0, n) on the caller's thread and on the idle threads it borrows,
// checked again before each index, so a thread freed in the meantime joins at once; the
// borrowed threads are released when all have finished. Rethrows as parallel_for does.
template <typename Work>
void run_with_idle_threads(IdleThreads& idle, size_t n, const Work& work) {
  IndexQueue<Work> queue(n, work);
  std::vector<std::thread> helpers;
  for (size_t rest = queue.unclaimed(); rest > 0; rest = queue.unclaimed()) {
    for (size_t t = idle.borrow(rest - 1); t > 0; --t) helpers.push_back(helper_thread(queue));
    if (!queue.run_next()) break;
  }
  for (std::thread& helper : helpers) helper.join();
  idle.release(helpers.size());
  queue.rethrow_lowest();
}

}  // namespace qd::common
