"""The plugin in the real meshlabserver 2020.09 (issue 3, bullet 4).

Each job runs a sample .mlx of sample_meshes/ through meshlabserver (private prefix, Xvfb) on a
float-rounded copy of a sample mesh with patch ids (and selected vertices), runs the quasidev
command with the equivalent options on the same file, and checks the output PLY: positions equal
the command's to 1e-5 of the bbox diagonal, curvature fell, selected vertices / fixed seams / the
kept boundary did not move, faces and face quality unchanged, quality and colour written.
Bad meshes must make the filter fail with our reason in the log and leave the output alone.
"""
from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pytest
from plyfile import PlyData

from ml2020_support import (REPO, Mesh, boundary_vertices, cli_arguments, float_rounded,
                            integrated_curvature, load_mesh, mlx_parameters, run_meshlabserver,
                            run_quasidev, save_float_mesh, seam_vertices)
from ply_columns import column, element, positions

SAMPLES = REPO / "sample_meshes"

# job name -> (sample mesh, sample script)
JOBS = {
    "default": ("bumpy_cylinder.ply", "default.mlx"),
    "whole_mesh": ("bumpy_cone.ply", "whole_mesh.mlx"),
    "patches_fixed_seams": ("selected.ply", "patches_fixed_seams.mlx"),
    "free_seams": ("selected.ply", "free_seams.mlx"),
    "keep_selected": ("selected.ply", "keep_selected.mlx"),
    "draped_defect_rows": ("draped_panels.ply", "default.mlx"),
}


@dataclass
class JobRun:
    name: str
    params: dict
    uses_patches: bool
    given: Mesh       # the float-rounded input both programs read
    plugin: Mesh      # meshlabserver's output
    command: Mesh     # the quasidev command's output
    log: str


@pytest.fixture(scope="module", params=sorted(JOBS))
def job(request, meshlab_prefix, quasidev_path, tmp_path_factory) -> JobRun:
    name = request.param
    sample, script = JOBS[name]
    work = tmp_path_factory.mktemp(name)
    given = float_rounded(load_mesh(SAMPLES / sample))
    params = mlx_parameters(SAMPLES / script)
    args, uses_patches = cli_arguments(params)
    save_float_mesh(given, work / "in.ply")
    save_float_mesh(given, work / "in_command.ply", face_quality=uses_patches)
    server = run_meshlabserver(meshlab_prefix, work / "in.ply", work / "plugin.ply", SAMPLES / script)
    (work / "meshlabserver.log").write_text(server.stdout)
    assert server.returncode == 0, f"meshlabserver failed (rc {server.returncode}):\n{server.stdout[-3000:]}"
    command = run_quasidev(work / "in_command.ply", work / "command.ply", args)
    assert command.returncode == 0, f"quasidev {' '.join(args)} failed:\n{command.stderr}"
    return JobRun(name, params, uses_patches, given, load_mesh(work / "plugin.ply"),
                  load_mesh(work / "command.ply"), server.stdout)


def _item(job: JobRun, name: str) -> str:
    _, value, items = job.params[name]
    return items[int(value)]


def test_positions_equal_the_quasidev_command(job):
    diagonal = job.given.diagonal()
    error = np.abs(job.plugin.v - job.command.v).max()
    assert error <= 1e-5 * diagonal, f"max |plugin - command| = {error:g}, diagonal {diagonal:g}"
    moved = np.linalg.norm(job.plugin.v - job.given.v, axis=1).max()
    assert moved > 1e-4 * diagonal, "the filter did not move any vertex"


def test_curvature_fell(job):
    interior = ~boundary_vertices(job.given)
    before = integrated_curvature(job.given, interior)
    after = integrated_curvature(job.plugin, interior)
    assert after < before, f"integrated |angle defect| {before:.6g} -> {after:.6g}"


def test_constrained_vertices_did_not_move(job):
    kept = job.given.selected.copy()
    assert job.name not in ("patches_fixed_seams", "free_seams", "keep_selected") or kept.any()
    if job.params["keep_boundary"][1] == "true":
        kept |= boundary_vertices(job.given)
    seams = seam_vertices(job.given) if job.uses_patches else np.zeros(len(job.given.v), bool)
    if _item(job, "seam_mode") == "fixed":
        kept |= seams
    np.testing.assert_array_equal(job.plugin.v[kept], job.given.v[kept])
    if _item(job, "seam_mode") == "free" and seams.any():
        free_seams = seams & ~kept
        assert (np.abs(job.plugin.v[free_seams] - job.given.v[free_seams]).max(axis=1) > 0).any(), \
            "free seams: no seam vertex moved"


def test_faces_and_face_data_unchanged(job):
    np.testing.assert_array_equal(job.plugin.f, job.given.f)
    np.testing.assert_array_equal(job.plugin.face_quality, job.given.face_quality)
    np.testing.assert_array_equal(job.plugin.selected, job.given.selected)


def test_quality_and_colour_written(job):
    q, c = job.plugin.quality, job.plugin.color
    assert q is not None and c is not None, "no per-vertex quality or colour in the output"
    assert np.isfinite(q).all() and np.ptp(q) > 0
    assert len(np.unique(c, axis=0)) > 10, "the colour ramp has (almost) one colour"
    scale = np.abs(job.command.quality).max()
    np.testing.assert_allclose(q, job.command.quality, rtol=0, atol=1e-4 * scale)
    mismatched = (np.abs(c.astype(int) - job.command.color.astype(int)).max(axis=1) > 2).mean()
    assert mismatched < 0.01, f"{mismatched:.1%} of the colours differ from the command's"
    if _item(job, "output_quality") == "displacement":
        moved = np.linalg.norm(job.plugin.v - job.given.v, axis=1)
        np.testing.assert_allclose(q, moved, rtol=0, atol=1e-5 * job.given.diagonal())


def test_log_has_a_line_per_patch_and_a_total(job):
    patches = len(np.unique(np.rint(job.given.face_quality))) if job.uses_patches else 1
    assert len(re.findall(r"^LOG: \d+ patch -?\d+: \d+ faces, .*ratio_ABD .*ratio_OBD .* AE, ",
                          job.log, re.M)) == patches, job.log
    assert re.search(r"^LOG: \d+ total: .* AE .* iterations", job.log, re.M), job.log


def test_log_names_the_developability_term(job):
    """auto measures: every patch line names the term it ran; where candidates were raced, the
    line gives each one's figures and the kept one removed the most of the raced terms (the
    angle-defect rows at a stronger weight, named `defect ×100 weight` (or ×30, ×10), where they
    beat the race's pick; where they are not kept, the line says which bound stopped them, and
    they may have removed more, or which stronger rows left less). On the draped sample the angle-defect rows are raced."""
    lines = re.findall(r"^LOG: \d+ patch -?\d+: .*$", job.log, re.M)
    assert lines, job.log
    raced = set()
    for line in lines:
        term = re.search(r"developability (curve|defect|both) \(", line)
        assert term, line
        measured = re.search(r"auto, measured:(.*?)\), \d+ iteration", line)
        if not measured:
            continue
        figures = {name: float(value) for name, value in
                   re.findall(r"((?:curve|defect|both)(?: ×[\d.]+ weight)?) −(-?[\d.]+)% in \d+ it\.",
                              measured.group(1))}
        kept = re.search("(" + term.group(1) + r"(?: ×[\d.]+ weight)?) −[-\d.]+% in \d+ it\. \(kept",
                         measured.group(1))
        assert kept, line
        raced_terms = {n: v for n, v in figures.items() if "×" not in n or n == kept.group(1)}
        assert figures[kept.group(1)] >= max(raced_terms.values()) - 0.05, line
        for name in set(figures) - set(raced_terms):  # stronger rows not kept: the line says why
            assert re.search(re.escape(name) + r" −[-\d.]+% in \d+ it\. \((?:stopped: |not kept: |"
                             r"passed, but defect ×[\d.]+ weight left less\))",
                             measured.group(1)), line
        raced |= {name.split()[0] for name in figures}
    if job.name == "draped_defect_rows":
        assert raced & {"defect", "both"}, job.log


def test_texture_coordinates_and_face_colours_untouched(meshlab_prefix, tmp_path):
    """Per-wedge texture coordinates and face colours (absent from the samples) survive."""
    ply = PlyData.read(SAMPLES / "selected.ply")
    vertices, faces = ply["vertex"], ply["face"]
    # float positions: what MeshLab 2020.09 stores, so the positions compare exactly
    vcols = [(p.name, "f4" if p.name in "xyz" else vertices[p.name].dtype, vertices[p.name])
             for p in vertices.properties]
    rng = np.random.default_rng(7)
    colours = rng.integers(0, 256, size=(faces.count, 3))
    texcoord = np.float32([rng.random(6) for _ in range(faces.count)])
    fcols = [(p.name, ("u1", "i4") if p.name == "vertex_indices" else faces[p.name].dtype, faces[p.name])
             for p in faces.properties]
    fcols += [(c, "u1", colours[:, k]) for k, c in enumerate(("red", "green", "blue"))]
    fcols.append(("texcoord", ("u1", "f4"), texcoord))
    given = PlyData([element("vertex", vcols), element("face", fcols)], comments=ply.comments)
    given.write(tmp_path / "in.ply")
    run = run_meshlabserver(meshlab_prefix, tmp_path / "in.ply", tmp_path / "out.ply", SAMPLES / "default.mlx",
                            saved=("vc", "vq", "vf", "fq", "fc", "wt"))
    assert run.returncode == 0, run.stdout[-3000:]
    out = PlyData.read(tmp_path / "out.ply")
    for k, c in enumerate(("red", "green", "blue")):
        assert column(out, "face", c) == colours[:, k].tolist(), f"face colour channel {c} changed"
    np.testing.assert_array_equal(np.array(column(out, "face", "texcoord")), texcoord)
    moved = np.abs(positions(out) - np.float32(positions(ply))).max()
    assert moved > 0, "the filter did not run"


# ---- bad meshes ---------------------------------------------------------------------------------

def _nan_vertex(mesh: Mesh) -> Mesh:
    mesh.v[len(mesh.v) // 2, 0] = np.nan
    return mesh


def _zero_area_face(mesh: Mesh) -> Mesh:
    a, _, c = mesh.f[len(mesh.f) // 2]
    mesh.v[c] = mesh.v[a]  # the face's corners a and c coincide: exactly zero area
    return mesh


def _tiny_patches(mesh: Mesh) -> Mesh:
    mesh.face_quality[:] = np.arange(len(mesh.f))  # every face its own patch: none can be fitted
    return mesh


BAD = {
    "nan_coordinates": (_nan_vertex, r"NaN or infinite"),
    "zero_area_face": (_zero_area_face, r"zero-area face"),
    "only_tiny_patches": (_tiny_patches, r"Patch 0 has only 1 face"),
}


@pytest.mark.parametrize("case", sorted(BAD))
def test_bad_mesh_fails_with_reason_and_leaves_output_alone(case, meshlab_prefix, tmp_path):
    make_bad, reason = BAD[case]
    save_float_mesh(make_bad(float_rounded(load_mesh(SAMPLES / "patches.ply"))), tmp_path / "bad.ply")
    out = tmp_path / "out.ply"
    out.write_bytes(b"previous result\n")
    run = run_meshlabserver(meshlab_prefix, tmp_path / "bad.ply", out, SAMPLES / "default.mlx")
    assert run.returncode != 0, run.stdout
    assert "Problem with filter" in run.stdout
    failure = re.search(r"Quasi-Developable Approximation failed: (.*)", run.stdout)
    assert failure, f"no reason logged:\n{run.stdout[-3000:]}"
    assert re.search(reason, failure.group(1)), failure.group(1)
    assert out.read_bytes() == b"previous result\n"
