// The libraries under CHOLMOD start threads of their own: OpenBLAS runs worker threads, and
// Debian's CHOLMOD 3 opens a 4-thread OpenMP region for every large supernode. The engine runs
// its own threads (one patch per core, or the two scalar factors of a lone patch's iterative
// solve), so theirs only contend and would change the rounding of CHOLMOD's results (measured in
// docs/measurements-behind-the-code.md). OpenBLAS's idle workers also spin after the library
// starts, so they are stopped; a threaded call after the engine's would start them again.
// While a SerialLibraries lives, OpenBLAS works in the calling thread only and
// OpenMP regions run on one thread (max-active-levels 0), if those libraries are loaded in this
// process; the previous settings come back afterwards, so a host such as MeshLab keeps its own.
//
// OpenBLAS's thread count is global, but OpenMP keeps max-active-levels per thread: a thread
// the engine starts inherits the process default, not the caller's setting, so parallel_for
// calls serial_openmp_in_this_thread() on each helper; without it two patches factorised at
// once would each open CHOLMOD's 4-thread regions.
#pragma once

#include <string>

namespace qd::common {

// The core type whose kernels the OpenBLAS loaded in this process runs ("SkylakeX", "Haswell",
// "Prescott", ...), or empty where no OpenBLAS is loaded. OpenBLAS picks it by CPU model when it
// is loaded, or takes OPENBLAS_CORETYPE (cli/blas_kernels.h).
std::string loaded_blas_core();

// OpenMP regions opened from the calling thread run on it alone (a thread the engine started).
void serial_openmp_in_this_thread();

class SerialLibraries {
 public:
  SerialLibraries();
  ~SerialLibraries();
  SerialLibraries(const SerialLibraries&) = delete;
  SerialLibraries& operator=(const SerialLibraries&) = delete;

 private:
  int saved_blas_threads_ = 0;  // OpenBLAS's thread count before; 0: OpenBLAS is not loaded
  int saved_omp_levels_ = -1;   // OpenMP's max-active-levels before; -1: OpenMP is not loaded
};

}  // namespace qd::common
