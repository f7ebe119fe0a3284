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
  irregular   0 = the regular grid; above 0 (below 0.25) each interior vertex slides within the
              surface by up to this fraction of a cell each way and every cell takes a random
              diagonal, so the triangles vary in shape and size while the surface stays smooth

Tube (for the benchmark family, scripts/bench_family.py) is the same idea at a given face count
and in units of the radius: a cylinder, cone or curved sheet of a chosen length, cell aspect and
bump amplitude, closed around or cut open along one generator. subdivide() and drape() make
garment variants: 4-to-1 midpoint subdivision keeping the per-face patch ids, and a smooth random
normal displacement plus jitter.

Used by scripts/robustness_sweep.py, scripts/bench_family.py, tests/sweep/ and tests/bench/.
numpy only (the mesh measures of compare_developability.py).
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
    irregular: float = 0.0  # fraction of a cell

    @property
    def name(self) -> str:
        return (f"{self.base}_a{self.amplitude:g}_w{self.wavelength:g}_j{self.jitter:g}"
                f"_r{self.resolution}_s{self.seed}" + (f"_i{self.irregular:g}" if self.irregular else ""))

    @classmethod
    def from_name(cls, name: str) -> "Member":
        """The member whose name is `name` (the inverse of .name)."""
        base, a, w, j, r, s, *i = name.split("_")
        return cls(base, float(a[1:]), float(w[1:]), float(j[1:]), int(r[1:]), int(s[1:]),
                   float(i[0][1:]) if i else 0.0)

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


def _grid_faces(nu: int, nv: int, periodic: bool, flips=None) -> np.ndarray:
    """Triangles of an nu x nv grid of vertices (periodic in u: nu columns of cells, else nu - 1),
    counter-clockwise in (u, v). Each cell's diagonal alternates like a checkerboard, or, given
    flips (one bool per cell, row by row), follows them."""
    cols = nu if periodic else nu - 1
    faces = []
    for j in range(nv - 1):
        for i in range(cols):
            a, b = j * nu + i, j * nu + (i + 1) % nu
            c, d = b + nu, a + nu
            first = (i + j) % 2 == 0 if flips is None else flips[j * cols + i]
            faces += [(a, b, c), (a, c, d)] if first else [(a, b, d), (b, c, d)]
    return np.array(faces, dtype=np.int64)


def _slide(u: np.ndarray, v: np.ndarray, nu: int, nv: int, periodic: bool, fraction: float,
           rng) -> tuple[np.ndarray, np.ndarray]:
    """Each interior grid vertex moved in (u, v) by up to `fraction` of a cell each way; the
    boundary stays put. Below a quarter of a cell no triangle folds: a cell's corner is 1/sqrt(2)
    of a cell from its diagonal, and the three corners together close at most 2 sqrt(2) times
    the fraction."""
    if not 0 <= fraction < 0.25:
        raise ValueError(f"irregular must be in [0, 0.25), not {fraction}")
    du, dv = (1 / nu if periodic else 1 / (nu - 1)), 1 / (nv - 1)
    off_u, off_v = rng.uniform(-fraction, fraction, (2, len(u)))
    inner_v = (v > 0) & (v < 1)
    inner_u = inner_v & (periodic | ((u > 0) & (u < 1)))
    return u + np.where(inner_u, off_u * du, 0), v + np.where(inner_v, off_v * dv, 0)


def _normals(surface, u: np.ndarray, v: np.ndarray, h: float = 1e-6) -> np.ndarray:
    """Unit normals of surface(u, v) by central differences."""
    su = surface(u + h, v) - surface(u - h, v)
    sv = surface(u, v + h) - surface(u, v - h)
    n = np.cross(su, sv)
    return n / np.linalg.norm(n, axis=-1, keepdims=True)


def _bumps(surface, u: np.ndarray, v: np.ndarray, periodic: bool, sigma: float, rng,
           count: int = BUMPS) -> tuple[np.ndarray, np.ndarray]:
    """The window (vanishing on the boundary) and the sum of `count` Gaussian bumps of width
    sigma, alternately out and in, centred at random away from the boundary, at each (u, v)."""
    cu = rng.uniform(0, 1, count) if periodic else rng.uniform(0.2, 0.8, count)
    cv = rng.uniform(0.3, 0.7, count)
    P = surface(u, v)
    window = np.sin(np.pi * v) ** 2 * (1 if periodic else np.sin(np.pi * u) ** 2)
    h = np.zeros_like(u)
    for k in range(count):
        c = surface(cu[k:k + 1], cv[k:k + 1])[0]
        h += (-1) ** k * np.exp(-np.sum((P - c) ** 2, axis=1) / (2 * sigma ** 2))
    return window, h


def jitter_vertices(V: np.ndarray, F: np.ndarray, length: float, rng) -> np.ndarray:
    """Each interior vertex moved by a random vector of that length; the boundary stays put."""
    d = rng.normal(size=V.shape)
    d /= np.linalg.norm(d, axis=1, keepdims=True)
    d[~interior_vertices(len(V), F)] = 0
    return V + length * d


def make(m: Member) -> tuple[np.ndarray, np.ndarray]:
    """Vertices (n x 3, float64) and triangles (m x 3) of a member."""
    if m.base not in BASES:
        raise ValueError(f"unknown base {m.base!r}; one of {', '.join(BASES)}")
    periodic = PERIODIC[m.base]
    nu, nv = 64 * m.resolution, 24 * m.resolution + 1
    uu = np.arange(nu) / nu if periodic else np.linspace(0, 1, nu)
    u, v = np.meshgrid(uu, np.linspace(0, 1, nv))
    u, v = u.ravel(), v.ravel()
    flips = None
    if m.irregular > 0:  # its own generator, so the bumps and jitter of a seed stay the same
        shuffle = np.random.default_rng([m.seed, 1])
        u, v = _slide(u, v, nu, nv, periodic, m.irregular, shuffle)
        flips = shuffle.uniform(size=(nu if periodic else nu - 1) * (nv - 1)) < 0.5
    F = _grid_faces(nu, nv, periodic, flips)
    V = _surface(m.base, u, v)
    ae = average_edge(V, F)
    rng = np.random.default_rng(m.seed)
    if m.amplitude > 0:
        def surface(a, b):
            return _surface(m.base, a, b)
        length = np.linalg.norm(surface(np.array([0.5]), np.array([1.0])) -
                                surface(np.array([0.5]), np.array([0.0])))
        window, h = _bumps(surface, u, v, periodic, m.wavelength * length, rng)
        V = V + (m.amplitude * ae * window * h)[:, None] * _normals(surface, u, v)
    if m.jitter > 0:
        V = jitter_vertices(V, F, m.jitter * ae, rng)
    return V, F


@dataclasses.dataclass(frozen=True)
class Tube:
    """A cylinder (taper 0), cone (the far end's radius 1 - taper) or curved sheet (sweep < 1:
    that fraction of the way around, always open) of radius 1 at v = 0."""
    faces: int              # about this many triangles
    length: float           # along the axis, in radii
    aspect: float = 1.0     # a cell's length around over its length along
    taper: float = 0.0
    sweep: float = 1.0
    amplitude: float = 0.0  # the bumps' height, in radii
    width: float = 0.3      # the bumps' sigma, in radii
    jitter: float = 0.0     # AE
    closed: bool = True     # False: cut along one generator (not periodic)
    bumps: int = BUMPS
    seed: int = 0

    @property
    def name(self) -> str:
        shape = "sheet" if self.sweep < 1 else "cone" if self.taper else "cylinder"
        return (f"{shape}_{'closed' if self.periodic else 'open'}_n{self.faces}_l{self.length:g}"
                f"_c{self.aspect:g}_t{self.taper:g}_a{self.amplitude:g}r_j{self.jitter:g}_s{self.seed}")

    @property
    def periodic(self) -> bool:
        return self.closed and self.sweep == 1

    def surface(self, u: np.ndarray, v: np.ndarray) -> np.ndarray:
        t = 2 * np.pi * self.sweep * u
        r = 1.0 - self.taper * v
        return np.stack([r * np.cos(t), r * np.sin(t), self.length * v], axis=-1)


def make_tube(m: Tube) -> tuple[np.ndarray, np.ndarray]:
    """Vertices and triangles of a Tube: cells around x rows = faces / 2, of the given aspect."""
    around = 2 * np.pi * m.sweep * (1 - m.taper / 2)  # the mean circumference (arc)
    cells = max(3, round(math.sqrt(around * m.faces / (2 * m.length * m.aspect))))
    rows = max(1, round(m.faces / (2 * cells)))
    nu = cells if m.periodic else cells + 1
    uu = np.arange(nu) / nu if m.periodic else np.linspace(0, 1, nu)
    u, v = np.meshgrid(uu, np.linspace(0, 1, rows + 1))
    u, v = u.ravel(), v.ravel()
    F = _grid_faces(nu, rows + 1, m.periodic)
    V = m.surface(u, v)
    rng = np.random.default_rng(m.seed)
    if m.amplitude > 0:
        window, h = _bumps(m.surface, u, v, m.periodic, m.width, rng, m.bumps)
        V = V + (m.amplitude * window * h)[:, None] * _normals(m.surface, u, v)
    if m.jitter > 0:
        V = jitter_vertices(V, F, m.jitter * average_edge(V, F), rng)
    return V, F


def subdivide(V: np.ndarray, F: np.ndarray, patch: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """4-to-1 midpoint subdivision: a vertex at each edge's midpoint, each face's 4 children
    (consecutive, corners first) keep its patch id."""
    E = np.sort(np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]]), axis=1)
    edges, inverse = np.unique(E, axis=0, return_inverse=True)
    mid = len(V) + inverse.ravel().reshape(3, -1)  # the midpoints of edges 01, 12, 20 per face
    a, b, c = F.T
    children = np.stack([np.stack([a, mid[0], mid[2]]), np.stack([mid[0], b, mid[1]]),
                         np.stack([mid[2], mid[1], c]), np.stack([mid[0], mid[1], mid[2]])])
    V2 = np.vstack([V, (V[edges[:, 0]] + V[edges[:, 1]]) / 2])
    return V2, children.transpose(2, 0, 1).reshape(-1, 3), np.repeat(patch, 4)


def vertex_normals(V: np.ndarray, F: np.ndarray) -> np.ndarray:
    """Area-weighted unit vertex normals."""
    n = np.cross(V[F[:, 1]] - V[F[:, 0]], V[F[:, 2]] - V[F[:, 0]])
    acc = np.zeros_like(V)
    for k in range(3):
        np.add.at(acc, F[:, k], n)
    return acc / np.maximum(np.linalg.norm(acc, axis=1), 1e-300)[:, None]


def drape(V: np.ndarray, F: np.ndarray, amplitude: float, jitter: float, seed: int,
          folds: int = 8, width: float = 0.15) -> np.ndarray:
    """V displaced along the vertex normals by a smooth random field of largest height
    `amplitude` AE (`folds` Gaussians of sigma = width x the bounding-box diagonal at random
    vertices, random weights in [-1, 1]), then jittered by `jitter` AE (interior vertices)."""
    rng = np.random.default_rng(seed)
    ae = average_edge(V, F)
    sigma = width * np.linalg.norm(V.max(axis=0) - V.min(axis=0))
    centres = V[rng.integers(0, len(V), folds)]
    weights = rng.uniform(-1, 1, folds)
    h = sum(w * np.exp(-np.sum((V - c) ** 2, axis=1) / (2 * sigma ** 2)) for w, c in zip(weights, centres))
    V = V + (amplitude * ae * h / np.max(np.abs(h)))[:, None] * vertex_normals(V, F)
    return jitter_vertices(V, F, jitter * ae, rng) if jitter > 0 else V


def write_ply(path, V: np.ndarray, F: np.ndarray, comment: str = "", quality=None) -> None:
    """Binary little-endian PLY: double x y z, int vertex_indices and, when given, a float face
    quality (the patch id, as the command reads it)."""
    header = ["ply", "format binary_little_endian 1.0"]
    if comment:
        header.append(f"comment {comment}")
    header += [f"element vertex {len(V)}", "property double x", "property double y",
               "property double z", f"element face {len(F)}",
               "property list uchar int vertex_indices"]
    header += ["property float quality"] if quality is not None else []
    header += ["end_header"]
    fields = [("n", "u1"), ("i", "<i4", (3,))] + ([("q", "<f4")] if quality is not None else [])
    faces = np.zeros(len(F), dtype=fields)
    faces["n"] = 3
    faces["i"] = F
    if quality is not None:
        faces["q"] = quality
    with open(path, "wb") as out:
        out.write(("\n".join(header) + "\n").encode("ascii"))
        out.write(np.ascontiguousarray(V, dtype="<f8").tobytes())
        out.write(faces.tobytes())
