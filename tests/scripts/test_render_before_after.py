"""scripts/render_before_after.py: both panels are drawn, on one |K| scale, and the title figures
are printed."""
import os
import subprocess
import sys

import numpy as np
import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BUILD = os.environ.get("QD_BUILD_DIR", os.path.join(ROOT, "build"))
QUASIDEV = os.path.join(BUILD, "bin", "quasidev")


def test_bumpy_cone_before_after(tmp_path):
    pytest.importorskip("pymeshlab")
    pytest.importorskip("matplotlib")
    from PIL import Image
    if not os.access(QUASIDEV, os.X_OK):
        pytest.skip(f"no quasidev at {QUASIDEV}")
    out = tmp_path / "cone.png"
    proc = subprocess.run([sys.executable, os.path.join(ROOT, "scripts", "render_before_after.py"),
                           os.path.join(ROOT, "sample_meshes", "bumpy_cone.ply"), "-o", str(out),
                           "--quasidev", QUASIDEV, "--panel", "240"],
                          capture_output=True, text=True, timeout=60)
    assert proc.returncode == 0, proc.stderr
    assert "G_ABD" in proc.stdout and "Hausdorff/diag" in proc.stdout
    img = np.asarray(Image.open(out).convert("RGB")).astype(int)
    h, w, _ = img.shape
    for half in (img[h // 5:, : w * 2 // 5], img[h // 5:, w * 2 // 5: w * 4 // 5]):
        assert (np.abs(half - 255).sum(axis=2) > 60).mean() > 0.1  # a mesh is drawn in each panel
