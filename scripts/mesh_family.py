"""Generated families of test meshes: developable (or nearly) bases with bumps and jitter.

A member is named by its parameters, not picked from a list, so a sweep over them finds cases
nobody looked at. Every member is deterministic for its parameters and seed.

  base        plane | cylinder | cone | tangent (the tangent developable of a helix) |
              lampshade (a cone whose generators bulge: K > 0 everywhere, like the paper's Fig. 4)
  amplitude   height of the smooth Gaussian bumps along the base's normal, in units of AE
              (the average edge length); 0 = none
  wavelength  the bumps' width (sigma) as a fraction of the base's size along v
  jitter      each interior vertex moved by a random vector of this length, in AE
  resolution  grid density: 1 = 64 x 24 cells (about 3k triangles), 2 = twice as fine each way

Used by scripts/robustness_sweep.py and tests/sweep/. numpy only (the mesh measures of
compare_developability.py).
"""
from __future__ import annotations

import dataclasses
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from compare_developability import average_edge, interior_vertices  # noqa: E402

BASES = ("plane", "cylinder", "cone", "tangent", "lampshade")
PERIODIC = {"plane": False, "cylinder": True, "cone": True, "tangent": False, "lampshade": True}
BUMPS = 4  # bumps per member, alternately out and in


@dataclasses.dataclass(frozen=True)
class Member:
    base: str
    amplitude: float   # AE
    wavelength: float  # fraction of the base's length along v
    jitter: float      # AE
    resolution: int = 1
    seed: int = 0

    @property
    def name(self) -> str:
        return (f"{self.base}_a{self.amplitude:g}_w{self.wavelength:g}_j{self.jitter:g}"
                f"_r{self.resolution}_s{self.seed}")

    @property
    def smooth(self) -> bool:
        """Smooth bumps and no jitter: what a developable approximation must remove almost all of."""
        return self.jitter == 0


def _surface(base: str, u: np.ndarray, v: np.ndarray) -> np.ndarray:
    """Points of the base at parameters u in [0, 1) (around for the periodic ones), v in [0, 1]."""
    t = 2 * np.pi * u
    if base == "plane":
        return np.stack([3.0 * u, 1.5 * v, 0 * u], axis=-1)
    if base == "cylinder":
        return np.stack([np.cos(t), np.sin(t), 2.0 * v], axis=-1)
    if base in ("cone", "lampshade"):
        r = 1.0 - 0.5 * v + (0.06 * np.sin(np.pi * v) if base == "lampshade" else 0)
        return np.stack([r * np.cos(t), r * np.sin(t), 1.2 * v], axis=-1)
    if base == "tangent":  # c(s) + w c'(s)/|c'(s)| on a helix of pitch 0.3, away from the cusp edge
        s = 1.5 * np.pi * u
        w = 0.3 + 1.2 * v
        c = np.stack([np.cos(s), np.sin(s), 0.3 * s], axis=-1)
        d = np.stack([-np.sin(s), np.cos(s), 0.3 + 0 * s], axis=-1) / math.hypot(1, 0.3)
        return c + w[..., None] * d
    raise ValueError(f"unknown base {base!r}; one of {', '.join(BASES)}")


def _grid_faces(nu: int, nv: int, periodic: bool) -> np.ndarray:
    """Triangles of an nu x nv grid of vertices (periodic in u: nu columns of cells, else nu - 1),
    diagonals alternating like a checkerboard, counter-clockwise in (u, v)."""
    cols = nu if periodic else nu - 1
    faces = []
    for j in range(nv - 1):
        for i in range(cols):
            a, b = j * nu + i, j * nu + (i + 1) % nu
            c, d = b + nu, a + nu
            faces += [(a, b, c), (a, c, d)] if (i + j) % 2 == 0 else [(a, b, d), (b, c, d)]
    return np.array(faces, dtype=np.int64)


def _normals(base: str, u: np.ndarray, v: np.ndarray, h: float = 1e-6) -> np.ndarray:
    su = _surface(base, u + h, v) - _surface(base, u - h, v)
    sv = _surface(base, u, v + h) - _surface(base, u, v - h)
    n = np.cross(su, sv)
    return n / np.linalg.norm(n, axis=-1, keepdims=True)


def make(m: Member) -> tuple[np.ndarray, np.ndarray]:
    """Vertices (n x 3, float64) and triangles (m x 3) of a member."""
    if m.base not in BASES:
        raise ValueError(f"unknown base {m.base!r}; one of {', '.join(BASES)}")
    periodic = PERIODIC[m.base]
    nu, nv = 64 * m.resolution, 24 * m.resolution + 1
    uu = np.arange(nu) / nu if periodic else np.linspace(0, 1, nu)
    u, v = np.meshgrid(uu, np.linspace(0, 1, nv))
    u, v = u.ravel(), v.ravel()
    F = _grid_faces(nu, nv, periodic)
    V = _surface(m.base, u, v)
    ae = average_edge(V, F)
    rng = np.random.default_rng(m.seed)
    if m.amplitude > 0:
        # bumps centred away from the boundary; the window makes them vanish on it
        cu = rng.uniform(0, 1, BUMPS) if periodic else rng.uniform(0.2, 0.8, BUMPS)
        cv = rng.uniform(0.3, 0.7, BUMPS)
        P = V.copy()
        length = np.linalg.norm(_surface(m.base, np.array([0.5]), np.array([1.0])) -
                                _surface(m.base, np.array([0.5]), np.array([0.0])))
        sigma = m.wavelength * length
        window = np.sin(np.pi * v) ** 2 * (1 if periodic else np.sin(np.pi * u) ** 2)
        h = np.zeros_like(u)
        for k in range(BUMPS):
            c = _surface(m.base, cu[k:k + 1], cv[k:k + 1])[0]
            h += (-1) ** k * np.exp(-np.sum((P - c) ** 2, axis=1) / (2 * sigma ** 2))
        V = V + (m.amplitude * ae * window * h)[:, None] * _normals(m.base, u, v)
    if m.jitter > 0:
        d = rng.normal(size=V.shape)
        d /= np.linalg.norm(d, axis=1, keepdims=True)
        d[~interior_vertices(len(V), F)] = 0  # the boundary stays put
        V = V + m.jitter * ae * d
    return V, F


def write_ply(path, V: np.ndarray, F: np.ndarray, comment: str = "") -> None:
    """Binary little-endian PLY: double x y z, int vertex_indices."""
    header = ["ply", "format binary_little_endian 1.0"]
    if comment:
        header.append(f"comment {comment}")
    header += [f"element vertex {len(V)}", "property double x", "property double y",
               "property double z", f"element face {len(F)}",
               "property list uchar int vertex_indices", "end_header"]
    faces = np.zeros(len(F), dtype=[("n", "u1"), ("i", "<i4", (3,))])
    faces["n"] = 3
    faces["i"] = F
    with open(path, "wb") as out:
        out.write(("\n".join(header) + "\n").encode("ascii"))
        out.write(np.ascontiguousarray(V, dtype="<f8").tobytes())
        out.write(faces.tobytes())
