"""scripts/install_plugin.sh, user-prefix mode (MESHLAB.md §3.2), for real: the launcher it makes
runs a meshlabserver that loads our plugin, and --uninstall removes exactly what it made."""
from __future__ import annotations

import os
import re
import subprocess
from pathlib import Path

from ml2020_support import FILTER_NAME, REPO, XVFB

INSTALL = ["bash", str(REPO / "scripts" / "install_plugin.sh")]


def install(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run(INSTALL + list(args), capture_output=True, text=True, check=False)


def test_user_install_loads_the_plugin_and_uninstall_removes_it(plugin_path, tmp_path):
    prefix, bindir = tmp_path / "opt" / "meshlab2020", tmp_path / "bin"
    done = install("--user", "--prefix", str(prefix), "--bin-dir", str(bindir), "--plugin", str(plugin_path))
    assert done.returncode == 0, done.stderr
    server = prefix / "bin" / "meshlabserver"
    assert server.is_file() and not server.is_symlink(), "the binary must be a copy (MESHLAB.md §3.1)"
    plugins = prefix / "lib" / "x86_64-linux-gnu" / "meshlab" / "plugins"
    assert (plugins / "libfilter_quasidev.so").read_bytes() == plugin_path.read_bytes()
    assert (plugins / "libio_base.so").is_symlink(), "the system plugins must stay available"
    launcher = bindir / "meshlabserver2020"
    assert launcher.resolve() == server.resolve()

    dump = tmp_path / "filters.txt"
    run = subprocess.run(XVFB + [str(launcher), "-d", str(dump)], capture_output=True, text=True,
                         env=dict(os.environ, HOME=str(tmp_path)), check=False, timeout=120)
    assert f"Current Plugins Dir is: {plugins}" in run.stdout + run.stderr
    assert re.search(rf"^\\section f\d+ {FILTER_NAME} $", dump.read_text(), re.M), "filter not in the dump"

    done = install("--user", "--prefix", str(prefix), "--bin-dir", str(bindir), "--uninstall")
    assert done.returncode == 0, done.stderr
    assert not prefix.exists() and not launcher.exists() and not (bindir / "meshlab2020").exists()


def test_uninstall_refuses_a_directory_it_did_not_make(tmp_path):
    foreign = tmp_path / "precious"
    foreign.mkdir()
    (foreign / "data.txt").write_text("keep me")
    done = install("--user", "--prefix", str(foreign), "--bin-dir", "none", "--uninstall")
    assert done.returncode != 0 and "not made by this script" in done.stderr
    assert (foreign / "data.txt").read_text() == "keep me"
