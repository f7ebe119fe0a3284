"""End-to-end tests of `quasidev flatten --marker`: the nested marker's files are written and read
back (the SVG as XML, the DXF's closed polylines on a FABRIC layer), its efficiency on the log is
a fraction in (0, 1], and marker files without a width are refused with nothing written.
"""
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
    svg, dxf = tmp_path / "m.svg", tmp_path / "m.dxf"
    r = run("flatten", CONE, tmp_path / "out.ply", "--marker", "3", "--marker-svg", svg, "--marker-dxf", dxf)
    assert r.returncode == 0, r.stderr
    match = re.search(r"marker: width 3, length ([0-9.e+-]+), efficiency ([0-9.e+-]+) %, (\d+) pieces", r.stdout)
    assert match, r.stdout
    length, efficiency, pieces = float(match[1]), float(match[2]) / 100, int(match[3])
    assert 0 < efficiency <= 1
    assert length > 0 and pieces == 3
    root = ET.parse(svg).getroot()
    ns = "{http://www.w3.org/2000/svg}"
    assert root.tag == ns + "svg"
    assert len(root.findall(f".//{ns}g[@class='piece']")) == pieces
    lines = dxf.read_text().splitlines()
    layers = [lines[i + 1] for i in range(0, len(lines) - 1, 2) if lines[i].strip() == "8"]
    assert "FABRIC" in layers
    assert lines[-1] == "EOF"


def test_marker_files_need_a_width(tmp_path):
    r = run("flatten", CONE, tmp_path / "out.ply", "--marker-svg", tmp_path / "m.svg")
    assert r.returncode == 2
    assert "--marker-width WIDTH" in r.stderr
    assert not (tmp_path / "m.svg").exists() and not (tmp_path / "out.ply").exists()
