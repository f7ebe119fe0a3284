"""End-to-end test of `quasidev flatten --dxf-style aama` (ASTM D6673 / AAMA DXF), read back with
ezdxf, an independent DXF library: one block per pattern piece inserted once, the standard
layers, closed boundaries, the unit declared, and each piece's boundary measuring what the
report says (cut_area, cut_perimeter). The plain DXF opens and audits clean in ezdxf too.
"""
import json
import math
import pathlib
import sys

import pytest

ezdxf = pytest.importorskip("ezdxf")

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from test_quasidev_cli import BINARY, REPO, assert_clean_failure, run  # noqa: E402

pytestmark = pytest.mark.skipif(not BINARY.exists(), reason=f"{BINARY} not built")

CONE = REPO / "sample_meshes" / "cone_panels.ply"
LAYERS = {"1", "4", "7", "11", "14", "15"}  # boundary, notches, grain, cut-outs, sew, annotation


def shoelace(points):
    return sum(a[0] * b[1] - b[0] * a[1] for a, b in zip(points, points[1:] + points[:1])) / 2


def perimeter(points):
    return sum(math.dist(a, b) for a, b in zip(points, points[1:] + points[:1]))


def loops_on(block, layer):
    """The (x, y) vertices of every closed POLYLINE of the block on the layer."""
    loops = []
    for e in block.query(f'POLYLINE[layer=="{layer}"]'):
        assert e.is_closed, f"an open polyline on layer {layer} of {block.name}"
        loops.append([(v.dxf.location.x, v.dxf.location.y) for v in e.vertices])
    return loops


def test_aama_dxf_reads_back_in_ezdxf_with_the_reports_measures(tmp_path):
    dxf, report = tmp_path / "p.dxf", tmp_path / "r.json"
    r = run("flatten", CONE, tmp_path / "out.ply", "--dxf", dxf, "--dxf-style", "aama", "--unit",
            "mm", "--seam-allowance", "0.05", "--report", report)
    assert r.returncode == 0, r.stderr
    pattern = json.loads(report.read_text())["pattern"]
    assert sum(p["quantity"] for p in pattern) == 3  # congruent panels cut grain-alike are one
    doc = ezdxf.readfile(dxf)
    assert not doc.audit().has_errors
    assert LAYERS <= {layer.dxf.name for layer in doc.layers}
    assert doc.header.get("$MEASUREMENT") == 1
    units = [t.dxf.text for t in doc.modelspace().query("TEXT") if t.dxf.text.startswith("Units:")]
    assert units == ["Units: METRIC"]
    inserts = [e.dxf.name for e in doc.modelspace().query("INSERT")]
    blocks = [b for b in doc.blocks if not b.name.startswith("*")]
    assert sorted(inserts) == sorted(b.name for b in blocks)
    assert len(inserts) == len(set(inserts)) == len(pattern)
    for piece in pattern:
        block = doc.blocks.get("PIECE_" + piece["label"].replace(".", "_"))
        assert block is not None, piece["label"]
        boundary = loops_on(block, "1")
        holes = loops_on(block, "11")
        assert len(boundary) == 1
        area = abs(shoelace(boundary[0])) - sum(abs(shoelace(h)) for h in holes)
        length = sum(perimeter(loop) for loop in boundary + holes)
        assert area == pytest.approx(piece["cut_area"], rel=1e-6)
        assert length == pytest.approx(piece["cut_perimeter"], rel=1e-6)
        assert len(block.query('LINE[layer=="7"]')) == 1
        texts = [t.dxf.text for t in block.query("TEXT")]
        assert f"Quantity: {piece['quantity']}" in texts
        assert any(t.startswith("Piece Name: ") for t in texts)


def test_plain_dxf_opens_and_audits_clean_in_ezdxf(tmp_path):
    dxf = tmp_path / "plain.dxf"
    r = run("flatten", CONE, tmp_path / "out.ply", "--dxf", dxf)
    assert r.returncode == 0, r.stderr
    doc = ezdxf.readfile(dxf)
    assert not doc.audit().has_errors
    boundaries = doc.modelspace().query('POLYLINE[layer=="PATCH_0"]')
    assert len(boundaries) >= 1 and all(p.is_closed for p in boundaries)
    assert len(doc.modelspace().query('LINE[layer=="PATCH_0_GRAIN"]')) == 1


def test_aama_dxf_without_a_unit_is_refused(tmp_path):
    dxf = tmp_path / "p.dxf"
    r = run("flatten", CONE, tmp_path / "out.ply", "--dxf", dxf, "--dxf-style", "aama")
    assert_clean_failure(r, tmp_path / "out.ply")
    assert not dxf.exists()
    assert "unit" in r.stderr
