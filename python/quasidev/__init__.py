"""quasidev: quasi-developable mesh approximation (Zeng et al. 2012) on numpy arrays, on the
engine of the `quasidev` command and the MeshLab filters.

    import quasidev
    result = quasidev.approximate(V, F, keep_boundary=True)
    result.positions, result.k_after, result.report["abd_reduction"]
    quasidev.segment(V, F).patches      # a patch id per face
    quasidev.flatten(V, F, patches).uv  # (m, 3, 2) texture coordinates per corner
    mesh = quasidev.read("in.ply"); quasidev.write("out.ply", mesh.V, mesh.F, mesh.patches)
    quasidev.batch("garments/", "out/", steps=("segment", "approximate"))  # many files
"""

from importlib.metadata import PackageNotFoundError, version

from . import _blas_kernels

_blas_kernels.choose_blas_kernels()  # before the engine below loads OpenBLAS

from ._approximate import ApproximateResult, approximate  # noqa: E402
from ._batch import BatchSummary, batch  # noqa: E402
from ._files import Mesh, read, write  # noqa: E402
from ._flatten import FlattenResult, flatten  # noqa: E402
from ._params import DECLARATION  # noqa: E402
from ._segment import SegmentResult, segment  # noqa: E402

try:
    __version__ = version("quasidev")
except PackageNotFoundError:  # not installed
    __version__ = "unknown"

__all__ = [
    "ApproximateResult",
    "BatchSummary",
    "DECLARATION",
    "FlattenResult",
    "Mesh",
    "SegmentResult",
    "approximate",
    "batch",
    "flatten",
    "read",
    "segment",
    "write",
]
