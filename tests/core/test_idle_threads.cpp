// A round's idle threads (idle_threads.h): borrowed only while idle, all given back, and the work
// runs once per index whoever runs it.
#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <thread>
#include <vector>

#include "common/idle_threads.h"

namespace qd {
namespace {

using common::IdleThreads;

TEST(IdleThreads, BorrowsOnlyWhatIsIdle) {
  IdleThreads idle(2);
  idle.hold();  // one item runs
  EXPECT_EQ(idle.borrow(5), 1u);
  EXPECT_EQ(idle.borrow(5), 0u);
  idle.release(1);
  idle.hold();  // a second item starts while none is idle: nothing to lend, never below zero
  EXPECT_EQ(idle.borrow(1), 0u);
}

TEST(IdleThreads, EveryIndexRunsOnceAndTheBorrowedThreadsComeBack) {
  for (const size_t threads : {1u, 2u, 4u}) {
    IdleThreads idle(threads);
    idle.hold();
    std::vector<std::atomic<int>> runs(50);
    std::vector<std::thread::id> who(50);
    common::run_with_idle_threads(idle, runs.size(), [&](size_t i) {
      ++runs[i];
      who[i] = std::this_thread::get_id();
    });
    for (const auto& r : runs) EXPECT_EQ(r.load(), 1);
    if (threads == 1) {  // nothing idle: all on the caller's thread
      for (const auto& id : who) EXPECT_EQ(id, std::this_thread::get_id());
    }
    EXPECT_EQ(idle.borrow(threads), threads - 1);  // every borrowed thread was released
  }
}

TEST(IdleThreads, TheLowestFailingIndexIsRethrown) {
  IdleThreads idle(3);
  idle.hold();
  try {
    common::run_with_idle_threads(idle, 20, [](size_t i) {
      if (i == 7 || i == 13) throw std::runtime_error(std::to_string(i));
    });
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "7");
  }
  EXPECT_EQ(idle.borrow(3), 2u);
}

}  // namespace
}  // namespace qd
