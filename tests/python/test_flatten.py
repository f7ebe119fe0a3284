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
    svg, dxf = tmp_path / "flat.svg", tmp_path / "flat.dxf"
    subprocess.run([str(quasidev_command), "flatten", str(PATCHES), str(out), "--report",
                    str(report), "--svg-file", str(svg), "--dxf-file", str(dxf), "--quiet"],
                   check=True, timeout=600)
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
    files = {"svg_file": "", "dxf_file": ""}  # the command was given them, the package is not
    assert r.report["parameters"] == {**command["parameters"], **files}
    assert len(r.report["pieces"]) == len(command["pieces"]) == len(np.unique(mesh.patches))
    assert r.svg == svg.read_text() and r.dxf == dxf.read_text()  # the command's writers
    written = tmp_path / "written.ply"
    quasidev.write(written, mesh.V, mesh.F, patches=mesh.patches, uv=r.uv)
    back = np.vstack(plyfile.PlyData.read(str(written))["face"]["texcoord"]).reshape(-1, 3, 2)
    assert np.abs(r.uv - back).max() <= 1e-6 * extent  # float32 in the file, as MeshLab reads


def test_bad_parameter_raises_value_error():
    mesh = quasidev.read(PATCHES)
    with pytest.raises(ValueError, match="arap_max_iter must not be negative, got -1"):
        quasidev.flatten(mesh.V, mesh.F, mesh.patches, arap_max_iter=-1)
    with pytest.raises(ValueError, match="unknown parameter 'svg_file'"):
        quasidev.flatten(mesh.V, mesh.F, mesh.patches, svg_file="x.svg")
    with pytest.raises(ValueError, match="uv must have shape"):
        quasidev.write("never.ply", mesh.V, mesh.F, uv=np.zeros((3, 3, 2)))
