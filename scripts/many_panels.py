#!/usr/bin/env python3
"""Many small panels (issue 23): a garment re-cut into about 50 panels, some of 3 to 20 faces,
against the same garment with its own panels, under fixed and free seams.

The re-cut is `quasidev segment GARMENT --keep-patches --target 50 --min-faces 3 --max-error 10`
(each original panel kept or split, never merged across). Every output is measured as in
scripts/tradeoff.py: G_ABD over the whole mesh's interior vertices (seams included) and the
symmetric Hausdorff distance over the bounding-box diagonal. Prints a Markdown table and writes
it to OUT/many_panels.md.

Usage: .venv/bin/python scripts/many_panels.py GARMENT.ply [--target 50] [--out DIR] [--quasidev PATH]
"""
from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import tradeoff  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("garment")
    ap.add_argument("--target", type=int, default=50)
    ap.add_argument("--out", default=os.path.join(ROOT, "docs"))
    ap.add_argument("--quasidev", default=tradeoff.DEFAULT_QUASIDEV)
    args = ap.parse_args()
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        recut, seg_report = os.path.join(tmp, "recut.ply"), os.path.join(tmp, "segment.json")
        subprocess.run([args.quasidev, "segment", args.garment, recut, "--keep-patches", "--target",
                        str(args.target), "--min-faces", "3", "--max-error", "10", "--quiet",
                        "--report", seg_report], check=True)
        sizes = sorted(p["faces"] for p in json.load(open(seg_report, encoding="utf-8"))["patches"])
        for label, mesh in (("its own panels", args.garment), (f"re-cut, {len(sizes)} panels", recut)):
            before = tradeoff.input_figures(mesh)
            for seams in ("fixed", "free"):
                fig = tradeoff.run_ours(args.quasidev, mesh, ["--seams", seams], before, tmp)
                rows.append((label, seams, fig))
    base = {seams: fig["reduction"] for label, seams, fig in rows if label == "its own panels"}
    name = os.path.basename(args.garment)
    lines = [f"Made by `scripts/many_panels.py {name} --target {args.target}`. The re-cut's smallest "
             f"panels: {', '.join(str(n) for n in sizes[:8])} faces.", "",
             "| panels | seams | G_ABD reduction (%) | share of the own panels' reduction | "
             "Hausdorff / diag |", "|---|---|---|---|---|"]
    for label, seams, fig in rows:
        share = 100 * fig["reduction"] / base[seams] if base[seams] > 0 else float("nan")
        lines.append(f"| {label} | {seams} | {fig['reduction']:.1f} | {share:.0f} % | "
                     f"{fig['hausdorff_rel']:.2e} |")
    text = "\n".join(lines) + "\n"
    print(text)
    os.makedirs(args.out, exist_ok=True)
    with open(os.path.join(args.out, "many_panels.md"), "w", encoding="utf-8") as f:
        f.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
