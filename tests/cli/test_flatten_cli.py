"""End-to-end tests of `quasidev flatten`: true lengths on developable meshes, texture coordinates
in model units, every other attribute kept bit for bit, the SVG and DXF patterns read back, the
report's per-piece figures, and bad command lines or files that leave nothing written.

Measures: scripts/flat_measures.py (numpy, independent of the engine). Meshes: sample_meshes/
(cone_panels.ply is exactly developable) and tests/data/ (public meshes).
"""
import json
import pathlib
import re
import sys
import xml.etree.ElementTree as ET

import numpy as np
import pytest

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from plyfile import PlyData  # noqa: E402
from test_quasidev_cli import BINARY, DATA, REPO, assert_clean_failure, run  # noqa: E402
from ply_columns import column, columns, element  # noqa: E402

sys.path.insert(0, str(REPO / "scripts"))
import flat_measures  # noqa: E402

pytestmark = pytest.mark.skipif(not BINARY.exists(), reason=f"{BINARY} not built")

CONE = REPO / "sample_meshes" / "cone_panels.ply"
CRANE = DATA / "developable_crumpled_crane.ply"
SHIRT = DATA / "garment_shirt_initial_diffavatar.ply"


def flattened(path):
    """(V, F, UV) of a flattened PLY."""
    elements = PlyData.read(path)
    V = np.array(list(zip(*(column(elements, "vertex", c) for c in "xyz"))), float)
    F = np.array(column(elements, "face", "vertex_indices"), int)
    UV = np.array(column(elements, "face", "texcoord"), float)
    return V, F, UV


def flatten(tmp_path, mesh, *options, name="out"):
    out, report = tmp_path / f"{name}.ply", tmp_path / f"{name}.json"
    r = run("flatten", mesh, out, "--report", report, *options)
    assert r.returncode == 0, r.stderr
    return out, json.loads(report.read_text()), r


def dxf_pairs(path):
    """The (group code, value) pairs of a DXF file."""
    lines = pathlib.Path(path).read_text().splitlines()
    assert len(lines) % 2 == 0, "a DXF file is a sequence of code/value line pairs"
    return [(int(lines[i]), lines[i + 1].strip()) for i in range(0, len(lines), 2)]


# ---------------------------------------------------------------------------------------------
# True lengths


def test_developable_cone_flattens_to_its_true_lengths(tmp_path):
    """Issue 14: a developable patch flattens with edge-length errors below 0.1 % and the same
    area to 0.1 %; the texture coordinates are in model units (lengths in UV = lengths in 3D)."""
    out, report, r = flatten(tmp_path, CONE)
    V, F, UV = flattened(out)
    assert flat_measures.edge_length_errors(V, F, UV).max() < 1e-3
    assert abs(flat_measures.area_ratio(V, F, UV) - 1) < 1e-3
    assert len(report["pieces"]) == 3 and report["flattenable_pieces"] == 3
    for piece in report["pieces"]:
        assert piece["max_distortion"] < 0.1 and abs(piece["area_change"]) < 0.1
        assert piece["flipped"] == piece["overlapping"] == 0 and piece["cut"] == ""
    # One log line per piece and a total, on stdout.
    lines = r.stdout.splitlines()
    assert [l.split(":")[0] for l in lines[:3]] == ["patch 0", "patch 1", "patch 2"]
    assert any(line.startswith("flattened 3 pieces in ") for line in lines[3:])


def test_a_tube_gets_one_cut_and_still_its_true_lengths(tmp_path):
    """The cone without patch ids is one tube: cut once (said in the log), then exact."""
    cone = PlyData.read(CONE)
    face = element("face", [c for c in columns(cone["face"]) if c[0] != "quality"])
    tube = tmp_path / "tube.ply"
    PlyData([cone["vertex"], face], comments=cone.comments).write(tube)
    out, report, r = flatten(tmp_path, tube)
    assert len(report["pieces"]) == 1 and not report["has_patch_ids"]
    assert "cut to a disk along 1 shortest path joining its 2 boundary loops" in report["pieces"][0]["cut"]
    assert "cut to a disk" in r.stdout
    V, F, UV = flattened(out)
    assert flat_measures.edge_length_errors(V, F, UV).max() < 1e-3


def test_crumpled_crane_flattens_to_its_known_pattern_lengths(tmp_path):
    """The exactly developable crumpled crane: edge lengths and area to 0.1 %, and its flat
    pattern (its texture coordinates) has the same edge lengths as ours."""
    out, report, _ = flatten(tmp_path, CRANE)
    V, F, UV = flattened(out)
    assert flat_measures.edge_length_errors(V, F, UV).max() < 1e-3
    assert abs(flat_measures.area_ratio(V, F, UV) - 1) < 1e-3
    known = np.array(column(PlyData.read(CRANE), "face", "texcoord"), float)
    scale = np.sqrt(flat_measures.area_ratio(V, F, known))  # its pattern's unit
    ours = flat_measures.edge_length_errors(V, F, UV)
    theirs = flat_measures.edge_length_errors(V, F, known / scale)
    assert ours.max() <= theirs.max() + 1e-3


# ---------------------------------------------------------------------------------------------
# What the output keeps and adds


def described(ply, name):
    """Each property of an element: its header line and its values."""
    return [(str(p), column(ply, name, p.name)) for p in ply[name].properties]


def test_everything_but_texcoord_quality_and_face_colour_is_kept_bit_for_bit(tmp_path):
    """Vertices (float positions stay float), faces and every other property and element of
    the input pass through unchanged; texcoord, face quality and colour are replaced."""
    src = tmp_path / "rich.ply"
    cone = PlyData.read(CONE)
    n, m = cone["vertex"].count, cone["face"].count
    vertex = [(c, "f4", cone["vertex"][c]) for c in "xyz"]
    vertex += [("nx", "f4", [0.5] * n), ("ny", "f4", [0.25] * n), ("nz", "f4", [-1.0] * n),
               ("red", "u1", [i % 256 for i in range(n)]), ("green", "u1", [7] * n), ("blue", "u1", [9] * n),
               ("flags", "i4", [32 * (i % 2) for i in range(n)]),
               ("temperature", "i2", [i % 300 - 150 for i in range(n)])]
    face = columns(cone["face"])
    face += [("texcoord", ("u1", "f4"), [(1.0, 2.0, 3.0, 4.0, 5.0, 6.0)] * m), ("red", "u1", [1] * m),
             ("patch", "i4", cone["face"]["quality"]), ("texnumber", "i4", [0] * m)]
    edge = element("edge", [("vertex1", "i4", [0, 1]), ("vertex2", "i4", [1, 2])])
    PlyData([element("vertex", vertex), element("face", face), edge], byte_order=">",
            comments=["made by test_flatten_cli", "TextureFile none.png"]).write(src)
    out, _, _ = flatten(tmp_path, src)
    inp, res = PlyData.read(src), PlyData.read(out)
    assert res.comments == inp.comments
    assert described(res, "vertex") == described(inp, "vertex"), "vertices bit for bit, types too"
    replaced = {"texcoord", "quality", "red", "green", "blue", "alpha"}
    got = dict(zip((p.name for p in res["face"].properties), described(res, "face")))
    for p, kept in zip(inp["face"].properties, described(inp, "face")):
        if p.name not in replaced:
            assert got[p.name] == kept, p.name
    assert described(res, "edge") == described(inp, "edge")
    assert str(res["face"].ply_property("texcoord")) == "property list uchar float texcoord", "what MeshLab reads"
    assert str(res["face"].ply_property("quality")) == "property double quality"
    assert column(res, "face", "texcoord") != column(inp, "face", "texcoord")
    assert set(column(res, "face", "alpha")) == {255}


def test_face_quality_is_the_signed_stretch_with_a_ramp_centred_on_green(tmp_path):
    mesh = SHIRT
    out, report, _ = flatten(tmp_path, mesh)
    V, F, UV = flattened(out)
    res = PlyData.read(out)
    q = np.array(column(res, "face", "quality"))
    s = flat_measures.singular_values(V, F, UV)
    # σ1 − 1, or −(1 − σ2) where the compression is larger: recomputed from the float UV (the
    # sign only where the two differ by more than that precision).
    stretch, squeeze = s[:, 0] - 1, 1 - s[:, 1]
    assert np.abs(np.abs(q) - np.maximum(stretch, squeeze)).max() < 1e-4
    clear = np.abs(stretch - squeeze) > 1e-4
    assert (np.sign(q[clear]) == np.where(squeeze > stretch, -1, 1)[clear]).all()
    assert max(report["pieces"], key=lambda p: p["max_distortion"])["max_distortion"] == \
        pytest.approx(100 * np.abs(q).max(), abs=0.01)
    rgb = np.stack([column(res, "face", c) for c in ("red", "green", "blue")], 1)
    assert (rgb[np.abs(q) < 1e-4] == [0, 255, 0]).all(), "no stretch reads green"
    assert (rgb[q == q.max()][:, 2] == 255).all() and (rgb[q == q.min()][:, 0] == 255).all()


def test_pieces_lie_side_by_side_without_overlap(tmp_path):
    mesh = SHIRT
    _, report, _ = flatten(tmp_path, mesh)
    boxes = [p["box"] for p in report["pieces"]]
    for i, a in enumerate(boxes):
        for b in boxes[:i]:
            apart = any(a["max"][k] <= b["min"][k] or b["max"][k] <= a["min"][k] for k in (0, 1))
            assert apart, (a, b)


def test_output_does_not_depend_on_the_number_of_threads(tmp_path):
    mesh = SHIRT
    one, _, _ = flatten(tmp_path, mesh, "--threads", "1", "--quiet", name="one")
    two, _, _ = flatten(tmp_path, mesh, "--threads", "2", "--quiet", name="two")
    assert one.read_bytes() == two.read_bytes()


def test_report_names_every_piece_figure(tmp_path):
    _, report, r = flatten(tmp_path, REPO / "sample_meshes" / "patches.ply", "--arap-max-iter", "7",
                           "--arap-tolerance", "0", "--gap", "0.5", "--notch-spacing", "0.3")
    assert report["parameters"] == {"arap_max_iter": 7, "arap_tolerance": 0.0, "gap": 0.5,
                                    "notch_spacing": 0.3, "seam_allowance": 0.0,
                                    "grain_direction": "0,1,0", "symmetry_tolerance": 1.0,
                                    "svg_file": "", "dxf_file": "", "dxf_style": "plain",
                                    "unit": "model", "marker_width": 0.0, "marker_svg_file": "",
                                    "marker_dxf_file": "", "pdf_file": "", "paper": "a4",
                                    "solver": "auto", "threads": 0}
    assert report["faces"] == sum(p["faces"] for p in report["pieces"])
    for p, line in zip(report["pieces"], r.stdout.splitlines()):
        for key in ("patch", "component", "label", "faces", "vertices", "cut", "iterations",
                    "stop_reason", "energy", "max_distortion", "mean_distortion", "area_change",
                    "boundary_change", "flipped", "overlapping", "flattenable", "box", "time_ms"):
            assert key in p, key
        assert p["iterations"] <= 7
        assert line.startswith(f"patch {p['label']}: {p['faces']} faces")
        assert f"length distortion max {p['max_distortion']:.2f} %" in line
    assert report["max_distortion"] == max(p["max_distortion"] for p in report["pieces"])


# ---------------------------------------------------------------------------------------------
# The pattern files


def test_congruent_pieces_are_one_pattern_piece_cut_several_times(tmp_path):
    """cone_panels.ply has 3 congruent panels; two of them lie grain-alike (the third's grain runs
    another way on it), so they are one pattern piece cut twice, the report says which and by
    how much they differ, and the SVG says "Cut 2". Tolerance 0 keeps every piece."""
    svg = tmp_path / "p.svg"
    cone = REPO / "sample_meshes" / "cone_panels.ply"
    _, report, r = flatten(tmp_path, cone, "--svg-file", svg)
    pattern = report["pattern"]
    assert sum(p["quantity"] for p in pattern) == len(report["pieces"]) == 3
    twice = [p for p in pattern if p["quantity"] == 2]
    assert len(twice) == 1 and len(twice[0]["pieces"]) == 2 and twice[0]["difference"] < 1
    assert any("one pattern piece, cut 2" in line for line in r.stdout.splitlines())
    texts = [t.text for t in ET.parse(svg).getroot().iter("{http://www.w3.org/2000/svg}text")]
    assert any(t.startswith("Cut 2") for t in texts)
    _, alone, _ = flatten(tmp_path, cone, "--symmetry-tolerance", "0", name="alone")
    assert [p["quantity"] for p in alone["pattern"]] == [1, 1, 1]


def test_svg_pattern_is_xml_with_every_piece_notches_and_a_scale_bar(tmp_path):
    svg = tmp_path / "p.svg"
    _, report, _ = flatten(tmp_path, REPO / "sample_meshes" / "patches.ply", "--svg-file", svg, "--unit", "cm",
                           "--symmetry-tolerance", "0")
    root = ET.parse(svg).getroot()
    ns = "{http://www.w3.org/2000/svg}"
    assert root.tag == f"{ns}svg" and root.get("width").endswith("cm")
    groups = {g.get("id"): g for g in root.iter(f"{ns}g") if g.get("id")}
    for p in report["pieces"]:
        g = groups[f"piece-{p['label']}"]
        assert f"Piece {p['label']}" in [t.text for t in g.findall(f"{ns}text")]
        assert g.find(f"{ns}path[@class='cut']").get("d").count("Z") == 1  # each piece is a disk
        assert g.find(f"{ns}path[@class='grain']") is not None
        assert g.find(f"{ns}path[@class='notches']") is not None, "seams between patches get notches"
    assert re.fullmatch(r"[0-9.]+ cm", groups["scale-bar"].find(f"{ns}text").text)
    # The viewBox spans the sheet (1 SVG unit = 1 model unit) plus margins.
    width, height = map(float, root.get("viewBox").split()[2:])
    sheet = report["sheet"]
    assert width > sheet["max"][0] - sheet["min"][0] and height > sheet["max"][1] - sheet["min"][1]


def test_dxf_pattern_reads_back_as_r12_polylines_per_patch(tmp_path):
    dxf = tmp_path / "p.dxf"
    _, report, _ = flatten(tmp_path, REPO / "sample_meshes" / "patches.ply", "--dxf-file", dxf,
                           "--symmetry-tolerance", "0")
    pairs = dxf_pairs(dxf)
    assert pairs[-1] == (0, "EOF")
    assert (9, "$ACADVER") in pairs and pairs[pairs.index((9, "$ACADVER")) + 1] == (1, "AC1009")
    polylines = [i for i, p in enumerate(pairs) if p == (0, "POLYLINE")]
    assert len(polylines) == len(report["pieces"])
    layers = {pairs[i + 1][1] for i in polylines if pairs[i + 1][0] == 8}
    assert layers == {f"PATCH_{p['patch']}" for p in report["pieces"]}
    # Every vertex of an outline lies on the sheet.
    sheet = report["sheet"]
    xs = [float(v) for c, v in pairs if c == 10]
    ys = [float(v) for c, v in pairs if c == 20]
    assert min(xs) >= sheet["min"][0] - 1e-6 and max(xs) <= sheet["max"][0] + 1e-6
    assert min(ys) >= sheet["min"][1] - 1e-6 and max(ys) <= sheet["max"][1] + 1e-6


# ---------------------------------------------------------------------------------------------
# Bad command lines and failures: a clear message, nothing written


@pytest.mark.parametrize("option,value,hint", [
    ("--arap-max-iter", "-1", "whole number from 0 to 100000"),
    ("--arap-max-iter", "2.5", "whole number"),
    ("--arap-tolerance", "1", "must be below 1"),
    ("--arap-tolerance", "-0.1", "must not be negative"),
    ("--gap", "nan", "expects a finite number"),
    ("--notch-spacing", "-2", "must not be negative"),
    ("--unit", "km", "model|mm|cm|in"),
    ("--threads", "-1", "whole number from 0 to 1024"),
    ("--solver", "magic", "auto|cholmod|eigen-llt|eigen-ldlt"),
])
def test_bad_option_names_option_value_and_writes_nothing(option, value, hint, tmp_path):
    out, svg = tmp_path / "out.ply", tmp_path / "p.svg"
    r = run("flatten", CONE, out, "--svg-file", svg, option, value)
    assert_clean_failure(r, out, status=2)
    assert option in r.stderr and value in r.stderr and hint in r.stderr, r.stderr
    assert not svg.exists()


@pytest.mark.parametrize("clash", [["--svg-file", "OUT"], ["--dxf-file", "IN"], ["--svg-file", "X", "--dxf-file", "X"],
                                   ["--report", "X", "--svg", "X"]])
def test_two_outputs_in_one_file_are_refused(clash, tmp_path):
    out = tmp_path / "out.ply"
    names = {"OUT": str(out), "IN": str(CONE), "X": str(tmp_path / "x")}
    r = run("flatten", CONE, out, *[names.get(a, a) for a in clash])
    assert_clean_failure(r, out, status=2)
    assert "must differ" in r.stderr


def test_an_unwritable_pattern_leaves_every_file_as_it_was(tmp_path):
    out, report = tmp_path / "out.ply", tmp_path / "r.json"
    out.write_bytes(b"precious")
    r = run("flatten", CONE, out, "--report", report, "--svg-file", tmp_path / "no" / "such" / "p.svg")
    assert r.returncode == 1 and r.stderr.count("\n") == 1, r.stderr
    assert "p.svg" in r.stderr
    assert out.read_bytes() == b"precious" and not report.exists()
    assert not list(tmp_path.glob("*quasidev-tmp*"))


def test_help_lists_flatten_and_its_defaults():
    top = run("--help")
    assert re.search(r"^Subcommands:\napproximate\n.*\nflatten\n", top.stdout, re.M | re.S), top.stdout
    sub = run("flatten", "--help")
    assert sub.returncode == 0 and "Usage: quasidev flatten [OPTIONS] INPUT OUTPUT" in sub.stdout
    for option, default in (("--arap-max-iter,--max-iter N", "100"), ("--arap-tolerance,--tolerance X", "0.0001"),
                            ("--gap X", "0"), ("--notch-spacing X", "0"), ("--unit NAME", "model"),
                            ("--threads N", "0")):
        entry = re.search(rf"  {option}\s.*?(?=\n  -|\n\n)", sub.stdout, re.S).group(0)
        assert f"default {default})" in " ".join(entry.split()), entry
    for option in ("--svg-file", "--dxf-file", "--report", "--progress", "--quiet", "--overwrite-input"):
        assert option in sub.stdout


def test_progress_quiet_and_obj_groups(tmp_path):
    """--progress ends at 100 %; --quiet prints nothing; OBJ groups are patches as PLY quality is."""
    r = run("flatten", CONE, tmp_path / "p.ply", "--progress", "--quiet")
    assert r.returncode == 0 and r.stdout == "", r.stderr
    progress = [l for l in r.stderr.splitlines() if l.startswith("quasidev: ")]
    assert progress and progress[-1].startswith("quasidev: 100%"), r.stderr
    obj = DATA / "garment_shirt_initial_diffavatar.obj"
    _, from_obj, _ = flatten(tmp_path, obj, "--quiet", name="obj")
    _, from_ply, _ = flatten(tmp_path, SHIRT, "--quiet", name="ply")
    assert from_obj["has_patch_ids"]
    assert sorted(p["faces"] for p in from_obj["pieces"]) == sorted(p["faces"] for p in from_ply["pieces"])
