"""No data loss through the real pymeshlab 2025.7.post1 (issue 6, bullet 5).

sample_meshes/patches.ply gets every attribute the filter does not own: vertex and face colours,
vertex and per-wedge texture coordinates, face quality (= patch id), vertex and face selection,
and custom per-vertex and per-face attributes (scalar and point). After the filter with
colourising off each of them is bit-identical, while the positions did change.
"""
from __future__ import annotations

import numpy as np

from pymeshlab_paths import FILTER, sample


def decorated_meshset(pymeshlab):
    plain = pymeshlab.MeshSet()
    plain.load_new_mesh(sample("patches.ply"))
    m = plain.current_mesh()
    V, F, patch = m.vertex_matrix(), m.face_matrix(), m.face_scalar_array()
    nv, nf = len(V), len(F)
    rng = np.random.default_rng(5)
    ms = pymeshlab.MeshSet()
    ms.add_mesh(pymeshlab.Mesh(vertex_matrix=V, face_matrix=F, f_scalar_array=patch,
                               v_color_matrix=rng.integers(0, 256, (nv, 4)) / 255.0,
                               f_color_matrix=rng.integers(0, 256, (nf, 4)) / 255.0,
                               v_tex_coords_matrix=rng.random((nv, 2)),
                               w_tex_coords_matrix=rng.random((3 * nf, 2))))
    # Custom attributes go on the MeshSet's own mesh: added to a free Mesh, they crash add_mesh.
    mesh = ms.current_mesh()
    mesh.add_vertex_custom_scalar_attribute(rng.random(nv), "qd_vertex_scalar")
    mesh.add_face_custom_scalar_attribute(rng.random(nf), "qd_face_scalar")
    mesh.add_vertex_custom_point_attribute(rng.random((nv, 3)), "qd_vertex_point")
    mesh.add_face_custom_point_attribute(rng.random((nf, 3)), "qd_face_point")
    ms.compute_selection_by_condition_per_face(condselect="fi/7 == rint(fi/7)")
    ms.compute_selection_by_condition_per_vertex(condselect="vi/11 == rint(vi/11)")
    return ms


def kept_attributes(mesh) -> dict[str, np.ndarray]:
    return {
        "faces": mesh.face_matrix(),
        "vertex colour": mesh.vertex_color_matrix(),
        "face colour": mesh.face_color_matrix(),
        "vertex texture coordinates": mesh.vertex_tex_coord_matrix(),
        "wedge texture coordinates": mesh.wedge_tex_coord_matrix(),
        "face quality": mesh.face_scalar_array(),
        "vertex selection": mesh.vertex_selection_array(),
        "face selection": mesh.face_selection_array(),
        "custom vertex scalar": mesh.vertex_custom_scalar_attribute_array("qd_vertex_scalar"),
        "custom face scalar": mesh.face_custom_scalar_attribute_array("qd_face_scalar"),
        "custom vertex point": mesh.vertex_custom_point_attribute_matrix("qd_vertex_point"),
        "custom face point": mesh.face_custom_point_attribute_matrix("qd_face_point"),
    }


def test_every_attribute_the_filter_does_not_own_is_bit_identical(pymeshlab_with_plugin):
    ms = decorated_meshset(pymeshlab_with_plugin)
    before = {k: v.copy() for k, v in kept_attributes(ms.current_mesh()).items()}
    V0 = ms.current_mesh().vertex_matrix().copy()
    assert before["vertex selection"].sum() > 100 and before["face selection"].sum() > 100
    assert len(np.unique(before["face quality"])) == 4
    ms.apply_filter(FILTER, colorize=False)
    after = kept_attributes(ms.current_mesh())
    for name, values in before.items():
        same = after[name].dtype == values.dtype and np.array_equal(after[name], values)
        assert same, f"{name} changed"
    assert np.abs(ms.current_mesh().vertex_matrix() - V0).max() > 1e-3, "the filter did not run"
