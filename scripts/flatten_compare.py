#!/usr/bin/env python3
"""How good are our pattern pieces? `quasidev flatten` against MeshLab's own parametrizations,
before and after making the patches developable, and against real sewing patterns.

Every figure is measured here, identically for every method, with scripts/flat_measures.py: per
face the singular values σ1 ≥ σ2 of the 3D→2D map, length distortion max(σ1 − 1, 1 − σ2); per
piece and per mesh the largest value and the area-weighted mean, in percent.

1. Ours against MeshLab (pymeshlab 2025.7.post1: compute_texcoord_parametrization_least_squares_
   conformal_maps and ..._harmonic, libigl's LSCM with two boundary vertices pinned at (0,0) and
   (1,0), and the harmonic map with the boundary on the unit circle) on the same pieces: each patch
   of the input as `quasidev flatten` cut it (a tube cut once, each edge-connected part its own
   piece), handed to MeshLab as a mesh of its own. MeshLab's maps are conformal or harmonic, not
   length-preserving, and their scale is arbitrary, so they are measured as they come AND after
   the uniform scale that is best for them (s = 2 / (max σ1 + min σ2), which minimises the
   largest distortion); ours is measured as it comes only (in model units, 1 unit = 1 unit).
2. Ours before and after making the patches developable: the input, the output of
   `quasidev approximate` (defaults), and the output of MeshLab's "Make mesh developable"
   (apply_coord_developability_of_mesh, 2000 evaluations, no edge flips or collapses so the
   patches survive), each flattened by `quasidev flatten`.
3. Meshes whose texture coordinates are a known pattern (the tees' real sewing patterns in cm,
   the crumpled crane's exact development): the mesh is first
   cut along that pattern's seams, so each of our pieces is cut like the pattern piece, then
   flattened (input and after `quasidev approximate`); per panel the RMS and the largest distance
   of corresponding corners after the best rigid motion (rotation + translation, no scale; a
   pattern piece drawn mirrored is matched mirrored), over the pattern piece's bounding-box diagonal.

Writes OUT/flatten.md (the tables) and OUT/flatten.json, and with --picture a PNG of a garment
after `quasidev approximate` (patch colours) beside its SVG pattern from `quasidev flatten`
(rendered by rsvg-convert, pieces filled in the same colours).

Usage: .venv/bin/python scripts/flatten_compare.py [--quasidev PATH] [--meshes DIR] [--out DIR]
       [--picture PNG] [--only NAME ...]
"""
from __future__ import annotations

import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
from PIL import Image, ImageDraw
from plyfile import PlyData

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import flat_measures as fm  # noqa: E402
import render  # noqa: E402
import ply_columns as pc  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent
LSCM = "compute_texcoord_parametrization_least_squares_conformal_maps"
HARMONIC = "compute_texcoord_parametrization_harmonic"
MAKE_DEVELOPABLE = "apply_coord_developability_of_mesh"
MAKE_DEVELOPABLE_ARGS = {"maxfunevals": 2000, "edgeflips": False, "edgecollapses": False}
GARMENTS = ["garment_shirt_initial_diffavatar", "garment_tee4panel_gpg", "garment_tee_gcd_0AZKWACRSY"]
# mesh -> whether it is approximated first (the crane is developable already)
MESHES = {**{g: True for g in GARMENTS}, "lampshade_frustum_ipc": True, "developable_crumpled_crane": False}
# texcoord = the real sewing pattern in cm (the tees) or the exact development (the crane)
PATTERNS = ["garment_tee4panel_gpg", "garment_tee_gcd_0AZKWACRSY", "developable_crumpled_crane"]
PICTURE_MESH = "garment_shirt_initial_diffavatar"


class Job:
    """A mesh file as the tables see it: positions, faces, patch id per face."""

    def __init__(self, path: Path):
        ply = PlyData.read(path)
        self.path = path
        self.ply = ply
        self.V = pc.positions(ply)
        self.F = np.asarray(pc.faces(ply), np.int64)
        for name in ("quality", "patch"):
            if pc.has(ply, "face", name):
                self.patch = np.rint(np.asarray(pc.column(ply, "face", name), float)).astype(np.int64)
                break
        else:
            self.patch = np.zeros(len(self.F), np.int64)


def run(*args) -> None:
    r = subprocess.run([str(a) for a in args], capture_output=True, text=True, timeout=3600)
    if r.returncode != 0:
        raise SystemExit(f"{' '.join(map(str, args))} failed:\n{r.stderr}")


def flatten(quasidev: Path, mesh: Path, work: Path, name: str) -> tuple[np.ndarray, dict, Path]:
    """(wedge UV, report, SVG path) of `quasidev flatten` on mesh."""
    out, report, svg = work / f"{name}.flat.ply", work / f"{name}.flat.json", work / f"{name}.svg"
    run(quasidev, "flatten", mesh, out, "--report", report, "--svg-file", svg, "--quiet")
    uv = np.asarray(pc.column(PlyData.read(out), "face", "texcoord"), float)
    return uv, json.loads(report.read_text()), svg


def approximate(quasidev: Path, mesh: Path, work: Path, name: str) -> tuple[Path, dict]:
    out, report = work / f"{name}.approx.ply", work / f"{name}.approx.json"
    run(quasidev, "approximate", mesh, out, "--report", report, "--quiet")
    return out, json.loads(report.read_text())


def make_developable(pymeshlab, mesh: Path, work: Path, name: str) -> Path:
    """MeshLab's Make mesh developable (topology kept), saved with its face quality (patch ids)."""
    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(str(mesh))
    ms.apply_filter(MAKE_DEVELOPABLE, **MAKE_DEVELOPABLE_ARGS)
    out = work / f"{name}.meshlab_dev.ply"
    ms.save_current_mesh(str(out), save_face_quality=True, binary=True)
    return out


def pieces(job: Job, uv: np.ndarray) -> list[tuple[int, np.ndarray, np.ndarray, np.ndarray]]:
    """Our pieces: (patch, 3D positions, faces, our per-vertex UV) of each edge-connected part of
    the mesh cut along our pattern's outlines."""
    vertex_of, F = fm.split_by_uv(job.F, uv)
    out = []
    for faces in fm.components(F):
        used, local = np.unique(F[faces], return_inverse=True)
        Fp = local.reshape(-1, 3)
        UVp = np.zeros((len(used), 2))
        UVp[Fp.reshape(-1)] = uv[faces].reshape(-1, 2)
        out.append((int(job.patch[faces[0]]), job.V[vertex_of[used]], Fp, UVp))
    return sorted(out, key=lambda p: (p[0], -len(p[2])))


def meshlab_uv(pymeshlab, V: np.ndarray, F: np.ndarray, filter_name: str) -> np.ndarray | None:
    """Per-vertex UV of one of MeshLab's parametrizations of a piece, None if it refuses."""
    ms = pymeshlab.MeshSet()
    ms.add_mesh(pymeshlab.Mesh(vertex_matrix=V, face_matrix=F.astype(np.int32)))
    try:
        ms.apply_filter(filter_name)
    except pymeshlab.PyMeshLabException:
        _KEEP.append(ms)   # pymeshlab corrupts the heap deleting a MeshSet whose filter raised
        return None
    return ms.current_mesh().vertex_tex_coord_matrix().copy()


_KEEP: list = []


def measured(V: np.ndarray, F: np.ndarray, uv_per_vertex: np.ndarray | None, scaled: bool) -> dict | None:
    if uv_per_vertex is None or not np.isfinite(uv_per_vertex).all():
        return None
    UV = fm.wedge_uv(uv_per_vertex, F)
    scale = fm.best_scale(V, F, UV) if scaled else 1.0
    summary = fm.distortion_summary(V, F, UV, scale)
    _, area = fm._frames(V, F)
    return {**summary, "area": float(area.sum()), "scale": scale}


def combined(rows: list[dict | None]) -> dict | None:
    """Largest and area-weighted mean over pieces (None if any piece has no figure)."""
    if not rows or any(r is None for r in rows):
        return None
    area = sum(r["area"] for r in rows)
    return {"max": max(r["max"] for r in rows), "mean": sum(r["mean"] * r["area"] for r in rows) / area,
            "flipped": sum(r["flipped"] for r in rows), "area": area}


def against_meshlab(pymeshlab, job: Job, uv: np.ndarray) -> list[dict]:
    rows = []
    for patch, V, F, ours in pieces(job, uv):
        lscm, harmonic = meshlab_uv(pymeshlab, V, F, LSCM), meshlab_uv(pymeshlab, V, F, HARMONIC)
        rows.append({"patch": patch, "faces": len(F), "ours": measured(V, F, ours, False),
                     "lscm": measured(V, F, lscm, False), "lscm_scaled": measured(V, F, lscm, True),
                     "harmonic": measured(V, F, harmonic, False),
                     "harmonic_scaled": measured(V, F, harmonic, True)})
    return rows


def cut_like_pattern(job: Job, positions: np.ndarray, work: Path, name: str) -> Path:
    """The mesh (with `positions`) cut along the seams of its texture coordinates, as a PLY."""
    pattern = np.asarray(pc.column(job.ply, "face", "texcoord"), float)
    vertex_of, F = fm.split_by_uv(job.F, pattern)
    V = positions[vertex_of]
    ply = PlyData([pc.element("vertex", [(c, "f8", V[:, k]) for k, c in enumerate("xyz")]),
                   pc.element("face", [("vertex_indices", ("u1", "i4"), F), ("quality", "f4", job.patch)])],
                  comments=["cut along its sewing pattern by flatten_compare.py"])
    out = work / f"{name}.cut.ply"
    ply.write(out)
    return out


def against_pattern(job: Job, uv: np.ndarray) -> list[dict]:
    """Per panel: our piece (cut like the pattern) against the pattern piece, rigidly aligned."""
    pattern = np.asarray(pc.column(job.ply, "face", "texcoord"), float)
    rows = []
    for patch in np.unique(job.patch):
        faces = job.patch == patch
        ours, theirs = uv[faces], pattern[faces]
        mirrored = fm.signed_area(ours) * fm.signed_area(theirs) < 0
        target = theirs.reshape(-1, 2) * ([-1.0, 1.0] if mirrored else [1.0, 1.0])
        rms, largest = fm.rigid_distance(ours.reshape(-1, 2), target)
        rows.append({"patch": int(patch), "faces": int(faces.sum()), "rms": rms, "max": largest,
                     "mirrored": bool(mirrored),
                     "area_ratio": abs(fm.signed_area(ours) / fm.signed_area(theirs))})
    return rows


def pct(x: float | None) -> str:
    """A fraction in percent, 3 significant digits."""
    return "n/a" if x is None else f"{100 * x:.3g}"


def pair(r: dict | None) -> str:
    return "failed" if r is None else f"{pct(r['max'])} / {pct(r['mean'])}"


def tables(data: dict) -> str:
    out = ["# Flattening: measured", "",
           "Made by `scripts/flatten_compare.py` (see its docstring for every definition). Length "
           "distortion per face = max(σ1 − 1, 1 − σ2) of the 3D→2D map; cells are *largest / "
           "area-weighted mean*, in percent (3 significant digits), over the pieces named.", "",
           "## Ours against MeshLab's parametrizations, on the same pieces", "",
           "Ours as it comes (model units). MeshLab's LSCM and harmonic maps have an arbitrary "
           "scale: *as is* is their output unchanged, *best scale* after the uniform scale that "
           "minimises their largest distortion.", "",
           "| mesh | pieces | faces | ours | LSCM as is | LSCM best scale | harmonic as is | harmonic best scale |",
           "|---|---|---|---|---|---|---|---|"]
    for name, rows in data["meshlab"].items():
        cells = [pair(combined([r[k] for r in rows])) for k in
                 ("ours", "lscm", "lscm_scaled", "harmonic", "harmonic_scaled")]
        out.append(f"| {name} | {len(rows)} | {sum(r['faces'] for r in rows)} | " + " | ".join(cells) + " |")
    out += ["", "Per piece:", "",
            "| mesh | patch | faces | ours | LSCM best scale | harmonic best scale | flipped: ours / LSCM / harmonic |",
            "|---|---|---|---|---|---|---|"]
    for name, rows in data["meshlab"].items():
        for r in rows:
            flips = " / ".join("n/a" if r[k] is None else str(r[k]["flipped"])
                               for k in ("ours", "lscm", "harmonic"))
            out.append(f"| {name} | {r['patch']} | {r['faces']} | {pair(r['ours'])} | "
                       f"{pair(r['lscm_scaled'])} | {pair(r['harmonic_scaled'])} | {flips} |")
    out += ["", "## Ours before and after making the patches developable", "",
            "`quasidev flatten` on the input, on the output of `quasidev approximate` (defaults), "
            "and on the output of MeshLab's *Make mesh developable* (2000 evaluations, no "
            "remeshing); in brackets the approximation's G_ABD reduction.", "",
            "| mesh | input | after `quasidev approximate` | after MeshLab's Make developable |",
            "|---|---|---|---|"]
    for name, stages in data["stages"].items():
        approx = stages.get("approximated")
        dev = stages.get("make_developable")
        out.append(f"| {name} | {pair(stages['input'])} | "
                   + (f"{pair(approx)} (−{approx['abd_reduction']:.1f} %)" if approx else "—") + " | "
                   + (pair(dev) if dev else "—") + " |")
    if data["patterns"]:
        out += ["", "## Against a known pattern", "",
                "The tees' texture coordinates are their real sewing patterns (cm), the crane's its "
                "exact development. Each panel cut like its pattern piece, flattened, rigidly aligned "
                "to it; distance of "
                "corresponding corners over the pattern piece's diagonal, *RMS / largest* in percent; "
                "area = our piece's area over the pattern piece's.", "",
                "| mesh | panel | faces | input: distance | input: area | after `quasidev approximate`: distance | area |",
                "|---|---|---|---|---|---|---|"]
        for name, stages in data["patterns"].items():
            for k, before in enumerate(stages["input"]):
                after = stages["approximated"][k] if "approximated" in stages else None
                mirrored = " (pattern mirrored)" if before["mirrored"] else ""
                out.append(f"| {name} | {before['patch']}{mirrored} | {before['faces']} | "
                           f"{pct(before['rms'])} / {pct(before['max'])} | {before['area_ratio']:.4f} | "
                           + (f"{pct(after['rms'])} / {pct(after['max'])} | {after['area_ratio']:.4f} |"
                              if after else "— | — |"))
    return "\n".join(out) + "\n"


def picture(mesh: Path, svg: Path, out: Path, size: tuple[int, int] = (1200, 560),
            caption: str = "quasidev flatten --svg: pieces at true scale, notches, scale bar") -> None:
    """The 3D mesh in patch colours beside its SVG pattern, pieces filled in the same colours."""
    if not shutil.which("rsvg-convert"):
        raise SystemExit("rsvg-convert missing (Debian package librsvg2-bin; scripts/setup.sh installs it)")
    m = render.Mesh(PlyData.read(mesh), mesh.name)
    ids = np.unique(m.patch)
    panel = (size[0] // 2, size[1] - 40)
    basis, scale, centre, _ = render.camera([m], None, None, panel)
    left = render.shade_panel(m, basis, scale, centre, panel, "patch", (0.0, 1.0), False)
    ns = "http://www.w3.org/2000/svg"
    ET.register_namespace("", ns)
    tree = ET.parse(svg)
    for g in tree.getroot().iter(f"{{{ns}}}g"):
        label = g.get("id", "")
        if label.startswith("piece-"):
            patch = float(label.removeprefix("piece-").split(".")[0])
            rgb = render.PATCH_PALETTE[int(np.searchsorted(ids, patch)) % len(render.PATCH_PALETTE)]
            g.find(f"{{{ns}}}path").set("fill", "rgb({},{},{})".format(*(int(255 * c) for c in rgb)))
    with tempfile.TemporaryDirectory() as d:
        filled, png = Path(d) / "filled.svg", Path(d) / "pattern.png"
        tree.write(filled, xml_declaration=True, encoding="UTF-8")
        subprocess.run(["rsvg-convert", "-w", str(panel[0] - 20), "-b", "white", "-o", str(png), str(filled)],
                       check=True)
        right = Image.open(png).convert("RGB")
        right.thumbnail((panel[0] - 20, panel[1]))
        canvas = Image.new("RGB", size, (255, 255, 255))
        canvas.paste(left, (0, 30))
        canvas.paste(right, (panel[0] + 10, 30 + (panel[1] - right.height) // 2))
    draw = ImageDraw.Draw(canvas)
    for x, text in ((panel[0] / 2, "3D, after quasidev approximate (colour = patch)"),
                    (panel[0] * 1.5, caption)):
        draw.text((x, 15), text, fill=(0, 0, 0), font=render.font(16), anchor="mm")
    canvas.save(out)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quasidev", type=Path, default=ROOT / "build" / "bin" / "quasidev")
    ap.add_argument("--meshes", type=Path, default=Path(os.environ.get("QD_SHARED_MESHES", ROOT / "tests" / "data")),
                    help="the folder of the meshes (default: $QD_SHARED_MESHES, else tests/data/)")
    ap.add_argument("--out", type=Path, default=ROOT / "docs")
    ap.add_argument("--picture", type=Path, help="write the garment picture here (PNG)")
    ap.add_argument("--only", nargs="*", help="mesh names (without .ply) to measure (default: all)")
    args = ap.parse_args()
    import pymeshlab
    names = [n for n in MESHES if not args.only or n in args.only]
    data: dict = {"meshlab": {}, "stages": {}, "patterns": {}}
    with tempfile.TemporaryDirectory() as tmp:
        work = Path(tmp)
        for name in names:
            path = args.meshes / f"{name}.ply"
            job = Job(path)
            uv, report, svg = flatten(args.quasidev, path, work, name)
            data["meshlab"][name] = against_meshlab(pymeshlab, job, uv)
            stages = {"input": fm.distortion_summary(job.V, job.F, uv)}
            positions = {"input": job.V}
            if MESHES[name]:
                approximated, approx_report = approximate(args.quasidev, path, work, name)
                moved = Job(approximated)
                positions["approximated"] = moved.V
                uv_a, _, svg_a = flatten(args.quasidev, approximated, work, name + ".approx")
                stages["approximated"] = {**fm.distortion_summary(moved.V, moved.F, uv_a),
                                          "abd_reduction": approx_report["abd_reduction"]}
                developed = Job(make_developable(pymeshlab, path, work, name))
                uv_d, _, _ = flatten(args.quasidev, developed.path, work, name + ".dev")
                stages["make_developable"] = fm.distortion_summary(developed.V, developed.F, uv_d)
                if name == PICTURE_MESH and args.picture:
                    picture(approximated, svg_a, args.picture)
            if name in PATTERNS:
                data["patterns"][name] = {
                    stage: against_pattern(job, flatten(args.quasidev, cut_like_pattern(job, V, work, f"{name}.{stage}"),
                                                        work, f"{name}.{stage}.cut")[0])
                    for stage, V in positions.items()}
            data["stages"][name] = stages
            print(f"{name}: done", flush=True)
    args.out.mkdir(parents=True, exist_ok=True)
    text = tables(data)
    (args.out / "flatten.md").write_text(text)
    (args.out / "flatten.json").write_text(json.dumps(data, indent=1) + "\n")
    print(text)
    os._exit(0)  # skip pymeshlab's MeshSet destructors (see _KEEP)


if __name__ == "__main__":
    main()
