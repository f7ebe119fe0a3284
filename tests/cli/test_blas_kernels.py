"""The command factorises on the dense kernels the CPU has (cli/blas_kernels.h): where OpenBLAS
does not know the CPU's model and falls back to its Prescott (SSE3) kernels, quasidev starts
itself again with OPENBLAS_CORETYPE set to the kernels of the CPU's instruction set; a value the
user set is kept. The report says which kernels ran (`blas_kernels`), and the kernels change the
result only by rounding.

Input: the 5-panel shirt of tests/data/ (5 iterations)."""
import json
import os
import pathlib
import subprocess
import sys

import numpy as np
import pytest

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from plyfile import PlyData  # noqa: E402
from test_quasidev_cli import BINARY, DATA  # noqa: E402

SHIRT = DATA / "garment_shirt_initial_diffavatar.ply"

pytestmark = pytest.mark.skipif(not BINARY.exists(), reason=f"{BINARY} not built")


def cpu_flags() -> set:
    with open("/proc/cpuinfo") as f:
        for line in f:
            if line.startswith("flags"):
                return set(line.split(":", 1)[1].split())
    return set()


def approximate(tmp_path, name, coretype=None):
    """The shirt's output positions and report, with OPENBLAS_CORETYPE unset or set."""
    env = {k: v for k, v in os.environ.items() if k != "OPENBLAS_CORETYPE"}
    if coretype:
        env["OPENBLAS_CORETYPE"] = coretype
    out, report = tmp_path / f"{name}.ply", tmp_path / f"{name}.json"
    r = subprocess.run([str(BINARY), "approximate", str(SHIRT), str(out), "--max-iter", "5",
                        "--quiet", "--report", str(report)], env=env, capture_output=True,
                       text=True, timeout=600)
    assert r.returncode == 0, r.stderr
    v = PlyData.read(str(out))["vertex"]
    return np.column_stack([v["x"], v["y"], v["z"]]), json.loads(report.read_text())


@pytest.fixture(scope="module")
def default_run(tmp_path_factory):
    return approximate(tmp_path_factory.mktemp("blas"), "default")


def test_the_report_names_the_kernels_and_they_are_not_prescott_on_a_cpu_with_avx2(default_run):
    _, report = default_run
    assert isinstance(report["blas_kernels"], str)
    if not report["blas_kernels"]:
        pytest.skip("no OpenBLAS in this process (another BLAS is installed)")
    if {"avx2", "fma"} <= cpu_flags():
        assert report["blas_kernels"] != "Prescott"


def test_kernels_the_user_chose_are_kept_and_change_the_result_only_by_rounding(default_run,
                                                                                tmp_path):
    V_default, default = default_run
    if not default["blas_kernels"]:
        pytest.skip("no OpenBLAS in this process (another BLAS is installed)")
    V, chosen = approximate(tmp_path, "prescott", "Prescott")
    assert chosen["blas_kernels"] == "Prescott"
    V0 = np.column_stack([PlyData.read(str(SHIRT))["vertex"][c] for c in "xyz"])
    moved = np.linalg.norm(V_default - V0, axis=1).max()
    assert moved > 0
    assert np.abs(V - V_default).max() <= 1e-6 * moved
    assert [p["iterations"] for p in chosen["patches"]] == [p["iterations"] for p in default["patches"]]
    assert chosen["abd_reduction"] == pytest.approx(default["abd_reduction"], abs=1e-6)
