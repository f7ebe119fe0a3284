"""quasidev.flatten on numpy arrays: per-corner texture coordinates and per-face stretch equal
the command's output, the report's figures are the command's, and bad input raises ValueError."""

import json
import subprocess

import numpy as np
import plyfile
import pytest
import quasidev
from conftest import REPO

PATCHES = REPO / "sample_meshes" / "patches.ply"


def test_equals_the_command_output(quasidev_command, tmp_path):
    out, report = tmp_path / "flat.ply", tmp_path / "flat.json"
    subprocess.run([str(quasidev_command), "flatten", str(PATCHES), str(out), "--report",
                    str(report), "--quiet"], check=True, timeout=600)
    mesh = quasidev.read(PATCHES)
    r = quasidev.flatten(mesh.V, mesh.F, mesh.patches)
    faces = plyfile.PlyData.read(str(out))["face"]
    uv = np.vstack(faces["texcoord"]).astype(np.float64).reshape(-1, 3, 2)
    assert r.uv.shape == (len(mesh.F), 3, 2) and r.stretch.shape == (len(mesh.F),)
    extent = np.abs(r.uv).max()
    assert np.abs(r.uv - uv).max() <= 1e-6 * extent  # the PLY stores texcoords as float32
    assert np.allclose(r.stretch, faces["quality"], rtol=0, atol=1e-12)
    command = json.loads(report.read_text())
    assert r.report["max_distortion"] == pytest.approx(command["max_distortion"], rel=1e-9)
    assert r.report["parameters"] == command["parameters"]
    assert len(r.report["pieces"]) == len(command["pieces"]) == len(np.unique(mesh.patches))


def test_bad_parameter_raises_value_error():
    mesh = quasidev.read(PATCHES)
    with pytest.raises(ValueError, match="arap_max_iter must not be negative, got -1"):
        quasidev.flatten(mesh.V, mesh.F, mesh.patches, arap_max_iter=-1)
    with pytest.raises(ValueError, match="unknown parameter 'svg_file'"):
        quasidev.flatten(mesh.V, mesh.F, mesh.patches, svg_file="x.svg")
