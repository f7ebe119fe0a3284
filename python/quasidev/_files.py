"""quasidev.read and quasidev.write: mesh files through the command's reader (PLY, OBJ, OFF) and
PLY writer, as numpy arrays."""

from __future__ import annotations

import os
from dataclasses import dataclass, field
from typing import Any, Optional

import numpy as np

from . import _arrays, _engine


@dataclass(frozen=True)
class Mesh:
    """A mesh file's arrays as quasidev.read returns them (new arrays owned by the caller)."""

    V: np.ndarray  #: (n, 3) float64 vertex positions
    F: np.ndarray  #: (m, 3) int64 triangles (polygons are fan-triangulated, see notes)
    patches: Optional[np.ndarray] = None  #: (m,) int64 patch ids the file holds, else None
    fixed: Optional[np.ndarray] = None  #: (n,) bool selected (fixed) vertices, else None
    patch_names: dict = field(default_factory=dict)  #: panel names by patch id
    notes: list = field(default_factory=list)  #: the reader's remarks


def read(path: str | os.PathLike) -> Mesh:
    """Read a PLY (ascii or binary), OBJ or OFF file as the quasidev command does: patch ids from
    the PLY face quality (rounded) or patch property or OBJ groups, fixed vertices from the PLY
    vertex selection. Raises ValueError with the reader's message for a bad file."""
    out = _engine.read(os.fspath(path))
    fixed = out["fixed"]
    return Mesh(
        V=out["V"],
        F=out["F"],
        patches=out["patches"],
        fixed=None if fixed is None else fixed.astype(bool),
        patch_names=dict(out["patch_names"]),
        notes=list(out["notes"]),
    )


def write(
    path: str | os.PathLike,
    V: Any,
    F: Any,
    patches: Any = None,
    quality: Any = None,
    uv: Any = None,
) -> None:
    """Write V (n, 3) and F (m, 3) as binary PLY with the command's writer: the patch ids (m,)
    as face quality, quality (n,) as vertex quality, uv (m, 3, 2) (quasidev.flatten's texture
    coordinates per corner) as the face texcoord MeshLab reads. The file is written atomically:
    it is replaced only once complete. The arrays are not modified."""
    V64, F64, ids = _arrays.mesh(V, F, patches)
    values = None
    if quality is not None:
        values = np.array(quality, dtype=np.float64, order="C", copy=True)
        if values.shape != (len(V64),):
            raise ValueError(f"quality must have shape ({len(V64)},), got {values.shape}")
    corners = None
    if uv is not None:
        corners = np.array(uv, dtype=np.float64, order="C", copy=True)
        if corners.shape != (len(F64), 3, 2):
            raise ValueError(f"uv must have shape ({len(F64)}, 3, 2), got {corners.shape}")
    _engine.write(os.fspath(path), V64, F64, ids, values, corners)
