"""quasidev batch on a real Dask cluster: a `dask scheduler` and two `dask worker` processes
started on localhost give files byte-identical to the local processes' run, from the command
line (--scheduler) and from the Python API (client=)."""

import json
import os
import subprocess
import sys
import time

import pytest
import quasidev
from batch_data import BROKEN, make_dataset

distributed = pytest.importorskip("distributed")

STEPS = ("segment", "approximate", "flatten")


@pytest.fixture(scope="module")
def cluster(tmp_path_factory):
    """A scheduler and two single-threaded workers, each its own process; yields the
    scheduler's address."""
    folder = tmp_path_factory.mktemp("dask")
    dask = os.path.join(os.path.dirname(sys.executable), "dask")
    scheduler_file = folder / "scheduler.json"
    common = ["--no-dashboard"]
    procs = [subprocess.Popen([dask, "scheduler", "--host", "127.0.0.1", "--port", "0",
                               "--scheduler-file", str(scheduler_file)] + common,
                              stdout=subprocess.DEVNULL, stderr=open(folder / "scheduler.log", "w"))]
    deadline = time.time() + 60
    while not scheduler_file.exists() and time.time() < deadline:
        time.sleep(0.1)
    for n in range(2):
        procs.append(subprocess.Popen([dask, "worker", "--scheduler-file", str(scheduler_file),
                                       "--nworkers", "1", "--nthreads", "1"] + common,
                                      stdout=subprocess.DEVNULL,
                                      stderr=open(folder / f"worker{n}.log", "w")))
    address = json.loads(scheduler_file.read_text())["address"]
    with distributed.Client(address, timeout=60) as client:
        client.wait_for_workers(2, timeout=60)
    yield address
    for p in reversed(procs):
        p.terminate()
    for p in procs:
        p.wait(timeout=30)


def _files(out):
    return {p.relative_to(out): p.read_bytes() for p in out.rglob("*")
            if p.suffix in (".ply", ".svg", ".dxf")}


def test_dask_gives_the_local_runs_files(cluster, tmp_path):
    root = tmp_path / "in"
    names = make_dataset(root, count=8)
    local = quasidev.batch(root, tmp_path / "local", STEPS, workers=2, progress=False)
    run = subprocess.run([sys.executable, "-m", "quasidev", "batch", str(root), "-o",
                          str(tmp_path / "dask"), "--steps", ",".join(STEPS), "--scheduler",
                          cluster, "--no-progress"], capture_output=True, text=True, timeout=600)
    assert run.returncode == 1, run.stderr  # the broken files failed on the workers too
    assert f"{len(names)} ok, {len(BROKEN)} failed" in run.stdout
    local_files, dask_files = _files(tmp_path / "local"), _files(tmp_path / "dask")
    assert len(local_files) == 3 * len(names) and dask_files == local_files
    records = json.loads((tmp_path / "dask" / "batch_summary.json").read_text())["files"]
    workers = {r["worker_pid"] for r in records}
    assert os.getpid() not in workers and {r["worker_pid"] for r in local.records}.isdisjoint(workers)
    assert {r["input"]: r["status"] for r in records} == {r["input"]: r["status"] for r in local.records}


def test_a_client_runs_the_api_batch_and_a_rerun_skips(cluster, tmp_path):
    root = tmp_path / "in"
    names = make_dataset(root, count=4)
    with distributed.Client(cluster) as client:
        first = quasidev.batch(root, tmp_path / "out", ("approximate",), client=client, progress=False)
        again = quasidev.batch(root, tmp_path / "out", ("approximate",), client=client, progress=False)
    assert first.counts == {"ok": len(names), "failed": len(BROKEN), "skipped": 0}
    assert again.counts == {"ok": 0, "failed": len(BROKEN), "skipped": len(names)}
