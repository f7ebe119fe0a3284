"""import quasidev chooses the dense kernels before its engine loads OpenBLAS
(quasidev/_blas_kernels.py): where OpenBLAS would fall back to its Prescott (SSE3) kernels on a
CPU with AVX2 and FMA, the engine runs on the kernels of the CPU's instructions; a value of
OPENBLAS_CORETYPE the user set is kept. The report says which kernels ran. Each case runs in a
fresh interpreter, since OpenBLAS is loaded once per process."""

import json
import os
import subprocess
import sys

from conftest import CYLINDER
from quasidev._blas_kernels import core_for_this_cpu

RUN = ("import json, sys, quasidev\n"
       "mesh = quasidev.read(sys.argv[1])\n"
       "r = quasidev.approximate(mesh.V, mesh.F, patches=mesh.patches, max_iter=2)\n"
       "print(json.dumps({'kernels': r.report['blas_kernels'],"
       " 'variable': __import__('os').environ.get('OPENBLAS_CORETYPE')}))")


def kernels(coretype=None):
    env = {k: v for k, v in os.environ.items() if k != "OPENBLAS_CORETYPE"}
    if coretype:
        env["OPENBLAS_CORETYPE"] = coretype
    r = subprocess.run([sys.executable, "-c", RUN, str(CYLINDER)], env=env, capture_output=True,
                       text=True, timeout=300)
    assert r.returncode == 0, r.stderr
    return json.loads(r.stdout)


def test_the_engine_does_not_run_prescott_kernels_on_a_cpu_with_avx2():
    got = kernels()
    if got["kernels"] and core_for_this_cpu():  # AVX2 and FMA at least
        assert got["kernels"] != "Prescott", got


def test_kernels_the_user_chose_are_kept():
    got = kernels("Prescott")
    assert got["variable"] == "Prescott"
    if got["kernels"]:
        assert got["kernels"] == "Prescott"
