"""The checks and conversions of the arrays a job takes: each input becomes a new C-contiguous
array of the type the engine reads (float64 positions, int64 indices and ids, bool flags), so
the caller's arrays are never modified nor kept."""

from __future__ import annotations

import numpy as np


def _array(name: str, a, kinds: str, what: str) -> np.ndarray:
    try:
        arr = np.asarray(a)
    except Exception as e:  # ragged lists and the like
        raise TypeError(f"{name} must be {what}: {e}") from None
    if arr.dtype.kind not in kinds:
        raise TypeError(f"{name} must be {what}, got an array of dtype {arr.dtype}")
    return arr


def _whole(name: str, arr: np.ndarray) -> np.ndarray:
    if arr.dtype.kind == "f":
        if not np.all(np.isfinite(arr)) or np.any(arr != np.round(arr)):
            raise TypeError(f"{name} must hold whole numbers")
    return np.array(arr, dtype=np.int64, order="C", copy=True)


def vertices(V) -> np.ndarray:
    """V as a new (n, 3) float64 C-ordered array."""
    arr = _array("V", V, "fiu", "an (n, 3) array of real numbers")
    if arr.ndim != 2 or arr.shape[1] != 3:
        raise ValueError(f"V must have shape (n, 3), got {arr.shape}")
    out = np.array(arr, dtype=np.float64, order="C", copy=True)
    if not np.all(np.isfinite(out)):
        raise ValueError("V holds a NaN or an infinite coordinate")
    return out


def faces(F, n: int) -> np.ndarray:
    """F as a new (m, 3) int64 C-ordered array of vertex indices in [0, n)."""
    arr = _array("F", F, "iuf", "an (m, 3) array of vertex indices")
    if arr.ndim != 2 or arr.shape[1] != 3:
        raise ValueError(f"F must have shape (m, 3), got {arr.shape}")
    out = _whole("F", arr)
    if out.size and (out.min() < 0 or out.max() >= n):
        raise ValueError(f"F holds vertex indices outside 0..{n - 1}")
    return out


def patch_ids(patches, m: int) -> np.ndarray | None:
    """patches (one id per face) as a new (m,) int64 array, or None."""
    if patches is None:
        return None
    arr = _array("patches", patches, "iuf", "an (m,) array of integer patch ids")
    if arr.shape != (m,):
        raise ValueError(f"patches must have shape ({m},) (one id per face), got {arr.shape}")
    return _whole("patches", arr)


def mesh(V, F, patches) -> tuple[np.ndarray, np.ndarray, np.ndarray | None]:
    """V, F and the patch ids as the engine takes them (vertices, faces, patch_ids above)."""
    V64 = vertices(V)
    F64 = faces(F, len(V64))
    return V64, F64, patch_ids(patches, len(F64))


def mask(name: str, value, count: int, items: str) -> np.ndarray | None:
    """value (a (count,) bool mask or an array of indices of items) as a new (count,) bool mask,
    or None."""
    if value is None:
        return None
    arr = _array(name, value, "biuf", f"a ({count},) bool mask or an array of {items} indices")
    if arr.dtype.kind == "b":
        if arr.shape != (count,):
            raise ValueError(f"a bool {name} mask must have shape ({count},), got {arr.shape}")
        return np.array(arr, dtype=bool, order="C", copy=True)
    index = _whole(name, arr.reshape(-1))
    if index.size and (index.min() < 0 or index.max() >= count):
        raise ValueError(f"{name} holds {items} indices outside 0..{count - 1}")
    out = np.zeros(count, dtype=bool)
    out[index] = True
    return out
