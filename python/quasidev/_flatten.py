"""quasidev.flatten: the flattening of a mesh's patches, given as numpy arrays, into pattern
pieces."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Callable, Optional

import numpy as np

from . import _arrays, _engine, _params


@dataclass(frozen=True)
class FlattenResult:
    """What quasidev.flatten returns: new arrays owned by the caller and the report."""

    uv: np.ndarray  #: (m, 3, 2) float64 texture coordinates (u, v) of each face's three corners
    stretch: np.ndarray  #: (m,) float64 signed stretch per face
    report: dict  #: the figures of `quasidev flatten --report` (without a marker)
    svg: str  #: the pattern as `quasidev flatten --svg` writes it
    dxf: str  #: the pattern as `quasidev flatten --dxf` writes it


def flatten(
    V: Any,
    F: Any,
    patches: Any = None,
    progress: Optional[Callable[[float], Any]] = None,
    **params: Any,
) -> FlattenResult:
    """Flatten each patch of the mesh (V, F) into a pattern piece.

    Parameters
    ----------
    {mesh}
    patches : array_like, (m,)
        The patch id per face (e.g. from quasidev.segment); None: the whole mesh is one patch.
    progress : callable, optional
        Called with the fraction done (0 to 1, never decreasing), with the GIL held.

    {contract}

    {parameters}
    """
    V64, F64, ids = _arrays.mesh(V, F, patches)
    out = _engine.flatten(V64, F64, ids, _params.engine_values(params), progress)
    return FlattenResult(
        uv=out["uv"],
        stretch=out["stretch"],
        report=_params.report_of(out["report"]),
        svg=out["svg"],
        dxf=out["dxf"],
    )


_params.document(flatten, "flatten")
