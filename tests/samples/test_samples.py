"""Tests of the generated sample meshes (scripts/make_samples.py), the PLY conveniences
(scripts/ply_columns.py) and the renderer (scripts/render.py).

Input:  sample_meshes/*.ply + SOURCES.md as committed; the scripts.
Output: pytest results. Run: .venv/bin/python -m pytest tests/samples
"""
from __future__ import annotations

import math
import re
import shutil
import subprocess
import sys
from collections import defaultdict
from pathlib import Path

import numpy as np
import pytest
from plyfile import PlyData

ROOT = Path(__file__).resolve().parents[2]
SCRIPTS = ROOT / "scripts"
SAMPLES = ROOT / "sample_meshes"
sys.path.insert(0, str(SCRIPTS))
import ply_columns  # noqa: E402
from ply_columns import column, element, has, positions  # noqa: E402

SINGLE = ["lampshade.ply", "bumpy_cylinder.ply", "bumpy_cone.ply"]
MULTI = ["patches.ply", "selected.ply"]
ALL = SINGLE + MULTI
SELECTED = 0x20


def load(name: str) -> PlyData:
    return PlyData.read(SAMPLES / name)


def vertices(ply: PlyData) -> list[tuple[float, float, float]]:
    return [tuple(p) for p in positions(ply).tolist()]


def directed_edges(faces):
    """Map (a, b) -> number of faces using the directed edge a->b."""
    count = defaultdict(int)
    for f in faces:
        for k in range(len(f)):
            count[(f[k], f[(k + 1) % len(f)])] += 1
    return count


def boundary_loops(faces) -> int:
    """Number of closed loops formed by edges with one face (each boundary vertex has one successor)."""
    de = directed_edges(faces)
    succ = {a: b for (a, b) in de if (b, a) not in de}
    seen, loops = set(), 0
    for start in succ:
        if start in seen:
            continue
        loops += 1
        v = start
        while v not in seen:
            seen.add(v)
            v = succ[v]
    return loops


def vertex_fans_connected(faces, nverts: int) -> bool:
    """True if the faces around every vertex form one edge-connected fan (vertex-manifold)."""
    around = defaultdict(list)
    for fi, f in enumerate(faces):
        for v in f:
            around[v].append(fi)
    if len(around) != nverts:
        return False
    for v, fs in around.items():
        others = {fi: set(faces[fi]) - {v} for fi in fs}
        reached, todo = {fs[0]}, [fs[0]]
        while todo:
            cur = todo.pop()
            for fi in fs:
                if fi not in reached and others[fi] & others[cur]:
                    reached.add(fi)
                    todo.append(fi)
        if len(reached) != len(fs):
            return False
    return True


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def face_normal(pts, f):
    """Area-scaled normal (twice the area vector) of triangle f."""
    return cross(sub(pts[f[1]], pts[f[0]]), sub(pts[f[2]], pts[f[0]]))


def mean_edge(pts, faces) -> float:
    edges = {tuple(sorted(e)) for e in directed_edges(faces)}
    return sum(math.dist(pts[a], pts[b]) for a, b in edges) / len(edges)


# --- generator ---------------------------------------------------------------------------------

def test_regenerating_gives_identical_bytes(tmp_path):
    for run in ("a", "b"):
        subprocess.run([sys.executable, str(SCRIPTS / "make_samples.py"), "--out", str(tmp_path / run)],
                       check=True, capture_output=True)
    for name in ALL + ["SOURCES.md"]:
        fresh = (tmp_path / "a" / name).read_bytes()
        assert fresh == (tmp_path / "b" / name).read_bytes(), f"{name} differs between two runs"
        assert fresh == (SAMPLES / name).read_bytes(), f"sample_meshes/{name} is stale: rerun make_samples.py"


def test_samples_are_small():
    total = sum((SAMPLES / n).stat().st_size for n in ALL)
    assert total < 2 * 1024 * 1024


def test_sources_md_lists_every_file_with_licence_and_command():
    text = (SAMPLES / "SOURCES.md").read_text()
    assert "CC0" in text and "python3 scripts/make_samples.py" in text
    for name in ALL:
        assert f"| {name} |" in text


# --- format and topology -------------------------------------------------------------------------

@pytest.mark.parametrize("name", ALL)
def test_format_is_the_documented_one(name):
    ply = load(name)
    assert not ply.text and ply.byte_order == "<"
    assert [str(p) for p in ply["vertex"].properties[:3]] == [f"property double {c}" for c in "xyz"]
    assert [str(p) for p in ply["face"].properties] == ["property list uchar int vertex_indices",
                                                        "property float quality"]
    assert any(c.startswith(name[:-4] + ":") for c in ply.comments), "header comment says what it is"
    assert 1000 <= ply["face"].count <= 10000


@pytest.mark.parametrize("name", ALL)
def test_manifold_consistently_oriented_open_no_degenerate_faces(name):
    ply = load(name)
    pts, faces = vertices(ply), ply_columns.faces(ply)
    assert all(len(f) == 3 for f in faces)
    de = directed_edges(faces)
    assert max(de.values()) == 1, "a directed edge used twice: inconsistent orientation or non-manifold"
    assert vertex_fans_connected(faces, len(pts))
    assert boundary_loops(faces) == 2, "an open band/tube has two boundary loops"
    h = mean_edge(pts, faces)
    min_area = min(0.5 * math.hypot(*face_normal(pts, f)) for f in faces)
    assert min_area > 0.05 * h * h


@pytest.mark.parametrize("name", SINGLE)
def test_surfaces_of_revolution_face_outwards_with_one_patch(name):
    ply = load(name)
    pts, faces = vertices(ply), ply_columns.faces(ply)
    assert set(column(ply, "face", "quality")) == {0.0}
    for f in faces:
        n = face_normal(pts, f)
        cx, cy = (sum(pts[v][0] for v in f) / 3, sum(pts[v][1] for v in f) / 3)
        assert n[0] * cx + n[1] * cy > 0, "normal must point away from the z axis"


@pytest.mark.parametrize("name", ["bumpy_cylinder.ply", "bumpy_cone.ply"])
def test_recorded_bump_amplitude_matches_geometry(name):
    ply = load(name)
    pts, faces = vertices(ply), ply_columns.faces(ply)
    header = " ".join(ply.comments)
    m = re.search(r"amplitude a = ([0-9.]+) model units = ([0-9.]+) x average edge length \(([0-9.]+)\)", header)
    assert m, "header records the bump amplitude"
    a, ratio, edge = (float(g) for g in m.groups())
    assert math.isclose(edge, mean_edge(pts, faces), rel_tol=1e-3)
    assert math.isclose(ratio, a / edge, rel_tol=1e-2)
    zmax = max(p[2] for p in pts)
    r_top = min(math.hypot(p[0], p[1]) for p in pts if p[2] == zmax)  # top ring is undisturbed
    r_bottom = min(math.hypot(p[0], p[1]) for p in pts if p[2] == 0.0)
    # distance from the base cone/cylinder through the two rims, measured radially
    slope = (r_top - r_bottom) / zmax
    deviation = max(abs(math.hypot(p[0], p[1]) - (r_bottom + slope * p[2])) for p in pts)
    assert a * 0.9 < deviation < a * 1.3
    text = (SAMPLES / "SOURCES.md").read_text()
    assert f"a = {m.group(1)} model units" in text


@pytest.mark.parametrize("name", MULTI)
def test_four_patches_each_edge_connected_with_seams(name):
    ply = load(name)
    faces, patch = ply_columns.faces(ply), column(ply, "face", "quality")
    assert sorted(set(patch)) == [0.0, 1.0, 2.0, 3.0]
    by_edge = defaultdict(list)
    for fi, f in enumerate(faces):
        for k in range(3):
            by_edge[tuple(sorted((f[k], f[(k + 1) % 3])))].append(fi)
    for pid in set(patch):
        members = {fi for fi, p in enumerate(patch) if p == pid}
        start = next(iter(members))
        reached, todo = {start}, [start]
        while todo:
            f = faces[todo.pop()]
            for k in range(3):
                for g in by_edge[tuple(sorted((f[k], f[(k + 1) % 3])))]:
                    if g in members and g not in reached:
                        reached.add(g)
                        todo.append(g)
        assert reached == members, f"patch {pid} is not one connected piece"
        assert 0.15 < len(members) / len(faces) < 0.35
    seam_edges = [e for e, fs in by_edge.items() if len(fs) == 2 and patch[fs[0]] != patch[fs[1]]]
    assert seam_edges, "patches meet along seams"


def test_selected_is_patches_plus_a_ring_of_selected_vertices():
    sel, base = load("selected.ply"), load("patches.ply")
    assert vertices(sel) == vertices(base) and ply_columns.faces(sel) == ply_columns.faces(base)
    assert column(sel, "face", "quality") == column(base, "face", "quality")
    assert not has(base, "vertex", "flags")
    flags = column(sel, "vertex", "flags")
    chosen = {v for v, fl in enumerate(flags) if fl & SELECTED}
    assert 8 <= len(chosen) < len(flags) // 4
    neighbours = defaultdict(set)
    for a, b in directed_edges(ply_columns.faces(sel)):
        if a in chosen and b in chosen:
            neighbours[a].add(b)
            neighbours[b].add(a)
    assert all(len(neighbours[v]) == 2 for v in chosen), "selection is a simple closed ring"
    start = next(iter(chosen))
    prev, cur, steps = None, start, 0
    while True:
        prev, cur = cur, next(n for n in neighbours[cur] if n != prev)
        steps += 1
        if cur == start:
            break
    assert steps == len(chosen), "the ring is one loop"


DELETE_SELECTED_MLX = """<!DOCTYPE FilterScript>
<FilterScript>
 <filter name="Delete Selected Vertices"/>
</FilterScript>
"""


@pytest.mark.skipif(not (shutil.which("meshlabserver") and shutil.which("xvfb-run")),
                    reason="needs meshlabserver (MeshLab 2020.09) and xvfb-run")
def test_meshlab_2020_reads_selection_and_patch_ids(tmp_path):
    (tmp_path / "del.mlx").write_text(DELETE_SELECTED_MLX)
    out = tmp_path / "out.ply"
    subprocess.run(["xvfb-run", "-a", "-s", "-screen 0 640x480x24", "meshlabserver", "-i", str(SAMPLES / "selected.ply"),
                    "-o", str(out), "-m", "fq", "-s", str(tmp_path / "del.mlx")],
                   check=True, capture_output=True, timeout=300)
    sel, res = load("selected.ply"), PlyData.read(out)
    nsel = sum(1 for fl in column(sel, "vertex", "flags") if fl & SELECTED)
    assert res["vertex"].count == sel["vertex"].count - nsel
    assert sorted(set(column(res, "face", "quality"))) == [0.0, 1.0, 2.0, 3.0]


# --- PLY reader ------------------------------------------------------------------------------------

def meshlab_style(ply: PlyData, text: bool = False) -> PlyData:
    """A copy like MeshLab 2020.09 writes it: float xyz, uchar rgba, float vertex quality, face
    list, a camera element."""
    pts = positions(ply)
    zmid = 0.5 * (pts[:, 2].min() + pts[:, 2].max())
    n = len(pts)
    vertex = [(c, "f4", pts[:, k]) for k, c in enumerate("xyz")]
    vertex += [("red", "u1", np.where(pts[:, 2] > zmid, 255, 0)), ("green", "u1", [90] * n),
               ("blue", "u1", [200] * n), ("alpha", "u1", [255] * n), ("quality", "f4", pts[:, 2] - zmid)]
    face = [("vertex_indices", ("u1", "i4"), ply_columns.faces(ply)), ("quality", "f4", ply["face"]["quality"])]
    camera = [("view_px", "f4", [0.25]), ("view_py", "f4", [0.5])]
    return PlyData([element("vertex", vertex), element("face", face), element("camera", camera)],
                   text=text, comments=["VCGLIB generated"])


@pytest.mark.parametrize("text, order", [(True, "="), (False, ">"), (False, "<")])
def test_ply_columns_read_meshlab_style_in_every_format(tmp_path, text, order):
    ply = meshlab_style(load("bumpy_cone.ply"))
    ply.text, ply.byte_order = text, order
    ply.write(tmp_path / "m.ply")
    back = PlyData.read(tmp_path / "m.ply")
    assert [e.name for e in back.elements] == ["vertex", "face", "camera"]
    assert ply_columns.faces(back) == ply_columns.faces(load("bumpy_cone.ply"))
    assert column(back, "vertex", "red") == column(ply, "vertex", "red")
    assert np.allclose(positions(back), positions(load("bumpy_cone.ply")), rtol=1e-6, atol=1e-6)
    assert has(back, "camera", "view_px") and not has(back, "camera", "x")
    assert column(back, "camera", "view_px") == [0.25]


# --- renderer -----------------------------------------------------------------------------------

def render(tmp_path, *args):
    from PIL import Image  # from scripts/requirements-render.txt
    out = tmp_path / "out.png"
    subprocess.run([sys.executable, str(SCRIPTS / "render.py"), *map(str, args), "-o", str(out)],
                   check=True, capture_output=True, timeout=120)
    return Image.open(out).convert("RGB")


def pixels(img) -> list[tuple[int, int, int]]:
    data = img.tobytes()
    return list(zip(data[0::3], data[1::3], data[2::3]))


def drawn_fraction(img) -> float:
    """Fraction of pixels that are not the white background."""
    px = pixels(img)
    return sum(1 for p in px if p != (255, 255, 255)) / len(px)


def test_render_before_after_is_not_blank(tmp_path):
    img = render(tmp_path, SAMPLES / "patches.ply", SAMPLES / "selected.ply", "--title", "before / after")
    assert img.size == (800, 450)
    assert drawn_fraction(img) > 0.05
    assert len(set(pixels(img))) > 100, "shaded, not a flat silhouette"
    left, right = img.crop((0, 40, 400, 420)), img.crop((400, 40, 800, 420))
    assert drawn_fraction(left) > 0.05 and drawn_fraction(right) > 0.05


def test_render_reads_meshlab_style_and_ascii_plys_with_quality(tmp_path):
    meshlab_style(load("lampshade.ply")).write(tmp_path / "ml.ply")
    meshlab_style(load("lampshade.ply"), text=True).write(tmp_path / "ml_ascii.ply")
    img = render(tmp_path, tmp_path / "ml.ply", tmp_path / "ml_ascii.ply", "--color", "quality", "--view", "30,20")
    assert drawn_fraction(img) > 0.05
    reds = sum(1 for r, g, b in pixels(img) if r > g + 60 and r > b + 60)
    blues = sum(1 for r, g, b in pixels(img) if b > r + 60)
    assert reds > 500 and blues > 500, "vertex quality is shown as a blue-red ramp"
