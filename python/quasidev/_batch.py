"""quasidev.batch: a pipeline (segment, approximate, flatten; any subset) over many mesh files,
on local processes or on a Dask cluster, resumable, with a summary."""

from __future__ import annotations

import csv
import hashlib
import io
import json
import multiprocessing
import os
import sys
import time
from concurrent.futures import ProcessPoolExecutor, as_completed
from concurrent.futures.process import BrokenProcessPool
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Iterable, Optional

from ._batch_files import expand, mirrored, write_atomically
from ._batch_job import STEPS, Task, input_signature, record_path, run_task
from ._batch_params import per_step

SUMMARY_CSV = "batch_summary.csv"
SUMMARY_JSON = "batch_summary.json"
CSV_COLUMNS = [
    "input", "output", "status", "seconds", "vertices", "faces", "patches", "g_abd_before",
    "g_abd_after", "abd_reduction", "max_disp", "pieces", "error",
]


@dataclass(frozen=True)
class BatchSummary:
    """What quasidev.batch returns; the same is in OUT/batch_summary.json and .csv."""

    records: list  #: one dict per input, in the inputs' order (see docs/batch.md)
    counts: dict  #: how many files are "ok", "failed" and "skipped" (finished before)
    seconds: float  #: the batch's wall time
    summary_csv: Path
    summary_json: Path


def run_key(steps: tuple, params: dict) -> str:
    """Names what a file's result depends on besides the input: steps, parameters, version."""
    from . import __version__

    text = json.dumps({"steps": steps, "params": params, "version": __version__}, sort_keys=True)
    return hashlib.sha256(text.encode("utf-8")).hexdigest()[:16]


def _finished(task: Task) -> Optional[dict]:
    """The record of an earlier run of this task when it finished with the same key on the
    same input and its files are all there, else None."""
    try:
        record = json.loads(record_path(task.output).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
    if (
        record.get("status") == "ok"
        and record.get("key") == task.key
        and record.get("input_signature") == input_signature(task.input)
        and all(os.path.exists(f) for f in record.get("files", []))
    ):
        return record
    return None


def _figures(record: dict) -> dict:
    """A record's row of the summary CSV."""
    row = {k: record.get(k, "") for k in ("input", "output", "status", "error")}
    row["seconds"] = f"{record.get('seconds', 0.0):.3f}"
    reports = record.get("reports", {})
    first = next(iter(reports.values()), {})
    row["vertices"], row["faces"] = first.get("vertices", ""), first.get("faces", "")
    if "segment" in reports:
        row["patches"] = reports["segment"].get("patch_count", "")
    a = reports.get("approximate")
    if a:
        row["g_abd_before"] = a["total_before"]["g_abd"]
        row["g_abd_after"] = a["total_after"]["g_abd"]
        row["abd_reduction"] = a["abd_reduction"]
        row["max_disp"] = a["total_after"]["max_disp"]
    if "flatten" in reports:
        row["pieces"] = len(reports["flatten"].get("pieces", []))
    return {c: row.get(c, "") for c in CSV_COLUMNS}


def _progress_bar(total: int, skipped: int, show: bool):
    if not show:
        return None
    from tqdm import tqdm

    bar = tqdm(total=total, unit="mesh", desc="quasidev batch", dynamic_ncols=True)
    if skipped:
        bar.write(f"{skipped} file(s) finished before with the same parameters: skipped", sys.stderr)
    return bar


def _run_local(tasks: list[Task], workers: int, done) -> None:
    """Runs tasks on `workers` local processes (spawned, one engine thread each). A process that
    dies fails the files it held; the pool is made anew for the rest."""
    pending = list(tasks)
    while pending:
        context = multiprocessing.get_context("spawn")
        with ProcessPoolExecutor(max_workers=workers, mp_context=context) as pool:
            futures = {pool.submit(run_task, t): t for t in pending}
            pending = []
            broken = False
            for future in as_completed(futures):
                task = futures[future]
                try:
                    done(future.result())
                except BrokenProcessPool:
                    if not broken:
                        broken = True
                        done(_crashed(task, "the worker process died (a crash or out of memory)"))
                    else:
                        pending.append(task)
                except Exception as e:  # the record could not be written (e.g. output folder)
                    done(_crashed(task, f"{type(e).__name__}: {e}"))


def _run_dask(tasks: list[Task], client, done) -> None:
    """Runs tasks on a Dask distributed cluster through client, one task per file."""
    from distributed import as_completed as dask_completed

    futures = {}
    for t in tasks:
        key = "quasidev-batch-" + hashlib.sha256((t.key + t.input).encode()).hexdigest()[:20]
        futures[client.submit(run_task, t, key=key, pure=False)] = t
    for future in dask_completed(list(futures)):
        try:
            done(future.result())
        except Exception as e:  # a worker died (KilledWorker) or could not write the record
            done(_crashed(futures[future], f"{type(e).__name__}: {e}"))


def _crashed(task: Task, error: str) -> dict:
    return {"input": task.input, "output": task.output, "key": task.key, "status": "failed",
            "error": error, "seconds": 0.0}


def _write_summary(out: Path, records: list, counts: dict, seconds: float, meta: dict):
    csv_path, json_path = out / SUMMARY_CSV, out / SUMMARY_JSON
    text = io.StringIO()
    writer = csv.DictWriter(text, fieldnames=CSV_COLUMNS, lineterminator="\n")
    writer.writeheader()
    writer.writerows(_figures(r) for r in records)
    write_atomically(csv_path, text.getvalue())
    rows = [{k: v for k, v in r.items() if k != "reports"} for r in records]
    write_atomically(json_path, json.dumps({**meta, "counts": counts, "seconds": seconds, "files": rows}, indent=1))
    return csv_path, json_path


def batch(
    inputs: str | os.PathLike | Iterable[str | os.PathLike],
    out_dir: str | os.PathLike,
    steps: Iterable[str] = ("approximate",),
    params: Optional[dict] = None,
    *,
    workers: Optional[int] = None,
    client: Any = None,
    progress: bool = True,
) -> BatchSummary:
    """Run a pipeline over many mesh files.

    inputs: folders (their .ply, .obj and .off files, recursively), globs, mesh files or list
    files (one path per line). Each output mirrors its input's name under out_dir as .ply, with
    the pattern (.svg, .dxf) beside it after flatten, and a record NAME.batch.json. steps: a
    subset of ("segment", "approximate", "flatten"), run in that order. params: keyword
    parameters of the jobs, either {"approximate": {...}, "segment": {...}} or one flat dict
    (each name goes to every step that declares it); each step runs on one engine thread unless
    threads is given. A file that finished before with the same steps, parameters and package
    version on the same input is skipped, so an interrupted batch resumes. A bad file is
    recorded as failed and the others go on. workers: local processes (default: the cores);
    client: a dask.distributed.Client to run on a Dask cluster instead. Writes
    out_dir/batch_summary.csv and .json and returns the same as a BatchSummary.
    """
    start = time.perf_counter()
    chosen = tuple(s for s in STEPS if s in set(steps))
    unknown = set(steps) - set(STEPS)
    if unknown or not chosen:
        raise ValueError(f"steps must be a non-empty subset of {STEPS}, got {sorted(set(steps))}")
    step_params = per_step(chosen, params or {})
    key = run_key(chosen, step_params)
    sources = [inputs] if isinstance(inputs, (str, os.PathLike)) else list(inputs)
    out = Path(out_dir).resolve()
    files = [f for f in expand(sources) if out not in f.parents]  # not an earlier run's outputs
    if not files:
        raise ValueError(f"no mesh file among the inputs outside the output folder {out}")
    outputs = mirrored(files, out_dir)
    tasks = [Task(str(i), str(o), chosen, step_params, key) for i, o in zip(files, outputs)]
    records: dict[int, dict] = {}
    for n, t in enumerate(tasks):
        earlier = _finished(t)
        if earlier is not None:
            records[n] = {**earlier, "status": "skipped"}
    todo = [t for n, t in enumerate(tasks) if n not in records]
    index = {t.output: n for n, t in enumerate(tasks)}
    bar = _progress_bar(len(todo), len(tasks) - len(todo), progress)

    def done(record: dict) -> None:
        records[index[record["output"]]] = record
        if bar is not None:
            if record["status"] == "failed":
                bar.write(f"failed: {record['input']}: {record['error']}", sys.stderr)
            bar.update(1)

    try:
        if client is not None:
            _run_dask(todo, client, done)
        elif todo:
            _run_local(todo, workers or len(os.sched_getaffinity(0)), done)
    finally:
        if bar is not None:
            bar.close()
    ordered = [records[n] for n in range(len(tasks)) if n in records]
    counts = {s: sum(r["status"] == s for r in ordered) for s in ("ok", "failed", "skipped")}
    seconds = time.perf_counter() - start
    meta = {"steps": list(chosen), "params": step_params, "key": key}
    csv_path, json_path = _write_summary(out, ordered, counts, seconds, meta)
    return BatchSummary(ordered, counts, seconds, csv_path, json_path)
