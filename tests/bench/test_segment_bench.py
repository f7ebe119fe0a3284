"""The segmentation benchmark (bench/qd_segment_bench) runs and its figures hang together: the
same patches for every thread count, a torus split into several patches within the limit, the
shared-style PLY input read through the command's reader, the approximation run on the result.
Timings themselves are not asserted (benchmarks, not timed tests)."""
import json
import os
import subprocess

import pytest

BUILD = os.environ.get("QD_BUILD_DIR", os.path.join(os.path.dirname(__file__), "..", "..", "build"))
BENCH = os.path.join(BUILD, "bin", "qd_segment_bench")
SAMPLES = os.path.join(os.path.dirname(__file__), "..", "..", "sample_meshes")


def run(*args):
    if not os.path.exists(BENCH):
        pytest.fail(f"{BENCH} is missing: build the project first")
    out = subprocess.run([BENCH, *args], check=True, capture_output=True, text=True, timeout=300)
    return [json.loads(line) for line in out.stdout.splitlines()]


def test_torus_patches_are_the_same_for_every_thread_count():
    (r,) = run("--torus", "20000", "--runs", "1", "--threads", "1,2,3")
    assert r["faces"] >= 19000
    assert r["same_for_all_threads"] is True
    assert set(r["ms_by_threads"]) == {"1", "2", "3"}
    assert r["patches"] > 1 and r["over_limit"] == 0
    assert r["max_error_deg"] <= r["max_error_limit"] + 1e-9
    assert r["peak_mb"] > 1


def test_a_mesh_file_is_segmented_and_then_approximated():
    (r,) = run("--mesh", os.path.join(SAMPLES, "patches.ply"), "--runs", "1", "--threads", "1",
               "--max-error-deg", "15", "--approximate")
    assert r["max_error_limit"] == 15 and r["patches"] >= 1
    assert "abd_reduction" in r and r["max_move_ae"] >= 0


def test_bad_arguments_fail_with_a_reason():
    out = subprocess.run([BENCH, "--runs", "2"], capture_output=True, text=True)
    assert out.returncode == 1 and "--torus" in out.stderr
    out = subprocess.run([BENCH, "--torus"], capture_output=True, text=True)
    assert out.returncode == 1 and "needs a value" in out.stderr
