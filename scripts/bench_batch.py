#!/usr/bin/env python3
"""The batch benchmark of issue 25: meshes per minute over a dataset of garment meshes.

The dataset (--size files, default 200, fixed seeds) is made from every 5-8k-triangle garment
found (scripts/bench_family.py's garments(): $QD_SHARED_MESHES and the shipped draped panels):
drape noise of random amplitude and jitter, one in five re-cut into 2 to 8 panels by
`quasidev segment --target N`, one in ten subdivided 4-to-1 (a finer resolution), and one in fifty
broken (truncated, not a mesh, empty). Each row runs `approximate` (the defaults) on every file:
  serial      a shell-style loop of `quasidev IN OUT` command calls, one after the other (the
              engine's default threads: all cores, one patch per thread);
  serial, 1 thread   the same loop with --threads 1;
  local       quasidev.batch on local processes (--workers, default the cores);
  dask 1, 2   quasidev.batch on a distributed.LocalCluster of 1 and 2 single-threaded worker
              processes (without the nanny's OMP_NUM_THREADS=1 environment, as the local batch).
--runs R repeats the rows R times, in turn, and gives each row's median. Also the scheduler's cost per task (no-op tasks on the 2-worker cluster), the peak memory per
worker, and from them a projection of throughput for 10, 100 and 1000 workers. Writes
OUT/benchmark-batch.md and .json and prints the markdown.

Run it with the Python that has the quasidev package and Dask (tests/python/run.sh makes one):
  build/python-venv/bin/python scripts/bench_batch.py [--size N] [--runs R] [--build DIR] [--cache DIR]
                                                      [--out DIR]
"""
from __future__ import annotations

import argparse
import json
import os
import resource
import subprocess
import sys
import tempfile
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)

import mesh_family  # noqa: E402
from bench_family import garments, read_garment, recut, stem  # noqa: E402

import quasidev  # noqa: E402


def make_dataset(quasidev_command: str, size: int, folder: str) -> list[str]:
    """size garment files under folder (made once; kept when they exist)."""
    sources = garments()
    rng = np.random.default_rng(25)
    paths = []
    for n in range(size):
        src = sources[n % len(sources)]
        path = os.path.join(folder, f"{n % 10}", f"{stem(src)}_{n:04d}.ply")
        paths.append(path)
        if os.path.exists(path):
            continue
        os.makedirs(os.path.dirname(path), exist_ok=True)
        if n % 50 == 7:
            broken = [b"ply\nformat binary_little_endian 1.0\nelement vertex 10\n", b"not a mesh\n", b""]
            with open(path, "wb") as f:
                f.write(broken[(n // 50) % 3])
            continue
        if n % 5 == 4:
            src, _ = recut(quasidev_command, src, 2 + (n // 5) % 7, os.path.dirname(path))
        V, F, patch = read_garment(src)
        if n % 10 == 3:
            V, F, patch = mesh_family.subdivide(V, F, patch)
        V = mesh_family.drape(V, F, rng.uniform(0.1, 0.6), rng.uniform(0, 0.05), n)
        mesh_family.write_ply(path, V, F, f"{stem(src)} with drape noise, seed {n}", patch)
    return paths


def serial(quasidev_command: str, paths: list[str], out: str, extra: list[str]) -> dict:
    """One `quasidev IN OUT --quiet EXTRA` call per file, one after the other."""
    start = time.perf_counter()
    failed = 0
    for p in paths:
        target = os.path.join(out, os.path.relpath(p, os.path.dirname(os.path.dirname(p))))
        os.makedirs(os.path.dirname(target), exist_ok=True)
        failed += subprocess.run([quasidev_command, p, target, "--quiet", *extra],
                                 capture_output=True).returncode != 0
    seconds = time.perf_counter() - start
    peak = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024
    return dict(seconds=seconds, failed=failed, peak_worker_mb=peak)


def batch_row(folder: str, out: str, **where) -> dict:
    s = quasidev.batch(folder, out, ("approximate",), progress=False, **where)
    peaks = {}
    for r in s.records:
        if "worker_pid" in r:
            peaks[r["worker_pid"]] = max(peaks.get(r["worker_pid"], 0.0), r["peak_memory_mb"])
    return dict(seconds=s.seconds, failed=s.counts["failed"], peak_worker_mb=max(peaks.values()),
                workers_used=len(peaks))


def median_row(rows: list[dict]) -> dict:
    """The row of the median time, with every run's seconds."""
    ordered = sorted(rows, key=lambda r: r["seconds"])
    return dict(ordered[(len(ordered) - 1) // 2], runs=[r["seconds"] for r in rows])


def _nothing(n: int) -> int:
    return n


def scheduler_cost(client, tasks: int) -> float:
    """Seconds per task of no-op tasks submitted one per file, as the batch does."""
    start = time.perf_counter()
    futures = [client.submit(_nothing, n, pure=False) for n in range(tasks)]
    client.gather(futures)
    return (time.perf_counter() - start) / tasks


def projection(per_mesh_s: float, task_s: float, mesh_bytes: float) -> list[dict]:
    """Meshes per minute for W workers: W / per_mesh_s, capped by the scheduler (1 / task_s,
    its cost measured on 2 workers); the file system must then carry mesh_bytes per mesh."""
    rows = []
    for w in (10, 100, 1000):
        compute, sched = w / per_mesh_s, 1 / task_s
        rate = min(compute, sched)
        rows.append(dict(workers=w, meshes_per_minute=60 * rate, limit="scheduler" if sched < compute else "workers",
                         io_mb_per_s=rate * mesh_bytes / 1e6))
    return rows


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--size", type=int, default=200)
    ap.add_argument("--runs", type=int, default=1)
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--workers", type=int, default=len(os.sched_getaffinity(0)))
    ap.add_argument("--cache")
    ap.add_argument("--out", default=os.path.join(ROOT, "docs"))
    a = ap.parse_args()
    import dask
    from distributed import Client, LocalCluster

    command = f"scripts/bench_batch.py --size {a.size} --runs {a.runs}"
    quasidev_command = os.path.join(a.build, "bin", "quasidev")
    load = [os.getloadavg()[0]]
    with tempfile.TemporaryDirectory() as tmp:
        data = a.cache or os.path.join(tmp, "data")
        print(f"making {a.size} garment files in {data}", file=sys.stderr)
        paths = make_dataset(quasidev_command, a.size, data)
        faces = [f for f in map(_faces, paths) if f is not None]
        mesh_bytes = 2 * np.mean([os.path.getsize(p) for p in paths])  # read one, write one
        runs: dict = {}
        task_s = []
        for n in range(a.runs):
            def out(name):
                return os.path.join(tmp, f"{name}{n}")
            print(f"run {n + 1} of {a.runs}: serial loops, local batch, dask 1 and 2", file=sys.stderr)
            runs.setdefault("serial", []).append(serial(quasidev_command, paths, out("serial"), []))
            runs.setdefault("serial, 1 thread", []).append(
                serial(quasidev_command, paths, out("serial1"), ["--threads", "1"]))
            runs.setdefault("local", []).append(batch_row(data, out("local"), workers=a.workers))
            for w in (1, 2):
                # Dask's nanny starts workers with OMP_NUM_THREADS=1 and the like by default, which
                # holds CHOLMOD's BLAS to one thread: the local batch's processes have no such
                # limit, so the rows compare like with like without it (docs/batch.md).
                with dask.config.set({"distributed.nanny.pre-spawn-environ": {}}), LocalCluster(n_workers=w, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, Client(cluster) as client:
                    runs.setdefault(f"dask {w}", []).append(batch_row(data, out(f"dask{w}"), client=client))
                    if w == 2:
                        task_s.append(scheduler_cost(client, a.size * 5))
    load.append(os.getloadavg()[0])
    rows = {name: median_row(rs) for name, rs in runs.items()}
    task_s = float(np.median(task_s))
    for r in rows.values():
        r["meshes_per_minute"] = 60 * len(paths) / r["seconds"]
    per_mesh_s = rows["dask 1"]["seconds"] / len(paths)  # one worker, one thread
    result = dict(command=command, files=len(paths), broken=len(paths) - len(faces),
                  faces=dict(min=min(faces), median=float(np.median(faces)), max=max(faces)),
                  load=load, rows=rows, scheduler_s_per_task=task_s,
                  projection=projection(per_mesh_s, task_s, mesh_bytes))
    text = report(result)
    print(text)
    os.makedirs(a.out, exist_ok=True)
    with open(os.path.join(a.out, "benchmark-batch.md"), "w") as f:
        f.write(text)
    with open(os.path.join(a.out, "benchmark-batch.json"), "w") as f:
        json.dump(result, f, indent=1)
    return 0


def _faces(path: str) -> int | None:
    """The file's triangle count, or None for a file the reader refuses (a broken one)."""
    try:
        return quasidev.read(path).F.shape[0]
    except ValueError:
        return None


def report(r: dict) -> str:
    rows = r["rows"]
    lines = [
        "# Batch benchmark (issue 25)", "",
        f"Made by `build/python-venv/bin/python {r['command']}` (load average {r['load'][0]:.2f} at "
        f"the start, {r['load'][1]:.2f} at the end) on {os.cpu_count()} cores. {r['files']} garment "
        f"files of {r['faces']['min']}-{r['faces']['max']} triangles (median {r['faces']['median']:.0f}), "
        f"{r['broken']} of them broken; each row runs `approximate` with the defaults on every file "
        f"(seconds: the median of {len(rows['serial']['runs'])} run(s), taken in turn).", "",
        "| row | seconds | meshes per minute | vs serial | vs serial, 1 thread | failed (broken) files | "
        "peak memory per worker (MB) |",
        "|---|---|---|---|---|---|---|",
    ]
    base, single = rows["serial"]["seconds"], rows["serial, 1 thread"]["seconds"]
    for name, row in rows.items():
        lines.append(f"| {name} | {row['seconds']:.1f} | {row['meshes_per_minute']:.0f} | "
                     f"{base / row['seconds']:.2f}x | {single / row['seconds']:.2f}x | {row['failed']} | "
                     f"{row['peak_worker_mb']:.0f} |")
    cores = os.cpu_count()
    floor = min(single, rows["dask 1"]["seconds"]) / cores  # the one-core work, spread perfectly
    lines += [
        "", f"Dask at 2 workers over the local batch: {rows['dask 2']['seconds'] / rows['local']['seconds']:.2f}x "
        "the time.",
        f"The bound on {cores} cores: the work on one core (the faster of the one-thread loop and one "
        f"Dask worker) spread perfectly over the cores takes {floor:.1f} s, so no schedule of it is "
        f"more than {base / floor:.2f}x the serial loop; the local batch is at {100 * floor / rows['local']['seconds']:.0f} % "
        "of that bound.",
        f"The scheduler's cost: {1e3 * r['scheduler_s_per_task']:.2f} ms per task (no-op tasks, one per "
        "file, on the 2-worker cluster).", "",
        "Projection (meshes per minute = workers / seconds per mesh on one worker, capped at one "
        "task per scheduler cost; the file system must carry the MB/s of reading and writing):", "",
        "| workers | meshes per minute | limited by | file system MB/s |", "|---|---|---|---|",
    ]
    for p in r["projection"]:
        lines.append(f"| {p['workers']} | {p['meshes_per_minute']:.0f} | {p['limit']} | {p['io_mb_per_s']:.0f} |")
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    sys.exit(main())
