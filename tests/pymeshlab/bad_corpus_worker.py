"""Runs a filter on one mesh in a fresh pymeshlab process and prints one JSON line saying what
happened, so a crash of pymeshlab or of the plugin shows as a signal to the caller
(test_bad_corpus_pymeshlab.py) instead of ending the whole test session.

Usage: python bad_corpus_worker.py PLUGIN FILTER MESH.ply PARAMETERS_JSON {file|arrays}
  file   = load MESH.ply with pymeshlab's own importer;
  arrays = read it with plyfile and hand pymeshlab the raw vertex and face arrays
           (pymeshlab's importer drops non-finite vertices, so NaN/inf reach the filter only so).
Output: {"stage": "load" | "filter" | "done", "message": str, "unchanged": bool,
         "faces_in": int, "faces_out": int, "finite": bool, "warnings": int (the filter's count),
         "moved": [indices of the vertices whose position changed]}
"""
from __future__ import annotations

import json
import os
import sys
from pathlib import Path

import numpy as np
import pymeshlab
from plyfile import PlyData

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts"))
from ply_columns import faces, positions  # noqa: E402


def snapshot(mesh) -> list[np.ndarray]:
    """Every per-vertex and per-face array pymeshlab exposes for a plain loaded mesh."""
    arrays = [mesh.vertex_matrix(), mesh.face_matrix(), mesh.vertex_selection_array(),
              mesh.face_selection_array()]
    if mesh.has_vertex_color():
        arrays.append(mesh.vertex_color_matrix())
    if mesh.has_vertex_scalar():
        arrays.append(mesh.vertex_scalar_array())
    if mesh.has_face_scalar():
        arrays.append(mesh.face_scalar_array())
    if mesh.has_face_color():
        arrays.append(mesh.face_color_matrix())
    if mesh.has_wedge_tex_coord():
        arrays.append(mesh.wedge_tex_coord_matrix())
    return [a.copy() for a in arrays]


def main(plugin: str, filter_name: str, path: str, parameters: str, mode: str) -> dict:
    pymeshlab.load_plugin(plugin)
    ms = pymeshlab.MeshSet()
    try:
        if mode == "file":
            ms.load_new_mesh(path)
        else:
            ply = PlyData.read(path)
            V = positions(ply)
            F = np.asarray(faces(ply), np.int32).reshape(-1, 3)
            ms.add_mesh(pymeshlab.Mesh(vertex_matrix=V, face_matrix=F))
    except pymeshlab.PyMeshLabException as e:
        return {"stage": "load", "message": str(e)}
    before = snapshot(ms.current_mesh())
    returned = {}
    try:
        returned = ms.apply_filter(filter_name, **json.loads(parameters))
        stage, message = "done", ""
    except pymeshlab.PyMeshLabException as e:
        stage, message = "filter", str(e)
    mesh = ms.current_mesh()
    after = snapshot(mesh)
    unchanged = len(before) == len(after) and all(
        a.shape == b.shape and np.array_equal(a, b, equal_nan=a.dtype.kind == "f")
        for a, b in zip(before, after))
    return {"stage": stage, "message": message, "unchanged": unchanged,
            "faces_in": int(len(before[1])), "faces_out": int(mesh.face_number()),
            "finite": bool(np.isfinite(mesh.vertex_matrix()).all()),
            "warnings": int(returned.get("warnings", 0)),
            "moved": np.flatnonzero((before[0] != after[0]).any(axis=1)).tolist()
            if before[0].shape == after[0].shape else []}


if __name__ == "__main__":
    print(json.dumps(main(*sys.argv[1:6])), flush=True)
    # Skip the MeshSet destructors: after a failed filter, pymeshlab 2025.7.post1 corrupts the
    # heap when that MeshSet is destroyed (see pymeshlab_paths.FAILED_MESHSETS).
    os._exit(0)
