"""Bad input through pymeshlab: PyMeshLabException carrying our message, the mesh unchanged."""
from __future__ import annotations

import numpy as np
import pytest

from pymeshlab_paths import FAILED_MESHSETS, FILTER, sample


def expect_failure(pymeshlab, ms, **kwargs) -> str:
    """Applies the filter expecting our error; checks the mesh is untouched; returns the details."""
    m = ms.current_mesh()
    V0, C0 = m.vertex_matrix().copy(), m.vertex_color_matrix().copy()
    FAILED_MESHSETS.append(ms)
    with pytest.raises(pymeshlab.PyMeshLabException) as info:
        ms.apply_filter(FILTER, **kwargs)
    text = str(info.value)
    assert text.startswith(f"Failed to apply filter: {FILTER}")
    m = ms.current_mesh()
    np.testing.assert_array_equal(m.vertex_matrix(), V0)
    np.testing.assert_array_equal(m.vertex_color_matrix(), C0)
    return text.split("Details:", 1)[1].strip()


def add_mesh(pymeshlab, V, F=None):
    ms = pymeshlab.MeshSet()
    if F is None:
        ms.add_mesh(pymeshlab.Mesh(vertex_matrix=V))
    else:
        ms.add_mesh(pymeshlab.Mesh(vertex_matrix=V, face_matrix=F))
    return ms


def test_point_cloud(pymeshlab_with_plugin):
    ms = add_mesh(pymeshlab_with_plugin, np.random.default_rng(1).random((20, 3)))
    assert "no faces" in expect_failure(pymeshlab_with_plugin, ms)


def test_nan_coordinates(pymeshlab_with_plugin):
    V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, np.nan]], dtype=float)
    ms = add_mesh(pymeshlab_with_plugin, V, np.array([[0, 1, 2], [1, 3, 2]]))
    assert "NaN or infinite coordinates" in expect_failure(pymeshlab_with_plugin, ms)


@pytest.mark.parametrize("kwargs, words", [
    ({"weight": -1.0}, "Developability weight (weight) must be greater than 0, got -1"),
    ({"max_iter": 0}, "Max iterations (max_iter) must be at least 1, got 0"),
    ({"tolerance_model": -0.5}, "Tolerance (model units) (tolerance_model) must not be negative, got -0.5"),
    ({"stop_abd": 150.0}, "Stop at ratio_ABD (%) (stop_abd) must be below 100, got 150"),
    ({"patch_tolerance_ae": "3=x"}, "Per-patch tolerance (AE) (patch_tolerance_ae) expects ID=X items"),
])
def test_absurd_parameters(meshset, pymeshlab_with_plugin, kwargs, words):
    assert words in expect_failure(pymeshlab_with_plugin, meshset(sample("bumpy_cylinder.ply")), **kwargs)


def test_everything_constrained(meshset, pymeshlab_with_plugin):
    ms = meshset(sample("bumpy_cone.ply"))
    ms.set_selection_all()
    assert "constrained" in expect_failure(pymeshlab_with_plugin, ms)
