#!/usr/bin/env python3
"""From a draped garment to a marker a cutting room can use: the figures of
docs/tutorials/cutting-room.md, the README's pattern picture, and the marker table docs/marker.md.

1. On the GCD tee (an OBJ with named panels, in cm): `quasidev approximate`, then `quasidev
   flatten --unit cm --seam-allowance 1 --grain-direction longest` (its sleeves are held out
   sideways, so their grain runs along their longest axis, not up) with every pattern file (SVG, AAMA DXF, printable PDF,
   marker SVG on 150 cm fabric); renders docs/garment_pattern.png (the 3D garment beside its
   pattern), docs/tutorials/cutting_room_marker.png and docs/tutorials/cutting_room_pdf.png (the
   PDF's assembly map and one tile page), and writes the commands' logs to docs/marker.json.
2. The marker table: every shared garment, approximated, flattened with a 1 cm allowance and
   nested on fabric 110 and 150 cm wide; the nested marker (libnest2d) against the row-by-row
   placement, from the JSON report.

Usage: QD_SHARED_MESHES=../shared/meshes .venv/bin/python scripts/cutting_room.py [--out DIR]
       [--tutorial-mesh OBJ] [--garments NAME ...]
"""
from __future__ import annotations

import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

from PIL import Image

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from flatten_compare import picture  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent
TUTORIAL_MESH = "garment_tee_gcd_0AZKWACRSY"  # obj/<name>.obj: named panels, cm
GARMENTS = ["garment_shirt_initial_diffavatar", "garment_tee4panel_gpg", "garment_tee_gcd_0AZKWACRSY"]
WIDTHS = [110, 150]  # cm: the common fabric widths
ALLOWANCE = 1  # cm


def run(*args) -> str:
    r = subprocess.run([str(a) for a in args], capture_output=True, text=True, timeout=3600)
    if r.returncode != 0:
        raise SystemExit(f"{' '.join(map(str, args))} failed:\n{r.stderr}")
    return r.stdout


def command(args) -> str:
    """The command as the docs show it (paths relative to a working folder)."""
    return "quasidev " + " ".join(Path(a).name if isinstance(a, Path) else str(a) for a in args)


def svg_png(svg: Path, png: Path, width: int) -> None:
    subprocess.run(["rsvg-convert", "-w", str(width), "-b", "white", "-o", str(png), str(svg)], check=True)


def pdf_png(pdf: Path, out: Path, pages: list[int]) -> None:
    """The PDF's pages side by side, each with a thin frame, at 60 dpi."""
    import pymupdf
    doc = pymupdf.open(pdf)
    images = []
    for k in pages:
        pix = doc[k].get_pixmap(dpi=60)
        images.append(Image.frombytes("RGB", (pix.width, pix.height), pix.samples))
    gap = 20
    canvas = Image.new("RGB", (sum(i.width for i in images) + gap * (len(images) + 1),
                               max(i.height for i in images) + 2 * gap), (230, 230, 230))
    x = gap
    for image in images:
        canvas.paste(image, (x, gap))
        x += image.width + gap
    canvas.save(out)


def tutorial(quasidev: Path, obj: Path, work: Path, out: Path) -> dict:
    """The tutorial's commands on the garment `obj`; returns their logs and reports."""
    dev, flat = work / "tee_dev.ply", work / "tee_flat.ply"
    files = {k: work / f"tee_{k}" for k in ("pattern.svg", "pattern.dxf", "pattern.pdf", "marker.svg",
                                             "marker.dxf", "flat.json")}
    approximate = [quasidev, "approximate", obj, dev]
    flatten = [quasidev, "flatten", dev, flat, "--unit", "cm", "--seam-allowance", ALLOWANCE,
               "--grain-direction", "longest",
               "--svg-file", files["pattern.svg"], "--dxf-file", files["pattern.dxf"], "--dxf-style", "aama",
               "--pdf-file", files["pattern.pdf"], "--paper", "a4",
               "--marker-width", 150, "--marker-svg-file", files["marker.svg"],
               "--marker-dxf-file", files["marker.dxf"], "--report", files["flat.json"]]
    logs = {"approximate": {"command": command(approximate[1:]), "log": run(*approximate)},
            "flatten": {"command": command(flatten[1:]), "log": run(*flatten)}}
    picture(dev, files["pattern.svg"], out / "garment_pattern.png",
            caption="quasidev flatten --svg: cut and sew lines, grainlines, labels, notches")
    svg_png(files["marker.svg"], out / "tutorials" / "cutting_room_marker.png", 1100)
    import pymupdf
    pages = len(pymupdf.open(files["pattern.pdf"]))
    pdf_png(files["pattern.pdf"], out / "tutorials" / "cutting_room_pdf.png", [0, min(3, pages - 1)])
    report = json.loads(files["flat.json"].read_text())
    logs["flatten"]["pattern"] = report["pattern"]
    logs["flatten"]["marker"] = report["marker"]
    return logs


def marker_rows(quasidev: Path, meshes: Path, garments: list[str], work: Path) -> list[dict]:
    rows = []
    for name in garments:
        dev = work / f"{name}.dev.ply"
        run(quasidev, "approximate", meshes / f"{name}.ply", dev, "--quiet")
        for width in WIDTHS:
            report = work / f"{name}.{width}.json"
            run(quasidev, "flatten", dev, work / f"{name}.flat.ply", "--unit", "cm", "--seam-allowance", ALLOWANCE,
                "--marker-width", width, "--report", report, "--quiet")
            r = json.loads(report.read_text())
            m = r["marker"]
            rows.append({"garment": name, "width": width, "pieces": m["placed"], "unplaced": m["unplaced"],
                         "pattern_pieces": len(r["pattern"]),
                         "nested": {k: m["nested"][k] for k in ("length", "efficiency", "placed")},
                         "rows": {k: m["rows"][k] for k in ("length", "efficiency", "placed")},
                         "kept": m["method"]})
    return rows


def table(rows: list[dict]) -> str:
    out = ["# Marker efficiency", "",
           "Each shared garment approximated (`quasidev approximate`), then flattened with a 1 cm seam "
           "allowance and nested on fabric 110 and 150 cm wide (`quasidev flatten --unit cm "
           "--seam-allowance 1 --marker-width W --report r.json`): the nested marker (libnest2d, real "
           "cut lines, grain along the length) against the simple row-by-row placement of the same "
           "pieces by their boxes. Efficiency = cut area of the pieces / (width × length). The command "
           "keeps the shorter (the last column). Made by `QD_SHARED_MESHES=../shared/meshes "
           ".venv/bin/python scripts/cutting_room.py`.", "",
           "| garment | width (cm) | pieces cut (pattern pieces) | nested: length (cm), efficiency | "
           "rows: length (cm), efficiency | kept |",
           "|---|---|---|---|---|---|"]
    for r in rows:
        def cell(m):
            return f"{m['length']:.1f}, {100 * m['efficiency']:.1f} %" + (
                f" ({m['placed']} placed)" if m["placed"] != r["pieces"] else "")
        unplaced = f"; wider than the fabric: {', '.join(r['unplaced'])}" if r["unplaced"] else ""
        out.append(f"| {r['garment']} | {r['width']} | {r['pieces']} ({r['pattern_pieces']}){unplaced} | "
                   f"{cell(r['nested'])} | {cell(r['rows'])} | {r['kept']} |")
    return "\n".join(out) + "\n"


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quasidev", type=Path, default=ROOT / "build" / "bin" / "quasidev")
    ap.add_argument("--meshes", type=Path, default=Path(os.environ.get("QD_SHARED_MESHES", "")),
                    help="the shared meshes' folder (default: $QD_SHARED_MESHES)")
    ap.add_argument("--out", type=Path, default=ROOT / "docs")
    ap.add_argument("--tutorial-mesh", type=Path,
                    help=f"the tutorial's garment (default: MESHES/obj/{TUTORIAL_MESH}.obj)")
    ap.add_argument("--garments", nargs="*", default=GARMENTS, help="the marker table's garments (MESHES/NAME.ply)")
    args = ap.parse_args()
    obj = args.tutorial_mesh or args.meshes / "obj" / f"{TUTORIAL_MESH}.obj"
    missing = [p for p in [obj, *(args.meshes / f"{g}.ply" for g in args.garments)] if not p.exists()]
    if missing:
        raise SystemExit(f"missing {', '.join(map(str, missing))}: set QD_SHARED_MESHES or pass --meshes")
    if not shutil.which("rsvg-convert"):
        raise SystemExit("rsvg-convert missing (Debian package librsvg2-bin; scripts/setup.sh installs it)")
    with tempfile.TemporaryDirectory() as tmp:
        work = Path(tmp)
        (args.out / "tutorials").mkdir(parents=True, exist_ok=True)
        logs = tutorial(args.quasidev, obj, work, args.out)
        rows = marker_rows(args.quasidev, args.meshes, args.garments, work)
    (args.out / "marker.md").write_text(table(rows))
    (args.out / "marker.json").write_text(json.dumps({"tutorial": logs, "markers": rows}, indent=1) + "\n")
    print(table(rows))


if __name__ == "__main__":
    main()
