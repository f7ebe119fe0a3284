"""The files of a batch: the meshes that folders, globs and list files name, the output path
that mirrors each input's name under the output folder, and atomic writes."""

from __future__ import annotations

import glob
import os
from pathlib import Path
from typing import Iterable

MESH_SUFFIXES = (".ply", ".obj", ".off")


def _is_mesh(path: Path) -> bool:
    return path.suffix.lower() in MESH_SUFFIXES


def _listed(list_file: Path) -> list[Path]:
    """The paths of a list file: one per line, relative to the list's folder; blank lines and
    lines starting with # are skipped."""
    out = []
    for line in list_file.read_text(encoding="utf-8").splitlines():
        line = line.strip()
        if line and not line.startswith("#"):
            out.append((list_file.parent / line).resolve())
    return out


def expand(sources: Iterable[str | os.PathLike]) -> list[Path]:
    """The meshes named by sources, each one a folder (its PLY, OBJ and OFF files, recursively),
    a glob pattern, a mesh file or a list file; sorted per source, each file once."""
    found: list[Path] = []
    for source in sources:
        text = os.fspath(source)
        path = Path(text)
        if path.is_dir():
            found += sorted(p.resolve() for p in path.rglob("*") if p.is_file() and _is_mesh(p))
        elif glob.has_magic(text):
            found += sorted(Path(p).resolve() for p in glob.glob(text, recursive=True) if Path(p).is_file())
        elif not path.exists():
            raise ValueError(f"{text}: no such file, folder or matching glob")
        elif _is_mesh(path):
            found.append(path.resolve())
        else:
            found += _listed(path)
    unique = list(dict.fromkeys(found))
    if not unique:
        raise ValueError("no mesh file (.ply, .obj, .off) among the inputs")
    return unique


def mirrored(inputs: list[Path], out_dir: str | os.PathLike) -> list[Path]:
    """Each input's output: its path relative to the inputs' common folder, under out_dir, as
    .ply. Raises ValueError when two inputs would share an output (batch() leaves out the
    files inside out_dir, so no output is an input)."""
    root = Path(os.path.commonpath([p.parent for p in inputs]))
    out = Path(out_dir).resolve()
    outputs = [(out / p.relative_to(root)).with_suffix(".ply") for p in inputs]
    seen: dict[Path, Path] = {}
    for source, target in zip(inputs, outputs):
        if target in seen:
            raise ValueError(f"{seen[target]} and {source} would both be written to {target}")
        seen[target] = source
    return outputs


def write_atomically(path: Path, data: str | bytes) -> None:
    """Write data to path through a temporary file in its folder, renamed once complete, so
    path holds either its old content or the whole new one."""
    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = path.with_name(f".{path.name}.{os.getpid()}.tmp")
    try:
        with open(tmp, "wb") as f:
            f.write(data.encode("utf-8") if isinstance(data, str) else data)
        os.replace(tmp, path)
    finally:
        if tmp.exists():
            tmp.unlink()
