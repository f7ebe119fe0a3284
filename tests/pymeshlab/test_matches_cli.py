"""pymeshlab + plugin and the `quasidev` command run the same engine on the same input: the vertex
matrix and the figures must agree to 1e-6 relative (default parameters and one non-default set)."""
from __future__ import annotations

import json
import os
import subprocess

import numpy as np
import pytest
from plyfile import PlyData

from pymeshlab_paths import CLI, FILTER, data, require_file, sample

# The shirt with 100 vertices that no face uses (with_unreferenced_vertices() makes it).
UNREFERENCED = "shirt_with_unreferenced_vertices.ply"
# (mesh, plugin keywords, the same as quasidev options)
CASES = [
    (sample("bumpy_cylinder.ply"), {}, []),
    (sample("lampshade.ply"), {}, []),
    (sample("patches.ply"), {}, []),
    (sample("selected.ply"), {}, []),
    (sample("patches.ply"),
     {"seam_mode": "free", "target_mode": "refit", "tolerance_mode": "total", "max_iter": 5,
      "weight": 20.0, "anchor": 5.0, "keep_boundary": False},
     ["--seam-mode", "free", "--target-mode", "refit", "--tolerance-mode", "total", "--max-iter", "5",
      "--weight", "20", "--anchor", "5", "--no-keep-boundary"]),
    (data("developable_crumpled_crane.ply"), {}, []),
    (data("bowl_hemisphere_ipc.ply"), {}, []),
    (data("garment_shirt_initial_diffavatar.ply"), {}, []),  # 5 patches
    (UNREFERENCED, {}, []),
]


def with_unreferenced_vertices(tmp_path) -> str:
    """The shirt of tests/data with copies of its first 100 vertices appended, unused by faces."""
    ply = PlyData.read(data("garment_shirt_initial_diffavatar.ply"))
    vertex = ply["vertex"]
    vertex.data = np.concatenate([vertex.data, vertex.data[:100]])
    path = tmp_path / UNREFERENCED
    ply.write(path)
    return str(path)


def run_cli(path: str, options: list[str], tmp_path) -> tuple[str, dict]:
    require_file(CLI, "build the quasidev target")
    out, report = tmp_path / "out.ply", tmp_path / "report.json"
    r = subprocess.run([CLI, path, str(out), "--quiet", "--report", str(report), *options],
                       capture_output=True, text=True, timeout=600)
    assert r.returncode == 0, r.stderr
    with open(report) as f:
        return str(out), json.load(f)


@pytest.mark.parametrize("path, kwargs, options", CASES,
                         ids=[f"{os.path.basename(c[0])}-{'tuned' if c[1] else 'defaults'}" for c in CASES])
def test_plugin_moves_vertices_as_the_cli_predicts(meshset, tmp_path, path, kwargs, options):
    if path == UNREFERENCED:
        path = with_unreferenced_vertices(tmp_path)
    ms = meshset(path)
    V0 = ms.current_mesh().vertex_matrix().copy()
    # pymeshlab passes float parameters as float32: the command gets the same defect weight.
    fig = ms.apply_filter(FILTER, **kwargs)
    options = [*options, "--defect-weight", repr(float(np.float32(0.03)))]
    V_plugin = ms.current_mesh().vertex_matrix()
    cli_output, report = run_cli(path, options, tmp_path)
    cli = meshset(cli_output)
    V_cli = cli.current_mesh().vertex_matrix()
    assert V_cli.shape == V_plugin.shape
    moved = np.linalg.norm(V_cli - V0, axis=1).max()
    if moved == 0:  # e.g. an already developable mesh: both must leave it alone
        np.testing.assert_array_equal(V_plugin, V0)
    else:
        assert np.abs(V_plugin - V_cli).max() <= 1e-6 * moved
    assert fig["abd_reduction"] == pytest.approx(report["abd_reduction"], rel=1e-6, abs=1e-9)
    assert fig["max_displacement"] == pytest.approx(report["total_after"]["max_disp"], rel=1e-6, abs=1e-12)
    # The same work: where the stronger rows' first step and their bound each move the farthest
    # vertex by the tolerance, the inputs' last digits must not decide whether they run on
    # (kMoveRounding, group_run.h).
    assert fig["factorizations"] == report["factorizations"]
    assert list(fig["patch_iterations"]) == [p["iterations"] for p in report["patches"]]
    np.testing.assert_allclose(cli.current_mesh().vertex_scalar_array(),
                               ms.current_mesh().vertex_scalar_array(), rtol=1e-6,
                               atol=1e-6 * np.abs(ms.current_mesh().vertex_scalar_array()).max())
