#!/usr/bin/env python3
"""Render one or two PLY meshes (before / after) side by side into a PNG with a title.

Input:  BEFORE.ply [AFTER.ply]: ascii or binary PLY, float or double x y z, optional vertex
        `red green blue` colour, vertex `quality`, face `quality` (patch id), any extra elements.
Output: a PNG (default 800x450): one panel per mesh, the same orthographic camera for both,
        z-buffered, Gouraud (or --flat) shading times the colour: vertex colour if present,
        else patch colours from face quality, else grey (or forced by --color).
Needs numpy, Pillow and plyfile (scripts/requirements-render.txt). Example:
    .venv/bin/python scripts/render.py in.ply out.ply -o cmp.png --title "quasidev" --color quality
"""
from __future__ import annotations

import argparse
import math
import sys
from pathlib import Path

import numpy as np
from PIL import Image, ImageDraw, ImageFont

sys.path.insert(0, str(Path(__file__).resolve().parent))
from plyfile import PlyData, PlyParseError  # noqa: E402

from ply_columns import column, faces, has, positions  # noqa: E402

SUPERSAMPLE = 2
BACKGROUND = (255, 255, 255)
GREY = (0.72, 0.72, 0.72)
BACK_FACE_DIM = 0.6       # inside (back) faces are drawn darker so open tubes read as tubes
AMBIENT = 0.25
AUTO_ELEVATION = 20.0     # degrees above the plane perpendicular to the up axis
AXES = {"x": np.array([1.0, 0.0, 0.0]), "y": np.array([0.0, 1.0, 0.0]), "z": np.array([0.0, 0.0, 1.0])}
PATCH_PALETTE = np.array([[0.90, 0.62, 0.35], [0.45, 0.68, 0.90], [0.55, 0.82, 0.50], [0.90, 0.55, 0.70],
                          [0.80, 0.78, 0.45], [0.65, 0.55, 0.88], [0.50, 0.82, 0.80], [0.88, 0.48, 0.45]])


class Mesh:
    """Triangles of a PLY (polygons fan-split) with the colour attributes it carries."""

    def __init__(self, ply: PlyData, name: str):
        self.name = name
        self.v = positions(ply)
        tris, owner = [], []
        for k, poly in enumerate(faces(ply)):
            for j in range(1, len(poly) - 1):
                tris.append((poly[0], poly[j], poly[j + 1]))
                owner.append(k)
        self.f = np.array(tris, dtype=np.int64).reshape(-1, 3)
        if len(self.v) == 0 or len(self.f) == 0:
            raise SystemExit(f"render.py: {name} has no vertices or no faces; nothing to draw")
        if self.f.min() < 0 or self.f.max() >= len(self.v):
            raise SystemExit(f"render.py: {name} has face indices outside 0..{len(self.v) - 1}")
        self.vcolor = None
        if all(has(ply, "vertex", c) for c in ("red", "green", "blue")):
            self.vcolor = np.stack([np.asarray(column(ply, "vertex", c), dtype=np.float64)
                                    for c in ("red", "green", "blue")], axis=1) / 255.0
        self.vquality = np.asarray(column(ply, "vertex", "quality"), np.float64) if has(ply, "vertex", "quality") else None
        patch = next((p for p in ("quality", "patch") if has(ply, "face", p)), None)  # as the command reads
        self.patch = (np.asarray(column(ply, "face", patch), np.float64)[np.array(owner, dtype=np.int64)]
                      if patch else None)

    def face_normals(self) -> tuple[np.ndarray, np.ndarray]:
        """Unit face normals and face areas."""
        p = self.v[self.f]
        n = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
        length = np.linalg.norm(n, axis=1)
        return n / np.maximum(length, 1e-300)[:, None], 0.5 * length

    def vertex_normals(self) -> np.ndarray:
        """Area-weighted unit vertex normals."""
        n, area = self.face_normals()
        acc = np.zeros_like(self.v)
        for k in range(3):
            np.add.at(acc, self.f[:, k], n * area[:, None])
        return acc / np.maximum(np.linalg.norm(acc, axis=1), 1e-300)[:, None]


def auto_up(mesh: Mesh) -> str:
    """World axis least aligned with the surface normals (a tube's axis, a garment's height)."""
    n, area = mesh.face_normals()
    moment = (area[:, None] * n * n).sum(axis=0) / area.sum()
    prefer = np.array([1.02, 1.01, 1.0])  # on near-ties prefer z, then y
    return "xyz"[int(np.argmin(moment * prefer))]


def view_direction(up: str, azimuth: float, elevation: float) -> np.ndarray:
    """Unit vector from the scene towards the camera."""
    u = AXES[up]
    a = AXES["yzx"["xyz".index(up)]]
    b = np.cross(u, a)
    az, el = math.radians(azimuth), math.radians(elevation)
    return math.cos(el) * (math.cos(az) * a + math.sin(az) * b) + math.sin(el) * u


def auto_azimuth(mesh: Mesh, up: str) -> float:
    """Azimuth (15 degree steps) that shows the largest front-facing projected area."""
    n, area = mesh.face_normals()
    best, best_az = -1.0, 0.0
    for az in range(0, 360, 15):
        d = view_direction(up, az, AUTO_ELEVATION)
        score = float((area * np.clip(n @ d, 0.0, None)).sum())
        if score > best * 1.001:
            best, best_az = score, float(az)
    return best_az


def camera_basis(to_camera: np.ndarray, up: str) -> np.ndarray:
    """Rows: screen right, screen up, towards the camera (looking along up: the next axis is up)."""
    w = to_camera / np.linalg.norm(to_camera)
    for axis in (AXES[up], AXES["yzx"["xyz".index(up)]]):
        u = axis - (axis @ w) * w
        if np.linalg.norm(u) > 1e-6:
            break
    u /= np.linalg.norm(u)
    return np.stack([np.cross(u, w), u, w])


def rasterize(xy: np.ndarray, depth: np.ndarray, faces: np.ndarray, width: int, height: int):
    """Z-buffer: per pixel the nearest face id (-1 = none) and barycentrics of corners 1, 2."""
    zbuf = np.full((height, width), -np.inf)
    fid = np.full((height, width), -1, dtype=np.int64)
    bary = np.zeros((height, width, 2))
    tri = xy[faces]
    tz = depth[faces]
    lo = np.floor(tri.min(axis=1) - 0.5).astype(np.int64)
    hi = np.ceil(tri.max(axis=1) - 0.5).astype(np.int64)
    lo = np.maximum(lo, 0)
    hi[:, 0] = np.minimum(hi[:, 0], width - 1)
    hi[:, 1] = np.minimum(hi[:, 1], height - 1)
    for t in np.nonzero((hi >= lo).all(axis=1))[0]:
        (x0, y0), (x1, y1), (x2, y2) = tri[t]
        det = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0)
        if abs(det) < 1e-12:
            continue
        px = np.arange(lo[t, 0], hi[t, 0] + 1) + 0.5
        py = np.arange(lo[t, 1], hi[t, 1] + 1)[:, None] + 0.5
        b1 = ((px - x0) * (y2 - y0) - (x2 - x0) * (py - y0)) / det
        b2 = ((x1 - x0) * (py - y0) - (px - x0) * (y1 - y0)) / det
        b0 = 1.0 - b1 - b2
        z = b0 * tz[t, 0] + b1 * tz[t, 1] + b2 * tz[t, 2]
        ys, xs = slice(lo[t, 1], hi[t, 1] + 1), slice(lo[t, 0], hi[t, 0] + 1)
        hit = (b0 >= 0) & (b1 >= 0) & (b2 >= 0) & (z > zbuf[ys, xs])
        if not hit.any():
            continue
        zbuf[ys, xs][hit] = z[hit]
        fid[ys, xs][hit] = t
        bary[ys, xs, 0][hit] = b1[hit]
        bary[ys, xs, 1][hit] = b2[hit]
    return fid, bary


def quality_colors(q: np.ndarray, qrange: tuple[float, float]) -> np.ndarray:
    """Blue - white - red ramp of q over qrange (blue = low)."""
    lo, hi = qrange
    s = np.clip((q - lo) / max(hi - lo, 1e-300), 0.0, 1.0)[:, None]
    blue, white, red = np.array([0.2, 0.35, 0.9]), np.array([0.95, 0.95, 0.95]), np.array([0.9, 0.2, 0.15])
    return np.where(s < 0.5, blue + (white - blue) * (2 * s), white + (red - white) * (2 * s - 1))


def corner_colors(mesh: Mesh, mode: str, qrange) -> np.ndarray:
    """Colour per face corner, shape (faces, 3, 3), for the chosen colour mode."""
    if mode == "auto":
        mode = "vertex" if mesh.vcolor is not None else "patch" if mesh.patch is not None else "grey"
    if mode == "vertex" and mesh.vcolor is not None:
        return mesh.vcolor[mesh.f]
    if mode == "quality" and mesh.vquality is not None:
        return quality_colors(mesh.vquality, qrange)[mesh.f]
    if mode == "patch" and mesh.patch is not None:
        ids = np.unique(mesh.patch, return_inverse=True)[1]
        return np.repeat(PATCH_PALETTE[ids % len(PATCH_PALETTE)][:, None, :], 3, axis=1)
    return np.broadcast_to(np.array(GREY), (len(mesh.f), 3, 3))


def shade_panel(mesh: Mesh, basis: np.ndarray, scale: float, centre: np.ndarray, size: tuple[int, int],
                mode: str, qrange, flat: bool) -> Image.Image:
    """One panel: the mesh seen through the camera (basis, scale px/unit, centre) at size."""
    w, h = size[0] * SUPERSAMPLE, size[1] * SUPERSAMPLE
    p = (mesh.v - centre) @ basis.T
    xy = np.stack([w / 2 + p[:, 0] * scale * SUPERSAMPLE, h / 2 - p[:, 1] * scale * SUPERSAMPLE], axis=1)
    fid, bary = rasterize(xy, p[:, 2], mesh.f, w, h)
    light = basis.T @ np.array([-0.35, 0.45, 1.0])   # from the upper left, in world coordinates
    light /= np.linalg.norm(light)
    fn = mesh.face_normals()[0]
    normals = np.repeat(fn[:, None, :], 3, axis=1) if flat else mesh.vertex_normals()[mesh.f]
    shade = AMBIENT + (1 - AMBIENT) * np.abs(normals @ light)              # two-sided lighting
    lit = corner_colors(mesh, mode, qrange) * shade[:, :, None]
    lit = lit * np.where(fn @ basis[2] < 0, BACK_FACE_DIM, 1.0)[:, None, None]
    img = np.tile(np.array(BACKGROUND, np.float64) / 255.0, (h, w, 1))
    mask = fid >= 0
    c = lit[fid[mask]]
    b1, b2 = bary[mask, 0][:, None], bary[mask, 1][:, None]
    img[mask] = (1 - b1 - b2) * c[:, 0] + b1 * c[:, 1] + b2 * c[:, 2]
    out = Image.fromarray(np.clip(img * 255 + 0.5, 0, 255).astype(np.uint8))
    return out.resize(size, Image.Resampling.BOX)


def shared_qrange(meshes: list[Mesh], given) -> tuple[float, float]:
    """Colour range for vertex quality: given, or symmetric 98th percentile of |q| over all panels."""
    if given is not None:
        return given
    qs = [m.vquality for m in meshes if m.vquality is not None]
    if not qs:
        return (0.0, 1.0)
    allq = np.concatenate(qs)
    if allq.min() >= 0:
        return (0.0, float(np.percentile(allq, 98)) or 1.0)
    m = float(np.percentile(np.abs(allq), 98)) or 1.0
    return (-m, m)


def camera(meshes: list[Mesh], view, up: str | None, panel: tuple[int, int]):
    """One camera for all meshes, framed to fit them all in a panel of that size: (basis, scale in
    px/unit, centre, (azimuth, elevation, up)); view and up default to auto from the first mesh."""
    up = up or auto_up(meshes[0])
    az, el = view if view is not None else (auto_azimuth(meshes[0], up), AUTO_ELEVATION)
    basis = camera_basis(view_direction(up, az, el), up)
    allv = np.concatenate([m.v for m in meshes])
    centre = 0.5 * (allv.min(axis=0) + allv.max(axis=0))
    extent = np.abs((allv - centre) @ basis.T)[:, :2].max(axis=0) * 2
    scale = 0.92 * min(panel[0] / max(extent[0], 1e-300), panel[1] / max(extent[1], 1e-300))
    return basis, scale, centre, (az, el, up)


def font(size: int):
    try:
        return ImageFont.load_default(size=size)
    except TypeError:  # Pillow without FreeType sizes
        return ImageFont.load_default()


def render(paths: list[Path], out: Path, title: str, labels: list[str], view, up: str | None,
           mode: str, qrange, flat: bool, size: tuple[int, int]) -> None:
    meshes = [Mesh(PlyData.read(p), p.name) for p in paths]
    title_h, label_h = 34, 22
    panel = (size[0] // len(meshes), size[1] - title_h - label_h)
    basis, scale, centre, (az, el, up) = camera(meshes, view, up, panel)
    qr = shared_qrange(meshes, qrange)
    canvas = Image.new("RGB", size, BACKGROUND)
    draw = ImageDraw.Draw(canvas)
    draw.text((size[0] / 2, title_h / 2), title, fill=(0, 0, 0), font=font(20), anchor="mm")
    for k, m in enumerate(meshes):
        canvas.paste(shade_panel(m, basis, scale, centre, panel, mode, qr, flat), (k * panel[0], title_h))
        text = labels[k] if k < len(labels) else m.name
        draw.text((k * panel[0] + panel[0] / 2, size[1] - label_h / 2), text, fill=(40, 40, 40),
                  font=font(14), anchor="mm")
    footer = f"view az {az:g} el {el:g}, up {up}"
    if mode == "quality":
        footer += f", quality {qr[0]:.3g} (blue) .. {qr[1]:.3g} (red)"
    draw.text((4, 2), footer, fill=(120, 120, 120), font=font(11))
    canvas.save(out)


def pair(text: str) -> tuple[float, float]:
    a, b = (float(s) for s in text.split(","))
    return a, b


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("meshes", nargs="+", type=Path, help="one or two PLY files (before [after])")
    ap.add_argument("-o", "--out", type=Path, required=True, help="output PNG")
    ap.add_argument("--title", default="", help="title above the panels")
    ap.add_argument("--labels", default="", help="comma-separated panel labels (default: file names)")
    ap.add_argument("--view", type=pair, help="azimuth,elevation in degrees about the up axis (default: auto)")
    ap.add_argument("--up", choices=sorted(AXES), help="world up axis (default: auto)")
    ap.add_argument("--color", default="auto", choices=["auto", "vertex", "quality", "patch", "grey"],
                    help="auto = vertex colour, else patch colours, else grey")
    ap.add_argument("--qrange", type=pair, help="min,max of vertex quality for --color quality")
    ap.add_argument("--flat", action="store_true", help="flat instead of Gouraud shading")
    ap.add_argument("--size", default="800x450", help="image size WxH (default 800x450)")
    args = ap.parse_args()
    if len(args.meshes) > 2:
        ap.error("give one or two meshes")
    for p in args.meshes:
        if not p.is_file():
            ap.error(f"{p}: no such file")
    w, h = (int(s) for s in args.size.lower().split("x"))
    labels = [s for s in args.labels.split(",") if s] if args.labels else []
    try:
        render(args.meshes, args.out, args.title, labels, args.view, args.up, args.color, args.qrange,
               args.flat, (w, h))
    except PlyParseError as exc:
        sys.exit(f"render.py: cannot read the input PLY: {exc}")


if __name__ == "__main__":
    main()
