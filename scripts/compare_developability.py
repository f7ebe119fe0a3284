#!/usr/bin/env python3
"""Side-by-side: our Quasi-Developable Approximation vs MeshLab's own "Make mesh developable".

Runs both filters in the same pymeshlab process on the same inputs -- ours
(apply_coord_quasi_developable_approximation, the 2025.07d plugin of this project) and MeshLab's
apply_coord_developability_of_mesh (Stein, Grinspun, Crane 2018) -- each with its defaults and one
tuned setting, and prints a Markdown table per run:
  wall time of the filter call, the G_ABD reduction (percent drop of G_ABD = sum |K| over interior
  vertices, from input to output: abd_reduction, as the filter's own figure; ratio_ABD, Eq. 19, is
  the drop of one iteration), max |K| after, max and mean displacement in AE (the input's
  average edge length), symmetric Hausdorff distance to the input relative to the input's bbox
  diagonal, and whether the topology was preserved.
K is computed here, identically for both outputs: angle defect over the mixed Voronoi area
(Meyer et al. 2003) at interior vertices (all incident edges shared by exactly two faces).
Displacement is |v' - v| per vertex when the output keeps the input's vertices; when a filter
remeshed (vertex count changed) it is the distance of each output vertex to the input surface,
marked with '*'.

Usage: .venv/bin/python scripts/compare_developability.py [--plugin SO] [--json OUT] [MESH.ply ...]
Inputs default to the meshes of $QD_SHARED_MESHES (when set) and tests/data/, then sample_meshes/*.ply.
"""
from __future__ import annotations

import argparse
import glob
import json
import os
import sys
import time

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT_PLUGIN = os.path.join(ROOT, "build", "bin", "pymeshlab", "libfilter_quasidev.so")
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mesh_folders import SAMPLES, mesh_folders  # noqa: E402

def _first_of_each_name(paths: list[str]) -> list[str]:
    """Each file name once, where it is first found (tests/data/ repeats some shared meshes)."""
    first: dict[str, str] = {}
    for path in paths:
        first.setdefault(os.path.basename(path), path)
    return list(first.values())


DEFAULT_MESHES = _first_of_each_name(
    [p for folder in mesh_folders() for p in sorted(glob.glob(os.path.join(folder, "*.ply")))] +
    sorted(glob.glob(os.path.join(SAMPLES, "*.ply"))))

OURS = "apply_coord_quasi_developable_approximation"
THEIRS = "apply_coord_developability_of_mesh"

# (label, filter, keyword arguments); defaults first, then one tuned setting each.
RUNS = [
    ("ours, defaults", OURS, {}),
    ("ours, tuned", OURS, {"target_mode": "refit"}),
    ("theirs, defaults", THEIRS, {}),
    ("theirs, tuned", THEIRS, {"maxfunevals": 2000, "edgeflips": False, "edgecollapses": False}),
]


# ---- measures (pure numpy; V: (n,3) float64, F: (m,3) int) -----------------------------------

def corner_angles(V: np.ndarray, F: np.ndarray) -> np.ndarray:
    """Interior angle at each corner of each face, shape (m,3)."""
    angles = np.empty(F.shape, dtype=float)
    for c in range(3):
        a, b, d = V[F[:, c]], V[F[:, (c + 1) % 3]], V[F[:, (c + 2) % 3]]
        u, w = b - a, d - a
        angles[:, c] = np.arctan2(np.linalg.norm(np.cross(u, w), axis=1), np.einsum("ij,ij->i", u, w))
    return angles


def mixed_areas(V: np.ndarray, F: np.ndarray, angles: np.ndarray) -> np.ndarray:
    """Mixed Voronoi area per vertex (Meyer et al. 2003, Fig. 4): Voronoi part of each
    non-obtuse face, else half the face area to the obtuse corner and a quarter to the others."""
    area = 0.5 * np.linalg.norm(np.cross(V[F[:, 1]] - V[F[:, 0]], V[F[:, 2]] - V[F[:, 0]]), axis=1)
    obtuse = angles > 0.5 * np.pi
    any_obtuse = obtuse.any(axis=1)
    with np.errstate(divide="ignore", invalid="ignore"):
        cot = 1.0 / np.tan(angles)
    A = np.zeros(len(V))
    for c in range(3):
        i, j, k = F[:, c], F[:, (c + 1) % 3], F[:, (c + 2) % 3]
        # Voronoi share of corner i: (|e_ij|^2 cot(angle k) + |e_ik|^2 cot(angle j)) / 8
        vor = (np.sum((V[j] - V[i]) ** 2, axis=1) * cot[:, (c + 2) % 3]
               + np.sum((V[k] - V[i]) ** 2, axis=1) * cot[:, (c + 1) % 3]) / 8.0
        share = np.where(any_obtuse, np.where(obtuse[:, c], area / 2.0, area / 4.0), vor)
        np.add.at(A, i, share)
    return A


def edge_use(F: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Each undirected edge of the triangles (k x 2, sorted) and how many faces have it."""
    edges = np.sort(np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]]), axis=1)
    return np.unique(edges, axis=0, return_counts=True)


def interior_vertices(n: int, F: np.ndarray) -> np.ndarray:
    """True for referenced vertices all of whose edges are shared by exactly two faces."""
    uniq, count = edge_use(F)
    interior = np.zeros(n, dtype=bool)
    interior[np.unique(F)] = True
    interior[uniq[count != 2].ravel()] = False
    return interior


def gaussian_curvature(V: np.ndarray, F: np.ndarray) -> np.ndarray:
    """K(v) = (2 pi - sum of angles) / mixed area at interior vertices, 0 elsewhere."""
    angles = corner_angles(V, F)
    angle_sum = np.zeros(len(V))
    np.add.at(angle_sum, F.ravel(), angles.ravel())
    A = mixed_areas(V, F, angles)
    interior = interior_vertices(len(V), F) & (A > 0)
    K = np.zeros(len(V))
    K[interior] = (2.0 * np.pi - angle_sum[interior]) / A[interior]
    return K


def average_edge(V: np.ndarray, F: np.ndarray) -> float:
    """Mean length of the unique edges (AE)."""
    edges = np.unique(np.sort(np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]]), axis=1), axis=0)
    return float(np.mean(np.linalg.norm(V[edges[:, 0]] - V[edges[:, 1]], axis=1)))


def euler_characteristic(V: np.ndarray, F: np.ndarray) -> int:
    edges = np.unique(np.sort(np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]]), axis=1), axis=0)
    return int(len(np.unique(F)) - len(edges) + len(F))


# pymeshlab 2025.7.post1 bug: destroying a MeshSet on which a filter raised corrupts the heap and a
# later MeshSet crashes at random; such MeshSets are kept referenced until the process ends.
_FAILED_MESHSETS: list = []


# ---- one run -----------------------------------------------------------------------------------

def hausdorff_one_way(ms, sampled: int, target: int, samples: int) -> dict:
    return ms.apply_filter("get_hausdorff_distance", sampledmesh=sampled, targetmesh=target,
                           samplevert=True, sampleface=True, samplenum=samples)


def run_one(path: str, label: str, filter_name: str, kwargs: dict) -> dict:
    import pymeshlab
    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(path)
    ms.load_new_mesh(path)  # mesh 1 is filtered, mesh 0 stays the input
    V0 = ms.mesh(0).vertex_matrix().copy()
    F0 = ms.mesh(0).face_matrix().copy()
    row = {"mesh": os.path.basename(path), "run": label}
    t0 = time.perf_counter()
    try:
        ms.apply_filter(filter_name, **kwargs)
    except pymeshlab.PyMeshLabException as e:
        _FAILED_MESHSETS.append(ms)
        row["error"] = str(e).split("Details:", 1)[-1].strip()
        return row
    row["time_s"] = time.perf_counter() - t0
    V1, F1 = ms.mesh(1).vertex_matrix(), ms.mesh(1).face_matrix()
    ae = average_edge(V0, F0)
    K0, K1 = gaussian_curvature(V0, F0), gaussian_curvature(V1, F1)
    g0, g1 = np.abs(K0).sum(), np.abs(K1).sum()
    row["abd_reduction"] = 100.0 * (g0 - g1) / g0 if g0 > 0 else 0.0
    row["max_k_before"], row["max_k"] = float(np.abs(K0).max()), float(np.abs(K1).max())
    diag = float(np.linalg.norm(V0.max(axis=0) - V0.min(axis=0)))
    samples = 10 * max(len(F0), len(F1))
    out_to_in = hausdorff_one_way(ms, 1, 0, samples)
    in_to_out = hausdorff_one_way(ms, 0, 1, samples)
    row["hausdorff_rel"] = max(out_to_in["max"], in_to_out["max"]) / diag
    same_vertices = len(V1) == len(V0)
    if same_vertices:
        d = np.linalg.norm(V1 - V0, axis=1)
        row["max_disp_ae"], row["mean_disp_ae"] = float(d.max()) / ae, float(d.mean()) / ae
    else:
        surface = ms.apply_filter("get_hausdorff_distance", sampledmesh=1, targetmesh=0,
                                  samplevert=True, sampleface=False)
        row["max_disp_ae"], row["mean_disp_ae"] = surface["max"] / ae, surface["mean"] / ae
    row["disp_is_to_surface"] = not same_vertices
    same_faces = same_vertices and F1.shape == F0.shape and bool(np.array_equal(F1, F0))
    row["topology"] = ("yes" if same_faces else
                       f"no: V {len(V0)}->{len(V1)}, F {len(F0)}->{len(F1)}, Euler char "
                       f"{euler_characteristic(V0, F0)}->{euler_characteristic(V1, F1)}")
    return row


def table(rows: list[dict]) -> str:
    head = ("| mesh | run | time (s) | G_ABD reduction (%) | max abs K before -> after | max disp (AE) | "
            "mean disp (AE) | Hausdorff / diag | topology preserved |")
    out = [head, "|" + "---|" * 9]
    for r in rows:
        if "error" in r:
            out.append(f"| {r['mesh']} | {r['run']} | failed: {r['error']} |||||||")
            continue
        star = "*" if r["disp_is_to_surface"] else ""
        out.append(f"| {r['mesh']} | {r['run']} | {r['time_s']:.2f} | {r['abd_reduction']:.1f} | "
                   f"{r['max_k_before']:.3g} -> {r['max_k']:.3g} | {r['max_disp_ae']:.3f}{star} | "
                   f"{r['mean_disp_ae']:.3f}{star} | {r['hausdorff_rel']:.2e} | {r['topology']} |")
    return "\n".join(out)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("meshes", nargs="*", default=DEFAULT_MESHES)
    ap.add_argument("--plugin", default=DEFAULT_PLUGIN, help="our 2025.07d plugin (.so)")
    ap.add_argument("--json", help="also write the rows as JSON to this file")
    args = ap.parse_args()
    import pymeshlab
    if not os.path.isfile(args.plugin):
        print(f"plugin not found: {args.plugin} (build it: cmake --build build)", file=sys.stderr)
        return 2
    pymeshlab.load_plugin(os.path.abspath(args.plugin))
    rows = []
    for path in args.meshes:
        for label, name, kwargs in RUNS:
            rows.append(run_one(path, label, name, kwargs))
            print(f"{os.path.basename(path)}: {label} done", file=sys.stderr, flush=True)
    print(table(rows))
    print("\nSettings: " + "; ".join(f"{label}: {kw or 'defaults'}" for label, _, kw in RUNS))
    print("* = remeshed: distance of each output vertex to the input surface instead of |v' - v|.")
    if args.json:
        with open(args.json, "w") as f:
            json.dump(rows, f, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main())
