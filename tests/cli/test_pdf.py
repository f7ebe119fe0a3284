"""End-to-end tests of `quasidev flatten --pdf-file`: the printable pattern's pages have the
paper's size, page 1 holds a test square of 50 mm measured in the PDF itself, the tile pages
draw the pattern at true scale, their count is the fewest pages that cover the pattern with
10 mm overlaps, and without a physical --unit nothing is written.

The PDF is read with PyMuPDF (independent of cairo, which writes it). 1 pt = 1/72 in.
"""
import math
import pathlib
import re
import sys

import numpy as np
import pytest

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from plyfile import PlyData  # noqa: E402
from test_quasidev_cli import BINARY, REPO, assert_clean_failure, run  # noqa: E402
from ply_columns import column  # noqa: E402

pymupdf = pytest.importorskip("pymupdf")
pytestmark = pytest.mark.skipif(not BINARY.exists(), reason=f"{BINARY} not built")

CONE = REPO / "sample_meshes" / "cone_panels.ply"
PT_PER_MM = 72 / 25.4
PAPERS = {"a4": (210 * PT_PER_MM, 297 * PT_PER_MM), "letter": (612.0, 792.0)}
MARGIN = OVERLAP = 10 * PT_PER_MM
CUT_LINE = 0.8  # pt, the width of the cut lines (pdf_writer.cpp)


def scaled(mesh, factor, path):
    """The mesh with every coordinate times factor, as a binary PLY."""
    ply = PlyData.read(mesh)
    for c in "xyz":
        ply["vertex"][c] *= factor
    ply.text, ply.byte_order = False, "<"
    ply.write(path)
    return path


def pattern_size(out_ply):
    """Width and height of the laid-out pattern: the texture coordinates' extent (model units)."""
    uv = np.array(column(PlyData.read(out_ply), "face", "texcoord"), float).reshape(-1, 2)
    return uv.max(axis=0) - uv.min(axis=0)


def pages_along(length, area):
    return max(1, math.ceil((length - OVERLAP) / (area - OVERLAP) - 1e-9))


def print_pdf(tmp_path, mesh, unit, paper, *more):
    out, pdf = tmp_path / "out.ply", tmp_path / "pattern.pdf"
    r = run("flatten", mesh, out, "--unit", unit, "--pdf", pdf, "--paper", paper, *more)
    assert r.returncode == 0, r.stderr
    return out, pymupdf.open(pdf), r.stdout


def squares_near_50_mm(page):
    """The closed rectangles of about 50 mm side drawn on the page."""
    return [d["rect"] for d in page.get_drawings()
            if [item[0] for item in d["items"]] == ["re"] and abs(d["rect"].width - 141.7) < 5]


def cut_line_extent(page):
    """The box of every stroke as wide as the cut lines (the outlines and notches) on a page."""
    rects = [d["rect"] for d in page.get_drawings()
             if d.get("width") and abs(d["width"] - CUT_LINE) < 1e-3]
    assert rects, "no cut lines on the page"
    box = rects[0]
    for r in rects[1:]:
        box |= r
    return box


@pytest.mark.parametrize("paper", ["a4", "letter"])
def test_pages_have_the_paper_size_and_page_one_a_50_mm_test_square(tmp_path, paper):
    _, doc, _ = print_pdf(tmp_path, CONE, "cm", paper)
    width, height = PAPERS[paper]
    for page in doc:
        assert page.rect.width == pytest.approx(width, abs=0.5)
        assert page.rect.height == pytest.approx(height, abs=0.5)
        assert "page" in page.get_text()
    squares = squares_near_50_mm(doc[0])
    assert len(squares) == 1
    assert squares[0].width == pytest.approx(50 * PT_PER_MM, abs=0.5)
    assert squares[0].height == pytest.approx(50 * PT_PER_MM, abs=0.5)
    assert "this square measures 5 cm at 100 %" in doc[0].get_text()


@pytest.mark.parametrize("unit, pt_per_unit", [("cm", 10 * PT_PER_MM), ("in", 72.0)])
def test_a_one_page_pattern_is_drawn_at_true_scale(tmp_path, unit, pt_per_unit):
    """The cone's pattern (a few units across) fits one tile: the extent of its cut lines on that
    page is its size in model units times the unit's length in points (every piece kept apart, so
    the pattern is the texture layout)."""
    out, doc, _ = print_pdf(tmp_path, CONE, unit, "a4", "--symmetry-tolerance", "0")
    assert len(doc) == 2 and "page 2 of 2" in doc[1].get_text()
    box = cut_line_extent(doc[1])
    w, h = pattern_size(out) * pt_per_unit
    assert box.width == pytest.approx(w, abs=0.5)
    assert box.height == pytest.approx(h, abs=0.5)
    assert box.x0 == pytest.approx(MARGIN, abs=0.5)  # the first tile starts at the pattern's corner
    assert box.y0 == pytest.approx(MARGIN, abs=0.5)


@pytest.mark.parametrize("paper", ["a4", "letter"])
def test_a_large_pattern_takes_the_fewest_overlapping_pages_it_reports(tmp_path, paper):
    """The grid is the fewest pages that cover the pattern; the pages no piece reaches are left out
    (the log says how many), every other tile is one page whose name and number the map shows."""
    big = scaled(CONE, 15, tmp_path / "big_cone.ply")  # about 62 x 39 cm in cm
    out, doc, log = print_pdf(tmp_path, big, "cm", paper, "--symmetry-tolerance", "0")
    width, height = PAPERS[paper]
    w, h = pattern_size(out) * 10 * PT_PER_MM
    columns = pages_along(w, width - 2 * MARGIN)
    rows = pages_along(h, height - 2 * MARGIN)
    assert rows * columns > 2
    m = re.search(rf"pdf: (\d+) pages of {paper} \(assembly map \+ (\d+) tiles of a (\d+) x (\d+) "
                  rf"grid, (\d+) empty left out\)", log)
    assert m, log
    pages, tiles, r, c, empty = (int(g) for g in m.groups())
    assert (r, c) == (rows, columns)
    assert tiles + empty == rows * columns and pages == tiles + 1 == len(doc)
    for k, page in enumerate(doc[1:], start=2):
        found = re.search(rf"page {k} of {len(doc)} \(row (\d+), column (\d+)\)", page.get_text())
        assert found, page.get_text()
        row, column = int(found.group(1)) - 1, int(found.group(2)) - 1
        assert f"{'ABCDEFGHIJ'[row]}{column + 1}\np.{k}" in doc[0].get_text()
        inside = [d for d in page.get_drawings() if d["rect"].width < width - 2 * MARGIN - 1
                  and d["rect"].x0 > MARGIN - 1 and d["rect"].y0 > MARGIN - 1]
        assert inside, f"page {k} has nothing of the pattern"


@pytest.mark.parametrize("unit", [[], ["--unit", "model"]])
def test_without_a_physical_unit_it_fails_naming_unit_and_writes_nothing(tmp_path, unit):
    out, pdf = tmp_path / "out.ply", tmp_path / "pattern.pdf"
    r = run("flatten", CONE, out, "--pdf", pdf, *unit)
    assert_clean_failure(r, out, status=2)
    assert "--unit" in r.stderr
    assert not pdf.exists()
