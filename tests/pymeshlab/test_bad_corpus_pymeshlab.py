"""The bad-input corpus of issue 6 (tests/cli/make_bad_corpus.py) through the real pymeshlab
2025.7.post1 with our plugin, each case in its own Python process (bad_corpus_worker.py):
cases() through the approximation, flatten_cases() through the flattening.

For every case: the process ends normally, never by a signal; files MeshLab's importer refuses
raise its PyMeshLabException; when our filter refuses the mesh it raises with our one-line reason
and every vertex and face array of the mesh is bit-identical to before; merely odd input succeeds
and keeps every face with finite positions (the flattening moves none); where it must leave part
of the mesh as it is, the filter's dict counts one warning and those vertices keep their positions to the bit.
"""
from __future__ import annotations

import json
import os
import re
import subprocess
import sys

import pytest

from pymeshlab_paths import FILTER, FLATTEN_FILTER, PLUGIN, ROOT, require_file

sys.path.insert(0, os.path.join(ROOT, "tests", "cli"))
import make_bad_corpus  # noqa: E402

CASES = make_bad_corpus.cases()
WARNED = make_bad_corpus.warned_cases()
# (filter, case, its expected outcome, its parameter for each option, warnings expected)
RUNS = [(FILTER, c, make_bad_corpus.PLUGIN_OUTCOMES[c[0]], None, c[0] in WARNED) for c in CASES] + \
       [(FLATTEN_FILTER, c, make_bad_corpus.FLATTEN_PLUGIN_OUTCOMES[c[0]], make_bad_corpus.FLATTEN_PARAMETERS,
         False) for c in make_bad_corpus.flatten_cases()]
WORKER = os.path.join(os.path.dirname(os.path.abspath(__file__)), "bad_corpus_worker.py")
# pymeshlab's importer silently drops non-finite vertices: these reach the filter as raw arrays.
AS_ARRAYS = {"nan_coordinates", "inf_coordinates"}


@pytest.mark.parametrize("filter_name,case,expected,options,warned", RUNS,
                         ids=[f"{'flatten' if f == FLATTEN_FILTER else 'approximate'}-{c[0]}"
                              for f, c, *_ in RUNS])
def test_corpus_case_through_pymeshlab(filter_name, case, expected, options, warned, tmp_path):
    require_file(PLUGIN, "build the project first")
    name, data, args, _ = case
    source = tmp_path / f"{name}.ply"
    source.write_bytes(data)
    parameters = json.dumps(make_bad_corpus.plugin_parameters(args, options))
    run = subprocess.run([sys.executable, WORKER, PLUGIN, filter_name, str(source), parameters,
                          "arrays" if name in AS_ARRAYS else "file"],
                         capture_output=True, text=True, timeout=600, check=False)
    assert run.returncode == 0, f"worker ended with {run.returncode}:\n{run.stderr[-3000:]}"
    got = json.loads(run.stdout.splitlines()[-1])
    if expected == make_bad_corpus.LOADER:
        assert got["stage"] == "load" and "Error encountered while loading" in got["message"], got
        return
    if expected is not None:
        assert got["stage"] == "filter", got
        head, reason = got["message"].split("\nDetails:", 1)
        assert head == f"Failed to apply filter: {filter_name}"
        assert "\n" not in reason.strip() and re.search(expected, reason), reason
        assert got["unchanged"], "a failed filter changed the mesh"
    else:
        assert got["stage"] == "done", got
        assert got["faces_out"] == got["faces_in"] and got["finite"], got
        assert got["warnings"] == (1 if warned else 0), got
        if filter_name == FLATTEN_FILTER:
            assert not got["moved"], "the flattening moved vertices"
        if warned:  # the kept vertices bit-identical, some others moved
            _, _, fixed, others = WARNED[name]
            assert not set(fixed) & set(got["moved"]), got["moved"]
            assert set(others) & set(got["moved"]), got["moved"]
