"""A small dataset for the batch tests: bumpy cylinders of several seeds and sizes in nested
folders (PLY and OBJ), one file that is no mesh and one empty file."""

import pathlib

import numpy as np
import quasidev

BROKEN = ("sub/broken.ply", "sub/deeper/empty.obj")


def bumpy_cylinder(seed: int, around: int, along: int):
    """(V, F) of an open cylinder of radius 1 with random radial bumps of 0.05."""
    rng = np.random.default_rng(seed)
    t = np.linspace(0, 2 * np.pi, around, endpoint=False)
    z = np.linspace(0, 2, along)
    T, Z = np.meshgrid(t, z)
    R = 1 + 0.05 * np.sin(3 * T + rng.uniform(0, 6)) * np.sin(2 * Z + rng.uniform(0, 6))
    V = np.stack([R * np.cos(T), R * np.sin(T), Z], axis=-1).reshape(-1, 3)
    F = []
    for j in range(along - 1):
        for i in range(around):
            a, b = j * around + i, j * around + (i + 1) % around
            c, d = a + around, b + around
            F += [[a, b, d], [a, d, c]]
    return V, np.array(F, dtype=np.int64)


def _write_obj(path: pathlib.Path, V, F):
    lines = [f"v {x:.17g} {y:.17g} {z:.17g}" for x, y, z in V]
    lines += [f"f {a + 1} {b + 1} {c + 1}" for a, b, c in F]
    path.write_text("\n".join(lines) + "\n")


def make_dataset(root: pathlib.Path, count: int = 6) -> list:
    """Writes count meshes and the broken files under root; returns the meshes' relative
    paths."""
    names = []
    for n in range(count):
        folder = root / ("" if n % 2 == 0 else "sub") / ("deeper" if n % 3 == 2 else "")
        folder.mkdir(parents=True, exist_ok=True)
        V, F = bumpy_cylinder(n, 16 + 2 * n, 8 + n)
        if n == 3:
            path = folder / f"mesh{n}.obj"
            _write_obj(path, V, F)
        else:
            path = folder / f"mesh{n}.ply"
            quasidev.write(path, V, F)
        names.append(str(path.relative_to(root)))
    for name in BROKEN:
        (root / name).parent.mkdir(parents=True, exist_ok=True)
    (root / BROKEN[0]).write_text("ply\nformat nonsense\n")
    (root / BROKEN[1]).write_bytes(b"")
    return names
