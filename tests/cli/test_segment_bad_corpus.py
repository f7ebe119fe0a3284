"""Runs `quasidev segment` on every case of the bad-input corpus (make_bad_corpus.py), with the
segmentation's own bad values in place of the approximation's options (segment_corpus.py).

"fail" cases: exit 1 or 2 with one stderr line, no output, an existing output untouched.
"odd" cases: success with one patch id per face, or such a clean failure. Never a signal, never
a partial file."""
import pathlib
import sys

import pytest

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import make_bad_corpus  # noqa: E402
from plyfile import column, element, read_ply  # noqa: E402
from segment_corpus import segment_options  # noqa: E402
from test_quasidev_cli import BINARY, run  # noqa: E402

CASES = make_bad_corpus.cases()

pytestmark = pytest.mark.skipif(not BINARY.exists(), reason=f"{BINARY} not built")


@pytest.mark.parametrize("case", CASES, ids=[c[0] for c in CASES])
def test_corpus_case(case, tmp_path):
    name, data, args, expect = case
    src = tmp_path / f"{name}.ply"
    src.write_bytes(data)
    out = tmp_path / "out.ply"
    out.write_bytes(b"precious")
    r = run("segment", src, out, "--quiet", *segment_options(args), timeout=600)
    assert r.returncode >= 0, f"killed by signal {-r.returncode}: {r.stderr}"
    errors = [line for line in r.stderr.splitlines() if not line.startswith("quasidev: warning: ")]
    if expect == "fail" or r.returncode != 0:
        assert r.returncode in (1, 2), r.stderr
        assert len(errors) == 1 and errors[0].startswith("quasidev: error: "), r.stderr
        assert out.read_bytes() == b"precious"
    else:
        assert errors == [], r.stderr
        res, _ = read_ply(out)
        ids = column(res, "face", "quality")
        assert len(ids) == element(res, "face")[1] > 0
        assert all(q == int(q) and q >= 0 for q in ids)
        assert sorted(set(ids)) == list(range(len(set(ids))))
    assert not list(tmp_path.glob("*quasidev-tmp*"))
