"""The 2025.07d plugin against the real pymeshlab 2025.7.post1 wheel: what the wheel needs from a
plugin (MESHLAB.md §5.5), checked on the built .so and by loading it in a fresh interpreter."""
from __future__ import annotations

import os
import re
import subprocess
import sys

import pytest

from pymeshlab_paths import FILTER, FLOAT_PLUGIN, PLUGIN, require_file

# Libraries every Linux host has (glibc, libgcc, libstdc++); everything else must be in the wheel.
BASE_LIBS = {"libc.so.6", "libm.so.6", "libgcc_s.so.1", "libstdc++.so.6", "ld-linux-x86-64.so.2"}


def dynamic_section(path: str) -> str:
    return subprocess.run(["readelf", "-d", path], check=True, capture_output=True, text=True).stdout


def wheel_lib_dir() -> str:
    import pymeshlab
    return os.path.join(os.path.dirname(pymeshlab.__file__), "lib")


def run_python(code: str, env: dict | None = None) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          env={**os.environ, **(env or {})}, timeout=300)


def test_plugin_needs_libmeshlab_common_and_only_libraries_the_wheel_or_libc_provide():
    require_file(PLUGIN, "build the filter_quasidev_pymeshlab target")
    needed = re.findall(r"\(NEEDED\)\s+Shared library: \[(.+?)\]", dynamic_section(PLUGIN))
    # RTLD_LOCAL host: without this entry FilterPlugin's typeinfo is unresolved at dlopen.
    assert "libmeshlab-common.so" in needed
    in_wheel = set(os.listdir(wheel_lib_dir()))
    foreign = [lib for lib in needed if lib not in in_wheel and lib not in BASE_LIBS]
    assert foreign == [], f"the wheel does not ship {foreign} (e.g. libGLEW: it has libexternal-glew)"


def test_plugin_has_no_runpath_into_a_build_or_venv():
    require_file(PLUGIN, "build the filter_quasidev_pymeshlab target")
    assert not re.search(r"\((RUNPATH|RPATH)\)", dynamic_section(PLUGIN))


def test_wheel_bundles_qt_5_15_which_accepts_our_qt_5_15_plugin_metadata():
    with open(os.path.join(wheel_lib_dir(), "libQt5Core.so.5"), "rb") as f:
        version = re.search(rb"Qt (5\.\d+\.\d+) \(x86_64", f.read()).group(1).decode()
    assert version.startswith("5.15."), version  # QLibrary: same major, plugin minor <= host minor


def test_loading_uses_only_the_wheels_qt_and_libmeshlab_common():
    require_file(PLUGIN, "build the filter_quasidev_pymeshlab target")
    code = (f"import pymeshlab; pymeshlab.load_plugin({PLUGIN!r}); "
            f"assert {FILTER!r} in pymeshlab.filter_list()")
    r = run_python(code, {"LD_DEBUG": "files"})
    assert r.returncode == 0, r.stderr[-2000:]
    loaded = set(re.findall(r"calling init: (\S+)", r.stderr))
    ours = [p for p in loaded if re.search(r"libQt5|libmeshlab-common|libGLEW|glew", p)]
    assert ours, "LD_DEBUG output not understood"
    outside = [p for p in ours if not p.startswith(wheel_lib_dir())]
    assert outside == [], f"a second copy was loaded: {outside}"
    assert PLUGIN in loaded


def test_float_variant_is_refused_with_the_precision_message():
    require_file(FLOAT_PLUGIN, "build the filter_quasidev_meshlab2025 target")
    r = run_python(f"import pymeshlab\ntry:\n pymeshlab.load_plugin({FLOAT_PLUGIN!r})\n"
                   f"except pymeshlab.PyMeshLabException as e:\n print('REFUSED', e)\n")
    assert "REFUSED" in r.stdout, r.stdout + r.stderr
    assert "different floating point precision" in r.stdout


@pytest.mark.parametrize("path, scalar", [(PLUGIN, "double"), (FLOAT_PLUGIN, "float")])
def test_each_variant_uses_its_own_scalar_in_meshlab_signatures(path, scalar):
    require_file(path, "build the filter_quasidev_pymeshlab / filter_quasidev_meshlab2025 targets")
    undefined = subprocess.run(["nm", "-DC", "--undefined-only", path], check=True,
                               capture_output=True, text=True).stdout
    assert f"RichFloat::RichFloat(QString const&, {scalar}, " in undefined
