"""Where the scripts find real meshes by name.

tests/data/ is in the repository (public meshes, credited in tests/data/SOURCES.md). The benchmark
and figure meshes that are not shipped (the 40k-face tee, ...) are read from the folder named by
the environment variable QD_SHARED_MESHES; a script that wants one it cannot find skips it and says
how to name the folder. No machine path is assumed.
"""
from __future__ import annotations

import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TEST_DATA = os.path.join(ROOT, "tests", "data")
SAMPLES = os.path.join(ROOT, "sample_meshes")
ENV = "QD_SHARED_MESHES"


def mesh_folders() -> list[str]:
    """The folders searched, in order: $QD_SHARED_MESHES when set, then tests/data/."""
    extra = os.environ.get(ENV)
    return ([extra] if extra else []) + [TEST_DATA]


def find_mesh(name: str) -> str | None:
    """The path of the mesh file `name` in mesh_folders(), or None."""
    for folder in mesh_folders():
        path = os.path.join(folder, name)
        if os.path.isfile(path):
            return path
    return None


def missing(names: list[str]) -> str:
    """The message for meshes not found: which, and how to name the folder that holds them."""
    return (f"{', '.join(names)} not in tests/data/; set {ENV}=DIR to the folder holding "
            f"{'it' if len(names) == 1 else 'them'}")


def existing(names: list[str], script: str) -> list[str]:
    """The paths of those of `names` that are found; says on stderr which are skipped."""
    found = {n: find_mesh(n) for n in names}
    lost = [n for n, p in found.items() if p is None]
    if lost:
        print(f"{script}: skipping {missing(lost)}", file=sys.stderr)
    return [p for p in found.values() if p]
