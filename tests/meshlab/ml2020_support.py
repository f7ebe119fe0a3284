"""Helpers of the MeshLab 2020.09 integration tests.

Inputs: PLY files (read with plyfile), .mlx filter scripts, the build directory.
Outputs: meshes as numpy arrays, independent geometry figures (angle defects, boundary and seam
vertices), the `quasidev` command line equivalent to an .mlx, and runners for the real
meshlabserver (under xvfb-run) and the quasidev command.
"""
from __future__ import annotations

import json
import math
import os
import subprocess
import sys
import xml.etree.ElementTree as ET
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from plyfile import PlyData

REPO = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(REPO / "scripts"))
from ply_columns import column, element, faces, has, positions  # noqa: E402

FILTER_NAME = "Quasi-Developable Approximation"
FLATTEN_FILTER_NAME = "Quasi-Developable Flattening"
SEGMENT_FILTER_NAME = "Quasi-Developable Segmentation"
SELECTED = 0x20  # vcg's SELECTED vertex flag, as MeshLab 2020.09 reads/writes PLY "flags"
XVFB = ["xvfb-run", "-a", "-s", "-screen 0 1024x768x24"]
XVFB_CLEANUP_ERROR = "xvfb-run: error: problem while cleaning up temporary directory"


def build_dir() -> Path:
    return Path(os.environ.get("QD_BUILD_DIR", REPO / "build"))


def declared_parameters(job: str) -> list[dict]:
    """The declared parameters of a job ("approximate", "segment" or "flatten"), in order, as
    `qd_reference --json` gives them (filter_quasidev/params/)."""
    out = subprocess.run([str(build_dir() / "bin" / "qd_reference"), "--json"], capture_output=True,
                         text=True, check=True).stdout
    return json.loads(out)[job]["parameters"]


@dataclass
class Mesh:
    """A triangle mesh with the per-element attributes the tests look at (None = absent)."""
    v: np.ndarray                        # (n, 3) float64
    f: np.ndarray                        # (m, 3) int64
    face_quality: np.ndarray | None = None
    flags: np.ndarray | None = None      # per-vertex int flags
    quality: np.ndarray | None = None    # per-vertex quality
    color: np.ndarray | None = None      # (n, 3) uint8
    texcoord: np.ndarray | None = None   # (m, 6) per-face corner u v
    face_color: np.ndarray | None = None  # (m, 3) uint8

    @property
    def selected(self) -> np.ndarray:
        if self.flags is None:
            return np.zeros(len(self.v), dtype=bool)
        return (self.flags & SELECTED) != 0

    def diagonal(self) -> float:
        return float(np.linalg.norm(self.v.max(axis=0) - self.v.min(axis=0)))


def _column(ply: PlyData, element: str, prop: str, dtype) -> np.ndarray | None:
    return np.asarray(column(ply, element, prop), dtype=dtype) if has(ply, element, prop) else None


def load_mesh(path: Path) -> Mesh:
    ply = PlyData.read(path)

    def rgb(element: str) -> np.ndarray | None:
        if not all(has(ply, element, c) for c in ("red", "green", "blue")):
            return None
        return np.stack([np.asarray(column(ply, element, c), np.uint8) for c in ("red", "green", "blue")], 1)
    texcoord = _column(ply, "face", "texcoord", np.float64)
    return Mesh(v=positions(ply),
                f=np.asarray(faces(ply), np.int64).reshape(-1, 3),
                face_quality=_column(ply, "face", "quality", np.float64),
                flags=_column(ply, "vertex", "flags", np.int64),
                quality=_column(ply, "vertex", "quality", np.float64),
                color=rgb("vertex"),
                texcoord=None if texcoord is None else texcoord.reshape(-1, 6),
                face_color=rgb("face"))


def save_float_mesh(mesh: Mesh, path: Path, face_quality: bool = True) -> None:
    """Writes mesh with float32 x y z (what MeshLab 2020.09 stores), vertex flags and face
    quality when present (face quality dropped when face_quality is False)."""
    vcols = [(c, "f4", mesh.v[:, k]) for k, c in enumerate("xyz")]
    if mesh.flags is not None:
        vcols.append(("flags", "i4", mesh.flags))
    fcols = [("vertex_indices", ("u1", "i4"), mesh.f)]
    if face_quality and mesh.face_quality is not None:
        fcols.append(("quality", "f4", mesh.face_quality))
    PlyData([element("vertex", vcols), element("face", fcols)], comments=["written by tests/meshlab"]).write(path)


def float_rounded(mesh: Mesh) -> Mesh:
    return Mesh(v=np.float32(mesh.v).astype(np.float64), f=mesh.f.copy(),
                face_quality=None if mesh.face_quality is None else mesh.face_quality.copy(),
                flags=None if mesh.flags is None else mesh.flags.copy())


# ---- independent geometry -----------------------------------------------------------------------

def _edge_faces(f: np.ndarray) -> dict[tuple[int, int], list[int]]:
    edges: dict[tuple[int, int], list[int]] = {}
    for k, (a, b, c) in enumerate(f):
        for u, w in ((a, b), (b, c), (c, a)):
            edges.setdefault((min(u, w), max(u, w)), []).append(k)
    return edges


def boundary_vertices(mesh: Mesh) -> np.ndarray:
    mask = np.zeros(len(mesh.v), dtype=bool)
    for (u, w), faces in _edge_faces(mesh.f).items():
        if len(faces) == 1:
            mask[[u, w]] = True
    return mask


def seam_vertices(mesh: Mesh) -> np.ndarray:
    """Vertices whose faces carry more than one patch id (rounded face quality)."""
    mask = np.zeros(len(mesh.v), dtype=bool)
    if mesh.face_quality is None:
        return mask
    patch = np.rint(mesh.face_quality).astype(np.int64)
    first = np.full(len(mesh.v), np.iinfo(np.int64).min)
    for k, tri in enumerate(mesh.f):
        for v in tri:
            if first[v] == np.iinfo(np.int64).min:
                first[v] = patch[k]
            elif first[v] != patch[k]:
                mask[v] = True
    return mask


def angle_defects(mesh: Mesh) -> np.ndarray:
    """2π − Σθ per vertex (meaningful at interior vertices)."""
    p = mesh.v[mesh.f]
    total = np.zeros(len(mesh.v))
    for k in range(3):
        a, b, c = p[:, k], p[:, (k + 1) % 3], p[:, (k + 2) % 3]
        e1, e2 = b - a, c - a
        cosine = np.einsum("ij,ij->i", e1, e2) / (np.linalg.norm(e1, axis=1) * np.linalg.norm(e2, axis=1))
        np.add.at(total, mesh.f[:, k], np.arccos(np.clip(cosine, -1.0, 1.0)))
    return 2 * math.pi - total


def integrated_curvature(mesh: Mesh, vertices: np.ndarray) -> float:
    """Σ|2π − Σθ| over the given vertex mask (density-independent total curvature)."""
    return float(np.abs(angle_defects(mesh)[vertices]).sum())


# ---- .mlx scripts and the equivalent quasidev command ---------------------------------------------

def mlx_parameters(path: Path, filter_name: str = FILTER_NAME) -> dict[str, tuple[str, str, list[str]]]:
    """name -> (type, value, enum items) of the named filter (default: the approximation) in an
    .mlx file."""
    root = ET.parse(path).getroot()
    for node in root.iter("filter"):
        if node.get("name") == filter_name:
            out = {}
            for p in node.iter("Param"):
                n = int(p.get("enum_cardinality", "0"))
                out[p.get("name")] = (p.get("type"), p.get("value"), [p.get(f"enum_val{i}") for i in range(n)])
            return out
    raise AssertionError(f"{path} has no '{filter_name}' filter")


def write_mlx(path: Path, values: dict[str, object], base: Path = REPO / "sample_meshes" / "default.mlx",
              before: str = "", after: str = "", filter_name: str = FILTER_NAME) -> Path:
    """Writes base's filter called filter_name (default: the approximation) to path with the
    given parameter values (Python bools become true/false), preceded and followed by the raw
    <filter> XML in before/after."""
    root = ET.parse(base).getroot()
    node = next(n for n in root.iter("filter") if n.get("name") == filter_name)
    for p in node.iter("Param"):
        if p.get("name") in values:
            v = values[p.get("name")]
            p.set("value", str(v).lower() if isinstance(v, bool) else str(v))
    ours = ET.tostring(node, encoding="unicode")
    path.write_text(f"<!DOCTYPE FilterScript>\n<FilterScript>\n{before}{ours}{after}</FilterScript>\n")
    return path


def cli_arguments(params: dict[str, tuple[str, str, list[str]]]) -> tuple[list[str], bool]:
    """The quasidev options equal to an .mlx's parameters, and whether patches are used. Every
    parameter has one name in both (docs/reference/): `name` in the .mlx is `--name` with '-'
    for '_' in the command, with the same unit and meaning."""
    args = []
    for name, (kind, value, items) in params.items():
        option = "--" + name.replace("_", "-")
        if kind == "RichBool":
            args.append(option if value == "true" else "--no-" + option[2:])
        elif kind == "RichEnum":
            args += [option, items[int(value)]]
        elif kind not in ("RichString", "RichSaveFile") or value:
            args += [option, value]
    return args, params["use_patches"][1] == "true"


# ---- running the binaries -------------------------------------------------------------------------

def run_meshlabserver(prefix: Path, mesh_in: Path, mesh_out: Path, script: Path,
                      saved: tuple[str, ...] = ("vc", "vq", "vf", "fq"),
                      timeout: float = 600) -> subprocess.CompletedProcess:
    """meshlabserver of the private prefix, under Xvfb, saving the `saved` attributes (default:
    vertex colour, quality, flags and face quality). stdout and stderr are merged into .stdout."""
    cmd = XVFB + [str(prefix / "bin" / "meshlabserver"), "-i", str(mesh_in), "-o", str(mesh_out),
                  "-m", *saved, "-s", str(script)]
    env = dict(os.environ, HOME=str(mesh_out.parent))
    for _ in range(3):
        run = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                             timeout=timeout, env=env, check=False)
        # xvfb-run sometimes fails to remove its temporary directory when the program ends at
        # once; it then exits 5 and meshlabserver's status is lost: run the job again.
        if not (run.returncode == 5 and XVFB_CLEANUP_ERROR in run.stdout):
            break
    return run


def run_quasidev(mesh_in: Path, mesh_out: Path, args: list[str], timeout: float = 600,
                 subcommand: str = "approximate") -> subprocess.CompletedProcess:
    cmd = [str(build_dir() / "bin" / "quasidev"), subcommand, str(mesh_in), str(mesh_out), "--quiet", *args]
    return subprocess.run(cmd, capture_output=True, text=True, timeout=timeout, check=False)
