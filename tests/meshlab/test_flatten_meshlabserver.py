"""The flattening filter in the real meshlabserver 2020.09 (private prefix, Xvfb).

sample_meshes/flatten.mlx on the exactly developable cone_panels.ply: the saved wedge texture
coordinates are in model units (every edge as long on the pattern as on the mesh, to 0.1 %), equal
the quasidev command's on the same float input, face quality is the stretch, the SVG and DXF
patterns are written, and the log has one line per piece and a total. The segment-less pipeline
sample_meshes/approximate_then_flatten.mlx runs both filters, and the approximation lowers the
pattern's distortion. Every other attribute (positions, vertex quality and colour, selection) is
left as it was.
"""
from __future__ import annotations

import re
import sys
import xml.etree.ElementTree as ET

import numpy as np
import pytest

from ml2020_support import (FLATTEN_FILTER_NAME, REPO, float_rounded, load_mesh, run_meshlabserver,
                            run_quasidev, save_float_mesh, write_mlx)

sys.path.insert(0, str(REPO / "scripts"))
import flat_measures  # noqa: E402

SAMPLES = REPO / "sample_meshes"
SAVED = ("vc", "vq", "vf", "fq", "fc", "wt")


def flatten_script(path, **values):
    return write_mlx(path, values, base=SAMPLES / "flatten.mlx", filter_name=FLATTEN_FILTER_NAME)


@pytest.fixture(scope="module")
def cone_run(meshlab_prefix, quasidev_path, tmp_path_factory):
    """meshlabserver and the command flattening the float cone; the plugin also writes both
    pattern files."""
    work = tmp_path_factory.mktemp("cone")
    given = float_rounded(load_mesh(SAMPLES / "cone_panels.ply"))
    save_float_mesh(given, work / "in.ply")
    script = flatten_script(work / "job.mlx", svg_file=work / "p.svg", dxf_file=work / "p.dxf", unit=2)
    server = run_meshlabserver(meshlab_prefix, work / "in.ply", work / "plugin.ply", script, saved=SAVED)
    assert server.returncode == 0, server.stdout[-3000:]
    command = run_quasidev(work / "in.ply", work / "command.ply", [], subcommand="flatten")
    assert command.returncode == 0, command.stderr
    return given, load_mesh(work / "plugin.ply"), load_mesh(work / "command.ply"), server.stdout, work


def test_texcoords_are_in_model_units(cone_run):
    given, plugin, _, _, _ = cone_run
    assert plugin.texcoord is not None, "meshlabserver saved no wedge texture coordinates"
    assert flat_measures.edge_length_errors(given.v, given.f, plugin.texcoord).max() < 1e-3
    assert abs(flat_measures.area_ratio(given.v, given.f, plugin.texcoord) - 1) < 1e-3


def test_texcoords_equal_the_quasidev_command(cone_run):
    given, plugin, command, _, _ = cone_run
    size = np.ptp(command.texcoord.reshape(-1, 2), axis=0).max()
    assert np.abs(plugin.texcoord - command.texcoord).max() <= 1e-5 * size


def test_face_quality_is_the_stretch_and_nothing_else_changed(cone_run):
    given, plugin, command, _, _ = cone_run
    assert np.abs(plugin.face_quality).max() < 1e-3, "an exact development has no stretch"
    np.testing.assert_allclose(plugin.face_quality, command.face_quality, atol=1e-6)
    assert (plugin.face_color == [0, 255, 0]).all(), "no stretch reads green"
    assert np.array_equal(plugin.v, given.v) and np.array_equal(plugin.f, given.f)


def test_log_has_a_line_per_piece_and_the_pattern_files(cone_run):
    _, _, _, log, work = cone_run
    pieces = re.findall(r"LOG: \d+ patch (\d+): \d+ faces; .* length distortion max ([0-9.]+) %", log)
    assert [p for p, _ in pieces] == ["0", "1", "2"], log[-3000:]
    assert all(float(d) < 0.1 for _, d in pieces)
    assert re.search(r"LOG: \d+ flattened 3 pieces in ", log)
    root = ET.parse(work / "p.svg").getroot()
    assert root.get("width").endswith("cm")
    assert (work / "p.dxf").read_text().rstrip().endswith("EOF")


def test_pipeline_approximates_then_flattens(meshlab_prefix, tmp_path):
    """approximate_then_flatten.mlx on the 4-patch trouser leg: vertex quality (curvature) from the
    approximation, texture coordinates from the flattening, and a lower largest distortion than
    flattening the input directly."""
    given = float_rounded(load_mesh(SAMPLES / "patches.ply"))
    save_float_mesh(given, tmp_path / "in.ply")
    direct = run_meshlabserver(meshlab_prefix, tmp_path / "in.ply", tmp_path / "direct.ply",
                               SAMPLES / "flatten.mlx", saved=SAVED)
    both = run_meshlabserver(meshlab_prefix, tmp_path / "in.ply", tmp_path / "both.ply",
                             SAMPLES / "approximate_then_flatten.mlx", saved=SAVED)
    assert direct.returncode == 0 and both.returncode == 0, both.stdout[-3000:]
    largest = [float(re.search(r"largest length distortion ([0-9.]+) %", r.stdout).group(1))
               for r in (direct, both)]
    assert largest[1] < largest[0], largest
    out = load_mesh(tmp_path / "both.ply")
    assert out.quality is not None and out.texcoord is not None
    assert not np.array_equal(out.v, given.v), "the approximation moved vertices"
    distortion = flat_measures.distortion_summary(out.v, out.f, out.texcoord)
    assert 100 * distortion["max"] == pytest.approx(largest[1], abs=0.05)


def test_failure_names_the_reason_and_leaves_the_output(meshlab_prefix, tmp_path):
    """A bad parameter: the filter fails with our reason in the log; nothing is written."""
    given = float_rounded(load_mesh(SAMPLES / "cone_panels.ply"))
    save_float_mesh(given, tmp_path / "in.ply")
    out, svg = tmp_path / "out.ply", tmp_path / "p.svg"
    out.write_bytes(b"previous")
    script = flatten_script(tmp_path / "job.mlx", arap_tolerance=-1, svg_file=svg)
    run = run_meshlabserver(meshlab_prefix, tmp_path / "in.ply", out, script, saved=SAVED)
    assert run.returncode == 255, run.stdout[-3000:]
    reasons = re.findall(rf"LOG: \d+ {FLATTEN_FILTER_NAME} failed: (.*)", run.stdout)
    assert len(reasons) == 1 and "ARAP tolerance (arap_tolerance) must not be negative, got -1" in reasons[0], \
        run.stdout[-3000:]
    assert out.read_bytes() == b"previous" and not svg.exists()
