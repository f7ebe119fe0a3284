"""The plugin in the real MeshLab 2020.09 GUI under Xvfb (issue 3, bullet 4, last point).

Starts the private prefix's meshlab (scripts/install_plugin.sh --user) on a sample with patch
ids and runs gui_support.run_and_check, the scenario shared with MeshLab 2025.07
(test_gui_2025.py): the filter is listed under Filters > Smoothing, Fairing and Deformation (the
flattening under Filters > Texture, the segmentation under Filters > Quality Measure and
Computations) and all three are found by the filter search, its dialog shows every parameter, Apply runs it, the grey input
becomes coloured by the ramp, and the mesh exported through the GUI has moved vertices, kept
boundary and seams, less curvature and the colours. Screenshots stay in the test's tmp dir.
"""
from __future__ import annotations

import pytest

from gui_support import MeshLabApp, MeshLabGui, run_and_check
from ml2020_support import FILTER_NAME


@pytest.fixture
def meshlab2020(display, meshlab_prefix, probe_lib, tmp_path):
    app = MeshLabApp(version="2020.09",
                     command=lambda mesh, env: ["env", *(f"{k}={v}" for k, v in env.items()),
                                                str(meshlab_prefix / "bin" / "meshlab"), str(mesh)],
                     app_path=lambda path: path,
                     applied_line=f"Applied filter {FILTER_NAME}")
    gui = MeshLabGui(display, app, tmp_path, probe_lib)
    try:
        yield gui
    finally:
        gui.stop()


def test_gui_menu_search_dialog_apply_and_export(meshlab2020, tmp_path):
    run_and_check(meshlab2020, tmp_path)
