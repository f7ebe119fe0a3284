"""Fixtures of the pymeshlab tests (MeshLab 2025.07 core, pymeshlab 2025.7.post1):
`pymeshlab_with_plugin` (the module with our 2025.07d plugin loaded once per session) and
`meshset(path)` (a new MeshSet with one mesh loaded). Paths: pymeshlab_paths.py."""
from __future__ import annotations

import pytest

from pymeshlab_paths import BUILD, FILTER, PLUGIN, require_file


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
        require_file(path, "sample meshes: scripts/make_samples.py; tests/data/: in the repository")
        ms = pymeshlab_with_plugin.MeshSet()
        ms.load_new_mesh(path)
        return ms
    return make
