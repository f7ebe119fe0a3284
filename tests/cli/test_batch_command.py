"""`quasidev batch` hands its arguments to the Python package's batch (`python -m quasidev
batch`; tests/python/test_batch.py runs it with the package installed). Here: without the
package, or without a Python, it fails with one clear line and writes nothing."""
import os
import pathlib
import subprocess
import sys

import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]
BUILD = pathlib.Path(os.environ.get("QD_BUILD_DIR", REPO / "build"))
BINARY = pathlib.Path(os.environ.get("QUASIDEV", BUILD / "bin" / "quasidev"))

pytestmark = pytest.mark.skipif(not BINARY.exists(), reason=f"{BINARY} not built")


def batch(tmp_path, python):
    env = {**os.environ, "QD_PYTHON": python}
    return subprocess.run([str(BINARY), "batch", str(REPO / "sample_meshes"), "-o", str(tmp_path / "out")],
                          capture_output=True, text=True, env=env, timeout=60)


def test_a_python_without_the_package_is_named_with_the_fix(tmp_path):
    probe = subprocess.run([sys.executable, "-c", "import quasidev"], capture_output=True)
    if probe.returncode == 0:
        pytest.skip(f"{sys.executable} has the quasidev package")
    r = batch(tmp_path, sys.executable)
    assert r.returncode == 1
    assert r.stderr.startswith("quasidev: error: ") and "pip install ." in r.stderr
    assert sys.executable in r.stderr and not (tmp_path / "out").exists()


def test_a_missing_python_is_a_usage_error(tmp_path):
    r = batch(tmp_path, str(tmp_path / "no_python"))
    assert r.returncode == 2
    assert "cannot start" in r.stderr and "QD_PYTHON" in r.stderr
    assert len(r.stderr.strip().splitlines()) == 1 and not (tmp_path / "out").exists()


def test_the_help_names_the_batch():
    r = subprocess.run([str(BINARY), "--help"], capture_output=True, text=True, timeout=60)
    assert r.returncode == 0 and "quasidev batch" in r.stdout
