"""scripts/cutting_room.py on the shipped shirt (its OBJ for the tutorial, its PLY for the marker
table): every figure is written and the marker table has a row per width whose kept marker is the
shorter, with every piece to cut placed."""
from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys

import pytest
from PIL import Image

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DATA = os.path.join(ROOT, "tests", "data")
QUASIDEV = os.path.join(os.environ.get("QD_BUILD_DIR", os.path.join(ROOT, "build")), "bin", "quasidev")
SHIRT = "garment_shirt_initial_diffavatar"


def test_figures_and_marker_table(tmp_path):
    if not os.access(QUASIDEV, os.X_OK):
        pytest.skip(f"no quasidev at {QUASIDEV}")
    pytest.importorskip("pymupdf")
    assert shutil.which("rsvg-convert"), "rsvg-convert missing: run scripts/setup.sh"
    proc = subprocess.run([sys.executable, os.path.join(ROOT, "scripts", "cutting_room.py"), "--quasidev", QUASIDEV,
                           "--meshes", DATA, "--tutorial-mesh", os.path.join(DATA, f"{SHIRT}.obj"),
                           "--garments", SHIRT, "--out", str(tmp_path)],
                          capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stderr
    for png in ("garment_pattern.png", "tutorials/cutting_room_marker.png", "tutorials/cutting_room_pdf.png"):
        with Image.open(tmp_path / png) as image:
            assert image.width > 400 and image.height > 200, png
    data = json.loads((tmp_path / "marker.json").read_text())
    flatten = data["tutorial"]["flatten"]
    assert "--seam-allowance 1" in flatten["command"] and "pdf: " in flatten["log"]
    assert sum(p["quantity"] for p in flatten["pattern"]) == 5  # the shirt's 5 panels, all cut
    rows = data["markers"]
    assert [r["width"] for r in rows] == [110, 150]
    for r in rows:
        kept = r[r["kept"]]
        assert kept["length"] == min(r["nested"]["length"], r["rows"]["length"])
        assert r["pieces"] == 5 and 0 < kept["efficiency"] <= 1
    assert (tmp_path / "marker.md").read_text().count(f"| {SHIRT} |") == 2
