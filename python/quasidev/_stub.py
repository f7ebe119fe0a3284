"""The package's type stub (__init__.pyi) made from the engine's parameter declaration, so that
every declared parameter is a typed keyword argument with its default. Rewrite it with
`python -m quasidev._stub > python/quasidev/__init__.pyi`; tests/python/test_stub.py checks that
the committed stub is current."""

from __future__ import annotations

from ._params import DECLARATION, python_type

_HEADER = '''# Made by `python -m quasidev._stub` from the engine's parameter declaration: do not edit.
import os
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Callable, Iterable, Literal, Optional

import numpy as np
import numpy.typing as npt

__version__: str
DECLARATION: dict[str, list[dict[str, Any]]]

_Progress = Optional[Callable[[float], Any]]


@dataclass(frozen=True)
class ApproximateResult:
    positions: np.ndarray
    k_before: np.ndarray
    k_after: np.ndarray
    displacement: np.ndarray
    patches: Optional[np.ndarray]
    report: dict[str, Any]


@dataclass(frozen=True)
class SegmentResult:
    patches: np.ndarray
    report: dict[str, Any]


@dataclass(frozen=True)
class FlattenResult:
    uv: np.ndarray
    stretch: np.ndarray
    report: dict[str, Any]
    svg: str
    dxf: str


@dataclass(frozen=True)
class Mesh:
    V: np.ndarray
    F: np.ndarray
    patches: Optional[np.ndarray] = None
    fixed: Optional[np.ndarray] = None
    patch_names: dict[int, str] = ...
    notes: list[str] = ...


def read(path: str | os.PathLike[str]) -> Mesh: ...


def write(
    path: str | os.PathLike[str],
    V: npt.ArrayLike,
    F: npt.ArrayLike,
    patches: Optional[npt.ArrayLike] = None,
    quality: Optional[npt.ArrayLike] = None,
    uv: Optional[npt.ArrayLike] = None,
) -> None: ...


@dataclass(frozen=True)
class BatchSummary:
    records: list[dict[str, Any]]
    counts: dict[str, int]
    seconds: float
    summary_csv: Path
    summary_json: Path


def batch(
    inputs: str | os.PathLike[str] | Iterable[str | os.PathLike[str]],
    out_dir: str | os.PathLike[str],
    steps: Iterable[Literal["segment", "approximate", "flatten"]] = ("approximate",),
    params: Optional[dict[str, Any]] = None,
    *,
    workers: Optional[int] = None,
    client: Any = None,
    progress: bool = True,
) -> BatchSummary: ...
'''

_ARGUMENTS = {
    "approximate": ["patches: Optional[npt.ArrayLike] = None",
                    "fixed: Optional[npt.ArrayLike] = None"],
    "segment": ["patches: Optional[npt.ArrayLike] = None",
                "selected: Optional[npt.ArrayLike] = None"],
    "flatten": ["patches: Optional[npt.ArrayLike] = None"],
}
_RESULTS = {
    "approximate": "ApproximateResult",
    "segment": "SegmentResult",
    "flatten": "FlattenResult",
}


def _function(job: str) -> str:
    lines = [f"def {job}(", "    V: npt.ArrayLike,", "    F: npt.ArrayLike,"]
    lines += [f"    {a}," for a in _ARGUMENTS[job]]
    lines += ["    progress: _Progress = None,", "    *,"]
    lines += [f"    {p['name']}: {python_type(p)} = {p['default']!r}," for p in DECLARATION[job]]
    lines.append(f") -> {_RESULTS[job]}: ...")
    return "\n".join(lines)


def stub_text() -> str:
    """The text of quasidev/__init__.pyi."""
    return _HEADER + "".join("\n\n" + _function(job) + "\n" for job in _RESULTS)


if __name__ == "__main__":
    print(stub_text(), end="")
