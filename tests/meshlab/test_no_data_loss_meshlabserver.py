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

from ml2020_support import (REPO, SELECTED, PlyProperty, read_ply, run_meshlabserver, write_mlx,
                            write_ply)

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
    ply = read_ply(REPO / "sample_meshes" / "selected.ply")
    rng = np.random.default_rng(6)
    vertices, faces = ply.elements["vertex"], ply.elements["face"]
    for prop in vertices.properties:
        if prop.name in "xyz":
            prop.type = "float"
            vertices.data[prop.name] = [float(c) for c in np.float32(vertices.data[prop.name])]
    uchar = ("red", "green", "blue", "alpha")
    vertices.properties += [PlyProperty(c, "uchar") for c in uchar]
    vertices.properties += [PlyProperty(c, "float") for c in ("texture_u", "texture_v")]
    for c in uchar:
        vertices.data[c] = [int(x) for x in rng.integers(0, 256, vertices.count)]
    for c in ("texture_u", "texture_v"):
        vertices.data[c] = [float(x) for x in np.float32(rng.random(vertices.count))]
    faces.properties.insert(1, PlyProperty("flags", "int"))
    faces.data["flags"] = [SELECTED if k % 7 == 0 else 0 for k in range(faces.count)]
    faces.properties += [PlyProperty(c, "uchar") for c in uchar]
    faces.properties.append(PlyProperty("texcoord", "float", "uchar"))
    for c in uchar:
        faces.data[c] = [int(x) for x in rng.integers(0, 256, faces.count)]
    corners = np.float32(rng.random((faces.count, 6)))
    faces.data["texcoord"] = [tuple(float(x) for x in row) for row in corners]
    write_ply(path, ply)


def test_every_attribute_the_filter_does_not_own_is_bit_identical(meshlab_prefix, tmp_path):
    decorated_input(tmp_path / "in.ply")
    script = write_mlx(tmp_path / "job.mlx", {"colorize": False}, before=DEFINE_ATTRIBUTE,
                       after=ATTRIBUTE_TO_QUALITY)
    run = run_meshlabserver(meshlab_prefix, tmp_path / "in.ply", tmp_path / "out.ply", script,
                            saved=("vc", "vf", "vq", "vt", "fc", "ff", "fq", "wt"))
    assert run.returncode == 0, run.stdout[-3000:]
    given, out = read_ply(tmp_path / "in.ply"), read_ply(tmp_path / "out.ply")
    assert any(f & SELECTED for f in given.get("vertex", "flags"))
    for prop in VERTEX_KEPT:
        assert out.get("vertex", prop) == given.get("vertex", prop), f"vertex {prop} changed"
    for prop in FACE_KEPT:
        assert out.get("face", prop) == given.get("face", prop), f"face {prop} changed"
    assert out.faces() == given.faces()
    assert out.get("vertex", "quality") == given.get("vertex", "x"), "the custom attribute changed"
    moved = np.abs(np.array(out.vertices()) - np.array(given.vertices())).max()
    assert moved > 1e-3, "the filter did not move the vertices"
