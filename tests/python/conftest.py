"""Shared fixtures of the quasidev Python package's tests (run by tests/python/run.sh against the
installed package): the sample mesh as arrays and the quasidev command of $QD_BUILD_DIR."""

import os
import pathlib

import numpy as np
import plyfile
import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]
BUILD = pathlib.Path(os.environ.get("QD_BUILD_DIR", REPO / "build"))
CYLINDER = REPO / "sample_meshes" / "bumpy_cylinder.ply"


def read_ply(path):
    """(V, F, per-face quality or None) of a PLY file."""
    ply = plyfile.PlyData.read(str(path))
    v = ply["vertex"]
    V = np.stack([np.asarray(v[c], dtype=np.float64) for c in "xyz"], axis=1)
    F = np.vstack(ply["face"]["vertex_indices"]).astype(np.int64)
    names = [p.name for p in ply["face"].properties]
    quality = np.asarray(ply["face"]["quality"]) if "quality" in names else None
    return V, F, quality


@pytest.fixture(scope="session")
def cylinder():
    """The bumpy cylinder: V (n, 3), F (m, 3) and its patch ids (the rounded face quality)."""
    V, F, quality = read_ply(CYLINDER)
    return V, F, np.rint(quality).astype(np.int64)


@pytest.fixture(scope="session")
def quasidev_command():
    path = pathlib.Path(os.environ.get("QUASIDEV", BUILD / "bin" / "quasidev"))
    if not path.exists():
        pytest.fail(f"the quasidev command is not built at {path} (set QD_BUILD_DIR)")
    return path
