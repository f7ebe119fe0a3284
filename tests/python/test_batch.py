"""quasidev.batch and `python -m quasidev batch` / `quasidev batch` on local processes: outputs
mirror the inputs and equal the API's result per file, bad files are reported while the others
go on, a rerun skips what finished (also after the batch was killed), and the summaries list
every file."""

import csv
import json
import os
import signal
import subprocess
import sys
import time

import numpy as np
import pytest
import quasidev
from batch_data import BROKEN, make_dataset

STEPS = ("segment", "approximate", "flatten")


@pytest.fixture()
def dataset(tmp_path):
    root = tmp_path / "in"
    return root, make_dataset(root)


def _outputs(out, names):
    return [out / os.path.splitext(n)[0] for n in names]


def test_batch_runs_each_file_as_the_api_does(dataset, tmp_path):
    root, names = dataset
    before = {p: p.read_bytes() for p in root.rglob("*") if p.is_file()}
    summary = quasidev.batch(root, tmp_path / "out", STEPS, {"tolerance_ae": 1.5}, workers=2,
                             progress=False)
    assert summary.counts == {"ok": len(names), "failed": len(BROKEN), "skipped": 0}
    for name, stem in zip(names, _outputs(tmp_path / "out", names)):
        mesh = quasidev.read(root / name)
        seg = quasidev.segment(mesh.V, mesh.F)
        r = quasidev.approximate(mesh.V, mesh.F, patches=seg.patches, tolerance_ae=1.5)
        flat = quasidev.flatten(r.positions, mesh.F, seg.patches)
        out = quasidev.read(stem.with_suffix(".ply"))
        assert np.allclose(out.V, r.positions, rtol=0, atol=1e-9)
        assert np.array_equal(out.F, mesh.F) and np.array_equal(out.patches, seg.patches)
        assert stem.with_suffix(".svg").read_text() == flat.svg
        record = json.loads(stem.with_suffix(".batch.json").read_text())
        assert record["status"] == "ok"
        after, before_g = (record["reports"]["approximate"][k]["g_abd"] for k in ("total_after", "total_before"))
        assert after < 0.5 * before_g
    assert {p: p.read_bytes() for p in root.rglob("*") if p.is_file()} == before  # inputs kept


def test_bad_files_are_reported_and_listed_in_the_summaries(dataset, tmp_path):
    root, names = dataset
    summary = quasidev.batch(root, tmp_path / "out", ("approximate",), workers=2, progress=False)
    failed = {os.path.relpath(r["input"], root): r["error"] for r in summary.records if r["status"] == "failed"}
    assert sorted(failed) == sorted(BROKEN)
    assert "PLY" in failed[BROKEN[0]] and "empty" in failed[BROKEN[1]].lower()
    rows = list(csv.DictReader(summary.summary_csv.open()))
    assert len(rows) == len(names) + len(BROKEN)
    assert {r["status"] for r in rows} == {"ok", "failed"}
    assert all(float(r["abd_reduction"]) > 50 for r in rows if r["status"] == "ok")
    data = json.loads(summary.summary_json.read_text())
    assert data["counts"] == summary.counts and len(data["files"]) == len(rows)


def test_a_rerun_skips_finished_files_and_redoes_what_changed(dataset, tmp_path):
    root, names = dataset
    out = tmp_path / "out"
    quasidev.batch(root, out, ("approximate",), workers=2, progress=False)
    plys = {p: p.stat().st_mtime_ns for p in out.rglob("*.ply")}
    again = quasidev.batch(root, out, ("approximate",), workers=2, progress=False)
    assert again.counts == {"ok": 0, "failed": len(BROKEN), "skipped": len(names)}
    assert {p: p.stat().st_mtime_ns for p in out.rglob("*.ply")} == plys
    first, second = _outputs(out, names)[:2]
    first.with_suffix(".batch.json").unlink()  # as if the batch stopped before this file's end
    quasidev.write(root / names[1], *_moved(quasidev.read(root / names[1])))  # a changed input
    third = quasidev.batch(root, out, ("approximate",), workers=2, progress=False)
    redone = {r["output"] for r in third.records if r["status"] == "ok"}
    assert redone == {str(first.with_suffix(".ply")), str(second.with_suffix(".ply"))}
    other = quasidev.batch(root, out, ("approximate",), {"tolerance_ae": 2}, workers=2, progress=False)
    assert other.counts["ok"] == len(names)


def _moved(mesh):
    return mesh.V + [0.0, 0.0, 1.0], mesh.F


def test_a_killed_batch_resumes(tmp_path):
    from batch_data import bumpy_cylinder

    root, out = tmp_path / "in", tmp_path / "out"
    root.mkdir()
    for n in range(16):
        quasidev.write(root / f"m{n:02d}.ply", *bumpy_cylinder(n, 40, 30))
    cmd = [sys.executable, "-m", "quasidev", "batch", str(root), "-o", str(out), "--workers", "1",
           "--no-progress"]
    proc = subprocess.Popen(cmd, start_new_session=True)
    deadline = time.time() + 120
    while not list(out.glob("*.batch.json")) and time.time() < deadline:
        time.sleep(0.05)
    os.killpg(proc.pid, signal.SIGKILL)  # the batch and its worker, mid-run
    proc.wait()
    finished = len(list(out.glob("*.batch.json")))
    assert 1 <= finished < 16
    done = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stderr
    summary = json.loads((out / "batch_summary.json").read_text())
    assert summary["counts"]["failed"] == 0
    assert summary["counts"]["skipped"] >= finished - 1  # a record may land as the kill does
    assert summary["counts"]["ok"] + summary["counts"]["skipped"] == 16
    for n in range(16):
        assert len(quasidev.read(out / f"m{n:02d}.ply").V) == 40 * 30


def test_inputs_by_glob_and_list_file_and_their_errors(dataset, tmp_path):
    root, names = dataset
    listing = tmp_path / "list.txt"
    listing.write_text("# two meshes\n" + f"in/{names[0]}\n\nin/{names[1]}\n")
    s = quasidev.batch([listing, str(root / "sub" / "**" / "*.ply")], tmp_path / "out",
                       workers=1, progress=False)
    expected = {names[0], names[1]} | {n for n in names + list(BROKEN) if n.startswith("sub") and n.endswith(".ply")}
    assert {os.path.relpath(r["input"], root) for r in s.records} == expected
    (root / "mesh0.obj").write_text("")  # beside mesh0.ply: both would be out/mesh0.ply
    with pytest.raises(ValueError, match="both be written"):
        quasidev.batch(root, tmp_path / "out2", progress=False)
    with pytest.raises(ValueError, match="outside the output folder"):
        quasidev.batch(root / names[0], root, progress=False)
    with pytest.raises(ValueError, match="no such file"):
        quasidev.batch(tmp_path / "missing", tmp_path / "out3", progress=False)
    assert not (tmp_path / "out2").exists() and not (tmp_path / "out3").exists()
    (root / "mesh0.obj").unlink()
    inside = [quasidev.batch(root, root / "out", workers=2, progress=False) for _ in range(2)]
    assert inside[1].counts["skipped"] == len(names)  # the first run's outputs are no inputs
    assert len(inside[1].records) == len(names) + len(BROKEN)


def test_parameters_are_checked_before_any_file_runs(dataset, tmp_path):
    root, _ = dataset
    for params, message in (({"no_such": 1}, "no parameter"), ({"developability": "x"}, "one of"),
                            ({"tolerance_ae": -1}, "range"), ({"flatten.gap": 1}, "not one of")):
        with pytest.raises(ValueError, match=message):
            quasidev.batch(root, tmp_path / "out", ("approximate",), params, progress=False)
    assert not (tmp_path / "out").exists()
    assert quasidev._batch.per_step(STEPS, {"approximate": {"tolerance_ae": 2}}) == \
        quasidev._batch.per_step(STEPS, {"approximate.tolerance_ae": 2})


@pytest.mark.parametrize("front", ["python", "command"])
def test_the_command_line_runs_the_batch(dataset, tmp_path, front, quasidev_command):
    root, names = dataset
    head = [sys.executable, "-m", "quasidev"] if front == "python" else [str(quasidev_command)]
    env = {**os.environ, "PATH": os.path.dirname(sys.executable) + os.pathsep + os.environ["PATH"]}
    run = subprocess.run(head + ["batch", str(root), "-o", str(tmp_path / "out"), "--steps",
                                 "segment,approximate", "--set", "segment.max_error_deg=12",
                                 "--set", "keep-boundary=false"],
                         capture_output=True, text=True, env=env, timeout=600)
    assert run.returncode == 1, run.stderr  # the broken files failed, the others ran
    assert f"{len(names)} ok, {len(BROKEN)} failed" in run.stdout
    assert "failed: " in run.stderr and "mesh/s" not in run.stdout  # the bar goes to stderr
    params = json.loads((tmp_path / "out" / "batch_summary.json").read_text())["params"]
    assert params["segment"]["max_error_deg"] == 12 and params["approximate"]["keep_boundary"] is False
    bad = subprocess.run(head + ["batch", str(root), "-o", str(tmp_path / "o2"), "--set", "nope=1"],
                         capture_output=True, text=True, env=env, timeout=60)
    assert bad.returncode == 2 and "nope" in bad.stderr and not (tmp_path / "o2").exists()
