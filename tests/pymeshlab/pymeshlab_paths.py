"""Paths and helpers of the pymeshlab tests (a module name of its own, so the tests can import it
whatever other conftest.py files pytest loads).

Inputs: the build directory (env QD_BUILD_DIR, default <repo>/build) holding
bin/pymeshlab/libfilter_quasidev.so (the 2025.07d plugin), bin/meshlab2025/ (the float variant)
and bin/quasidev (the CLI); the meshes in sample_meshes/ (generated) and tests/data/ (public
meshes, tests/data/SOURCES.md), both in the repository.
"""
from __future__ import annotations

import os
import sys

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BUILD = os.environ.get("QD_BUILD_DIR", os.path.join(ROOT, "build"))
PLUGIN = os.path.join(BUILD, "bin", "pymeshlab", "libfilter_quasidev.so")
FLOAT_PLUGIN = os.path.join(BUILD, "bin", "meshlab2025", "libfilter_quasidev.so")
CLI = os.path.join(BUILD, "bin", "quasidev")
SAMPLES = os.path.join(ROOT, "sample_meshes")
DATA = os.path.join(ROOT, "tests", "data")
FILTER = "apply_coord_quasi_developable_approximation"
SEGMENT_FILTER = "compute_segmentation_quasi_developable"
FLATTEN_FILTER = "compute_texcoord_quasi_developable_flattening"

sys.path.insert(0, os.path.join(ROOT, "scripts"))  # compare_developability: K, AE; flat_measures

# pymeshlab 2025.7.post1 bug (seen with MeshLab's own filters too): destroying a MeshSet on which
# a filter raised corrupts the heap, and a later MeshSet crashes at random (SIGSEGV, abort,
# std::bad_alloc). Keeping such MeshSets referenced until the process ends avoids it.
FAILED_MESHSETS: list = []


def sample(name: str) -> str:
    return os.path.join(SAMPLES, name)


def data(name: str) -> str:
    return os.path.join(DATA, name)


def require_file(path: str, how: str) -> None:
    if not os.path.isfile(path):
        pytest.fail(f"missing {path}: {how}")
