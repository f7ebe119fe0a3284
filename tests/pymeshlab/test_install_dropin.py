"""README install route 2: the .so dropped into pymeshlab/lib/plugins makes ms.<python name>(...)
exist at import. Checked on a symlink copy of the installed package (the venv stays untouched)."""
from __future__ import annotations

import os
import shutil
import subprocess
import sys

from pymeshlab_paths import FILTER, PLUGIN, require_file, sample


def overlay_package(dest: str) -> str:
    """A pymeshlab package under dest whose files link to the installed one, with its own
    lib/plugins directory; returns the directory to put on PYTHONPATH."""
    import pymeshlab
    src = os.path.dirname(pymeshlab.__file__)
    pkg = os.path.join(dest, "pymeshlab")
    os.makedirs(os.path.join(pkg, "lib", "plugins"))
    for sub, skip in (("", "lib"), ("lib", "plugins"), (os.path.join("lib", "plugins"), None)):
        for name in os.listdir(os.path.join(src, sub)):
            if name != skip:
                os.symlink(os.path.join(src, sub, name), os.path.join(pkg, sub, name))
    return dest


def test_dropped_in_plugin_is_a_meshset_method(tmp_path):
    require_file(PLUGIN, "build the filter_quasidev_pymeshlab target")
    root = overlay_package(str(tmp_path))
    shutil.copy(PLUGIN, os.path.join(root, "pymeshlab", "lib", "plugins", "libfilter_quasidev.so"))
    code = (
        "import pymeshlab, sys\n"
        f"assert pymeshlab.__file__.startswith({root!r}), pymeshlab.__file__\n"
        "ms = pymeshlab.MeshSet()\n"
        f"ms.load_new_mesh({sample('bumpy_cone.ply')!r})\n"
        f"fig = ms.{FILTER}(max_iter=3)\n"
        "print('ABD', fig['abd_reduction'], fig['iterations'])\n")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300,
                       env={**os.environ, "PYTHONPATH": root}, cwd=str(tmp_path))
    assert r.returncode == 0, r.stdout + r.stderr
    assert "Warning" not in r.stdout, r.stdout  # pymeshlab warns at import about refused plugins
    _, abd, iterations = r.stdout.split()
    assert float(abd) > 0 and 1 <= int(iterations) <= 3
