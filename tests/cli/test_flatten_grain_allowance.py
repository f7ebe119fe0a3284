"""End-to-end tests of the cutting room's seam allowance and grainlines in `quasidev flatten`:
the cut lines reach the allowance (and at most twice it) beyond the sew lines and keep pieces
apart, the allowance leaves the flattening itself unchanged, every piece lies with the model's
up direction along +y on the sheet, and named panels (OBJ groups, PLY "comment patch" lines) go
through. The SVG writer is another unit's: only that the SVG parses is checked here.

Meshes: sample_meshes/cone_panels.ply (3 developable panels, axis z) and a generated OBJ.
"""
import json
import pathlib
import sys
import xml.etree.ElementTree as ET

import numpy as np
import pytest

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from plyfile import PlyData  # noqa: E402
from test_quasidev_cli import BINARY, REPO, run  # noqa: E402
from ply_columns import column  # noqa: E402

pytestmark = pytest.mark.skipif(not BINARY.exists(), reason=f"{BINARY} not built")

CONE = REPO / "sample_meshes" / "cone_panels.ply"
REACH = 2  # the cut line lies at most this many allowances outside the sew line (miter limit)


def flatten(tmp_path, mesh, *options, name="out"):
    """Runs the command with an SVG and a report; returns (output PLY, report, SVG root)."""
    out, report, svg = (tmp_path / f"{name}.{ext}" for ext in ("ply", "json", "svg"))
    # Symmetric pieces are one pattern piece laid out anew: keep every piece where it was flattened.
    r = run("flatten", mesh, out, "--report", report, "--svg", svg, "--symmetry-tolerance", "0",
            *options)
    assert r.returncode == 0, r.stderr
    return out, json.loads(report.read_text()), ET.parse(svg).getroot()


def mesh_uv(path):
    """(V, F, UV per face corner as F×3×2) of a flattened PLY."""
    elements = PlyData.read(path)
    V = np.array(list(zip(*(column(elements, "vertex", c) for c in "xyz"))), float)
    F = np.array(column(elements, "face", "vertex_indices"), int)
    UV = np.array(column(elements, "face", "texcoord"), float).reshape(-1, 3, 2)
    return V, F, UV


def mapped_direction(V, F, UV, faces, up):
    """Area-weighted sum over the faces of `up` mapped by each face's linear map 3D → UV."""
    total = np.zeros(2)
    for f in faces:
        E = (V[F[f, 1:]] - V[F[f, 0]]).T  # 3×2
        U = (UV[f, 1:] - UV[f, 0]).T      # 2×2
        area = np.linalg.norm(np.cross(E[:, 0], E[:, 1])) / 2
        total += area * U @ np.linalg.solve(E.T @ E, E.T @ up)
    return total


def box(b):
    return np.array(b["min"]), np.array(b["max"])


def assert_cut_lines_reach_the_allowance(report, a):
    """The sheet (bounding every cut line) lies between a and REACH·a beyond the sew lines'
    boxes, and the pieces' boxes grown by REACH·a do not overlap."""
    boxes = [box(p["box"]) for p in report["pieces"]]
    sew_min = np.min([lo for lo, _ in boxes], axis=0)
    sew_max = np.max([hi for _, hi in boxes], axis=0)
    sheet_min, sheet_max = box(report["sheet"])
    eps = 1e-6
    assert np.all(sew_min - sheet_min >= a - eps) and np.all(sheet_max - sew_max >= a - eps)
    assert np.all(sew_min - sheet_min <= REACH * a + eps)
    assert np.all(sheet_max - sew_max <= REACH * a + eps)
    for i, (lo_i, hi_i) in enumerate(boxes):
        for lo_j, hi_j in boxes[i + 1:]:
            apart = np.maximum(lo_i, lo_j) - np.minimum(hi_i, hi_j)
            assert apart.max() >= 2 * REACH * a - eps, "cut lines of two pieces may touch"


def test_cone_panels_get_an_allowance_and_lie_grain_up(tmp_path):
    a = 0.05
    patch = np.array(column(PlyData.read(CONE), "face", "quality")).round().astype(int)
    out, report, _ = flatten(tmp_path, CONE, "--seam-allowance", a, "--grain-direction", "0,0,1")
    assert len(report["pieces"]) == 3
    assert_cut_lines_reach_the_allowance(report, a)
    V, F, UV = mesh_uv(out)
    for p in report["pieces"]:
        up = mapped_direction(V, F, UV, np.flatnonzero(patch == p["patch"]), np.array([0.0, 0, 1]))
        angle = np.degrees(np.arctan2(abs(up[0]), up[1]))
        assert angle < 0.5, f"piece {p['label']}: the cone's axis runs {angle:.2f}° off +y"


def test_allowance_moves_pieces_but_does_not_change_them(tmp_path):
    plain, _, _ = flatten(tmp_path, CONE, "--grain-direction", "0,0,1", name="plain")
    cut, _, _ = flatten(tmp_path, CONE, "--seam-allowance", 0.05, "--grain-direction", "0,0,1",
                        name="cut")
    _, _, UV0 = mesh_uv(plain)
    _, _, UV1 = mesh_uv(cut)
    edges = lambda UV: UV[:, 1:] - UV[:, :1]  # noqa: E731
    ulp = np.spacing(np.float32(max(np.abs(UV0).max(), np.abs(UV1).max())))  # texcoords are floats
    np.testing.assert_allclose(edges(UV1), edges(UV0), rtol=0, atol=4 * float(ulp))
    assert np.abs(UV1 - UV0).max() > 0.05  # laid out farther apart


def test_obj_with_named_groups_flattens_grain_up(tmp_path):
    """Two quarter-cylinder panels of height 2 along y (the default up) and arc length ≈ 1.57:
    laid grain-up each is 2 tall; turned by its longest axis it would be 2 wide."""
    columns, rows, height = 16, 8, 2.0
    lines = []
    for j in range(rows + 1):
        for i in range(2 * columns + 1):
            t = np.pi * i / (2 * columns)
            lines.append(f"v {np.cos(t):.17g} {height * j / rows:.17g} {np.sin(t):.17g}")
    width = 2 * columns + 1
    for name, first in (("front", 0), ("back panel", columns)):
        lines.append(f"g {name}")
        for j in range(rows):
            for i in range(first, first + columns):
                a, b = j * width + i + 1, j * width + i + 2
                lines += [f"f {a} {b} {b + width}", f"f {a} {b + width} {a + width}"]
    obj = tmp_path / "panels.obj"
    obj.write_text("\n".join(lines) + "\n")
    a = 0.1
    out, report, _ = flatten(tmp_path, obj, "--seam-allowance", a)
    assert report["has_patch_ids"] and [p["patch"] for p in report["pieces"]] == [0, 1]
    assert_cut_lines_reach_the_allowance(report, a)
    for p in report["pieces"]:
        lo, hi = box(p["box"])
        assert hi[1] - lo[1] == pytest.approx(height, rel=1e-3)
        assert hi[0] - lo[0] < 1.6
    _, F, UV = mesh_uv(out)
    assert len(F) == 2 * 2 * columns * rows and np.isfinite(UV).all()


def test_ply_panel_names_stay_in_the_output(tmp_path):
    data = CONE.read_bytes()
    header_end = data.index(b"end_header")
    names = b"comment patch 0 front\ncomment patch 2 left side\n"
    named = data[:header_end] + names + data[header_end:]
    mesh = tmp_path / "named.ply"
    mesh.write_bytes(named)
    out, report, _ = flatten(tmp_path, mesh, "--seam-allowance", 0.02)
    assert len(report["pieces"]) == 3
    comments = PlyData.read(out).comments
    assert "patch 0 front" in comments and "patch 2 left side" in comments
