"""The flattening filter inside real pymeshlab (compute_texcoord_quasi_developable_flattening):
wedge texture coordinates in model units on a developable mesh, the returned dict with every
per-piece figure, the same result as `quasidev flatten`, the pattern files, the .mlx samples, and a
failure that changes nothing."""
from __future__ import annotations

import json
import subprocess
import xml.etree.ElementTree as ET

import numpy as np
import pytest

import flat_measures
from pymeshlab_paths import CLI, FAILED_MESHSETS, FLATTEN_FILTER, FILTER, data, require_file, sample

PIECE_LISTS = {"piece_patch", "piece_component", "piece_faces", "piece_vertices", "piece_cut",
               "piece_iterations", "piece_energy", "piece_max_distortion", "piece_mean_distortion",
               "piece_area_change", "piece_boundary_change", "piece_flipped", "piece_overlapping",
               "piece_flattenable", "piece_time_ms"}
TOTALS = {"pieces", "flattenable_pieces", "max_distortion", "sheet_width", "sheet_height", "time_ms"}
# report key of each per-piece list of the dict
REPORT_KEY = {name: name.removeprefix("piece_") for name in PIECE_LISTS}
REPORT_KEY["piece_cut"] = "cut"


def wedge_uv(mesh) -> np.ndarray:
    """(m,6) per-face corner coordinates of a pymeshlab mesh."""
    return mesh.wedge_tex_coord_matrix().reshape(-1, 6)


def run_cli(path: str, tmp_path, *options) -> dict:
    require_file(CLI, "build the quasidev target")
    out, report = tmp_path / "cli.ply", tmp_path / "cli.json"
    r = subprocess.run([CLI, "flatten", path, str(out), "--quiet", "--report", str(report), *options],
                       capture_output=True, text=True, timeout=600)
    assert r.returncode == 0, r.stderr
    return {"mesh": str(out), "report": json.loads(report.read_text())}


def test_developable_cone_gets_texcoords_in_model_units(meshset):
    ms = meshset(sample("cone_panels.ply"))
    V0, F0 = ms.current_mesh().vertex_matrix().copy(), ms.current_mesh().face_matrix().copy()
    fig = ms.apply_filter(FLATTEN_FILTER)
    m = ms.current_mesh()
    assert m.has_wedge_tex_coord()
    UV = wedge_uv(m)
    assert flat_measures.edge_length_errors(V0, F0, UV).max() < 1e-3
    assert abs(flat_measures.area_ratio(V0, F0, UV) - 1) < 1e-3
    np.testing.assert_array_equal(m.vertex_matrix(), V0)
    np.testing.assert_array_equal(m.face_matrix(), F0)
    assert fig["pieces"] == 3 and fig["flattenable_pieces"] == 3 and fig["max_distortion"] < 0.1
    assert np.abs(m.face_scalar_array()).max() < 1e-3


@pytest.mark.parametrize("path", [sample("patches.ply"), data("garment_shirt_initial_diffavatar.ply"),
                                  data("lampshade_frustum_ipc.ply")])
def test_dict_has_every_piece_figure_and_matches_the_command(meshset, tmp_path, path):
    ms = meshset(path)
    fig = ms.apply_filter(FLATTEN_FILTER)
    assert TOTALS | PIECE_LISTS <= set(fig), set(fig) ^ (TOTALS | PIECE_LISTS)
    assert isinstance(fig["pieces"], int) and isinstance(fig["flattenable_pieces"], int)
    cli = run_cli(path, tmp_path)
    report = cli["report"]
    assert fig["pieces"] == len(report["pieces"])
    assert fig["max_distortion"] == pytest.approx(report["max_distortion"], rel=1e-6)
    for name, key in REPORT_KEY.items():
        assert len(fig[name]) == fig["pieces"], name
        expected = [bool(p[key]) if key == "cut" else p[key] for p in report["pieces"]]
        if name == "piece_time_ms":
            continue
        np.testing.assert_allclose(np.asarray(fig[name], float), np.asarray(expected, float),
                                   rtol=1e-6, atol=1e-9, err_msg=name)
    # Same texture coordinates as the command's output (read back through pymeshlab).
    theirs = meshset(cli["mesh"])
    np.testing.assert_allclose(wedge_uv(ms.current_mesh()), wedge_uv(theirs.current_mesh()),
                               atol=1e-6 * max(fig["sheet_width"], fig["sheet_height"]))
    np.testing.assert_allclose(ms.current_mesh().face_scalar_array(),
                               theirs.current_mesh().face_scalar_array(), atol=1e-7)


def test_pattern_files_and_parameters(meshset, tmp_path):
    svg, dxf = tmp_path / "p.svg", tmp_path / "p.dxf"
    ms = meshset(sample("patches.ply"))
    fig = ms.apply_filter(FLATTEN_FILTER, svg_file=str(svg), dxf_file=str(dxf), unit="mm",
                          arap_max_iter=3, gap=0.5, notch_spacing=0.25, arap_tolerance=0.0,
                          seam_allowance=0.05, symmetry_tolerance=0.0)
    assert max(fig["piece_iterations"]) <= 3
    root = ET.parse(svg).getroot()
    assert root.get("width").endswith("mm")
    groups = [g for g in root.iter("{http://www.w3.org/2000/svg}g")
              if (g.get("id") or "").startswith("piece-")]
    assert len(groups) == fig["pieces"]
    assert all({p.get("class") for p in g.iter("{http://www.w3.org/2000/svg}path")} >= {"cut", "sew", "grain"}
               for g in groups)
    assert dxf.read_text().count("POLYLINE") == 2 * fig["pieces"]  # cut line and sew line


def test_failure_changes_nothing_and_writes_no_file(pymeshlab_with_plugin, meshset, tmp_path):
    svg = tmp_path / "p.svg"
    ms = meshset(sample("patches.ply"))
    m = ms.current_mesh()
    before = (m.vertex_matrix().copy(), m.face_scalar_array().copy(), m.has_wedge_tex_coord(),
              m.has_face_color())
    FAILED_MESHSETS.append(ms)
    with pytest.raises(pymeshlab_with_plugin.PyMeshLabException) as info:
        ms.apply_filter(FLATTEN_FILTER, gap=-1.0, svg_file=str(svg))
    assert "Gap between pieces (gap) must not be negative, got -1" in str(info.value)
    m = ms.current_mesh()
    np.testing.assert_array_equal(m.vertex_matrix(), before[0])
    np.testing.assert_array_equal(m.face_scalar_array(), before[1])
    assert (m.has_wedge_tex_coord(), m.has_face_color()) == before[2:]
    assert not svg.exists()


@pytest.mark.parametrize("script", ["flatten.mlx", "approximate_then_flatten.mlx"])
def test_sample_scripts_run_through_pymeshlab(meshset, script):
    """The .mlx samples (shared with meshlabserver 2020.09) give what apply_filter gives."""
    ms = meshset(sample("patches.ply"))
    ms.load_filter_script(sample(script))
    ms.apply_filter_script()
    ref = meshset(sample("patches.ply"))
    if script.startswith("approximate"):
        ref.apply_filter(FILTER)
    ref.apply_filter(FLATTEN_FILTER)
    np.testing.assert_allclose(ms.current_mesh().vertex_matrix(), ref.current_mesh().vertex_matrix(),
                               rtol=0, atol=1e-12)
    np.testing.assert_allclose(wedge_uv(ms.current_mesh()), wedge_uv(ref.current_mesh()), rtol=0, atol=1e-6)
