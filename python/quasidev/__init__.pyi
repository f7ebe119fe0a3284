# Made by `python -m quasidev._stub` from the engine's parameter declaration: do not edit.
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


def approximate(
    V: npt.ArrayLike,
    F: npt.ArrayLike,
    patches: Optional[npt.ArrayLike] = None,
    fixed: Optional[npt.ArrayLike] = None,
    progress: _Progress = None,
    *,
    tolerance_ae: float = 1.0,
    tolerance_model: float = 0.0,
    patch_tolerance_ae: str = '',
    tolerance_mode: Literal['step', 'total'] = 'step',
    clamp: Literal['scale', 'vertex'] = 'scale',
    max_iter: int = 30,
    stop_rule: Literal['plateau', 'paper'] = 'plateau',
    stop_abd: float = 1.0,
    stop_obd: float = 1.0,
    weight: float = 30.0,
    developability: Literal['curve', 'defect', 'both', 'auto'] = 'auto',
    defect_weight: float = 0.03,
    anchor: float = 3.0,
    target_mode: Literal['fixed', 'reproject', 'refit', 'reproject-then-refit'] = 'reproject-then-refit',
    seam_mode: Literal['fixed', 'free'] = 'fixed',
    segment_first: Literal['auto', 'never', 'always'] = 'auto',
    keep_boundary: bool = True,
    use_patches: bool = True,
    solver: Literal['auto', 'cholmod', 'eigen-llt', 'eigen-ldlt'] = 'auto',
    method: Literal['auto', 'direct', 'iterative'] = 'auto',
    threads: int = 0,
) -> ApproximateResult: ...


def segment(
    V: npt.ArrayLike,
    F: npt.ArrayLike,
    patches: Optional[npt.ArrayLike] = None,
    selected: Optional[npt.ArrayLike] = None,
    progress: _Progress = None,
    *,
    max_error_deg: float = 20.0,
    min_faces: int = 20,
    min_area: float = 0.0,
    target_patches: int = 0,
    keep_patches: bool = False,
    selection_border: bool = True,
    crease_deg: float = 60.0,
    max_rounds: int = 10,
    threads: int = 0,
) -> SegmentResult: ...


def flatten(
    V: npt.ArrayLike,
    F: npt.ArrayLike,
    patches: Optional[npt.ArrayLike] = None,
    progress: _Progress = None,
    *,
    arap_max_iter: int = 100,
    arap_tolerance: float = 0.0001,
    gap: float = 0.0,
    notch_spacing: float = 0.0,
    seam_allowance: float = 0.0,
    grain_direction: str = '0,1,0',
    symmetry_tolerance: float = 1.0,
    solver: Literal['auto', 'cholmod', 'eigen-llt', 'eigen-ldlt'] = 'auto',
    threads: int = 0,
) -> FlattenResult: ...
