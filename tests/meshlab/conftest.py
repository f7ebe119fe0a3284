"""Fixtures of the MeshLab integration tests: the built plugin, a private MeshLab 2020.09
prefix (MESHLAB.md §3.2) made by scripts/install_plugin.sh --user, one per test session; and for
the GUI tests of both generations (gui_support.py) a private Xvfb display and the window probe."""
from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import pytest

from gui_support import Display, build_probe
from ml2020_support import REPO, build_dir


@pytest.fixture(scope="session")
def plugin_path() -> Path:
    path = build_dir() / "bin" / "plugins" / "libfilter_quasidev.so"
    assert path.is_file(), (f"{path} missing: build it (scripts/setup.sh, then cmake --build "
                            f"{build_dir()}) or set QD_BUILD_DIR")
    return path


@pytest.fixture(scope="session")
def quasidev_path() -> Path:
    path = build_dir() / "bin" / "quasidev"
    assert path.is_file(), f"{path} missing: build the project first or set QD_BUILD_DIR"
    return path


@pytest.fixture(scope="session")
def meshlab_prefix(plugin_path, tmp_path_factory) -> Path:
    """A private MeshLab 2020.09 prefix with our plugin, installed the way a user without root
    would (copied binaries, linked system plugins)."""
    for tool in ("xvfb-run", "meshlabserver"):
        assert shutil.which(tool), f"{tool} missing: run scripts/setup.sh"
    prefix = tmp_path_factory.mktemp("meshlab2020") / "prefix"
    done = subprocess.run(["bash", str(REPO / "scripts" / "install_plugin.sh"), "--user",
                           "--prefix", str(prefix), "--bin-dir", "none", "--plugin", str(plugin_path)],
                          capture_output=True, text=True, check=False)
    assert done.returncode == 0, done.stdout + done.stderr
    return prefix


@pytest.fixture(scope="session")
def probe_lib(tmp_path_factory) -> Path:
    """gui_probe.cpp built against the host's Qt, once per session."""
    return build_probe(tmp_path_factory.mktemp("gui_probe"))


@pytest.fixture
def display(tmp_path):
    d = Display(tmp_path)
    try:
        yield d
    finally:
        d.close()
