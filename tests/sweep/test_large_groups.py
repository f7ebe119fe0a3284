"""Auto on a solve group above 25,000 vertices (kMaxDefectRaceVertices), through the real quasidev
command on generated members (scripts/mesh_family.py at resolution 5, about 77k faces).

There auto runs the curve term alone, since its conjugate gradients cost a fraction of the
angle-defect rows' factorisations. Where that run removes less than δ_ABD of G_ABD, the
angle-defect rows run from the same start too and the better is kept (the tangent developable
with jittered bumps: every curve step folds faces); where it removes more, nothing else runs and
the result is the curve term's own, bit for bit."""
import json
import os
import subprocess
import sys

import numpy as np
import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import mesh_family  # noqa: E402
import robustness_sweep as rs  # noqa: E402

QUASIDEV = os.path.join(os.environ.get("QD_BUILD_DIR", os.path.join(ROOT, "build")), "bin",
                        "quasidev")
STEPS = ["--max-iter", "3"]  # enough to tell the terms apart, and quick at 77k faces


def run(tmp, name: str, term: str) -> tuple[dict, np.ndarray]:
    mesh = tmp / f"{name}.ply"
    if not mesh.exists():
        V, F = mesh_family.make(mesh_family.Member.from_name(name))
        mesh_family.write_ply(str(mesh), V, F, name)
    out, report = tmp / f"{name}_{term}.ply", tmp / f"{name}_{term}.json"
    subprocess.run([QUASIDEV, "approximate", str(mesh), str(out), "--developability", term,
                    "--report", str(report), "--no-progress", *STEPS],
                   check=True, capture_output=True, text=True)
    return json.loads(report.read_text(encoding="utf-8")), rs.positions(str(out))


def test_where_the_curve_term_removes_nothing_auto_runs_the_angle_defect_rows(tmp_path):
    name = "tangent_a0.5_w0.12_j0.1_r5_s1"
    curve, _ = run(tmp_path, name, "curve")
    defect, V_defect = run(tmp_path, name, "defect")
    auto, V_auto = run(tmp_path, name, "auto")
    assert auto["vertices"] > 25000
    assert curve["abd_reduction"] < 1.0  # the case this test is about
    assert defect["abd_reduction"] > 50.0
    patch = auto["patches"][0]
    assert patch["developability"] == "defect"
    assert [(c["term"], c["kept"]) for c in patch["candidates"]] == [("curve", False),
                                                                     ("defect", True)]
    assert np.array_equal(V_auto, V_defect)  # the angle-defect rows' own run, kept
    line = next(s for s in auto["log"] if s.startswith("patch 0:"))
    assert "the curve term runs alone, and it removed less than δ_ABD" in line, line
    assert "defect −" in line and "(kept)" in line, line


def test_where_the_curve_term_removes_more_auto_is_the_curve_term_alone(tmp_path):
    name = "cylinder_a0.5_w0.12_j0_r5_s1"
    curve, V_curve = run(tmp_path, name, "curve")
    auto, V_auto = run(tmp_path, name, "auto")
    assert auto["vertices"] > 25000
    assert curve["abd_reduction"] > 50.0
    assert auto["patches"][0]["candidates"] == []
    assert auto["factorizations"] == curve["factorizations"]
    assert np.array_equal(V_auto, V_curve)


if __name__ == "__main__":
    sys.exit(pytest.main([__file__, "-q"]))
