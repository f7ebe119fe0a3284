// The libraries under CHOLMOD start threads of their own: OpenBLAS runs worker threads, and
// Debian's CHOLMOD 3 (SuiteSparse 5.12) opens an OpenMP region of 4 threads
// (CHOLMOD_OMP_NUM_THREADS, fixed when it was built) for every large supernode, only to fill a
// map and zero a block. The engine runs its own threads (one patch per core, or the two scalar
// factors of a lone patch's iterative solve), so theirs would only contend: bench/qd_bench, 100k
// triangles in 16 patches, engine 1.65 s with OpenBLAS's threads, 0.48 s without; the 40k-face
// tee, 10 iterations, 1 thread, 6.0 s with CHOLMOD's OpenMP regions (a futex wake per region,
// 35 % of the time in the kernel), 2.7 s without. Their number would also change the rounding of
// CHOLMOD's results. OpenBLAS's idle workers also spin (sched_yield) for a while after the library
// starts, which took a core from short runs (the shirt: 0.1 s of system time in a 0.12 s run), so
// they are stopped; a threaded call after the engine's would start them again.
// While a SerialLibraries lives, OpenBLAS works in the calling thread only and
// OpenMP regions run on one thread (max-active-levels 0), if those libraries are loaded in this
// process; the previous settings come back afterwards, so a host such as MeshLab keeps its own.
//
// OpenBLAS's thread count is global, but OpenMP keeps max-active-levels per thread: a thread
// the engine starts inherits the process default, not the caller's setting, so parallel_for
// calls serial_openmp_in_this_thread() on each helper. Without it two patches factorised at
// once each opened CHOLMOD's 4-thread regions: 250 ms per factorisation instead of 110 ms (a
// 2.6 GFlop system, two threads on 2 cores).
#pragma once

namespace qd {

// OpenMP regions opened from the calling thread run on it alone (a thread the engine started).
void serial_openmp_in_this_thread();

class SerialLibraries {
 public:
  SerialLibraries();
  ~SerialLibraries();
  SerialLibraries(const SerialLibraries&) = delete;
  SerialLibraries& operator=(const SerialLibraries&) = delete;

 private:
  int saved_blas_threads_ = 0;     // OpenBLAS's thread count before; 0: OpenBLAS is not loaded
  int saved_omp_levels_ = -1;      // OpenMP's max-active-levels before; -1: OpenMP is not loaded
};

}  // namespace qd
