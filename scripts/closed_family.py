"""Generated closed shapes without patch ids: what a scan or a CAD part gives the command.

The robustness issue asks that any mesh without patches take one default path and land on or
above MeshLab's trade-off curve. The shared closed meshes are few and were looked at; these are
made by parameters, so a run over them finds what nobody tuned for:

  shape   ellipsoid (axes 1, 0.7, 0.45) | torus (radii 1 and 0.35) | capsule (a cylinder of
          length 1.5 with hemispherical caps) | roundbox (a superellipsoid of exponent 6: flat
          sides, rounded edges, like a moulded part) | blob (a sphere with 8 random Gaussian
          bumps in and out)
  jitter  every vertex moved by a random vector of this length, in AE (a scan's noise), or by a
          third of its lowest triangle's altitude where that is less (near the capsule's poles)
  level   resolution: an icosahedron subdivided this many times (4: 5,120 triangles), the
          torus and the capsule grids of about as many (6,144 and 5,888)
  seed    the blob's bumps and the jitter

Every member is deterministic for its parameters. numpy only (mesh_family.py's helpers).
Usage: python scripts/closed_family.py --out DIR [--shapes ...] [--jitters ...] [--level L]
[--seed S] writes DIR/NAME.ply for each member and prints the paths, e.g. for scripts/tradeoff.py
--meshes.
"""
from __future__ import annotations

import argparse
import dataclasses
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mesh_family import average_edge, jitter_vertices, subdivide, write_ply  # noqa: E402

SHAPES = ("ellipsoid", "torus", "capsule", "roundbox", "blob")


@dataclasses.dataclass(frozen=True)
class Closed:
    shape: str
    jitter: float = 0.0  # AE
    level: int = 4
    seed: int = 1

    @property
    def name(self) -> str:
        return f"{self.shape}_j{self.jitter:g}_l{self.level}_s{self.seed}"


def icosphere(level: int) -> tuple[np.ndarray, np.ndarray]:
    """The unit sphere: an icosahedron whose triangles are split 4-to-1 `level` times, the new
    vertices pushed out to the sphere."""
    t = (1 + 5 ** 0.5) / 2
    V = np.array([(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t),
                  (0, -1, -t), (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)], float)
    F = np.array([(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9),
                  (5, 11, 4), (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6),
                  (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)])
    for _ in range(level):
        V, F = subdivide(V, F, np.zeros(len(F)))[:2]
    return V / np.linalg.norm(V, axis=1, keepdims=True), F


def torus(level: int, R: float = 1.0, r: float = 0.35) -> tuple[np.ndarray, np.ndarray]:
    """A torus on a grid of 6·2^level × 2·2^level cells, two triangles each."""
    nu, nv = 6 * 2 ** level, 2 * 2 ** level
    a, b = np.meshgrid(2 * np.pi * np.arange(nu) / nu, 2 * np.pi * np.arange(nv) / nv, indexing="ij")
    V = np.stack([(R + r * np.cos(b)) * np.cos(a), (R + r * np.cos(b)) * np.sin(a),
                  r * np.sin(b)], axis=-1).reshape(-1, 3)
    i, j = np.meshgrid(np.arange(nu), np.arange(nv), indexing="ij")
    p, q = i * nv + j, (i + 1) % nu * nv + j
    pr, qr = i * nv + (j + 1) % nv, (i + 1) % nu * nv + (j + 1) % nv
    F = np.concatenate([np.stack([p, q, qr], -1).reshape(-1, 3), np.stack([p, qr, pr], -1).reshape(-1, 3)])
    return V, F


def capsule(level: int, length: float = 1.5) -> tuple[np.ndarray, np.ndarray]:
    """A cylinder of radius 1 and this length with hemispherical caps, as a surface of
    revolution: 4·2^level vertices around each ring, rings evenly spaced along the profile's
    arc length, a vertex at each pole."""
    nu = 4 * 2 ** level
    arc = np.pi + length
    nv = round(nu * arc / (2 * np.pi))
    s = arc * np.arange(1, nv) / nv  # the rings' arc length from the top pole
    top, side = s < np.pi / 2, s <= np.pi / 2 + length
    phi = np.where(top, s, s - length)
    rho = np.where(top | ~side, np.sin(phi), 1.0)
    z = np.where(top, length / 2 + np.cos(phi), np.where(side, length / 2 - (s - np.pi / 2),
                                                         -length / 2 + np.cos(phi)))
    a = 2 * np.pi * np.arange(nu) / nu
    rings = np.stack([rho[:, None] * np.cos(a), rho[:, None] * np.sin(a),
                      np.broadcast_to(z[:, None], (nv - 1, nu))], axis=-1).reshape(-1, 3)
    V = np.vstack([[0, 0, length / 2 + 1], rings, [0, 0, -length / 2 - 1]])
    ring = 1 + nu * np.arange(nv - 1)[:, None] + np.arange(nu)  # ring j's vertices, around
    nxt = np.roll(ring, -1, axis=1)                                # each one's neighbour
    top = np.stack([np.zeros(nu, int), ring[0], nxt[0]], -1)
    bottom = np.stack([np.full(nu, len(V) - 1), nxt[-1], ring[-1]], -1)
    bands = np.stack([np.stack([ring[:-1], ring[1:], nxt[1:]], -1),  # two triangles per cell,
                      np.stack([ring[:-1], nxt[1:], nxt[:-1]], -1)], 1)  # band by band
    return V, np.concatenate([top, bands.reshape(-1, 3), bottom])


def lowest_altitude(V: np.ndarray, F: np.ndarray) -> np.ndarray:
    """Per vertex, the smallest altitude of the triangles around it (twice the area over the
    longest side): three corners each moved by less than a third of it cannot fold a triangle."""
    P = V[F]
    area2 = np.linalg.norm(np.cross(P[:, 1] - P[:, 0], P[:, 2] - P[:, 0]), axis=1)
    longest = np.linalg.norm(P - np.roll(P, 1, axis=1), axis=2).max(axis=1)
    low = np.full(len(V), np.inf)
    for k in range(3):
        np.minimum.at(low, F[:, k], area2 / longest)
    return low


def make(m: Closed) -> tuple[np.ndarray, np.ndarray]:
    """Vertices (n x 3) and triangles (m x 3, outward) of a member."""
    if m.shape not in SHAPES:
        raise ValueError(f"unknown shape {m.shape!r}; one of {', '.join(SHAPES)}")
    rng = np.random.default_rng(m.seed)
    if m.shape == "torus":
        V, F = torus(m.level)
    elif m.shape == "capsule":
        V, F = capsule(m.level)
    else:
        V, F = icosphere(m.level)
        if m.shape == "ellipsoid":
            V = V * np.array([1.0, 0.7, 0.45])
        elif m.shape == "roundbox":
            V = V / (np.abs(V) ** 6).sum(axis=1, keepdims=True) ** (1 / 6) * np.array([1.0, 0.6, 0.4])
        elif m.shape == "blob":
            centres = rng.normal(size=(8, 3))
            centres /= np.linalg.norm(centres, axis=1, keepdims=True)
            signs = np.resize([1.0, -1.0], 8)
            bumps = np.exp(-((V[:, None, :] - centres[None]) ** 2).sum(axis=-1) / 0.15) @ signs
            V = V * (1 + 0.25 * bumps)[:, None]
    if m.jitter > 0:  # at most a third of each vertex's lowest triangle: no triangle folds
        V = jitter_vertices(V, F, np.minimum(m.jitter * average_edge(V, F), lowest_altitude(V, F) / 3)[:, None], rng)
    return V, F


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", required=True, help="folder for the PLY files")
    ap.add_argument("--shapes", nargs="+", default=list(SHAPES), choices=SHAPES)
    ap.add_argument("--jitters", nargs="+", type=float, default=[0.0, 0.1])
    ap.add_argument("--level", type=int, default=4)
    ap.add_argument("--seed", type=int, default=1)
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    for shape in args.shapes:
        for j in args.jitters:
            member = Closed(shape, j, args.level, args.seed)
            path = os.path.join(args.out, member.name + ".ply")
            write_ply(path, *make(member), comment=f"scripts/closed_family.py {member.name}")
            print(path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
