"""The bad-input corpus for the segmentation (tests/cli/make_bad_corpus.py: segment_cases())
through the segmentation filter in real pymeshlab, each case in its own Python process
(bad_corpus_worker.py): never a signal; files MeshLab's importer refuses raise its exception;
a mesh the filter refuses raises with a one-line reason and every array of the mesh is
bit-identical to before; otherwise every face keeps its place and no vertex moves."""
from __future__ import annotations

import json
import os
import subprocess
import sys

import pytest

from pymeshlab_paths import PLUGIN, ROOT, SEGMENT_FILTER, require_file

sys.path.insert(0, os.path.join(ROOT, "tests", "cli"))
import make_bad_corpus  # noqa: E402

CASES = make_bad_corpus.segment_cases()
WORKER = os.path.join(os.path.dirname(os.path.abspath(__file__)), "bad_corpus_worker.py")
AS_ARRAYS = {"nan_coordinates", "inf_coordinates"}  # pymeshlab's importer drops them


@pytest.mark.parametrize("case", CASES, ids=[c[0] for c in CASES])
def test_corpus_case_through_the_segmentation(case, tmp_path):
    require_file(PLUGIN, "build the project first")
    name, data, args, expect = case
    source = tmp_path / f"{name}.ply"
    source.write_bytes(data)
    run = subprocess.run([sys.executable, WORKER, PLUGIN, SEGMENT_FILTER, str(source),
                          json.dumps(make_bad_corpus.plugin_parameters(args, make_bad_corpus.SEGMENT_PARAMETERS)),
                          "arrays" if name in AS_ARRAYS else "file"],
                         capture_output=True, text=True, timeout=600, check=False)
    assert run.returncode == 0, f"worker ended with {run.returncode}:\n{run.stderr[-3000:]}"
    got = json.loads(run.stdout.splitlines()[-1])
    if make_bad_corpus.PLUGIN_OUTCOMES[name] == make_bad_corpus.LOADER:
        assert got["stage"] == "load" and "Error encountered while loading" in got["message"], got
    elif got["stage"] == "filter":
        head, reason = got["message"].split("\nDetails:", 1)
        assert head == f"Failed to apply filter: {SEGMENT_FILTER}"
        assert reason.strip() and "\n" not in reason.strip(), reason
        assert got["unchanged"], "a failed filter changed the mesh"
    else:
        assert expect == "odd" and got["stage"] == "done", got
        assert got["faces_out"] == got["faces_in"] and not got["moved"], got
