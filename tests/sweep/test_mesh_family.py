"""The generated family's irregular triangulations (scripts/mesh_family.py `irregular`): the same
smooth surface, other triangles, none folded, and a name that gives the member back."""
import os
import sys

import numpy as np
import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import mesh_family  # noqa: E402


def corner_angles(V, F):
    a, b, c = (V[F[:, k]] for k in range(3))

    def angle(p, q, r):
        u, v = q - p, r - p
        return np.degrees(np.arccos(np.clip(np.einsum("ij,ij->i", u, v) /
                                            (np.linalg.norm(u, axis=1) * np.linalg.norm(v, axis=1)), -1, 1)))
    return np.stack([angle(a, b, c), angle(b, c, a), angle(c, a, b)], axis=1)


@pytest.mark.parametrize("base", mesh_family.BASES)
def test_irregular_members_keep_the_surface_and_fold_no_triangle(base):
    regular = mesh_family.Member(base, 0, 0.12, 0, 1, 3)
    irregular = mesh_family.Member(base, 0, 0.12, 0, 1, 3, 0.24)
    V0, F0 = mesh_family.make(regular)
    V1, F1 = mesh_family.make(irregular)
    assert V1.shape == V0.shape and F1.shape == F0.shape
    # Other triangles: interior vertices moved, the cells' diagonals changed.
    assert np.abs(V1 - V0).max() > 0.05 * mesh_family.average_edge(V0, F0)
    assert (np.sort(F1, axis=1) != np.sort(F0, axis=1)).any(axis=1).sum() > len(F0) // 4
    # No triangle folded: each faces the way its cell (two faces in a row, in both) does.
    def normals(V, F):
        return np.cross(V[F[:, 1]] - V[F[:, 0]], V[F[:, 2]] - V[F[:, 0]])
    cell = normals(V0, F0).reshape(-1, 2, 3).sum(axis=1)
    assert (np.einsum("ij,ij->i", normals(V1, F1), np.repeat(cell, 2, axis=0)) > 0).all()
    assert corner_angles(V1, F1).min() > 0.5
    # The same surface: on the cylinder every vertex stays at radius 1.
    if base == "cylinder":
        assert np.allclose(np.linalg.norm(V1[:, :2], axis=1), 1.0)


def test_the_name_gives_the_member_back_and_regular_names_stay_as_they_were():
    m = mesh_family.Member("cone", 1, 0.16, 0, 2, 4, 0.1)
    assert mesh_family.Member.from_name(m.name) == m
    assert mesh_family.Member("cone", 1, 0.16, 0, 2, 4).name == "cone_a1_w0.16_j0_r2_s4"
    with pytest.raises(ValueError):
        mesh_family.make(mesh_family.Member("plane", 0, 0.12, 0, 1, 1, 0.3))
