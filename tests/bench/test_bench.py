"""The benchmark program (bench/qd_bench) runs and its figures hang together: stage times fit in
the engine's wall clock (one thread), the floor is what the solver alone needs, memory is
reported, the progress callback stays rare. Timings themselves are not asserted (benchmarks,
not timed tests)."""
import json
import os
import subprocess

import pytest

BUILD = os.environ.get("QD_BUILD_DIR", os.path.join(os.path.dirname(__file__), "..", "..", "build"))
BENCH = os.path.join(BUILD, "bin", "qd_bench")


def run(*args):
    if not os.path.exists(BENCH):
        pytest.fail(f"{BENCH} is missing: build the project first")
    out = subprocess.run([BENCH, *args], check=True, capture_output=True, text=True, timeout=300)
    return json.loads(out.stdout)


def test_one_patch_figures_hang_together():
    r = run("--grid", "2000", "--runs", "3", "--", "--threads", "1", "--max-iter", "3")
    assert r["faces"] >= 2000 and r["patches"] == 1
    ms = r["ms"]
    stages = sum(ms[s] for s in ["setup", "step1", "assembly", "factorization", "solve", "metrics"])
    assert 0 < stages <= ms["engine"] * 1.05
    # the sum of three medians, each printed to 0.001 ms
    assert ms["end_to_end"] == pytest.approx(ms["engine"] + ms["read"] + ms["write"], abs=0.002)
    # reprojected targets: one factorisation per solve, and the floor counts them all
    assert r["factorizations"] == r["solves"] >= r["iterations"] >= 1
    floor = r["bare_ms"]["floor"]
    assert floor >= r["bare_ms"]["factorization"] + r["solves"] * r["bare_ms"]["solve"] * 0.999
    assert r["overhead"] == pytest.approx(ms["engine"] / floor, rel=1e-2)
    assert r["peak_mb"] > 1
    assert r["abd_reduction"] > 20  # the bumpy sheet does get more developable
    assert r["progress_calls"] <= 2 * r["iterations"] + 2


def test_patches_come_from_face_quality_and_fixed_targets_factor_once():
    r = run("--grid", "3000", "--patches", "4", "--runs", "1", "--", "--target-mode", "fixed",
            "--developability", "curve", "--max-iter", "10", "--stop-abd", "0")
    assert r["patches"] == 4
    # one per patch, and one more per back-off of the developability weights (two at most),
    # however many iterations
    assert r["factorizations"] <= 4 * 3 < r["solves"]


def test_bad_arguments_fail_with_a_reason():
    out = subprocess.run([BENCH, "--runs", "2"], capture_output=True, text=True)
    assert out.returncode == 1 and "--grid" in out.stderr


def test_iterative_method_never_factorises_the_coupled_system_and_agrees():
    curve = ("--developability", "curve")  # angle-defect rows are always factorised
    direct = run("--grid", "20000", "--runs", "1", "--", "--method", "direct", "--max-iter", "3", *curve)
    cg = run("--grid", "20000", "--runs", "1", "--", "--method", "iterative", "--max-iter", "3", *curve)
    assert direct["cg_iterations"] == 0 and direct["factorizations"] == direct["solves"]
    assert cg["factorizations"] == 2  # the two scalar factors of the frame preconditioner
    assert cg["cg_iterations"] > cg["solves"] == direct["solves"]
    # CG solves to 1e-2 of each step (kCgTolerance): the same reduction to 0.1 percentage point
    assert cg["abd_reduction"] == pytest.approx(direct["abd_reduction"], abs=0.1)
