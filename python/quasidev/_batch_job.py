"""One file of a batch: read it, run the pipeline's steps on it, write its outputs and then its
record, each atomically. The local processes and the Dask workers run the same function."""

from __future__ import annotations

import json
import os
import time
import traceback
import warnings
from dataclasses import dataclass
from pathlib import Path

from ._approximate import approximate
from ._batch_files import write_atomically
from ._files import read, write
from ._flatten import flatten
from ._segment import segment

STEPS = ("segment", "approximate", "flatten")


@dataclass(frozen=True)
class Task:
    """What a worker needs for one file (plain data, so that it pickles for any executor)."""

    input: str
    output: str  #: the output PLY; the pattern and the record sit beside it
    steps: tuple  #: a subset of STEPS, run in STEPS' order
    params: dict  #: the keyword parameters per step
    key: str  #: names the steps, parameters and package version (see _batch.run_key)


def record_path(output: str | os.PathLike) -> Path:
    """Where a file's record is written: beside its output, as NAME.batch.json."""
    out = Path(output)
    return out.with_name(out.stem + ".batch.json")


def input_signature(path: str | os.PathLike) -> dict:
    """The input's size and modification time: a rerun redoes a file whose input changed."""
    st = os.stat(path)
    return {"size": st.st_size, "mtime_ns": st.st_mtime_ns}


def _peak_memory_mb() -> float:
    """This process's peak resident memory so far (VmHWM), in MB; 0 where /proc has none."""
    try:
        with open("/proc/self/status", encoding="ascii") as f:
            for line in f:
                if line.startswith("VmHWM:"):
                    return int(line.split()[1]) / 1024.0
    except OSError:
        pass
    return 0.0


def _pipeline(task: Task) -> tuple[list[str], dict]:
    """Runs the steps on the input and writes the mesh (and the pattern after flatten); returns
    the files written and each step's report."""
    mesh = read(task.input)
    V, patches, quality, uv = mesh.V, mesh.patches, None, None
    reports: dict = {}
    output = Path(task.output)
    output.parent.mkdir(parents=True, exist_ok=True)
    files = [str(output)]
    if "segment" in task.steps:
        seg = segment(V, mesh.F, patches=patches, **task.params.get("segment", {}))
        patches = seg.patches
        reports["segment"] = seg.report
    if "approximate" in task.steps:
        r = approximate(V, mesh.F, patches=patches, fixed=mesh.fixed, **task.params.get("approximate", {}))
        V, quality = r.positions, r.k_after
        patches = patches if r.patches is None else r.patches
        reports["approximate"] = r.report
    if "flatten" in task.steps:
        flat = flatten(V, mesh.F, patches, **task.params.get("flatten", {}))
        uv = flat.uv
        reports["flatten"] = flat.report
        for suffix, text in ((".svg", flat.svg), (".dxf", flat.dxf)):
            write_atomically(output.with_suffix(suffix), text)
            files.append(str(output.with_suffix(suffix)))
    write(output, V, mesh.F, patches=patches, quality=quality, uv=uv)
    return files, reports


def run_task(task: Task) -> dict:
    """Runs one file and returns its record (also written beside the output): status "ok" or
    "failed" with the error, the files written, each step's report, the engine's warnings, the
    time and this worker's peak memory. Never raises for a bad file."""
    start = time.perf_counter()
    record: dict = {"input": task.input, "output": task.output, "key": task.key}
    record["input_signature"] = input_signature(task.input) if os.path.exists(task.input) else None
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            record["files"], record["reports"] = _pipeline(task)
            record["status"] = "ok"
        except Exception as e:  # a bad file is reported and the batch goes on
            record["status"] = "failed"
            record["error"] = f"{type(e).__name__}: {e}"
            if not isinstance(e, (ValueError, OSError, MemoryError)):
                record["traceback"] = traceback.format_exc()
    record["warnings"] = [str(w.message) for w in caught]
    record["seconds"] = time.perf_counter() - start
    record["worker_pid"] = os.getpid()
    record["peak_memory_mb"] = _peak_memory_mb()
    write_atomically(record_path(task.output), json.dumps(record, indent=1))
    return record
