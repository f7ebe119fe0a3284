"""Runs `quasidev approximate`, `quasidev segment` and `quasidev flatten` on every case of the
generated bad-input corpus (make_bad_corpus.py: cases(), segment_cases() and flatten_cases()).

"fail" cases: exit 1 or 2 with one stderr line, no output, an existing output untouched and no
report or pattern file written.
"odd" cases: success with a complete output (same face count; from the segmentation one patch
id per face, numbered from 0), or such a clean failure.
Never a signal, never a partial file.
"""
import json
import pathlib
import re
import sys

import pytest

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import make_bad_corpus  # noqa: E402
from plyfile import PlyData  # noqa: E402
from test_quasidev_cli import BINARY, run  # noqa: E402
from ply_columns import column  # noqa: E402

CASES = make_bad_corpus.cases()
WARNED = make_bad_corpus.warned_cases()
# (subcommand, case, the files it writes besides OUTPUT)
RUNS = [("approximate", c, ["--report"]) for c in CASES] + \
       [("segment", c, ["--report"]) for c in make_bad_corpus.segment_cases()] + \
       [("flatten", c, ["--report", "--svg-file", "--dxf-file"]) for c in make_bad_corpus.flatten_cases()]

pytestmark = pytest.mark.skipif(not BINARY.exists(), reason=f"{BINARY} not built")


@pytest.mark.parametrize("job,case,extra", RUNS, ids=[f"{j}-{c[0]}" for j, c, _ in RUNS])
def test_corpus_case(job, case, extra, tmp_path):
    name, data, args, expect = case
    src = tmp_path / f"{name}.ply"
    src.write_bytes(data)
    out = tmp_path / "out.ply"
    out.write_bytes(b"precious")
    files = {option: tmp_path / f"written{option.replace('-', '_')}" for option in extra}
    r = run(job, src, out, *args, "--quiet", *[a for o, f in files.items() for a in (o, f)],
            timeout=600)
    assert r.returncode >= 0, f"killed by signal {-r.returncode}: {r.stderr}"
    errors = [line for line in r.stderr.splitlines() if not line.startswith("quasidev: warning: ")]
    if expect == "fail" or r.returncode != 0:
        assert r.returncode in (1, 2), r.stderr
        assert len(errors) == 1 and errors[0].startswith("quasidev: error: "), r.stderr
        assert out.read_bytes() == b"precious"
        assert not [f for f in files.values() if f.exists()]
    else:
        assert errors == [], r.stderr
        res = PlyData.read(out)
        inp_faces = data.count(b"\n3 ") if data.startswith(b"ply\nformat ascii") else None
        assert res["vertex"].count > 0
        if inp_faces is not None:
            assert res["face"].count == inp_faces
        if job == "segment":
            ids = column(res, "face", "quality")
            assert len(ids) == res["face"].count and all(q == int(q) >= 0 for q in ids)
            assert sorted(set(ids)) == list(range(len(set(ids))))
    assert not list(tmp_path.glob("*quasidev-tmp*"))


def test_every_case_says_what_the_plugin_does():
    """make_bad_corpus.PLUGIN_OUTCOMES and FLATTEN_PLUGIN_OUTCOMES (used by the meshlabserver and
    pymeshlab corpus tests) cover exactly their corpus' cases."""
    assert set(make_bad_corpus.PLUGIN_OUTCOMES) == {c[0] for c in CASES}
    assert set(make_bad_corpus.FLATTEN_PLUGIN_OUTCOMES) == {c[0] for c in make_bad_corpus.flatten_cases()}


def positions(path):
    elements = PlyData.read(path)
    return list(zip(*(column(elements, "vertex", c) for c in "xyz")))


@pytest.mark.parametrize("name", sorted(WARNED))
def test_warned_case_keeps_its_part_and_does_the_rest(name, tmp_path):
    """A run that must leave part of the mesh as it is succeeds, says so once on stderr (with or
    without --quiet: not again in the log on stdout) and in the report (count and first example), keeps those vertices bit-identical and moves others."""
    data, warning, fixed, others = WARNED[name]
    src, out, report = tmp_path / f"{name}.ply", tmp_path / "out.ply", tmp_path / "r.json"
    src.write_bytes(data)
    r = run(src, out, "--quiet", "--report", report)
    assert r.returncode == 0, r.stderr
    said = r.stderr.splitlines()
    assert len(said) == 1 and said[0].startswith("quasidev: warning: "), r.stderr
    assert re.search(warning, said[0]), said[0]
    text = said[0].removeprefix("quasidev: warning: ")
    assert json.loads(report.read_text())["warnings"] == [text]
    loud = run(src, out, "--report", report)  # without --quiet: the log, but the warning only once
    assert loud.returncode == 0 and loud.stdout.strip(), loud.stderr
    assert (loud.stdout + loud.stderr).count(text) == 1, loud.stdout + loud.stderr
    before, after = positions(src), positions(out)
    assert [after[v] for v in fixed] == [before[v] for v in fixed]
    assert any(after[v] != before[v] for v in others)
