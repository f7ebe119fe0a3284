"""The repaired wheel's smoke test, run by scripts/test_wheel.sh inside a minimal Debian 12 chroot
that has neither SuiteSparse nor OpenBLAS: quasidev imports with the libraries auditwheel bundled
in quasidev.libs, reads a sample mesh, and segment, approximate and flatten give real results. On
a CPU with AVX2 and FMA the bundled OpenBLAS runs the CPU's kernels, not its Prescott fallback
(quasidev/_blas_kernels.py asks the copy the engine links, whatever auditwheel renamed it to).

    python wheel_smoke.py MESH.ply
"""

import glob
import pathlib
import sys

import numpy as np
import quasidev
from quasidev._blas_kernels import core_for_this_cpu

SYSTEM_LIB_DIRS = ["/lib", "/lib64", "/usr/lib", "/usr/lib64", "/usr/local/lib"]
ABSENT = ["libcholmod*", "libopenblas*", "libsuitesparse*", "libblas.so*", "liblapack.so*"]


def system_libraries(pattern):
    return [p for d in SYSTEM_LIB_DIRS for p in glob.glob(f"{d}/**/{pattern}", recursive=True)]


def loaded_libraries(name):
    """The files whose name starts with `name` that this process has mapped."""
    maps = pathlib.Path("/proc/self/maps").read_text().split("\n")
    paths = {line.split()[-1] for line in maps if "/" in line}
    return sorted(p for p in paths if pathlib.Path(p).name.startswith(name))


def main(mesh_path):
    for pattern in ABSENT:
        found = system_libraries(pattern)
        assert not found, f"the clean environment has {found}"
    bundled = (pathlib.Path(quasidev.__file__).parent.parent / "quasidev.libs").resolve()
    cholmod = loaded_libraries("libcholmod")
    assert cholmod and all(pathlib.Path(p).resolve().parent == bundled for p in cholmod), cholmod
    print(f"quasidev {quasidev.__version__}: libcholmod from {cholmod[0]}")

    mesh = quasidev.read(mesh_path)
    V, F = mesh.V, mesh.F
    seg = quasidev.segment(V, F, max_error_deg=5.0)
    k = seg.report["patch_count"]
    assert seg.patches.shape == (len(F),) and k >= 2
    assert set(np.unique(seg.patches)) == set(range(k))  # every face has a patch, ids 0..k-1
    print(f"segment: {len(F)} faces into {k} patches")

    r = quasidev.approximate(V, F, keep_boundary=True)
    before, after = r.report["total_before"]["g_abd"], r.report["total_after"]["g_abd"]
    assert after <= 0.5 * before, (before, after)
    assert r.positions.shape == V.shape and np.isfinite(r.positions).all()
    print(f"approximate: G_ABD {before:.4g} -> {after:.4g}")
    kernels = r.report["blas_kernels"]
    assert kernels, "the bundled BLAS is not OpenBLAS"
    if core_for_this_cpu():  # AVX2 and FMA at least
        assert kernels != "Prescott", kernels
    print(f"dense kernels: {kernels}")

    flat = quasidev.flatten(r.positions, F, seg.patches)
    assert flat.uv.shape == (len(F), 3, 2) and np.isfinite(flat.uv).all()
    assert np.isfinite(flat.stretch).all()
    assert len(flat.report["pieces"]) == k
    print(f"flatten: {k} pieces, max distortion {flat.report['max_distortion']:.4g}")
    print("wheel smoke test passed")


if __name__ == "__main__":
    main(sys.argv[1])
