"""Shared fixtures of the pymeshlab tests (MeshLab 2025.07 core, pymeshlab 2025.7.post1).

Inputs: the build directory (env QD_BUILD_DIR, default <repo>/build) holding
bin/pymeshlab/libfilter_quasidev.so (the 2025.07d plugin) and bin/quasidev (the CLI), and the
meshes in sample_meshes/ and /work/shared/meshes/ (env QD_SHARED_MESHES).
Outputs: fixtures `pymeshlab_with_plugin` (the module, plugin loaded once per session),
`meshset(path)` (a new MeshSet with one mesh loaded) and paths.
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
SHARED = os.environ.get("QD_SHARED_MESHES", "/work/shared/meshes")
FILTER = "apply_coord_quasi_developable_approximation"

sys.path.insert(0, os.path.join(ROOT, "scripts"))  # compare_developability: K, AE


def sample(name: str) -> str:
    return os.path.join(SAMPLES, name)


def shared(name: str) -> str:
    return os.path.join(SHARED, name)


def require_file(path: str, how: str) -> None:
    if not os.path.isfile(path):
        pytest.fail(f"missing {path}: {how}")


@pytest.fixture(scope="session")
def pymeshlab_with_plugin():
    require_file(PLUGIN, f"build it: cmake --build {BUILD} --target filter_quasidev_pymeshlab")
    import pymeshlab
    if FILTER not in pymeshlab.filter_list():
        pymeshlab.load_plugin(PLUGIN)
    return pymeshlab


@pytest.fixture
def meshset(pymeshlab_with_plugin):
    def make(path: str):
        require_file(path, "sample meshes: scripts/make_samples.py; shared meshes: QD_SHARED_MESHES")
        ms = pymeshlab_with_plugin.MeshSet()
        ms.load_new_mesh(path)
        return ms
    return make
