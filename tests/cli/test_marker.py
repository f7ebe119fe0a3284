"""End-to-end tests of `quasidev flatten --marker`: the nested marker's files are written and read
back (the SVG as XML, the DXF's closed polylines on a FABRIC layer), its efficiency on the log is
a fraction in (0, 1], and marker files without a width are refused with nothing written.
"""
import json
import pathlib
import re
import sys
import xml.etree.ElementTree as ET

import pytest

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from test_quasidev_cli import BINARY, REPO, run  # noqa: E402

pytestmark = pytest.mark.skipif(not BINARY.exists(), reason=f"{BINARY} not built")

CONE = REPO / "sample_meshes" / "cone_panels.ply"


def test_marker_files_and_efficiency(tmp_path):
    """The marker keeps the shorter of the nesting and the rows, places every piece to cut (with
    its quantity) and its efficiency is their cut area over the fabric it takes."""
    svg, dxf, report = tmp_path / "m.svg", tmp_path / "m.dxf", tmp_path / "r.json"
    r = run("flatten", CONE, tmp_path / "out.ply", "--marker", "3", "--marker-svg", svg, "--marker-dxf", dxf,
            "--seam-allowance", "0.02", "--report", report)
    assert r.returncode == 0, r.stderr
    rep = json.loads(report.read_text())
    marker, pattern = rep["marker"], rep["pattern"]
    assert marker["method"] in ("nested", "rows")
    assert marker["length"] == min(marker["nested"]["length"], marker["rows"]["length"])
    assert marker["placed"] == sum(p["quantity"] for p in pattern) == 3 and marker["unplaced"] == []
    area = sum(p["cut_area"] * p["quantity"] for p in pattern)
    assert marker["efficiency"] == pytest.approx(area / (3 * marker["length"]), rel=1e-6)
    assert "(kept: the shorter)" in r.stdout
    root = ET.parse(svg).getroot()
    ns = "{http://www.w3.org/2000/svg}"
    assert root.tag == ns + "svg"
    assert len(root.findall(f".//{ns}g[@class='piece']")) == marker["placed"]
    lines = dxf.read_text().splitlines()
    layers = [lines[i + 1] for i in range(0, len(lines) - 1, 2) if lines[i].strip() == "8"]
    assert "FABRIC" in layers
    assert lines[-1] == "EOF"


def test_marker_files_need_a_width(tmp_path):
    r = run("flatten", CONE, tmp_path / "out.ply", "--marker-svg", tmp_path / "m.svg")
    assert r.returncode == 2
    assert "--marker-width WIDTH" in r.stderr
    assert not (tmp_path / "m.svg").exists() and not (tmp_path / "out.ply").exists()
