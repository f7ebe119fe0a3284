"""Conveniences over PyPI `plyfile` that the scripts and the tests share.

Input:  a plyfile.PlyData (read with plyfile.PlyData.read: ascii or binary, any elements, e.g.
        MeshLab's camera element).
Output: a property as a Python list (list properties as tuples), the vertex positions as an
        (n, 3) array, the faces as index tuples; element() builds a plyfile.PlyElement from
        columns for writing, columns() gives an element's columns back.
"""
from __future__ import annotations

import numpy as np
from plyfile import PlyData, PlyElement, PlyListProperty


def has(ply: PlyData, element: str, prop: str) -> bool:
    """Whether ply has an element of that name with that property."""
    return element in ply and prop in ply[element].data.dtype.names


def column(ply: PlyData, element: str, prop: str) -> list:
    """One property's values as Python numbers; a list property gives one tuple per row."""
    values = ply[element][prop]
    if values.dtype == object:
        return [tuple(v.tolist()) for v in values]
    return values.tolist()


def positions(ply: PlyData) -> np.ndarray:
    """Vertex positions x, y, z as an (n, 3) float64 array."""
    v = ply["vertex"]
    return np.column_stack([v[c] for c in "xyz"]).astype(np.float64).reshape(-1, 3)


def faces(ply: PlyData) -> list[tuple[int, ...]]:
    """Face vertex index tuples (property vertex_indices or vertex_index); none without faces."""
    for name in ("vertex_indices", "vertex_index"):
        if has(ply, "face", name):
            return column(ply, "face", name)
    return []


def columns(el: PlyElement) -> list[tuple]:
    """The (property, type, values) triples of an element, to copy it with changes by element()."""
    return [(p.name, (p.len_dtype, p.val_dtype) if isinstance(p, PlyListProperty) else p.val_dtype,
             el[p.name]) for p in el.properties]


def element(name: str, columns: list[tuple]) -> PlyElement:
    """A PlyElement from (property, type, values) triples, in that order. type is a numpy type
    ("f8", "u1", ...) or, for a list property, a (count type, value type) pair."""
    count = len(columns[0][2]) if columns else 0
    fields = [(p, object if isinstance(t, tuple) else t) for p, t, _ in columns]
    data = np.empty(count, dtype=fields)
    for p, t, values in columns:
        if isinstance(t, tuple):
            rows = np.empty(count, dtype=object)
            rows[:] = [np.asarray(v, dtype=t[1]) for v in values]
            data[p] = rows
        else:
            data[p] = values
    lists = {p: t for p, t, _ in columns if isinstance(t, tuple)}
    return PlyElement.describe(data, name, len_types={p: t[0] for p, t in lists.items()},
                               val_types={p: t[1] for p, t in lists.items()})
