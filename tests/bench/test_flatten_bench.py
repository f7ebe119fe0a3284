"""The flattening benchmark (bench/qd_flatten_bench) against ground truth: tests/data/
developable_crumpled_crane.ply is exactly developable and its per-corner texcoord is its exact
flattening, so our pattern's edge lengths must match both the 3D edges and that pattern to 0.1 %.
The SVG it writes must parse as XML and the DXF as group-code pairs. Timings are not asserted."""
import json
import os
import pathlib
import subprocess
import xml.etree.ElementTree as ET

import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]
BUILD = pathlib.Path(os.environ.get("QD_BUILD_DIR", REPO / "build"))
BENCH = BUILD / "bin" / "qd_flatten_bench"
CRANE = REPO / "tests" / "data" / "developable_crumpled_crane.ply"


def run(*args):
    if not BENCH.exists():
        pytest.fail(f"{BENCH} is missing: build the project first")
    out = subprocess.run([str(BENCH), *map(str, args)], check=True, capture_output=True, text=True, timeout=300)
    return json.loads(out.stdout)


def dxf_groups(path):
    lines = path.read_text().splitlines()
    assert len(lines) % 2 == 0
    return [(int(lines[i]), lines[i + 1].strip()) for i in range(0, len(lines), 2)]


def test_crane_flattens_to_its_known_pattern(tmp_path):
    r = run("--mesh", CRANE, "--svg-file", tmp_path / "crane.svg", "--dxf-file", tmp_path / "crane.dxf")
    assert r["pieces"] == 1
    assert r["max_edge_error_vs_3d"] < 1e-3
    assert r["max_edge_error_vs_texcoord"] < 1e-3
    svg = ET.parse(tmp_path / "crane.svg").getroot()
    assert svg.tag == "{http://www.w3.org/2000/svg}svg"
    pieces = [g for g in svg.iter("{http://www.w3.org/2000/svg}g") if g.get("id", "").startswith("piece-")]
    assert len(pieces) == 1
    groups = dxf_groups(tmp_path / "crane.dxf")
    assert groups[0] == (0, "SECTION") and groups[-1] == (0, "EOF")
    assert groups.count((0, "POLYLINE")) == groups.count((0, "SEQEND")) == 1


def test_patches_of_a_sheet_become_pieces_that_parse(tmp_path):
    r = run("--grid", "20000", "--patches", "4", "--svg-file", tmp_path / "p.svg", "--dxf-file", tmp_path / "p.dxf",
            "--unit", "cm")
    assert r["pieces"] == 4
    assert r["max_edge_error_vs_3d"] < 0.05  # a bumpy sheet: near-developable, not exactly
    svg = ET.parse(tmp_path / "p.svg").getroot()
    assert svg.get("width").endswith("cm")
    texts = [t.text for t in svg.iter("{http://www.w3.org/2000/svg}text")]
    labels = {t.removeprefix("Piece ") for t in texts if t.startswith("Piece ")}
    assert "0" in labels and labels <= {"0", "1", "2", "3"}
    assert sum(int(t.split()[1]) for t in texts if t.startswith("Cut ")) == 4  # every patch cut
    groups = dxf_groups(tmp_path / "p.dxf")
    layers = {v for c, v in groups if c == 8}
    assert {f"PATCH_{label}" for label in labels} | {"PATCH_0_NOTCHES"} <= layers
