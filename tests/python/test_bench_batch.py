"""scripts/bench_batch.py on a small dataset: every row runs every file, the broken file fails in
every row and nowhere else, and the tables are written."""

import json
import os
import subprocess
import sys

from conftest import BUILD, REPO


def test_the_batch_benchmark_runs_every_row(tmp_path):
    env = {k: v for k, v in os.environ.items() if k != "QD_SHARED_MESHES"}
    run = subprocess.run([sys.executable, str(REPO / "scripts" / "bench_batch.py"), "--size", "8",
                          "--build", str(BUILD), "--out", str(tmp_path)],
                         capture_output=True, text=True, env=env, timeout=900)
    assert run.returncode == 0, run.stderr
    result = json.loads((tmp_path / "benchmark-batch.json").read_text())
    assert result["files"] == 8 and result["broken"] == 1
    assert set(result["rows"]) == {"serial", "serial, 1 thread", "local", "dask 1", "dask 2"}
    for row in result["rows"].values():
        assert row["failed"] == 1 and row["meshes_per_minute"] > 0 and row["peak_worker_mb"] > 0
    assert result["rows"]["dask 2"]["workers_used"] <= 2
    assert 0 < result["scheduler_s_per_task"] < 1
    assert "| dask 2 |" in (tmp_path / "benchmark-batch.md").read_text()
