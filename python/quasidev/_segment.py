"""quasidev.segment: the split of a mesh given as numpy arrays into nearly developable patches."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Callable, Optional

import numpy as np

from . import _arrays, _engine, _params


@dataclass(frozen=True)
class SegmentResult:
    """What quasidev.segment returns: a new array owned by the caller and the report."""

    patches: np.ndarray  #: (m,) int64 patch id per face, 0 to k-1; each patch is edge-connected
    report: dict  #: the figures of `quasidev segment --report`


def segment(
    V: Any,
    F: Any,
    patches: Any = None,
    selected: Any = None,
    progress: Optional[Callable[[float], Any]] = None,
    **params: Any,
) -> SegmentResult:
    """Split the mesh (V, F) into nearly developable patches.

    Parameters
    ----------
    {mesh}
    patches : array_like, (m,), optional
        Existing patch ids per face, kept where they fit (with keep_patches=True).
    selected : array_like, optional
        Selected faces, an (m,) bool mask or face indices: no patch crosses the selection's
        border (with selection_border=True, the default).
    progress : callable, optional
        Called with the fraction done (0 to 1, never decreasing), with the GIL held.

    {contract}

    {parameters}
    """
    V64, F64, ids = _arrays.mesh(V, F, patches)
    chosen = _arrays.mask("selected", selected, len(F64), "face")
    out = _engine.segment(V64, F64, ids, chosen, _params.engine_values(params), progress)
    return SegmentResult(
        patches=out["patches"].astype(np.int64), report=_params.report_of(out["report"])
    )


_params.document(segment, "segment")
