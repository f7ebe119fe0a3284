"""The result figures of issue 2, bullet 5, through the real quasidev command
(scripts/paper_figures.py prints the same figures as tables)."""
import os
import sys

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import paper_figures as pf  # noqa: E402
from mesh_folders import find_mesh, missing  # noqa: E402
from ply_columns import faces, positions  # noqa: E402

BUILD = os.environ.get("QD_BUILD_DIR", os.path.join(ROOT, "build"))


def test_lampshade_reproduces_table1_shape():
    """δ_err = 10·AE, boundary fixed: ≥ 90 % within ≤ 5 iterations, first iteration does most."""
    r = pf.lampshade(BUILD)
    patch = r["patches"][0]
    history = patch["history"]
    before = patch["before"]["g_abd"]
    after_five = history[min(4, len(history) - 1)]["figures"]["g_abd"]
    assert 100 * (1 - after_five / before) >= 90.0
    assert history[0]["ratio_abd"] >= 0.5 * 100 * (1 - after_five / before)


@pytest.mark.parametrize("name", ["bumpy_cylinder.ply", "bumpy_cone.ply"])
def test_bumps_are_removed_within_three_amplitudes(name):
    r = pf.bumps(BUILD, name)
    a = pf.a_in_ae(os.path.join(pf.SAMPLES, name)) * r["average_edge"]
    assert r["abd_reduction"] >= 90.0
    assert r["total_after"]["max_disp"] <= 3 * a


@pytest.mark.parametrize("name", ["garment_shirt_initial_diffavatar.ply", "garment_tee4panel_gpg.ply"])
def test_garments_never_get_worse(name):
    """The shirt is in tests/data/; the tee's licence does not let us ship it, so it runs where
    $QD_SHARED_MESHES names a folder holding it (a figure input)."""
    path = find_mesh(name)
    if path is None:
        pytest.skip(missing([name]))
    r, flips, seam_move = pf.garment(BUILD, path)
    assert flips == 0
    assert r["total_after"]["g_abd"] <= r["total_before"]["g_abd"]
    assert seam_move == 0.0  # the held seams: those the report joins may move
    assert all(p["fit_residual_deg"] >= 0 for p in r["patches"])


def test_tolerance_trend_as_table2():
    trend = pf.tolerance_trend(BUILD, os.path.join(pf.SAMPLES, "bumpy_cone.ply"))
    reductions = [r["abd_reduction"] for _, r in trend]
    displacements = [r["total_after"]["max_disp"] for _, r in trend]
    assert reductions[0] > reductions[1] > reductions[2] > 0
    assert displacements[0] > displacements[1] > displacements[2] > 0


def test_free_seams_move_stay_closed_and_go_further():
    fixed, free, seam_fixed, seam_free, before, after_free = pf.seams(BUILD)
    assert seam_fixed == 0.0
    assert seam_free > 0.0
    # no crack: same vertex count and the same face index lists, so every seam vertex is shared
    assert faces(after_free) == faces(before)
    assert len(positions(after_free)) == len(positions(before))
    assert free["abd_reduction"] > fixed["abd_reduction"]
