"""quasidev.read and quasidev.write: the command's reader gives the file's arrays and patch ids,
the writer's PLY reads back to the same arrays, and a failed write leaves the target as it was."""

import numpy as np
import plyfile
import pytest
import quasidev
from conftest import CYLINDER


def test_read_gives_the_files_arrays(cylinder):
    V, F, patches = cylinder
    mesh = quasidev.read(CYLINDER)
    assert mesh.V.dtype == np.float64 and mesh.F.dtype == np.int64
    assert np.array_equal(mesh.V, V) and np.array_equal(mesh.F, F)
    assert np.array_equal(mesh.patches, patches)
    assert mesh.fixed is None


def test_write_reads_back(cylinder, tmp_path):
    V, F, patches = cylinder
    k = np.linspace(-1, 1, len(V))
    path = tmp_path / "out.ply"
    quasidev.write(path, np.asfortranarray(V), F.astype(np.int32), patches=patches, quality=k)
    back = quasidev.read(str(path))
    assert np.array_equal(back.V, V) and np.array_equal(back.F, F)
    assert np.array_equal(back.patches, patches)
    assert np.array_equal(plyfile.PlyData.read(str(path))["vertex"]["quality"], k)


def test_a_failed_write_leaves_the_target(cylinder, tmp_path):
    V, F, _ = cylinder
    path = tmp_path / "out.ply"
    path.write_bytes(b"old")
    with pytest.raises(ValueError):
        quasidev.write(path, V, F, quality=np.zeros(3))
    with pytest.raises(ValueError):
        quasidev.write(tmp_path / "no_such_dir" / "out.ply", V, F)
    assert path.read_bytes() == b"old"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out.ply"]


def test_read_refuses_a_missing_or_bad_file(tmp_path):
    with pytest.raises(ValueError):
        quasidev.read(tmp_path / "missing.ply")
    bad = tmp_path / "bad.ply"
    bad.write_text("ply\nformat ascii 1.0\nelement vertex 1\nend_header\n")
    with pytest.raises(ValueError):
        quasidev.read(bad)
