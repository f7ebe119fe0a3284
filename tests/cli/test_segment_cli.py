"""`quasidev segment IN OUT`: every face gets exactly one patch id 0..k-1 as face quality and one
colour per patch, everything else of the input is kept, the capped cylinder splits into its
three developable pieces, existing patches are kept with --keep-patches, the selection border
is kept, the report holds every patch's figures, and bad values are named."""
import collections
import json
import pathlib
import sys

import pytest

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from plyfile import PlyData  # noqa: E402
from test_quasidev_cli import BINARY, REPO, assert_clean_failure, run  # noqa: E402
from ply_columns import column, columns, element, has  # noqa: E402

pytestmark = pytest.mark.skipif(not BINARY.exists(), reason=f"{BINARY} not built")

CAPPED = REPO / "sample_meshes" / "capped_cylinder.ply"
PATCHES = REPO / "sample_meshes" / "patches.ply"


def segment(tmp_path, mesh, *options):
    out, report = tmp_path / "out.ply", tmp_path / "report.json"
    r = run("segment", mesh, out, "--report", report, *options)
    assert r.returncode == 0, r.stderr
    elements = PlyData.read(out)
    return elements, json.loads(report.read_text()), r


def patch_ids(elements):
    return [int(q) for q in column(elements, "face", "quality")]


def assert_one_patch_per_face(elements, report):
    ids = patch_ids(elements)
    assert all(q == int(q) for q in column(elements, "face", "quality"))
    assert sorted(set(ids)) == list(range(report["patch_count"]))
    assert [p["faces"] for p in report["patches"]] == [ids.count(k) for k in range(report["patch_count"])]
    colours = collections.defaultdict(set)
    for k, c in zip(ids, zip(*(column(elements, "face", n) for n in ("red", "green", "blue")))):
        colours[k].add(c)
    assert all(len(c) == 1 for c in colours.values())
    assert len({next(iter(c)) for c in colours.values()}) == len(colours)


@pytest.mark.parametrize("mesh", ["capped_cylinder.ply", "patches.ply", "draped_panels.ply"])
def test_every_face_gets_one_patch_and_the_rest_is_kept(mesh, tmp_path):
    source = REPO / "sample_meshes" / mesh
    elements, report, r = segment(tmp_path, source)
    assert_one_patch_per_face(elements, report)
    given = PlyData.read(source)
    for c in "xyz":
        assert column(elements, "vertex", c) == column(given, "vertex", c)
    assert column(elements, "face", "vertex_indices") == column(given, "face", "vertex_indices")
    assert elements["vertex"].count == given["vertex"].count
    lines = r.stdout.splitlines()
    assert len(lines) == report["patch_count"] + 1 and lines[-1].startswith("Segmented ")
    assert all(line.startswith(f"Patch {k}: ") for k, line in enumerate(lines[:-1]))


def test_capped_cylinder_splits_into_its_three_pieces(tmp_path):
    elements, report, _ = segment(tmp_path, CAPPED)
    given = PlyData.read(CAPPED)
    pieces = [int(q) for q in column(given, "face", "quality")]
    ids = patch_ids(elements)
    assert report["patch_count"] == 3
    assert len(set(zip(pieces, ids))) == 3  # each piece is one patch, each patch one piece
    kinds = sorted(p["proxy"]["kind"] for p in report["patches"])
    assert kinds == ["cylinder", "plane", "plane"]
    assert sorted(p["disk"] for p in report["patches"]) == [False, True, True]
    for p in report["patches"]:
        assert p["max_error_deg"] <= 20 and not p["over_limit"] and p["over_limit_reason"] == ""
        assert p["boundary_loops"] == (2 if p["proxy"]["kind"] == "cylinder" else 1)


def test_keep_patches_keeps_the_fitting_input_patches(tmp_path):
    elements, report, _ = segment(tmp_path, PATCHES, "--keep-patches")
    given = PlyData.read(PATCHES)
    pairs = set(zip((int(q) for q in column(given, "face", "quality")), patch_ids(elements)))
    assert report["patch_count"] == 4 and len(pairs) == 4
    assert all(p["kept"] for p in report["patches"])
    assert report["parameters"]["keep_patches"] is True


def test_selection_border_is_kept(tmp_path):
    """Selecting the faces of the side's lower half (PLY face flags bit 0x20) adds a border."""
    given = PlyData.read(CAPPED)
    V = list(zip(*(column(given, "vertex", c) for c in "xyz")))
    F = column(given, "face", "vertex_indices")
    pieces = [int(q) for q in column(given, "face", "quality")]
    lower = [int(p == 0 and sum(V[v][2] for v in f) / 3 < 1.0) for f, p in zip(F, pieces)]
    flags = [0x20 * s for s in lower]
    face = element("face", columns(given["face"]) + [("flags", "i4", flags)])
    src = tmp_path / "selected.ply"
    PlyData([given["vertex"], face], comments=given.comments).write(src)
    elements, report, _ = segment(tmp_path, src)
    assert report["patch_count"] == 4 and report["selected_faces"] == sum(lower)
    ids = patch_ids(elements)
    assert not {ids[f] for f in range(len(F)) if lower[f]} & {ids[f] for f in range(len(F)) if not lower[f]}
    assert column(elements, "face", "flags") == flags


def test_report_and_log_name_every_figure(tmp_path):
    _, report, r = segment(tmp_path, PATCHES, "--max-error-deg", "15", "--min-faces", "30")
    assert report["parameters"]["max_error_deg"] == 15 and report["parameters"]["min_faces"] == 30
    for p in report["patches"]:
        assert set(p) >= {"faces", "area", "proxy", "max_error_deg", "rms_error_deg",
                          "boundary_loops", "euler", "disk", "over_limit", "over_limit_reason"}
        assert p["proxy"]["kind"] in ("plane", "cylinder", "cone") and len(p["proxy"]["axis"]) == 3
        assert p["rms_error_deg"] <= p["max_error_deg"]
        assert p["max_error_deg"] <= 15 or p["over_limit"]
    assert "fit error max" in r.stdout


def test_same_patches_for_any_thread_count(tmp_path):
    outputs = []
    for threads in ("1", "2"):
        out = tmp_path / f"t{threads}.ply"
        r = run("segment", PATCHES, out, "--threads", threads, "--quiet")
        assert r.returncode == 0 and r.stdout == "", r.stderr
        outputs.append(out.read_bytes())
    assert outputs[0] == outputs[1]


def test_target_count_is_met_by_merging(tmp_path):
    _, report, _ = segment(tmp_path, CAPPED, "--target-patches", "2")
    assert report["patch_count"] in (2, 3)
    if report["patch_count"] == 3:
        assert any("target" in w for w in report["warnings"])


@pytest.mark.parametrize("option,value,hint", [("--max-error-deg", "0", "greater than 0"),
                                               ("--max-error-deg", "91", "at most 90"),
                                               ("--min-faces", "0", "whole number from 1"),
                                               ("--crease-deg", "nan", "finite number"),
                                               ("--target-patches", "-1", "whole number from 0"),
                                               ("--min-area", "1", "below 1"),
                                               ("--threads", "x", "whole number")])
def test_bad_value_names_option_and_value(option, value, hint, tmp_path):
    out = tmp_path / "out.ply"
    r = run("segment", CAPPED, out, option, value)
    assert_clean_failure(r, out, status=2)
    assert option in r.stderr and value in r.stderr and hint in r.stderr, r.stderr


def test_unknown_option_missing_files_and_the_approximation_options(tmp_path):
    out = tmp_path / "out.ply"
    for args, said in ((["--seam-mode", "free"], "unknown option '--seam-mode'"),
                       (["--frobnicate"], "unknown option '--frobnicate'")):
        r = run("segment", CAPPED, out, *args)
        assert_clean_failure(r, out, status=2)
        assert said in r.stderr, r.stderr
    r = run("segment", CAPPED)
    assert_clean_failure(r, out, status=2)
    assert "expected INPUT and OUTPUT, got 1" in r.stderr
    r = run("segment", CAPPED, CAPPED)
    assert r.returncode == 2 and "--overwrite-input" in r.stderr


def test_missing_input_names_the_file(tmp_path):
    out = tmp_path / "out.ply"
    r = run("segment", tmp_path / "nope.ply", out)
    assert_clean_failure(r, out, status=1)
    assert "nope.ply" in r.stderr


def test_help_lists_segment_and_its_defaults():
    assert "segment" in run("--help").stdout
    sub = run("segment", "--help")
    assert sub.returncode == 0 and "Usage: quasidev segment [OPTIONS] INPUT OUTPUT" in sub.stdout
    for option, default in (("--max-error-deg,--max-error X", "20"), ("--min-faces N", "20"),
                            ("--target-patches,--target N", "0"), ("--crease-deg,--crease X", "60"),
                            ("--threads N", "0")):
        entry = sub.stdout[sub.stdout.index(option):]
        end = entry.find("\n  --", 1)
        assert f"default {default})" in " ".join(entry[:end if end > 0 else None].split()), entry


def test_segment_then_approximate_runs_on_a_closed_mesh(tmp_path):
    """The pipeline's two commands as the README gives them: the segmentation's patch ids are
    what the approximation reads (one patch per piece of the capped cylinder)."""
    seg, out, report = tmp_path / "seg.ply", tmp_path / "approx.ply", tmp_path / "a.json"
    assert run("segment", CAPPED, seg, "--max-error-deg", "30", "--quiet").returncode == 0
    r = run("approximate", seg, out, "--seam-mode", "free", "--report", report)
    assert r.returncode == 0, r.stderr
    assert [p["faces"] for p in json.loads(report.read_text())["patches"]] == [1536, 240, 240]
    assert has(PlyData.read(out), "face", "quality")


def test_each_warning_is_said_once(tmp_path):
    """Spot at 30 degrees leaves patches below the smallest size: the warning goes to stderr
    once, not again in the log on stdout (issue 24)."""
    _, report, r = segment(tmp_path, REPO / "tests" / "data" / "classic_spot_lowres_crane.ply",
                           "--max-error-deg", "30")
    assert report["warnings"], "spot at 30 degrees should warn"
    for warning in report["warnings"]:
        assert f"quasidev: warning: {warning}" in r.stderr
        assert (r.stdout + r.stderr).count(warning) == 1, r.stdout + r.stderr
