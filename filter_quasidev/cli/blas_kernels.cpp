#include "blas_kernels.h"

#include <unistd.h>

#include <cstdlib>
#include <string>

#include "common/serial_libraries.h"

namespace qd::cli {
namespace {

// The OpenBLAS core type whose kernels this CPU's instructions run: "SkylakeX" (AVX-512 F, BW,
// DQ and VL), "Haswell" (AVX2 and FMA), or empty.
std::string blas_core_for_this_cpu() {
  __builtin_cpu_init();
  if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw") &&
      __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512vl"))
    return "SkylakeX";
  if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) return "Haswell";
  return "";
}

}  // namespace

void restart_with_fast_blas_kernels(char** argv) {
  if (std::getenv("OPENBLAS_CORETYPE") || common::loaded_blas_core() != "Prescott") return;
  const std::string core = blas_core_for_this_cpu();
  if (core.empty() || setenv("OPENBLAS_CORETYPE", core.c_str(), 1) != 0) return;
  execv("/proc/self/exe", argv);  // returns only on failure: go on with the kernels loaded
  unsetenv("OPENBLAS_CORETYPE");
}

}  // namespace qd::cli
