// The dense kernels under the engine's factorisations. OpenBLAS picks them by CPU model when it
// is loaded; Debian 12's OpenBLAS 0.3.21 does not know recent Intel models (e.g. Xeon family 6
// model 207) and falls back to its "Prescott" SSE3 kernels, on which the factorisations ran
// 1.3–3.4 times slower than on the CPU's AVX-512 kernels, the engine 1.1–1.5 times
// (docs/performance.md, "BLAS kernels"). OpenBLAS reads OPENBLAS_CORETYPE only when it is loaded,
// so a process must be started with it: the command (and qd_bench) run themselves again with it
// set, before doing anything else, where OpenBLAS fell back to Prescott on a CPU with AVX2 and
// FMA (a true Prescott has neither). A value the user set is kept. `import quasidev` sets it
// itself (python/quasidev/_blas_kernels.py); MeshLab and pymeshlab load OpenBLAS before the
// plugin, so there the user sets it (docs/install.md).
#pragma once

namespace qd::cli {

// Runs this program again (the same arguments) with OPENBLAS_CORETYPE set to the core type whose
// kernels this CPU's instructions run ("SkylakeX" with AVX-512 F, BW, DQ and VL, else "Haswell"
// with AVX2 and FMA) where OpenBLAS fell back to Prescott and the variable is unset;
// returns, and the program goes on as it is, where that is not so or the new start fails.
void restart_with_fast_blas_kernels(char** argv);

}  // namespace qd::cli
