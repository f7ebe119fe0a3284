"""quasidev.segment on numpy arrays: patch ids 0..k-1 per face, the same as the command's, the
report's figures, and the engine's message for bad parameters."""

import json
import subprocess

import numpy as np
import pytest
import quasidev
from conftest import CYLINDER, read_ply


def test_patches_equal_the_command_output(cylinder, quasidev_command, tmp_path):
    V, F, _ = cylinder
    out, report = tmp_path / "seg.ply", tmp_path / "seg.json"
    subprocess.run([str(quasidev_command), "segment", str(CYLINDER), str(out), "--report",
                    str(report), "--max-error-deg", "5", "--quiet"], check=True, timeout=600)
    r = quasidev.segment(np.asfortranarray(V), F.astype(np.int32), max_error_deg=5.0)
    _, _, quality = read_ply(out)
    command = json.loads(report.read_text())
    assert r.patches.shape == (len(F),) and r.patches.dtype == np.int64
    assert np.array_equal(r.patches, np.rint(quality).astype(np.int64))
    k = r.report["patch_count"]
    assert k == command["patch_count"] and k >= 2
    assert set(np.unique(r.patches)) == set(range(k))
    assert r.report["parameters"] == command["parameters"]
    assert [p["faces"] for p in r.report["patches"]] == [int(np.sum(r.patches == i)) for i in range(k)]


def test_bad_parameter_and_mesh_raise_value_error(cylinder):
    V, F, _ = cylinder
    with pytest.raises(ValueError, match="max_error_deg must be greater than 0, got 0"):
        quasidev.segment(V, F, max_error_deg=0)
    with pytest.raises(ValueError, match="unknown parameter 'tolerance_ae'"):
        quasidev.segment(V, F, tolerance_ae=1)
    with pytest.raises(ValueError):
        quasidev.segment(np.zeros((3, 3)), [[0, 1, 2]])
