"""quasidev.approximate: the quasi-developable approximation (Zeng et al. 2012) of a mesh given
as numpy arrays."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Callable, Optional

import numpy as np

from . import _arrays, _engine, _params


@dataclass(frozen=True)
class ApproximateResult:
    """What quasidev.approximate returns: new arrays owned by the caller and the report."""

    positions: np.ndarray  #: (n, 3) float64, the deformed vertices, in the input's order
    k_before: np.ndarray  #: (n,) float64, Gaussian curvature K(v) of the input (0 on the boundary)
    k_after: np.ndarray  #: (n,) float64, K(v) of the result
    displacement: np.ndarray  #: (n,) float64, how far each vertex moved, in model units
    patches: Optional[np.ndarray]  #: (m,) int64 patch ids when the engine segmented first, else None
    report: dict  #: the figures of the command's JSON report (`quasidev --report`)


def approximate(
    V: Any,
    F: Any,
    patches: Any = None,
    fixed: Any = None,
    progress: Optional[Callable[[float], Any]] = None,
    **params: Any,
) -> ApproximateResult:
    """Make the mesh (V, F) nearly developable, patch by patch.

    Parameters
    ----------
    {mesh}
    patches : array_like, (m,), optional
        A patch id per face; each patch is made developable on its own. None: the whole mesh is
        one patch (or the engine splits it first, see segment_first).
    fixed : array_like, optional
        Vertices that must not move: an (n,) bool mask or an array of vertex indices.
    progress : callable, optional
        Called with the fraction done (0 to 1, never decreasing) while the engine runs, with the
        GIL held; an exception it raises is raised once the engine has finished.

    The inputs are copied and never modified; the result's arrays are new and owned by Python.
    The GIL is released while the engine runs. The engine's warnings are issued as
    UserWarning. Raises ValueError with the engine's message for a bad parameter or a mesh the
    engine refuses, ValueError or TypeError for arrays of the wrong shape or dtype.

    {parameters}
    """
    V64, F64, ids = _arrays.mesh(V, F, patches)
    mask = _arrays.mask("fixed", fixed, len(V64), "vertex")
    out = _engine.approximate(V64, F64, ids, mask, _params.engine_values(params), progress)
    report = _params.report_of(out["report"])
    return ApproximateResult(
        positions=out["positions"],
        k_before=out["k_before"],
        k_after=out["k_after"],
        displacement=out["displacement"],
        patches=None if "patches" not in out else out["patches"].astype(np.int64),
        report=report,
    )


_params.document(approximate, "approximate")
