#!/usr/bin/env python3
"""Trade-off sweep: curvature removed against surface moved, ours vs MeshLab's "Make mesh developable".

For each mesh, sweeps
  * ours, through the `quasidev` command (one process per point). With `--developability` and
    `--defect-weight` in `quasidev --help`: `--defect-weight` (log-spaced) with `--developability
    auto`; `--weight` with `--developability curve` (the paper's method) as a separate series; and
    `--tolerance-ae` with `--tolerance-mode total` and `--developability auto`. Without them: the
    curve method's `--weight`, `--tolerance-ae` (step mode, the default: caps each iteration's move)
    and `--tolerance-ae` with `--tolerance-mode total`. The total mode caps the whole move, so only it
    reaches the small distances where MeshLab's points lie;
    On a mesh with a boundary, also `--free-boundary` with `--tolerance-mode total`: ours keeps the
    open boundary by default, MeshLab's filter moves it, and this series compares like with like;
  * MeshLab's own apply_coord_developability_of_mesh (Stein, Grinspun, Crane 2018) in pymeshlab with
    edgeflips=False, edgecollapses=False (topology kept), over `maxfunevals`;
plus our default run (no options) and MeshLab's defaults without remeshing (maxfunevals 400); and,
as a reference, the input only scaled up about its bounding box's centre: G_ABD, a sum of |K|,
falls as 1/s^2 when a mesh grows by s, with no shape changed, so a point no better than that
scale at its distance has removed no curvature that matters. The verdicts say which are.
Every output is measured here, identically for both, with scripts/compare_developability.py's
functions:
  G_ABD reduction (%) = 100 (G0 - G1) / G0, G = sum |K| over interior vertices, K = angle defect /
    mixed Voronoi area;
  Hausdorff / diag = symmetric Hausdorff distance (max over both directions of pymeshlab's
    get_hausdorff_distance, vertex + face samples) over the input's bounding-box diagonal;
  mean distance / diag = the larger of the two directions' mean distances, over the diagonal;
  max move (AE) = max |v' - v| over the input's average edge length (same vertex order), and
    boundary move (AE) the same over the open boundary's vertices;
  time (s) = the filter's own time: quasidev's report `time_ms` (engine, without file I/O), and
    the pymeshlab filter call. The wall time of the quasidev process is kept in the JSON.
Writes OUT/tradeoff.png (one panel per mesh: reduction against Hausdorff / diag), OUT/tradeoff.md
and OUT/tradeoff.json, prints the table and a one-line verdict per mesh.

Usage: .venv/bin/python scripts/tradeoff.py [--meshes M ...] [--quick] [--quasidev PATH] [--out DIR]
"""
from __future__ import annotations

import argparse
import json
import math
import os
import re
import subprocess
import sys
import tempfile
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from compare_developability import (_FAILED_MESHSETS, average_edge, edge_use,  # noqa: E402
                                    gaussian_curvature, hausdorff_one_way)
from mesh_folders import SAMPLES, existing  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# The 3 garments and the lampshade: tests/data/ or $QD_SHARED_MESHES (scripts/mesh_folders.py);
# those found in neither are skipped with a message.
DEFAULT_MESHES = existing(["garment_shirt_initial_diffavatar.ply", "garment_tee_gcd_0AZKWACRSY.ply",
                           "garment_tee4panel_gpg.ply", "lampshade_frustum_ipc.ply"], "tradeoff.py") + [
    os.path.join(SAMPLES, "bumpy_cone.ply"),
    os.path.join(SAMPLES, "bumpy_cylinder.ply"),
]
DEFAULT_QUASIDEV = os.path.join(ROOT, "build", "bin", "quasidev")
THEIRS = "apply_coord_developability_of_mesh"
THEIRS_KEEP_TOPOLOGY = {"edgeflips": False, "edgecollapses": False}
THEIRS_DEFAULT_EVALS = 400  # pymeshlab 2025.7's default maxfunevals
UNCHANGED = 1e-7  # Hausdorff / diag at or below this: the output is the input (drawn at a floor)

# Sweep values: full, and --quick (2 points a series).
SWEEPS = {
    "defect_weight": ([0.01, 0.03, 0.1, 0.3, 1, 3, 10, 100], [0.3, 10]),
    "weight": ([3, 10, 30, 100, 300], [10, 100]),
    "tolerance": ([0.03, 0.1, 0.2, 0.3, 0.5, 1, 3], [0.3, 3]),
    "maxfunevals": ([100, 300, 1000, 2000, 4000, 8000, 16000], [100, 1000]),
    "scale": ([1.001, 1.003, 1.01, 1.03], [1.003, 1.03]),
}
SCALED = "the input scaled up (no shape change)"
FREE_BOUNDARY = "ours, --free-boundary, total"  # run only on meshes with an open boundary
# series name -> (filter, marker, colour); a series' default point is drawn as a star.
STYLE = {
    "ours, --defect-weight": ("ours", "o", "tab:blue"),
    "ours, curve --weight": ("ours", "s", "tab:green"),
    "ours, --weight": ("ours", "o", "tab:blue"),
    "ours, --tolerance-ae": ("ours", "s", "tab:green"),
    "ours, --tolerance-mode total": ("ours", "D", "tab:purple"),
    FREE_BOUNDARY: ("ours", "v", "tab:orange"),
    "ours, default": ("ours", "*", "tab:blue"),
    "MeshLab, maxfunevals": ("meshlab", "^", "tab:red"),
    "MeshLab, default (no remeshing)": ("meshlab", "*", "tab:red"),
    SCALED: ("scaled", "x", "tab:gray"),
}


# ---- what to run --------------------------------------------------------------------------------

def quasidev_options(quasidev: str) -> set[str]:
    """The long options `quasidev --help` lists, with their other names (`--a,--b`)."""
    out = subprocess.run([quasidev, "--help"], capture_output=True, text=True, check=True).stdout
    return {name for names in re.findall(r"^\s*(--[a-z][a-z,-]*)", out, flags=re.M)
            for name in names.split(",") if name.startswith("--")}


def plan(options: set[str], quick: bool) -> list[tuple[str, str, list[str] | dict]]:
    """(series, setting label, quasidev arguments or MeshLab keyword arguments) per point."""
    pick = {k: v[1] if quick else v[0] for k, v in SWEEPS.items()}
    points: list[tuple[str, str, list[str] | dict]] = [("ours, default", "defaults", [])]
    total = ["--tolerance-mode", "total"]
    if "--developability" in options and "--defect-weight" in options:
        auto = ["--developability", "auto"]
        points += [("ours, --defect-weight", f"auto, defect-weight {w:g}", [*auto, "--defect-weight", f"{w:g}"])
                   for w in pick["defect_weight"]]
        points += [("ours, curve --weight", f"curve, weight {w:g}",
                    ["--developability", "curve", "--weight", f"{w:g}"]) for w in pick["weight"]]
        points += [("ours, --tolerance-mode total", f"auto, total tolerance {t:g} AE",
                    [*auto, *total, "--tolerance-ae", f"{t:g}"]) for t in pick["tolerance"]]
        if "--free-boundary" in options:
            points += [(FREE_BOUNDARY, f"auto, free boundary, total tolerance {t:g} AE",
                        [*auto, "--free-boundary", *total, "--tolerance-ae", f"{t:g}"])
                       for t in pick["tolerance"]]
    else:
        points += [("ours, --weight", f"weight {w:g}", ["--weight", f"{w:g}"]) for w in pick["weight"]]
        points += [("ours, --tolerance-ae", f"tolerance {t:g} AE", ["--tolerance-ae", f"{t:g}"])
                   for t in pick["tolerance"]]
        points += [("ours, --tolerance-mode total", f"total tolerance {t:g} AE",
                    [*total, "--tolerance-ae", f"{t:g}"]) for t in pick["tolerance"]]
    points.append(("MeshLab, default (no remeshing)", f"maxfunevals {THEIRS_DEFAULT_EVALS} (default)",
                   dict(THEIRS_KEEP_TOPOLOGY)))
    points += [("MeshLab, maxfunevals", f"maxfunevals {n}", {"maxfunevals": n, **THEIRS_KEEP_TOPOLOGY})
               for n in pick["maxfunevals"] if n != THEIRS_DEFAULT_EVALS]
    points += [(SCALED, f"scaled by {x:g}", {"scale": x}) for x in pick["scale"]]
    return points


# ---- running and measuring ----------------------------------------------------------------------

def measure(ms, before: dict) -> dict:
    """Figures of mesh 1 of `ms` against the input (mesh 0), whose figures are in `before`."""
    V1, F1 = ms.mesh(1).vertex_matrix(), ms.mesh(1).face_matrix()
    g1 = float(np.abs(gaussian_curvature(V1, F1)).sum())
    samples = 10 * max(before["faces"], len(F1))
    both = [hausdorff_one_way(ms, a, b, samples) for a, b in ((1, 0), (0, 1))]
    fig = {
        "vertices": len(V1), "faces": len(F1),
        "g_abd": g1, "reduction": 100.0 * (before["g_abd"] - g1) / before["g_abd"],
        "hausdorff_rel": max(h["max"] for h in both) / before["diag"],
        "mean_dist_rel": max(h["mean"] for h in both) / before["diag"],
        "max_move_ae": None,
    }
    fig["boundary_move_ae"] = None
    if len(V1) == before["vertices"]:
        move = np.linalg.norm(V1 - before["V"], axis=1) / before["ae"]
        fig["max_move_ae"] = float(move.max())
        if len(before["boundary"]):
            fig["boundary_move_ae"] = float(move[before["boundary"]].max())
    return fig


def boundary_vertices(F: np.ndarray) -> np.ndarray:
    """The vertices on edges that only one face has (the open boundary), sorted."""
    edges, count = edge_use(F)
    return np.unique(edges[count == 1])


def load_pair(input_path: str, output_path: str | None = None):
    """A MeshSet with the input as mesh 0 and the output (or a second copy of the input) as mesh 1."""
    import pymeshlab
    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(input_path)
    ms.load_new_mesh(output_path or input_path)
    return ms


def input_figures(path: str) -> dict:
    ms = load_pair(path)
    V, F = ms.mesh(0).vertex_matrix().copy(), ms.mesh(0).face_matrix()
    return {"V": V, "vertices": len(V), "faces": len(F), "ae": average_edge(V, F),
            "boundary": boundary_vertices(F),
            "diag": float(np.linalg.norm(V.max(axis=0) - V.min(axis=0))),
            "g_abd": float(np.abs(gaussian_curvature(V, F)).sum())}


def run_ours(quasidev: str, path: str, args: list[str], before: dict, tmp: str) -> dict:
    out, report = os.path.join(tmp, "out.ply"), os.path.join(tmp, "report.json")
    cmd = [quasidev, path, out, "--report", report, "--quiet", "--no-progress", *args]
    t0 = time.perf_counter()
    proc = subprocess.run(cmd, capture_output=True, text=True)
    wall = time.perf_counter() - t0
    if proc.returncode != 0:
        return {"error": proc.stderr.strip().splitlines()[-1] if proc.stderr.strip() else f"rc {proc.returncode}"}
    with open(report) as f:
        rep = json.load(f)
    fig = measure(load_pair(path, out), before)
    fig.update(time_s=rep["time_ms"] / 1000.0, wall_s=wall, options=" ".join(args),
               quasidev_abd_reduction=rep.get("abd_reduction"))
    return fig


def run_meshlab(path: str, kwargs: dict, before: dict) -> dict:
    import pymeshlab
    ms = load_pair(path)
    ms.set_current_mesh(1)
    t0 = time.perf_counter()
    try:
        ms.apply_filter(THEIRS, **kwargs)
    except pymeshlab.PyMeshLabException as e:
        _FAILED_MESHSETS.append(ms)  # see compare_developability.py: never destroy it
        return {"error": str(e).split("Details:", 1)[-1].strip()}
    elapsed = time.perf_counter() - t0
    fig = measure(ms, before)
    fig.update(time_s=elapsed, kwargs=kwargs)
    return fig


def run_scaled(path: str, scale: float, before: dict) -> dict:
    """The input scaled by `scale` about its bounding box's centre, measured as an output."""
    import pymeshlab
    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(path)
    V, F = ms.mesh(0).vertex_matrix(), ms.mesh(0).face_matrix()
    centre = (V.max(axis=0) + V.min(axis=0)) / 2
    ms.add_mesh(pymeshlab.Mesh(vertex_matrix=centre + scale * (V - centre), face_matrix=F))
    fig = measure(ms, before)
    fig.update(time_s=0.0, scale=scale)
    return fig


def sweep(paths: list[str], quasidev: str, quick: bool) -> tuple[list[dict], list[str]]:
    options = quasidev_options(quasidev)
    points = plan(options, quick)
    rows = []
    with tempfile.TemporaryDirectory(prefix="tradeoff-") as tmp:
        for path in paths:
            name = os.path.splitext(os.path.basename(path))[0]
            try:
                before = input_figures(path)
            except Exception as e:  # noqa: BLE001 - pymeshlab raises its own type; report and go on
                rows.append({"mesh": name, "filter": "-", "series": "-", "setting": "reading the input",
                             "error": str(e).splitlines()[0]})
                print(f"{name}: cannot read: {rows[-1]['error']}", file=sys.stderr, flush=True)
                continue
            for series, setting, how in points:
                if series == FREE_BOUNDARY and not len(before["boundary"]):
                    continue  # closed: nothing to free
                kind = STYLE[series][0]
                fig = (run_ours(quasidev, path, how, before, tmp) if kind == "ours" else
                       run_scaled(path, how["scale"], before) if kind == "scaled" else
                       run_meshlab(path, how, before))
                row = {"mesh": name, "filter": {"ours": "ours", "meshlab": "MeshLab"}.get(kind, kind),
                       "series": series,
                       "setting": setting, "g_abd_before": before["g_abd"],
                       "vertices_before": before["vertices"], **fig}
                rows.append(row)
                print(f"{name}: {series}: {setting}: " + (f"failed: {row['error']}" if "error" in row else
                      f"{row['reduction']:.1f} %, H/diag {row['hausdorff_rel']:.2e}, {row['time_s']:.2f} s"),
                      file=sys.stderr, flush=True)
    return rows, sorted(options)


# ---- reporting ----------------------------------------------------------------------------------

def fmt(x, spec: str) -> str:
    return "n/a" if x is None else format(x, spec)


def table(rows: list[dict]) -> str:
    out = ["| mesh | filter | setting | G_ABD reduction (%) | Hausdorff / diag | mean distance / diag | "
           "max move (AE) | boundary move (AE) | time (s) |", "|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        if "error" in r:
            out.append(f"| {r['mesh']} | {r['filter']} | {r['setting']} | failed: {r['error']} ||||||")
            continue
        out.append(f"| {r['mesh']} | {r['filter']} | {r['setting']} | {r['reduction']:.1f} | "
                   f"{r['hausdorff_rel']:.2e} | {r['mean_dist_rel']:.2e} | {fmt(r['max_move_ae'], '.2f')} | "
                   f"{fmt(r.get('boundary_move_ae'), '.2f')} | {r['time_s']:.2f} |")
    return "\n".join(out)


def envelope(points: list[dict], h: float) -> float | None:
    """Best reduction among `points` whose Hausdorff / diag is at most h (None: none that close)."""
    ok = [p["reduction"] for p in points if p["hausdorff_rel"] <= h * (1 + 1e-9)]
    return max(ok) if ok else None


def above_below(ours: list[dict], theirs: list[dict]) -> tuple[int, int, list[str]]:
    """At how many of `theirs` the best of `ours` at no larger Hausdorff removes more, and at how
    many less or as much; and per MeshLab point, the two figures."""
    above, below, details = 0, 0, []
    for t in sorted(theirs, key=lambda r: r["hausdorff_rel"]):
        best = envelope(ours, t["hausdorff_rel"])
        above += best is not None and best > t["reduction"]
        below += best is not None and best <= t["reduction"]
        details.append(f"{t['kwargs'].get('maxfunevals', THEIRS_DEFAULT_EVALS)}: "
                       f"{'none' if best is None else f'{best:.0f}'} vs {t['reduction']:.0f}")
    return above, below, details


def scale_reduction(scaled: list[dict], h: float) -> float | None:
    """What scaling the input up removes at Hausdorff / diag h: the distance grows linearly with
    s - 1 (fitted on the scaled points), G_ABD falls as 1/s^2."""
    slopes = [r["hausdorff_rel"] / (r["scale"] - 1) for r in scaled]
    if not slopes:
        return None
    s = 1 + h / float(np.median(slopes))
    return 100.0 * (1 - 1 / s ** 2)


def no_better_than_scale(mesh: str, rows: list[dict]) -> str:
    """Which MeshLab points, and whether our default, remove no more than a scale at their distance."""
    good = [r for r in rows if r["mesh"] == mesh and "error" not in r]
    scaled = [r for r in good if r["filter"] == "scaled"]
    theirs = [r for r in good if r["filter"] == "MeshLab"]
    default = next((r for r in good if r["series"] == "ours, default"), None)
    if not scaled:
        return ""
    flat = [t for t in theirs if t["reduction"] <= scale_reduction(scaled, t["hausdorff_rel"])]
    text = (f"; scaling the input up (no shape change) removes {scale_reduction(scaled, 1e-3):.1f} % "
            f"at H/diag 1e-3: {len(flat)} of {len(theirs)} MeshLab points remove no more than such a "
            "scale at their distance" + (" (" + ", ".join(
                f"{t['kwargs'].get('maxfunevals', THEIRS_DEFAULT_EVALS)}: {t['reduction']:.1f} vs "
                f"{scale_reduction(scaled, t['hausdorff_rel']):.1f}" for t in flat) + ")" if flat else ""))
    if default is not None:
        ref = scale_reduction(scaled, default["hausdorff_rel"])
        text += (f", and our default {'more' if default['reduction'] > ref else 'no more'} "
                 f"({default['reduction']:.1f} vs {ref:.1f})")
    return text


def verdict(mesh: str, rows: list[dict]) -> str:
    good = [r for r in rows if r["mesh"] == mesh and "error" not in r]
    ours = [r for r in good if r["filter"] == "ours" and r["series"] != FREE_BOUNDARY]
    freed = [r for r in good if r["series"] == FREE_BOUNDARY]
    theirs = [r for r in good if r["filter"] == "MeshLab"]
    if not ours or not theirs:
        return f"{mesh}: not enough successful points for a verdict"
    above, below, details = above_below(ours, theirs)
    text = (f"{mesh}: ours above MeshLab at {above}, below at {below}, and no point of ours as close at "
            f"{len(theirs) - above - below} of {len(theirs)} MeshLab points (per maxfunevals, our best "
            f"reduction at no larger Hausdorff vs theirs, %: {'; '.join(details)})")
    if freed:
        moved = max((t.get("boundary_move_ae") or 0.0) for t in theirs)
        above, below, details = above_below(freed, theirs)
        text += (f"; MeshLab's points move the open boundary up to {moved:.2f} AE, which ours keeps: "
                 f"with it free (--free-boundary), ours above at {above} and below at {below} of "
                 f"{len(theirs)} ({'; '.join(details)})")
    default = next((r for r in ours if r["series"] == "ours, default"), None)
    if default is not None:
        h = default["hausdorff_rel"]
        theirs_best = envelope(theirs, h)
        h_max = max(t["hausdorff_rel"] for t in theirs)
        if theirs_best is None:
            where = f"closer than every MeshLab point (their closest: H/diag {min(t['hausdorff_rel'] for t in theirs):.1e})"
        else:
            where = (f"{'above' if default['reduction'] > theirs_best else 'below'} their curve "
                     f"({default['reduction']:.0f} % vs their best {theirs_best:.0f} % at no larger Hausdorff"
                     + (f"; it moves more than any MeshLab point, whose largest H/diag is {h_max:.1e})"
                        if h > h_max else ")"))
        text += f"; our default ({default['reduction']:.0f} %, H/diag {h:.1e}) is {where}"
    return text + no_better_than_scale(mesh, rows)


def plot(rows: list[dict], meshes: list[str], out_png: str) -> None:
    import matplotlib
    matplotlib.use("Agg")  # headless
    import matplotlib.pyplot as plt
    from matplotlib.ticker import LogFormatterSciNotation
    cols = min(3, len(meshes))
    nrows = math.ceil(len(meshes) / cols)
    fig, axes = plt.subplots(nrows, cols, figsize=(max(5.2 * cols, 9.0), 4.2 * nrows + 1.2), squeeze=False)
    for ax, mesh in zip(axes.ravel(), meshes):
        good = [r for r in rows if r["mesh"] == mesh and "error" not in r]
        # Unchanged outputs (distance ~0) are drawn at the panel's floor, so the log axis stays readable.
        moved = [r["hausdorff_rel"] for r in good if r["hausdorff_rel"] > UNCHANGED]
        floor = 0.5 * min(moved) if moved else UNCHANGED
        for series, (_, marker, colour) in STYLE.items():
            pts = [r for r in good if r["series"] == series]  # in sweep order
            if series == "MeshLab, maxfunevals":  # its line passes through the default (400)
                pts = sorted(pts + [r for r in good if r["series"].startswith("MeshLab, default")],
                             key=lambda r: r["kwargs"].get("maxfunevals", THEIRS_DEFAULT_EVALS))
            if not pts:
                continue
            x = [max(r["hausdorff_rel"], floor) for r in pts]
            y = [r["reduction"] for r in pts]
            star = marker == "*"
            ax.plot(x, y, marker=marker, color=colour, linestyle="none" if star else "-",
                    markersize=15 if star else 6, markeredgecolor="black" if star else colour,
                    label=series, zorder=3 if star else 2)
            if not star:  # one label per place: points on top of each other share it
                labels: dict[tuple[float, float], list[str]] = {}
                for r, xi, yi in zip(pts, x, y):
                    if r["series"] == series:
                        labels.setdefault((xi, round(yi, 1)), []).append(
                            re.findall(r"\d+(?:\.\d+)?", r["setting"])[-1])
                for (xi, yi), values in labels.items():
                    text = ", ".join(values) + (" (unchanged)" if xi <= UNCHANGED or xi == floor else "")
                    ax.annotate(text, (xi, yi), fontsize=7, textcoords="offset points", xytext=(4, -9),
                                color=colour)
        ax.set_xscale("log")
        # no minor labels from 0.9 decades up (they overlap there), some below
        ax.xaxis.set_minor_formatter(LogFormatterSciNotation(labelOnlyBase=False, minor_thresholds=(0.9, 0.35)))
        ax.set_title(mesh, fontsize=10)
        ax.set_xlabel("symmetric Hausdorff distance / bbox diagonal")
        ax.set_ylabel("G_ABD reduction (%)")
        ax.axhline(0, color="grey", linewidth=0.5)
        ax.grid(True, which="both", alpha=0.3)
    for ax in axes.ravel()[len(meshes):]:
        ax.axis("off")
    handles, labels = axes.ravel()[0].get_legend_handles_labels()
    seen = dict(zip(labels, handles))
    for ax in axes.ravel()[1:len(meshes)]:
        for h, lab in zip(*ax.get_legend_handles_labels()):
            seen.setdefault(lab, h)
    fig.legend(seen.values(), seen.keys(), loc="lower center", ncol=min(len(seen), 3 if cols > 1 else 2),
               fontsize=9, frameon=False)
    fig.suptitle("Curvature removed vs surface moved: ours (quasidev) and MeshLab's\n"
                 "Make mesh developable (no remeshing). Point labels: the swept value (weight, defect weight,\n"
                 "tolerance in AE, or maxfunevals); stars: each filter's defaults", fontsize=10)
    legend_rows = math.ceil(len(seen) / (3 if cols > 1 else 2))
    bottom = (0.25 + 0.22 * legend_rows) / fig.get_figheight()
    fig.tight_layout(rect=(0, bottom, 1, 1))  # leaves room for the suptitle itself
    fig.savefig(out_png, dpi=110)
    plt.close(fig)


def resolve_mesh(name: str) -> str:
    """A path, or a name (with or without .ply) in the default mesh list."""
    if os.path.isfile(name):
        return name
    for p in DEFAULT_MESHES:
        stem = os.path.splitext(os.path.basename(p))[0]
        if name in (stem, stem + ".ply") or stem.endswith("_" + name) or stem.startswith(name):
            return p
    raise SystemExit(f"tradeoff.py: no mesh '{name}' (give a path or one of: "
                     + ", ".join(os.path.basename(p) for p in DEFAULT_MESHES) + ")")


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--meshes", nargs="+", default=DEFAULT_MESHES,
                    help="PLY paths or names from the default list (default: the 3 garments, "
                         "the lampshade, bumpy_cone and bumpy_cylinder)")
    ap.add_argument("--quick", action="store_true", help="2 points per series")
    ap.add_argument("--quasidev", default=DEFAULT_QUASIDEV, help="the quasidev command")
    ap.add_argument("--out", default=os.path.join(ROOT, "docs"), help="output folder")
    args = ap.parse_args()
    if not os.access(args.quasidev, os.X_OK):
        print(f"tradeoff.py: quasidev not found: {args.quasidev} (build it)", file=sys.stderr)
        return 2
    paths = [resolve_mesh(m) for m in args.meshes]
    os.makedirs(args.out, exist_ok=True)
    rows, options = sweep(paths, args.quasidev, args.quick)
    meshes = list(dict.fromkeys(r["mesh"] for r in rows))
    verdicts = [verdict(m, rows) for m in meshes]
    tab = table(rows)
    plot(rows, meshes, os.path.join(args.out, "tradeoff.png"))
    version = subprocess.run([args.quasidev, "--version"], capture_output=True, text=True).stdout.strip()
    commit = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"], capture_output=True,
                            text=True).stdout.strip()
    if commit and subprocess.run(["git", "-C", ROOT, "diff", "--quiet", "HEAD", "--", "filter_quasidev"]).returncode:
        commit += " with uncommitted engine changes"
    mode = ("--developability auto with --defect-weight, --developability curve with --weight, and "
            "--developability auto with --tolerance-mode total and --tolerance-ae"
            if "--defect-weight" in options else "the curve method's --weight, --tolerance-ae, and --tolerance-ae with --tolerance-mode total")
    with open(os.path.join(args.out, "tradeoff.md"), "w") as f:
        f.write("# Trade-off: curvature removed against surface moved\n\n"
                f"Made by `scripts/tradeoff.py{' --quick' if args.quick else ''}` "
                f"({time.strftime('%Y-%m-%d')}, {version or 'quasidev'} built from the tree at {commit or '?'}); figure: [tradeoff.png](tradeoff.png), data: "
                "[tradeoff.json](tradeoff.json). Ours is the `quasidev` command, sweeping " + mode +
                "; MeshLab's is `apply_coord_developability_of_mesh` with edgeflips and edgecollapses "
                "off (topology kept), sweeping maxfunevals. Measured identically for both: G_ABD = "
                "sum of |K| (angle defect / mixed Voronoi area) over interior vertices; Hausdorff = "
                "symmetric, over the input's bounding-box diagonal; mean distance = the larger of the "
                "two directions' means; max move = max |v' - v| in the input's average edge length "
                "(AE); time = the filter alone (quasidev's engine time, the pymeshlab call). The grey "
                "series is a reference: the input only scaled up about its bounding box's centre, "
                "which changes no shape but lowers G_ABD as 1/s²; the verdicts say which points remove "
                "no more than that.\n\n")
        f.write(tab + "\n\n## Verdicts\n\n" + "\n".join(f"- {v}" for v in verdicts) + "\n")
    with open(os.path.join(args.out, "tradeoff.json"), "w") as f:
        json.dump({"quick": args.quick, "quasidev": os.path.relpath(args.quasidev, ROOT), "quasidev_version": version,
                   "commit": commit, "quasidev_options": options,
                   "meshes": [os.path.basename(p) for p in paths], "rows": rows, "verdicts": verdicts}, f, indent=1)
    print(tab)
    print()
    print("\n".join(verdicts))
    return 0


if __name__ == "__main__":
    sys.exit(main())
