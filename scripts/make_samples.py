#!/usr/bin/env python3
"""Deterministic generator of the project's sample meshes (writes them with PyPI plyfile).

Input:  optional --out DIR (default: sample_meshes/ beside scripts/).
Output: DIR/{lampshade,bumpy_cylinder,bumpy_cone,patches,selected,draped_panels,capped_cylinder,cone_panels}.ply (binary little-endian
        PLY: vertex double x y z [int flags, bit 0x20 = selected], face list uchar int
        vertex_indices + float quality = patch id) and DIR/SOURCES.md describing them.
Running it twice gives byte-identical files. All meshes but capped_cylinder (a closed tube with
two discs) are open tubes/bands parametrised by
u in [0,1) around and v in [0,1] along; faces are counter-clockwise in (u, v), so the normal
d/du x d/dv points outwards and the orientation is consistent.
"""
from __future__ import annotations

import argparse
import math
from pathlib import Path

from plyfile import PlyData

from ply_columns import column, element

SELECTED = 0x20  # vcg SELECTED vertex flag, read by MeshLab 2020.09 from a PLY 'flags' property
DIGITS = 9       # coordinates are rounded so that tiny libm differences do not change the bytes
COMMAND = "python3 scripts/make_samples.py"

Vec = tuple[float, float, float]


def add(a: Vec, b: Vec, s: float = 1.0) -> Vec:
    return (a[0] + s * b[0], a[1] + s * b[1], a[2] + s * b[2])


def sub(a: Vec, b: Vec) -> Vec:
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def cross(a: Vec, b: Vec) -> Vec:
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def norm(a: Vec) -> float:
    return math.sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2])


def unit(a: Vec) -> Vec:
    n = norm(a)
    return (a[0] / n, a[1] / n, a[2] / n)


def tube_faces(n_around: int, n_along: int) -> list[tuple[int, int, int, int, int]]:
    """Triangles of a grid periodic in u (n_around columns) and open in v (n_along rows).

    Returns (a, b, c, column, row) with vertex index = row * n_around + column; the quad
    diagonal alternates like a checkerboard for a regular-looking triangulation."""
    faces = []
    for j in range(n_along):
        for i in range(n_around):
            a = j * n_around + i
            b = j * n_around + (i + 1) % n_around
            c = b + n_around
            d = a + n_around
            if (i + j) % 2 == 0:
                faces += [(a, b, c, i, j), (a, c, d, i, j)]
            else:
                faces += [(a, b, d, i, j), (b, c, d, i, j)]
    return faces


def sample_grid(surface, n_around: int, n_along: int) -> list[Vec]:
    """Points surface(u, v) on the grid u = i / n_around, v = j / n_along."""
    return [surface(i / n_around, j / n_along) for j in range(n_along + 1) for i in range(n_around)]


def surface_normal(surface, u: float, v: float, h: float = 1e-6) -> Vec:
    """Unit normal d/du x d/dv of a parametric surface by central differences."""
    su = sub(surface(u + h, v), surface(u - h, v))
    sv = sub(surface(u, v + h), surface(u, v - h))
    return unit(cross(su, sv))


def with_bumps(surface, bumps, sigma: float):
    """surface displaced along its normal by Gaussian bumps.

    bumps: (u, v, amplitude) per bump; the distance is the 3D distance on the base surface."""
    centres = [(surface(u, v), amp) for u, v, amp in bumps]

    def bumped(u: float, v: float) -> Vec:
        p = surface(u, v)
        h = sum(amp * math.exp(-norm(sub(p, c)) ** 2 / (2.0 * sigma * sigma)) for c, amp in centres)
        return add(p, surface_normal(surface, u, v), h)
    return bumped


def revolution(radius, height: float):
    """Surface of revolution around z: z = height * v, radius radius(u, v)."""
    def surf(u: float, v: float) -> Vec:
        t = 2.0 * math.pi * u
        r = radius(u, v)
        return (r * math.cos(t), r * math.sin(t), height * v)
    return surf


def lampshade_radius(u: float, v: float) -> float:
    """Curved cone-like lampshade (paper Fig. 4): radius 1 -> 0.5, bulging generators and a
    small 5-fold wave that makes it non-developable."""
    bulge = 0.04 * math.sin(math.pi * v)
    wave = 0.01 * math.sin(10.0 * math.pi * u) * math.sin(2.0 * math.pi * v)
    return 1.0 - 0.5 * v + bulge + wave


def leg_surface(u: float, v: float) -> Vec:
    """Tapered tube ("trouser leg") of length 4 along a circular arc of radius 5 in the xz-plane."""
    alpha = 4.0 * v / 5.0
    centre = (5.0 * (1.0 - math.cos(alpha)), 0.0, 5.0 * math.sin(alpha))
    normal = (math.cos(alpha), 0.0, -math.sin(alpha))   # (T, N, B) right-handed, B = +y
    r = 0.6 - 0.15 * v
    t = 2.0 * math.pi * u
    return (centre[0] + r * math.cos(t) * normal[0], r * math.sin(t),
            centre[2] + r * math.cos(t) * normal[2])


def average_edge_length(points: list[Vec], faces) -> float:
    edges = {tuple(sorted((f[k], f[(k + 1) % 3]))) for f in faces for k in range(3)}
    return sum(norm(sub(points[a], points[b])) for a, b in edges) / len(edges)


def mesh_ply(points: list[Vec], faces, patch_of, comments: list[str], flags=None) -> PlyData:
    """PlyData of a triangle mesh; patch_of(column, row) gives the face's patch id."""
    vcols = [(name, "f8", [round(p[k], DIGITS) + 0.0 for p in points]) for k, name in enumerate("xyz")]
    if flags is not None:
        vcols.append(("flags", "i4", flags))
    face = element("face", [("vertex_indices", ("u1", "i4"), [f[:3] for f in faces]),
                            ("quality", "f4", [float(patch_of(f[3], f[4])) for f in faces])])
    base = ["generated by scripts/make_samples.py, licence CC0",
            "face quality = patch id (MeshLab reads it as per-face quality)"]
    return PlyData([element("vertex", vcols), face], comments=comments + base)


def one_patch(_i: int, _j: int) -> int:
    return 0


def make_lampshade() -> tuple[PlyData, str]:
    n_around, n_along = 96, 24
    pts = sample_grid(revolution(lampshade_radius, 1.0), n_around, n_along)
    faces = tube_faces(n_around, n_along)
    what = ("curved cone-like lampshade (paper Fig. 4): open band between two circles, radius 1 -> 0.5 "
            "over height 1 with bulging generators (+0.04 sin(pi v)) and a small 5-fold wave (0.01); "
            "near a cone but not developable; 1 patch")
    return mesh_ply(pts, faces, one_patch, ["lampshade: " + what]), what


def bumpy(name: str, surface, shape: str, n_around: int, n_along: int, amp: float, sigma: float):
    """A developable base surface with four Gaussian bumps of amplitude amp (two out, two in)."""
    bumps = [(0.1, 0.3, amp), (0.35, 0.7, -amp), (0.6, 0.4, amp), (0.85, 0.65, -amp)]
    pts = sample_grid(with_bumps(surface, bumps, sigma), n_around, n_along)
    faces = tube_faces(n_around, n_along)
    edge = average_edge_length(pts, faces)
    what = (f"{shape} (developable) with 4 smooth Gaussian bumps (sigma {sigma:g}) along the normal, "
            f"amplitude a = {amp:g} model units = {amp / edge:.3f} x average edge length ({edge:.5f}); "
            f"1 patch")
    return mesh_ply(pts, faces, one_patch, [f"{name}: " + what]), what


def leg_mesh() -> tuple[list[Vec], list, int, int]:
    """Bumpy trouser-leg tube: grid points, faces, n_around, n_along."""
    n_around, n_along = 48, 60
    bumps = [(0.25, 0.25, 0.03), (0.75, 0.3, -0.03), (0.2, 0.75, -0.03), (0.7, 0.7, 0.03)]
    pts = sample_grid(with_bumps(leg_surface, bumps, 0.15), n_around, n_along)
    return pts, tube_faces(n_around, n_along), n_around, n_along


def leg_patch(n_around: int, n_along: int):
    """Patch id of a grid cell: 2 halves along the leg x 2 halves around it -> ids 0..3."""
    return lambda i, j: 2 * (2 * j >= n_along) + (2 * i >= n_around)


LEG_WHAT = ("curved tapered tube ('trouser leg', length 4 along an arc of radius 5, radius 0.6 -> 0.45), "
            "split into 4 patches (2 along x 2 around; seams at mid-length and at u = 0, 0.5), "
            "each near-developable with one Gaussian bump (amplitude 0.03, sigma 0.15); open ends")


def make_patches() -> tuple[PlyData, str]:
    pts, faces, n_around, n_along = leg_mesh()
    return mesh_ply(pts, faces, leg_patch(n_around, n_along), ["patches: " + LEG_WHAT]), LEG_WHAT


def make_selected() -> tuple[PlyData, str]:
    pts, faces, n_around, n_along = leg_mesh()
    ring = n_along // 4
    flags = [SELECTED if k // n_around == ring else 0 for k in range(len(pts))]
    what = (f"patches.ply with vertex flags: the {n_around} vertices of the ring at a quarter of the "
            f"length (v = 0.25) are selected (flags bit 0x20), for 'keep selected vertices' jobs")
    return mesh_ply(pts, faces, leg_patch(n_around, n_along), ["selected: " + what], flags), what


def make_draped() -> tuple[PlyData, str]:
    """The trouser leg draped: 16 small bumps and dents (sigma 0.07) wrinkle every patch in two
    directions, so its Gauss image is a blob, not a curve (the angle-defect term's case)."""
    n_around, n_along = 48, 60
    bumps = [((2 * k + 1) / 8 + 0.05 * (j % 2), (2 * j + 1) / 8, 0.12 * (-1) ** (k + j))
             for k in range(4) for j in range(4)]
    pts = sample_grid(with_bumps(leg_surface, bumps, 0.07), n_around, n_along)
    what = ("the trouser leg of patches.ply wrinkled like draped cloth: 16 bumps and dents "
            "(amplitude 0.12, sigma 0.07) in a 4 x 4 grid, 4 patches whose Gauss images are blobs, "
            "not curves (fit residual above 5 degrees)")
    return mesh_ply(pts, tube_faces(n_around, n_along), leg_patch(n_around, n_along),
                    ["draped_panels: " + what]), what


def cap_faces(outer: list[int], inner_rings: list[list[int]], centre: int, piece: int, up: bool):
    """Triangles of a disc: bands between the rings (outer first, same count each) and a fan to
    the centre; counter-clockwise seen from +z when up, else from -z. (a, b, c, piece, 0)."""
    def oriented(a: int, b: int, c: int) -> tuple[int, int, int, int, int]:
        return (a, b, c, piece, 0) if up else (a, c, b, piece, 0)
    faces, n = [], len(outer)
    for o, q in zip([outer] + inner_rings[:-1], inner_rings):
        for i in range(n):
            k = (i + 1) % n
            faces += [oriented(o[i], o[k], q[k]), oriented(o[i], q[k], q[i])]
    last = inner_rings[-1]
    faces += [oriented(centre, last[i], last[(i + 1) % n]) for i in range(n)]
    return faces


def make_capped_cylinder() -> tuple[PlyData, str]:
    """A closed cylinder of three developable pieces (side, bottom and top disc), the piece as
    face quality: the segmentation's known answer."""
    n_around, n_along, height = 48, 16, 2.0
    pts = sample_grid(revolution(lambda _u, _v: 1.0, height), n_around, n_along)
    faces = [(a, b, c, 0, 0) for a, b, c, _, _ in tube_faces(n_around, n_along)]
    for piece, z, row in ((1, 0.0, 0), (2, height, n_along)):
        rings = []
        for r in (2.0 / 3.0, 1.0 / 3.0):
            rings.append(list(range(len(pts), len(pts) + n_around)))
            pts += [(r * math.cos(2 * math.pi * i / n_around), r * math.sin(2 * math.pi * i / n_around), z)
                    for i in range(n_around)]
        pts.append((0.0, 0.0, z))
        outer = list(range(row * n_around, (row + 1) * n_around))
        faces += cap_faces(outer, rings, len(pts) - 1, piece, up=piece == 2)
    what = ("closed cylinder, radius 1, height 2, capped by two flat discs: 3 developable pieces "
            "(face quality 0 = side, 1 = bottom, 2 = top), the pieces a segmentation must find")
    return mesh_ply(pts, faces, lambda piece, _: piece, ["capped_cylinder: " + what]), what


def make_cone_panels() -> tuple[PlyData, str]:
    """An exactly developable cone frustum in three panels: every quad of the grid joins two
    rings at the same angles, so it is a planar isosceles trapezoid and the mesh unrolls into an
    annulus sector with no stretch (the flattening's ground truth)."""
    n_around, n_along = 96, 24
    pts = sample_grid(revolution(lambda _u, v: 1.0 - 0.5 * v, 1.0), n_around, n_along)
    what = ("exactly developable cone frustum (a lampshade without the bulge), radius 1 -> 0.5 over "
            "height 1, in 3 panels of 120 degrees each (seams along generators); its exact "
            "development is an annulus sector of radii 2.236 and 1.118 and angle 161 degrees, so "
            "its flat pattern is known")
    return mesh_ply(pts, tube_faces(n_around, n_along), lambda i, _j: 3 * i // n_around,
                    ["cone_panels: " + what]), what


def samples() -> list[tuple[str, PlyData, str]]:
    cyl, cyl_what = bumpy("bumpy_cylinder", revolution(lambda _u, _v: 1.0, 2.0), "open cylinder, radius 1, height 2",
                          96, 32, 0.05, 0.18)
    cone, cone_what = bumpy("bumpy_cone", revolution(lambda _u, v: 1.0 - 0.6 * v, 1.5),
                            "open cone frustum, radius 1 -> 0.4, height 1.5", 96, 32, 0.04, 0.15)
    return [("lampshade.ply", *make_lampshade()),
            ("bumpy_cylinder.ply", cyl, cyl_what),
            ("bumpy_cone.ply", cone, cone_what),
            ("patches.ply", *make_patches()),
            ("selected.ply", *make_selected()),
            ("draped_panels.ply", *make_draped()),
            ("capped_cylinder.ply", *make_capped_cylinder()),
            ("cone_panels.ply", *make_cone_panels())]


def sources_md(entries: list[tuple[str, PlyData, str]]) -> str:
    lines = ["# Sample meshes (generated)", "",
             f"Made by `{COMMAND}` (deterministic: running it again gives byte-identical files).",
             "Licence: CC0 1.0 (generated by this project; no third-party data).", "",
             "Format: binary little-endian PLY, vertex `double x y z` (selected.ply also `int flags`, "
             "bit 0x20 = selected, which MeshLab 2020.09 reads as vertex selection), face "
             "`list uchar int vertex_indices` and `float quality` = patch id (MeshLab: per-face "
             "quality). Open (but capped_cylinder.ply, closed), manifold, consistently oriented (outward "
             "normals), no zero-area faces.",
             "", "| file | faces | vertices | patches | what it is |", "|---|---|---|---|---|"]
    for name, ply, what in entries:
        npatch = len(set(column(ply, "face", "quality")))
        lines.append(f"| {name} | {ply['face'].count} | {ply['vertex'].count} | {npatch} | {what} |")
    return "\n".join(lines) + "\n"


def main() -> None:
    default = Path(__file__).resolve().parent.parent / "sample_meshes"
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", type=Path, default=default, help="output folder (default: %(default)s)")
    args = ap.parse_args()
    args.out.mkdir(parents=True, exist_ok=True)
    entries = samples()
    for name, ply, _ in entries:
        ply.write(args.out / name)
    (args.out / "SOURCES.md").write_text(sources_md(entries), encoding="utf-8")
    print(f"wrote {len(entries)} meshes and SOURCES.md to {args.out}")


if __name__ == "__main__":
    main()
