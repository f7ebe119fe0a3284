#!/usr/bin/env python3
"""Segment then approximate, against MeshLab's "Make mesh developable", on closed meshes.

For each mesh runs
  * ours: `quasidev segment IN SEG --max-error-deg E` then `quasidev approximate SEG OUT --seam-mode S`
    for E in {20, 30} degrees and S in {fixed, free} (every other option at its default; the
    pipeline's documented setting is E = 30, S = free), and `quasidev approximate IN OUT` alone
    (the whole mesh one patch) as the baseline;
  * ours with MeshLab's distance as a budget: segment at 30 degrees, then `approximate --seam-mode
    free --tolerance-mode total --tolerance-ae T`, T = the smaller Hausdorff distance of MeshLab's
    two runs in the approximation's average edge lengths (AE), rounded down to three digits. No
    vertex then moves more than T, so the surfaces are at most T apart: a distance no larger
    than MeshLab's (the three passes of free seams share the budget);
  * MeshLab's apply_coord_developability_of_mesh (Stein, Grinspun, Crane 2018) in pymeshlab at
    its defaults (which remesh: edge flips and collapses) and without remeshing
    (edgeflips=False, edgecollapses=False);
and measures every output against the input with scripts/tradeoff.py's functions (those of
scripts/compare_developability.py): G_ABD reduction (%) = 100 (G0 - G1) / G0 with G = sum |K|
over interior vertices, K = angle defect / mixed Voronoi area; Hausdorff / diag = symmetric
Hausdorff distance over the input's bounding-box diagonal; mean distance / diag; max move (AE).
Also gives the segmentation's patch count, patches over the limit and disks, and the time of
each step (the commands' own time_ms; the pymeshlab call).

Usage: .venv/bin/python scripts/segment_pipeline.py [--meshes M ...] [--quasidev PATH] [--json F]
           [--max-errors E ...] [--seams S ...] [--ours-only]
Prints a Markdown table (the one in docs/segment.md). --max-errors and --seams replace the grid
of segmented runs; --ours-only leaves out MeshLab's runs and the budget row (for sweeps).
"""
from __future__ import annotations

import argparse
import json
import math
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mesh_folders import existing  # noqa: E402
from tradeoff import (DEFAULT_QUASIDEV, THEIRS_DEFAULT_EVALS, THEIRS_KEEP_TOPOLOGY,  # noqa: E402
                      input_figures, load_pair, measure, run_meshlab)

DEFAULT_MESHES = existing(["classic_spot_lowres_crane.ply", "piecewise_wingnut_stein2018.ply",
                           "bowl_hemisphere_ipc.ply"], "segment_pipeline.py")
MAX_ERRORS = (20, 30)
SEAMS = ("fixed", "free")
# the pipeline's documented setting (docs/usage.md, sample_meshes/segment_then_approximate.mlx)
PIPELINE_MAX_ERROR = 30


def quasidev(binary: str, *args: str) -> dict:
    """Runs one subcommand with --report; its report, or {"error": its message}."""
    report = args[2] + ".json"
    proc = subprocess.run([binary, *args, "--report", report, "--quiet", "--no-progress"],
                          capture_output=True, text=True, check=False)
    if proc.returncode != 0:
        return {"error": proc.stderr.strip().splitlines()[-1]}
    with open(report) as f:
        return json.load(f)


def run_pipeline(binary: str, path: str, max_error: int | None, seams: str, before: dict, tmp: str,
                 extra: tuple[str, ...] = ()) -> dict:
    """Segment (unless max_error is None) then approximate (with `extra` options), measured
    against the input; also the approximation's average edge length."""
    seg, out = os.path.join(tmp, f"seg{max_error}.ply"), os.path.join(tmp, f"out{max_error}{seams}.ply")
    s = {"time_ms": 0.0}
    if max_error is not None:
        s = quasidev(binary, "segment", path, seg, "--max-error-deg", str(max_error))
        if "error" in s:
            return s
    a = quasidev(binary, "approximate", path if max_error is None else seg, out, "--seam-mode", seams, *extra)
    if "error" in a:
        return a
    fig = measure(load_pair(path, out), before)
    fig.update(time_s=(s["time_ms"] + a["time_ms"]) / 1000.0, average_edge=a["average_edge"])
    if max_error is not None:
        fig.update(patches=s["patch_count"], over=sum(p["over_limit"] for p in s["patches"]),
                   disks=sum(p["disk"] for p in s["patches"]))
    return fig


def round_down(x: float, digits: int = 3) -> str:
    """x rounded down to `digits` significant digits, as text (a budget never above x)."""
    unit = 10.0 ** (math.floor(math.log10(x)) - digits + 1)
    return f"{math.floor(x / unit + 1e-9) * unit:.{digits}g}"


def rows_for(binary: str, path: str, max_errors=MAX_ERRORS, seams_modes=SEAMS, meshlab: bool = True) -> list[dict]:
    name = os.path.splitext(os.path.basename(path))[0]
    before = input_figures(path)
    rows = []
    with tempfile.TemporaryDirectory(prefix="segment-pipeline-") as tmp:
        rows.append({"mesh": name, "run": "ours: approximate alone (one patch)",
                     **run_pipeline(binary, path, None, "fixed", before, tmp)})
        for e in max_errors:
            for seams in seams_modes:
                fig = run_pipeline(binary, path, e, seams, before, tmp)
                rows.append({"mesh": name, "run": f"ours: segment --max-error-deg {e}, approximate --seam-mode {seams}",
                             **fig})
                print(f"{name}: {rows[-1]['run']} done", file=sys.stderr, flush=True)
        if not meshlab:
            return rows
        theirs = []
        for label, kwargs in ((f"MeshLab defaults (remeshing, maxfunevals {THEIRS_DEFAULT_EVALS})", {}),
                              ("MeshLab defaults without remeshing", dict(THEIRS_KEEP_TOPOLOGY))):
            theirs.append({"mesh": name, "run": label, **run_meshlab(path, kwargs, before)})
            print(f"{name}: {label} done", file=sys.stderr, flush=True)
        distances = [r["hausdorff_rel"] for r in theirs if "error" not in r]
        ae = next((r["average_edge"] for r in rows if "average_edge" in r), None)
        if distances and ae:
            budget = round_down(min(distances) * before["diag"] / ae)
            fig = run_pipeline(binary, path, PIPELINE_MAX_ERROR, "free", before, tmp,
                               ("--tolerance-mode", "total", "--tolerance-ae", budget))
            rows.append({"mesh": name, "run": f"ours: segment --max-error-deg {PIPELINE_MAX_ERROR}, approximate "
                         f"--seam-mode free --tolerance-mode total --tolerance-ae {budget} (MeshLab's distance)",
                         **fig})
            print(f"{name}: {rows[-1]['run']} done", file=sys.stderr, flush=True)
    return rows + theirs


def fmt(x, spec: str) -> str:
    return "-" if x is None else format(x, spec)


def table(rows: list[dict]) -> str:
    out = ["| mesh | run | patches (over limit, disks) | G_ABD removed (%) | Hausdorff / diag | "
           "mean dist / diag | max move (AE) | time (s) |", "|" + "---|" * 8]
    for r in rows:
        if "error" in r:
            out.append(f"| {r['mesh']} | {r['run']} | failed: {r['error']} ||||||")
            continue
        patches = f"{r['patches']} ({r['over']}, {r['disks']})" if "patches" in r else "-"
        out.append(f"| {r['mesh']} | {r['run']} | {patches} | {r['reduction']:.1f} | "
                   f"{r['hausdorff_rel']:.3e} | {r['mean_dist_rel']:.2e} | {fmt(r['max_move_ae'], '.2f')} | "
                   f"{r['time_s']:.2f} |")
    return "\n".join(out)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--meshes", nargs="*", default=DEFAULT_MESHES)
    ap.add_argument("--quasidev", default=DEFAULT_QUASIDEV)
    ap.add_argument("--json", help="also write the rows as JSON to this file")
    ap.add_argument("--max-errors", nargs="+", type=int, default=list(MAX_ERRORS),
                    help="segmentation limits (deg) of the grid")
    ap.add_argument("--seams", nargs="+", choices=SEAMS, default=list(SEAMS), help="seam modes of the grid")
    ap.add_argument("--ours-only", action="store_true", help="no MeshLab runs, no budget row")
    args = ap.parse_args()
    rows = [row for path in args.meshes
            for row in rows_for(args.quasidev, path, args.max_errors, args.seams, not args.ours_only)]
    print(table(rows))
    if args.json:
        with open(args.json, "w") as f:
            json.dump(rows, f, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main())
