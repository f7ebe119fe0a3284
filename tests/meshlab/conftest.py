"""Fixtures of the MeshLab 2020.09 integration tests: the built plugin, and a private MeshLab
prefix (MESHLAB.md §3.2) made by scripts/install_plugin.sh --user, one per test session."""
from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import pytest

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
