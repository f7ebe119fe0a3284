"""How a flat pattern distorts its mesh, measured independently of the C++ engine (numpy only).

Inputs: V (n,3) float positions, F (m,3) int faces, UV (m,6) per-face corner coordinates
u0 v0 u1 v1 u2 v2 (wedge texture coordinates), or (n,2) per-vertex ones spread with wedge_uv().
Outputs (docs/design.md "Metrics", Flattening): per face the singular values σ1 ≥ σ2 of the 3D→2D
map, signed σ2 < 0 where the face is flipped; length distortion max(σ1 − 1, 1 − σ2) per face,
its largest value and its area-weighted mean (as fractions); the edge-length error |l₂/l₃ − 1|
of every face edge; the total area ratio; the best uniform scale of a pattern.
"""
from __future__ import annotations

import numpy as np


def wedge_uv(uv_per_vertex: np.ndarray, F: np.ndarray) -> np.ndarray:
    """(m,6) corner coordinates from per-vertex ones."""
    return uv_per_vertex[F].reshape(len(F), 6)


def _frames(V: np.ndarray, F: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Per face its edges e1 = p1 − p0 and e2 = p2 − p0 in a 2D frame of its plane, (m,2,2)
    with the edges as columns, and its area."""
    p0, p1, p2 = V[F[:, 0]], V[F[:, 1]], V[F[:, 2]]
    e1, e2 = p1 - p0, p2 - p0
    l1 = np.linalg.norm(e1, axis=1)
    x = e1 / l1[:, None]
    n = np.cross(e1, e2)
    area = 0.5 * np.linalg.norm(n, axis=1)
    y = np.cross(n / (2 * area)[:, None], x)
    local = np.empty((len(F), 2, 2))
    local[:, 0, 0], local[:, 1, 0] = l1, 0.0
    local[:, 0, 1], local[:, 1, 1] = np.einsum("ij,ij->i", e2, x), np.einsum("ij,ij->i", e2, y)
    return local, area


def singular_values(V: np.ndarray, F: np.ndarray, UV: np.ndarray) -> np.ndarray:
    """(m,2): σ1 ≥ |σ2| of each face's Jacobian J (flat edges = J · 3D edges); σ2 < 0 flipped."""
    local, _ = _frames(V, F)
    flat = np.empty((len(F), 2, 2))
    flat[:, :, 0] = UV[:, 2:4] - UV[:, 0:2]
    flat[:, :, 1] = UV[:, 4:6] - UV[:, 0:2]
    J = flat @ np.linalg.inv(local)
    s = np.linalg.svd(J, compute_uv=False)
    s[:, 1] *= np.sign(np.linalg.det(J))
    return s


def length_distortion(V: np.ndarray, F: np.ndarray, UV: np.ndarray, scale: float = 1.0) -> np.ndarray:
    """Per face max(σ1 − 1, 1 − σ2) of the pattern scaled by `scale`."""
    s = scale * singular_values(V, F, UV)
    return np.maximum(s[:, 0] - 1, 1 - s[:, 1])


def distortion_summary(V: np.ndarray, F: np.ndarray, UV: np.ndarray, scale: float = 1.0) -> dict:
    """Largest and area-weighted mean length distortion (fractions) and flipped faces."""
    d = length_distortion(V, F, UV, scale)
    _, area = _frames(V, F)
    return {"max": float(d.max()), "mean": float((d * area).sum() / area.sum()),
            "flipped": int((singular_values(V, F, UV)[:, 1] <= 0).sum())}


def best_scale(V: np.ndarray, F: np.ndarray, UV: np.ndarray) -> float:
    """The uniform scale s minimising the largest length distortion max_f max(sσ1 − 1, 1 − sσ2):
    s = 2 / (max σ1 + min σ2), which balances the worst stretch against the worst compression."""
    s = singular_values(V, F, UV)
    return float(2.0 / (s[:, 0].max() + s[:, 1].min()))


def edge_length_errors(V: np.ndarray, F: np.ndarray, UV: np.ndarray) -> np.ndarray:
    """(m,3): |l_flat / l_3D − 1| of the edge from corner k to corner k+1 of every face."""
    out = np.empty((len(F), 3))
    for k in range(3):
        a, b = k, (k + 1) % 3
        l3 = np.linalg.norm(V[F[:, b]] - V[F[:, a]], axis=1)
        l2 = np.linalg.norm(UV[:, 2 * b:2 * b + 2] - UV[:, 2 * a:2 * a + 2], axis=1)
        out[:, k] = np.abs(l2 / l3 - 1)
    return out


def area_ratio(V: np.ndarray, F: np.ndarray, UV: np.ndarray) -> float:
    """Total flat area over total 3D area."""
    _, area = _frames(V, F)
    u1, u2 = UV[:, 2:4] - UV[:, 0:2], UV[:, 4:6] - UV[:, 0:2]
    flat = 0.5 * np.abs(u1[:, 0] * u2[:, 1] - u1[:, 1] * u2[:, 0])
    return float(flat.sum() / area.sum())


def split_by_uv(F: np.ndarray, UV: np.ndarray, digits: int = 7) -> tuple[np.ndarray, np.ndarray]:
    """The mesh cut wherever neighbouring faces' corners have different coordinates (a pattern's
    seams): (vertex of each new vertex, new faces). A new vertex is one (vertex, u, v) corner,
    with u, v rounded to `digits` significant decimals of the pattern's extent."""
    extent = float(np.ptp(UV.reshape(-1, 2), axis=0).max()) or 1.0
    q = np.round(UV.reshape(-1, 2) / extent * 10 ** digits).astype(np.int64)
    keys = np.column_stack([F.reshape(-1), q])
    unique, inverse = np.unique(keys, axis=0, return_inverse=True)
    return unique[:, 0], inverse.reshape(-1, 3)


def components(F: np.ndarray) -> list[np.ndarray]:
    """Edge-connected components of faces (face indices, each sorted), largest first."""
    parent = np.arange(len(F))

    def find(x: int) -> int:
        while parent[x] != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x
    owner: dict[tuple[int, int], int] = {}
    for f, tri in enumerate(F):
        for k in range(3):
            edge = tuple(sorted((int(tri[k]), int(tri[(k + 1) % 3]))))
            if edge in owner:
                a, b = find(owner[edge]), find(f)
                if a != b:
                    parent[a] = b
            else:
                owner[edge] = f
    roots = np.array([find(f) for f in range(len(F))])
    groups = [np.flatnonzero(roots == r) for r in np.unique(roots)]
    return sorted(groups, key=len, reverse=True)


def signed_area(UV: np.ndarray) -> float:
    """Total signed area of a pattern's faces (> 0: counter-clockwise, as the mesh)."""
    u1, u2 = UV[:, 2:4] - UV[:, 0:2], UV[:, 4:6] - UV[:, 0:2]
    return float(0.5 * (u1[:, 0] * u2[:, 1] - u1[:, 1] * u2[:, 0]).sum())


def rigid_distance(ours: np.ndarray, target: np.ndarray) -> tuple[float, float]:
    """Distances between corresponding 2D points after the rotation and translation of `ours`
    that best fit `target` (least squares, Kabsch; no reflection: mirror a mirrored target
    first, see signed_area). Returns (RMS, largest), over the target's bounding-box diagonal."""
    a = ours - ours.mean(axis=0)
    b = target - target.mean(axis=0)
    U, _, Vt = np.linalg.svd(a.T @ b)
    D = np.diag([1.0, np.sign(np.linalg.det(U @ Vt))])
    d = np.linalg.norm(a @ (U @ D @ Vt) - b, axis=1)
    diagonal = float(np.linalg.norm(np.ptp(target, axis=0)))
    return float(np.sqrt((d ** 2).mean()) / diagonal), float(d.max() / diagonal)
