// While the engine works, the OpenMP regions of the libraries under CHOLMOD run on one thread,
// on the caller's thread and on the engine's own helper threads alike: OpenMP keeps that
// setting per thread, so a helper that did not set it would open CHOLMOD's 4-thread regions.
// OpenBLAS's idle workers are stopped: they spin for a while after the library starts.
#include <dirent.h>
#include <dlfcn.h>
#include <gtest/gtest.h>

#include <atomic>
#include <vector>

#include "common/parallel_for.h"
#include "common/serial_libraries.h"

namespace qd {
namespace {

using namespace qd::common;

TEST(SerialLibraries, HelperThreadsRunOpenMpRegionsSerially) {
  using GetCount = int (*)();
  const auto max_active_levels =
      reinterpret_cast<GetCount>(dlsym(RTLD_DEFAULT, "omp_get_max_active_levels"));
  if (!max_active_levels)
    GTEST_SKIP() << "no OpenMP runtime in this process (a build without CHOLMOD)";
  const SerialLibraries serial;
  constexpr size_t kThreads = 4;
  std::vector<int> levels(kThreads, -1);
  std::atomic<size_t> started{0};
  parallel_for(kThreads, kThreads, [&](size_t i) {
    ++started;
    while (started < kThreads) {  // every index waits for the others: one index per thread
    }
    levels[i] = max_active_levels();
  });
  for (size_t i = 0; i < kThreads; ++i) EXPECT_EQ(levels[i], 0) << "index " << i;
}

int threads_in_this_process() {
  int count = 0;
  DIR* tasks = opendir("/proc/self/task");
  while (const dirent* entry = readdir(tasks)) count += entry->d_name[0] != '.';
  closedir(tasks);
  return count;
}

TEST(SerialLibraries, OpenBlasWorkersStopWhileTheEngineRuns) {
  if (!dlsym(RTLD_DEFAULT, "blas_thread_shutdown_"))
    GTEST_SKIP() << "OpenBLAS is not this process's BLAS";
  const int before = threads_in_this_process();
  if (before == 1) GTEST_SKIP() << "OpenBLAS started no workers (one core)";
  {
    const SerialLibraries serial;
    EXPECT_EQ(threads_in_this_process(), 1) << "was " << before;
  }
}

}  // namespace
}  // namespace qd
