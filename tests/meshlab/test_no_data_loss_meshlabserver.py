"""No data loss through the real meshlabserver 2020.09 (issue 6, bullet 5).

A copy of sample_meshes/selected.ply gets every attribute the filter does not own: vertex colours,
vertex and per-wedge texture coordinates, vertex and face selection (PLY flags), face quality
(= patch id), face colours, and a custom per-vertex attribute. One meshlabserver job defines the
custom attribute (= the input x), runs our filter with colourising off, then copies the attribute
into vertex quality so that it reaches the saved file. Every one of those values must be
bit-identical after the filter, while the positions did change.
MeshLab 2020.09 can neither save a custom per-face attribute from meshlabserver nor read one in
an expression, so that case is checked through pymeshlab only (test_no_data_loss_pymeshlab.py).
"""
from __future__ import annotations

import numpy as np

from plyfile import PlyData

from ml2020_support import REPO, SELECTED, run_meshlabserver, write_mlx
from ply_columns import column, element, faces, positions

VERTEX_KEPT = ("flags", "red", "green", "blue", "alpha", "texture_u", "texture_v")
FACE_KEPT = ("flags", "quality", "red", "green", "blue", "alpha", "texcoord")

# "Define New Per Vertex Attribute" before our filter, "Per Vertex Quality Function" after it.
DEFINE_ATTRIBUTE = """ <filter name="Define New Per Vertex Attribute">
  <Param name="name" type="RichString" value="qd_custom" description="Name"/>
  <Param name="expr" type="RichString" value="x" description="Function ="/>
 </filter>
"""
ATTRIBUTE_TO_QUALITY = """ <filter name="Per Vertex Quality Function">
  <Param name="q" type="RichString" value="qd_custom" description="func q = "/>
  <Param name="normalize" type="RichBool" value="false" description="normalize"/>
  <Param name="map" type="RichBool" value="false" description="map into color"/>
  <Param name="onselected" type="RichBool" value="false" description="only on selection"/>
 </filter>
"""


def decorated_input(path) -> None:
    """selected.ply with float positions and every attribute above, from a fixed random seed."""
    ply = PlyData.read(REPO / "sample_meshes" / "selected.ply")
    rng = np.random.default_rng(6)
    vert, face = ply["vertex"], ply["face"]
    uchar = ("red", "green", "blue", "alpha")
    vcols = [(p.name, "f4" if p.name in "xyz" else vert[p.name].dtype, vert[p.name])
             for p in vert.properties]
    vcols += [(c, "u1", rng.integers(0, 256, vert.count)) for c in uchar]
    vcols += [(c, "f4", rng.random(vert.count)) for c in ("texture_u", "texture_v")]
    fcols = [("vertex_indices", ("u1", "i4"), face["vertex_indices"]),
             ("flags", "i4", [SELECTED if k % 7 == 0 else 0 for k in range(face.count)]),
             ("quality", "f4", face["quality"])]
    fcols += [(c, "u1", rng.integers(0, 256, face.count)) for c in uchar]
    fcols.append(("texcoord", ("u1", "f4"), rng.random((face.count, 6))))
    PlyData([element("vertex", vcols), element("face", fcols)], comments=ply.comments).write(path)


def test_every_attribute_the_filter_does_not_own_is_bit_identical(meshlab_prefix, tmp_path):
    decorated_input(tmp_path / "in.ply")
    script = write_mlx(tmp_path / "job.mlx", {"colorize": False}, before=DEFINE_ATTRIBUTE,
                       after=ATTRIBUTE_TO_QUALITY)
    run = run_meshlabserver(meshlab_prefix, tmp_path / "in.ply", tmp_path / "out.ply", script,
                            saved=("vc", "vf", "vq", "vt", "fc", "ff", "fq", "wt"))
    assert run.returncode == 0, run.stdout[-3000:]
    given, out = PlyData.read(tmp_path / "in.ply"), PlyData.read(tmp_path / "out.ply")
    assert any(f & SELECTED for f in column(given, "vertex", "flags"))
    for prop in VERTEX_KEPT:
        assert column(out, "vertex", prop) == column(given, "vertex", prop), f"vertex {prop} changed"
    for prop in FACE_KEPT:
        assert column(out, "face", prop) == column(given, "face", prop), f"face {prop} changed"
    assert faces(out) == faces(given)
    assert column(out, "vertex", "quality") == column(given, "vertex", "x"), "the custom attribute changed"
    moved = np.abs(positions(out) - positions(given)).max()
    assert moved > 1e-3, "the filter did not move the vertices"
