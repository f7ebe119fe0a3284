#!/usr/bin/env python3
"""Render a mesh before and after the filter side by side, both coloured by |K| on ONE scale.

Input:  BEFORE.ply and optionally AFTER.ply (same vertices and faces, e.g. a quasidev output);
        without AFTER.ply, `quasidev BEFORE AFTER [--options ...]` is run into a temporary file.
Output: a PNG: two panels seen through the same camera (scripts/render.py's renderer: numpy
        z-buffer and Pillow, no display needed), coloured by |K| per vertex (angle defect over the
        mixed Voronoi area at interior vertices, as in scripts/compare_developability.py) on a
        shared range 0 .. the BEFORE mesh's 98th percentile (values above are clipped), a colour
        bar with units, and titles giving G_ABD before and after, the reduction, the largest vertex
        move and, when pymeshlab is installed, the symmetric Hausdorff distance over the
        bounding-box diagonal (scripts/demo.sh's venv has no pymeshlab, so its picture has none).
The figure is laid out with matplotlib (Agg backend, headless). Example:
    .venv/bin/python scripts/render_before_after.py sample_meshes/bumpy_cone.ply \\
        -o docs/bumpy_cone_before_after.png
"""
from __future__ import annotations

import argparse
import os
import shlex
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np
from plyfile import PlyData

sys.path.insert(0, str(Path(__file__).resolve().parent))
import render  # noqa: E402
from compare_developability import average_edge, gaussian_curvature  # noqa: E402
from tradeoff import DEFAULT_QUASIDEV, input_figures, load_pair, measure  # noqa: E402

COLORMAP = "YlOrRd"


def abs_curvature(mesh: render.Mesh) -> np.ndarray:
    return np.abs(gaussian_curvature(mesh.v, mesh.f))


def measure_pair(before_path: Path, after_path: Path, meshes: list, k: list) -> tuple[float, dict]:
    """G_ABD before, and after: G_ABD, the reduction (%), the largest move (AE) and, with pymeshlab,
    the Hausdorff distance over the bounding-box diagonal (else None)."""
    try:
        import pymeshlab  # noqa: F401
    except ImportError:
        g0, g1 = float(k[0].sum()), float(k[1].sum())
        ae = average_edge(meshes[0].v, meshes[0].f)
        move = np.linalg.norm(meshes[1].v - meshes[0].v, axis=1).max() / ae
        return g0, {"g_abd": g1, "reduction": 100.0 * (g0 - g1) / g0, "hausdorff_rel": None,
                    "max_move_ae": float(move)}
    before = input_figures(str(before_path))
    return before["g_abd"], measure(load_pair(str(before_path), str(after_path)), before)


def make_figure(before_path: Path, after_path: Path, out: Path, name: str, after_label: str, units: str,
                view, up, percentile: float, panel: tuple[int, int]) -> dict:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib import cm, colors

    meshes = [render.Mesh(PlyData.read(p), p.name) for p in (before_path, after_path)]
    if len(meshes[0].v) != len(meshes[1].v):
        raise SystemExit("render_before_after.py: BEFORE and AFTER have different vertex counts")
    k = [abs_curvature(m) for m in meshes]
    interior = k[0] > 0
    top = float(np.percentile(k[0][interior], percentile)) if interior.any() else 1.0
    norm = colors.Normalize(vmin=0.0, vmax=top, clip=True)
    cmap = matplotlib.colormaps[COLORMAP]
    if panel[1] <= 0:  # auto height: the meshes' projected aspect, within 0.6 .. 1.3 of the width
        basis, _, centre, _ = render.camera(meshes, view, up, (1, 1))
        proj = (np.concatenate([m.v for m in meshes]) - centre) @ basis.T
        aspect = np.ptp(proj[:, 1]) / max(np.ptp(proj[:, 0]), 1e-300)
        panel = (panel[0], int(panel[0] * min(max(aspect, 0.6), 1.3)) + 40)
    basis, scale, centre, (az, el, up) = render.camera(meshes, view, up, panel)
    images = []
    for m, km in zip(meshes, k):
        m.vcolor = cmap(norm(km))[:, :3]
        images.append(np.asarray(render.shade_panel(m, basis, scale, centre, panel, "vertex", None, False)))

    g0, fig_after = measure_pair(before_path, after_path, meshes, k)
    g1 = fig_after["g_abd"]

    dpi = 100
    width = 2 * panel[0] / dpi + 1.2
    fig = plt.figure(figsize=(width, panel[1] / dpi + 1.3), dpi=dpi)
    grid = fig.add_gridspec(1, 3, width_ratios=[panel[0], panel[0], 0.06 * panel[0]], wspace=0.04,
                            left=0.01, right=0.93, top=1 - 0.85 / (panel[1] / dpi + 1.3), bottom=0.03)
    titles = [f"before: G_ABD = {g0:.4g}", f"{after_label}: G_ABD = {g1:.4g}"]
    for j, (img, title) in enumerate(zip(images, titles)):
        ax = fig.add_subplot(grid[0, j])
        ax.imshow(img)
        ax.set_title(title, fontsize=11)
        ax.axis("off")
    cax = fig.add_subplot(grid[0, 2])
    bar = fig.colorbar(cm.ScalarMappable(norm=norm, cmap=cmap), cax=cax, extend="max")
    bar.set_label(f"|K|, Gaussian curvature ({units})\nshared scale: 0 .. {percentile:g}th percentile "
                  "of before", fontsize=9)
    move = fig_after["max_move_ae"]
    hausdorff = fig_after["hausdorff_rel"]
    fig.suptitle(f"{name}: G_ABD reduced by {fig_after['reduction']:.1f} %"
                 + (f", Hausdorff / bbox diagonal {hausdorff:.2e}" if hausdorff is not None else "")
                 + (f", largest vertex move {move:.2f} AE" if move is not None else ""), fontsize=12)
    fig.text(0.01, 0.005, f"same camera (azimuth {az:g}, elevation {el:g}, up {up}); "
             "|K| = angle defect / mixed Voronoi area at interior vertices, 0 on the boundary",
             fontsize=7, color="grey")
    fig.savefig(out, dpi=dpi)
    plt.close(fig)
    return {"g_abd_before": g0, "g_abd_after": g1, "scale_max": top, **fig_after}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("before", type=Path, help="input PLY")
    ap.add_argument("after", type=Path, nargs="?", help="filtered PLY (default: run quasidev on BEFORE)")
    ap.add_argument("-o", "--out", type=Path, required=True, help="output PNG")
    ap.add_argument("--quasidev", default=DEFAULT_QUASIDEV, help="the quasidev command (without AFTER)")
    ap.add_argument("--options", default="", help="quasidev options, one string (default: none)")
    ap.add_argument("--name", help="mesh name in the title (default: BEFORE's file name)")
    ap.add_argument("--after-label", help="title of the right panel (default: 'after quasidev [options]')")
    ap.add_argument("--units", default="1 / model unit²", help="units of |K| for the colour bar, e.g. 'cm⁻²'")
    ap.add_argument("--view", type=render.pair, help="azimuth,elevation in degrees (default: auto)")
    ap.add_argument("--up", choices=sorted(render.AXES), help="world up axis (default: auto)")
    ap.add_argument("--percentile", type=float, default=98.0, help="top of the colour scale (default 98)")
    ap.add_argument("--panel", default="560", help="size of one panel in pixels: W (height from the "
                    "meshes' aspect) or WxH (default 560)")
    args = ap.parse_args()
    panel = tuple(int(s) for s in (args.panel.lower() + "x0").split("x")[:2])
    name = args.name or args.before.stem
    label = args.after_label or ("after quasidev" + (f" {args.options}" if args.options else " (defaults)"))
    with tempfile.TemporaryDirectory(prefix="before-after-") as tmp:
        after = args.after
        if after is None:
            after = Path(tmp) / "after.ply"
            subprocess.run([args.quasidev, str(args.before), str(after), "--quiet", "--no-progress",
                            *shlex.split(args.options)], check=True)
        figures = make_figure(args.before, after, args.out, name, label, args.units, args.view, args.up,
                              args.percentile, panel)
    hausdorff = figures["hausdorff_rel"]
    print(f"{args.out}: G_ABD {figures['g_abd_before']:.4g} -> {figures['g_abd_after']:.4g} "
          f"({figures['reduction']:.1f} %), "
          + (f"Hausdorff/diag {hausdorff:.2e}, " if hausdorff is not None else "")
          + f"largest move {figures['max_move_ae']:.2f} AE, "
          f"|K| scale 0..{figures['scale_max']:.3g}")


if __name__ == "__main__":
    main()
