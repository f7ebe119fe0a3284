"""quasidev.approximate on numpy arrays: it removes curvature, keeps fixed vertices, equals the
command's result, does not depend on the input's dtype or memory order, leaves the inputs as
they were, refuses bad input with the engine's message, reports progress and releases the GIL."""

import json
import subprocess
import threading
import time

import numpy as np
import pytest
import quasidev
from conftest import CYLINDER, read_ply


def boundary_vertices(F):
    edges = np.sort(np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]]), axis=1)
    unique, counts = np.unique(edges, axis=0, return_counts=True)
    return np.unique(unique[counts == 1])


@pytest.fixture(scope="module")
def kept(cylinder):
    V, F, patches = cylinder
    return quasidev.approximate(V, F, patches=patches, keep_boundary=True)


def test_curvature_falls_by_half_and_the_boundary_stays(cylinder, kept):
    V, F, _ = cylinder
    before, after = kept.report["total_before"]["g_abd"], kept.report["total_after"]["g_abd"]
    assert after <= 0.5 * before
    assert np.abs(kept.k_after).sum() < np.abs(kept.k_before).sum()
    b = boundary_vertices(F)
    assert len(b) > 0
    assert np.array_equal(kept.positions[b], V[b])
    moved = np.linalg.norm(kept.positions - V, axis=1)
    assert np.allclose(kept.displacement, moved, rtol=0, atol=1e-12)
    assert kept.positions.shape == V.shape and kept.positions.dtype == np.float64


def test_fixed_vertices_do_not_move(cylinder):
    V, F, patches = cylinder
    index = np.arange(0, len(V), 7)
    mask = np.zeros(len(V), dtype=bool)
    mask[index] = True
    by_index = quasidev.approximate(V, F, patches=patches, fixed=index, keep_boundary=False)
    by_mask = quasidev.approximate(V, F, patches=patches, fixed=mask, keep_boundary=False)
    assert np.array_equal(by_index.positions[index], V[index])
    assert np.array_equal(by_index.positions, by_mask.positions)
    assert by_index.report["constrained_vertices"] == len(index)


def test_equals_the_command_output(cylinder, kept, quasidev_command, tmp_path):
    out, report = tmp_path / "out.ply", tmp_path / "report.json"
    subprocess.run([str(quasidev_command), str(CYLINDER), str(out), "--report", str(report),
                    "--keep-boundary", "--quiet"], check=True, timeout=600)
    W, _, _ = read_ply(out)
    ae = kept.report["average_edge"]
    assert np.abs(kept.positions - W).max() <= 1e-9 * ae
    command = json.loads(report.read_text())
    assert command["average_edge"] == pytest.approx(ae, rel=1e-12)
    for key in ("g_abd", "angle_defect", "max_disp"):
        assert kept.report["total_after"][key] == pytest.approx(
            command["total_after"][key], rel=1e-9, abs=1e-12)
    assert kept.report["parameters"] == command["parameters"]
    assert [p["id"] for p in kept.report["patches"]] == [p["id"] for p in command["patches"]]


def test_dtype_and_memory_order_do_not_matter(cylinder, kept):
    V, F, patches = cylinder
    ae = kept.report["average_edge"]
    fortran = quasidev.approximate(np.asfortranarray(V), np.asfortranarray(F.astype(np.int32)),
                                   patches=patches.astype(np.int16), keep_boundary=True)
    assert np.abs(fortran.positions - kept.positions).max() <= 1e-12 * ae
    V32 = V.astype(np.float32)
    single = quasidev.approximate(V32, F, patches=patches, keep_boundary=True)
    double = quasidev.approximate(V32.astype(np.float64), F, patches=patches, keep_boundary=True)
    assert np.abs(single.positions - double.positions).max() <= 1e-12 * ae
    assert single.positions.dtype == np.float64


def test_inputs_are_unchanged_and_outputs_are_new(cylinder):
    V, F, patches = cylinder
    V1, F1, P1 = V.copy(), F.copy(), patches.copy()
    fixed = np.zeros(len(V), dtype=bool)
    r = quasidev.approximate(V1, F1, patches=P1, fixed=fixed, max_iter=2)
    assert np.array_equal(V1, V) and np.array_equal(F1, F) and np.array_equal(P1, patches)
    assert not fixed.any()
    assert not np.shares_memory(r.positions, V1)
    r.positions[:] = 0  # writable and owned by the result alone
    assert np.array_equal(V1, V)


@pytest.mark.parametrize("params, text", [
    ({"no_such_parameter": 1}, "unknown parameter 'no_such_parameter'"),
    ({"tolerance_ae": -1}, "tolerance_ae must be greater than 0, got -1"),
    ({"max_iter": 0}, "max_iter must be at least 1, got 0"),
    ({"developability": "sideways"}, "developability must be one of"),
    ({"patch_tolerance_ae": "3=x"}, "patch_tolerance_ae "),
])
def test_bad_parameters_raise_value_error(cylinder, params, text):
    V, F, _ = cylinder
    with pytest.raises(ValueError, match=text):
        quasidev.approximate(V, F, **params)


def test_degenerate_mesh_raises_the_engines_message():
    V = np.zeros((3, 3))
    with pytest.raises(ValueError, match="average edge length"):
        quasidev.approximate(V, [[0, 1, 2]])


@pytest.mark.parametrize("V, F, error, text", [
    (np.zeros((4, 2)), [[0, 1, 2]], ValueError, r"V must have shape \(n, 3\)"),
    (np.zeros((4, 3)), [[0, 1, 9]], ValueError, "F holds vertex indices outside"),
    (np.array([["a"] * 3] * 4), [[0, 1, 2]], TypeError, "V must be"),
    (np.eye(3), [[0, 1.5, 2]], TypeError, "F must hold whole numbers"),
])
def test_wrong_arrays_raise_clear_errors(V, F, error, text):
    with pytest.raises(error, match=text):
        quasidev.approximate(V, F)


def test_progress_rises_to_one(cylinder):
    V, F, patches = cylinder
    seen = []
    quasidev.approximate(V, F, patches=patches, progress=seen.append)
    assert len(seen) >= 2
    assert all(0 <= f <= 1 for f in seen)
    assert seen == sorted(seen)
    assert seen[-1] >= 0.99


def test_an_exception_in_progress_is_raised_after_the_run(cylinder):
    V, F, patches = cylinder

    def stop(_):
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        quasidev.approximate(V, F, patches=patches, progress=stop)


def test_another_thread_runs_while_the_engine_does(cylinder):
    V, F, patches = cylinder
    ticks, done = [], threading.Event()

    def count():
        while not done.is_set():
            ticks.append(time.perf_counter())
            time.sleep(0.001)

    counter = threading.Thread(target=count)
    counter.start()
    start = time.perf_counter()
    try:
        quasidev.approximate(V, F, patches=patches, max_iter=60, stop_abd=0.01)
    finally:
        end = time.perf_counter()
        done.set()
        counter.join()
    during = [t for t in ticks if start < t < end]
    # The run lasts many 1 ms sleeps; with the GIL held the counter would tick at most once.
    assert end - start > 0.05
    assert len(during) >= 10
