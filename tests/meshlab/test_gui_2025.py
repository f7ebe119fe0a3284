"""The plugin in the real MeshLab 2025.07 GUI (Debian sid's meshlab 2025.07~dfsg-4, Qt 5) under
Xvfb, run in the sid chroot that scripts/setup_sid_chroot.sh makes once (issue 12, item 5).

The float plugin build/bin/meshlab2025/libfilter_quasidev.so is installed the two ways a user
does (README): as root into the package's plugin folder /usr/lib/x86_64-linux-gnu/meshlab/plugins
of the chroot, or without root into ~/.local/share/VCG/MeshLab_64bit_fp/MeshLabExtraPlugins/2025.07.
Then the scenario shared with MeshLab 2020.09 (gui_support.run_and_check, test_gui.py: the
approximation, the segmentation and the flattening each in its Filters submenu and in the filter
search, the approximation's dialog, Apply and export) runs on the GUI in the chroot, plus what
only 2025.07 has: no "Unable to load the following plugins" box
(any message box fails the run with its text) and the dialog's pymeshlab name.

The chroot's mounts (/dev, /proc, the X socket, the work dir) live in a private mount namespace of
the MeshLab process (sid_chroot.command); the fixture still checks, after every run, that nothing
is mounted in the chroot, and unmounts and fails if something is.
"""
from __future__ import annotations

import os
import shutil

import pytest

import sid_chroot
from gui_support import MeshLabApp, MeshLabGui, exercise_filter, run_and_check
from ml2020_support import FILTER_NAME, REPO, build_dir

PYMESHLAB_NAME = "apply_coord_quasi_developable_approximation"


@pytest.fixture(scope="session")
def sid_root():
    if sid_chroot.UNAVAILABLE.exists():
        pytest.skip(f"MeshLab 2025.07 GUI not tested: {sid_chroot.UNAVAILABLE.read_text().strip()}")
    assert sid_chroot.MARKER.is_file(), (f"no complete sid chroot at {sid_chroot.CHROOT}: run "
                                         f"scripts/setup.sh (or scripts/setup_sid_chroot.sh) as root")
    if os.geteuid() != 0:
        pytest.skip("MeshLab 2025.07 GUI not tested: running it in the sid chroot needs root "
                    "(unshare --mount, chroot)")
    for tool in ("unshare", "chroot"):
        assert shutil.which(tool), f"{tool} missing"
    return sid_chroot.CHROOT


@pytest.fixture(scope="session")
def plugin2025():
    path = build_dir() / "bin" / "meshlab2025" / "libfilter_quasidev.so"
    assert path.is_file(), f"{path} missing: cmake --build {build_dir()} --target filter_quasidev_meshlab2025"
    return path


@pytest.fixture(params=["system", "user"])
def meshlab2025(request, sid_root, plugin2025, display, probe_lib, tmp_path):
    if request.param == "system":
        installed = sid_root / sid_chroot.SYSTEM_PLUGINS / plugin2025.name
    else:
        installed = tmp_path / "home" / sid_chroot.USER_PLUGINS / plugin2025.name
    app = MeshLabApp(version="2025.07",
                     command=lambda mesh, env: sid_chroot.command(tmp_path, env, ["meshlab", str(mesh)]),
                     app_path=lambda path: sid_chroot.app_path(tmp_path, path),
                     applied_line=f"Applied filter: {FILTER_NAME}")
    gui = MeshLabGui(display, app, tmp_path, probe_lib)
    try:
        installed.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy(plugin2025, installed)
        yield gui
    finally:
        gui.stop()
        if request.param == "system":
            installed.unlink(missing_ok=True)
        left = sid_chroot.unmount_all(sid_root)
        assert not left, f"left mounted in the sid chroot (now unmounted): {left}"


def test_gui_2025_menu_search_dialog_apply_and_export(meshlab2025, tmp_path):
    run = run_and_check(meshlab2025, tmp_path)
    texts = run.dialog.texts()
    assert "PyMeshLab Filter" in texts and PYMESHLAB_NAME in texts, run.dialog.describe()


@pytest.mark.parametrize("meshlab2025", ["user"], indirect=True)
def test_gui_2025_run_fails_on_plugin_load_errors(meshlab2025, tmp_path):
    """The check behind "no plugin load error box" sees MeshLab's box: a file that is no plugin,
    in the user's plugin folder, makes MeshLab 2025.07 show it, and the run fails with its text."""
    broken = tmp_path / "home" / sid_chroot.USER_PLUGINS / "libnot_a_plugin.so"
    broken.parent.mkdir(parents=True, exist_ok=True)
    broken.write_bytes(b"not an ELF file")
    mesh = tmp_path / "patches.ply"
    shutil.copy(REPO / "sample_meshes" / "patches.ply", mesh)
    with pytest.raises(AssertionError, match="Unable to load the following plugins") as failure:
        exercise_filter(meshlab2025, mesh, tmp_path)
    assert "libnot_a_plugin.so" in str(failure.value), failure.value
    print(failure.value)
