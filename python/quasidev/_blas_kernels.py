"""The dense kernels under the engine's factorisations, chosen before the engine loads OpenBLAS.

Debian 12's OpenBLAS 0.3.21 picks its kernels by CPU model when it is loaded and falls back to its
Prescott (SSE3) kernels on models it does not know, where the factorisations ran 1.3-3.4 times
slower than on the AVX-512 kernels the CPU has, the engine 1.1-1.5 times (docs/performance.md,
"BLAS kernels"). It reads OPENBLAS_CORETYPE only when loaded, so, as the command does
(cli/blas_kernels.h): where the variable is unset and OpenBLAS, loaded in a short-lived probe
process (about 0.05 s), names Prescott on a CPU with AVX2 and FMA (a true Prescott has neither),
it is set before quasidev._engine loads OpenBLAS. The probe loads the extension itself, so it asks
the OpenBLAS the engine links, whichever file that is: Debian's libopenblas for a source install,
the copy auditwheel renamed into quasidev.libs for the repaired wheel. A value the user set is
kept; a process that loaded OpenBLAS already keeps its kernels.
"""
from __future__ import annotations

import importlib.util
import os
import subprocess
import sys

# Loads the extension (argv[1]) with its libraries into the global scope, then asks OpenBLAS.
_PROBE = ("import ctypes, os, sys\n"
          "ctypes.CDLL(sys.argv[1], mode=os.RTLD_GLOBAL)\n"
          "name = ctypes.CDLL(None).openblas_get_corename\n"
          "name.restype = ctypes.c_char_p\n"
          "print(name().decode())")


def _engine_path() -> str:
    """The file of quasidev._engine, found without importing it."""
    spec = importlib.util.find_spec(f"{__package__}._engine")
    return spec.origin if spec and spec.origin else ""


def core_for_this_cpu() -> str:
    """"SkylakeX" (AVX-512 F, BW, DQ and VL), "Haswell" (AVX2 and FMA), or ""."""
    try:
        with open("/proc/cpuinfo") as f:
            flags = next((set(line.split(":", 1)[1].split()) for line in f
                          if line.startswith("flags")), set())
    except OSError:
        return ""
    if {"avx512f", "avx512bw", "avx512dq", "avx512vl"} <= flags:
        return "SkylakeX"
    return "Haswell" if {"avx2", "fma"} <= flags else ""


def choose_blas_kernels() -> None:
    """Sets OPENBLAS_CORETYPE where it is unset and OpenBLAS would fall back to Prescott."""
    if "OPENBLAS_CORETYPE" in os.environ:
        return
    core, engine = core_for_this_cpu(), _engine_path()
    if not core or not engine:
        return
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1")
    try:
        probe = subprocess.run([sys.executable, "-I", "-S", "-c", _PROBE, engine], env=env,
                               capture_output=True, text=True, timeout=30)
    except (OSError, subprocess.SubprocessError):
        return
    if probe.returncode == 0 and probe.stdout.strip() == "Prescott":
        os.environ["OPENBLAS_CORETYPE"] = core
