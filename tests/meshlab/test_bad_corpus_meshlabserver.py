"""The bad-input corpus of issue 6 (tests/cli/make_bad_corpus.py) through the real meshlabserver
2020.09 with our plugin: cases() through the approximation, flatten_cases() through the
flattening.

For every case: meshlabserver ends by exit status, never by a signal; when MeshLab's importer
refuses the file it says so; when our filter refuses the mesh, the log carries our one-line
reason and the output file (and the flattening's pattern file) keeps its previous bytes; when the
input is merely odd the filter succeeds and writes the whole mesh (same faces, finite positions).
"""
from __future__ import annotations

import re
import sys

import numpy as np
import pytest

from ml2020_support import (FILTER_NAME, FLATTEN_FILTER_NAME, REPO, load_mesh, run_meshlabserver,
                            write_mlx)

sys.path.insert(0, str(REPO / "tests" / "cli"))
import make_bad_corpus  # noqa: E402

CASES = make_bad_corpus.cases()
WARNED = make_bad_corpus.warned_cases()
PREVIOUS = b"previous result\n"
# (filter, case, its expected outcome, the filter's .mlx, its parameter for each option)
RUNS = [(FILTER_NAME, c, make_bad_corpus.PLUGIN_OUTCOMES[c[0]], "default.mlx", None) for c in CASES] + \
       [(FLATTEN_FILTER_NAME, c, make_bad_corpus.FLATTEN_PLUGIN_OUTCOMES[c[0]], "flatten.mlx",
         make_bad_corpus.FLATTEN_PARAMETERS) for c in make_bad_corpus.flatten_cases()]


@pytest.mark.parametrize("filter_name,case,expected,base,options", RUNS,
                         ids=[f"{'flatten' if f == FLATTEN_FILTER_NAME else 'approximate'}-{c[0]}"
                              for f, c, *_ in RUNS])
def test_corpus_case_through_meshlabserver(filter_name, case, expected, base, options, meshlab_prefix, tmp_path):
    name, data, args, _ = case
    source = tmp_path / f"{name}.ply"
    source.write_bytes(data)
    values = make_bad_corpus.plugin_parameters(args, options)
    svg = tmp_path / "pattern.svg"
    if filter_name == FLATTEN_FILTER_NAME:
        values["svg_file"] = svg
        svg.write_bytes(PREVIOUS)
    script = write_mlx(tmp_path / "job.mlx", values, base=REPO / "sample_meshes" / base,
                       filter_name=filter_name)
    out = tmp_path / "out.ply"
    out.write_bytes(PREVIOUS)
    run = run_meshlabserver(meshlab_prefix, source, out, script)
    log = run.stdout
    # meshlabserver exits 0 or 255 (-1); xvfb-run reports a signal as 128 + its number.
    assert run.returncode in (0, 255), f"meshlabserver ended with {run.returncode}:\n{log[-3000:]}"
    if expected == make_bad_corpus.LOADER:
        assert "Failed loading of" in log, log[-3000:]
        assert out.read_bytes() == PREVIOUS
    elif expected is not None:
        assert run.returncode == 255 and "Problem with filter" in log, log[-3000:]
        reasons = re.findall(rf"LOG: \d+ {filter_name} failed: (.*)", log)
        assert len(reasons) == 1, f"expected one logged reason:\n{log[-3000:]}"
        assert re.search(expected, reasons[0]), reasons[0]
        assert out.read_bytes() == PREVIOUS
        assert not svg.exists() or svg.read_bytes() == PREVIOUS
    else:
        assert run.returncode == 0, log[-3000:]
        result = load_mesh(out)
        faces_in = data.count(b"\n3 ") if data.startswith(b"ply\nformat ascii") else None
        if faces_in is not None:
            assert len(result.f) == faces_in
        assert np.isfinite(result.v).all()


@pytest.mark.parametrize("name", sorted(WARNED))
def test_warned_case_through_meshlabserver(name, meshlab_prefix, tmp_path):
    """The filter succeeds on a mesh it must partly leave as it is, logs one warning with the
    count and first example, keeps those vertices bit-identical and moves others."""
    data, warning, fixed, others = WARNED[name]
    source, out = tmp_path / f"{name}.ply", tmp_path / "out.ply"
    source.write_bytes(data)
    run = run_meshlabserver(meshlab_prefix, source, out, write_mlx(tmp_path / "job.mlx", {}))
    assert run.returncode == 0, run.stdout[-3000:]
    said = re.findall(r"LOG: \d+ warning: (.*)", run.stdout)
    assert len(said) == 1 and re.search(warning, said[0]), run.stdout[-3000:]
    before = load_mesh(source).v.astype(np.float32)  # MeshLab 2020.09 holds float positions
    after = load_mesh(out).v.astype(np.float32)
    assert np.array_equal(after[fixed], before[fixed])
    assert (after[others] != before[others]).any()
