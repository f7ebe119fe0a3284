#!/usr/bin/env python3
"""The tutorials' pictures (docs/tutorials/*.png), each made by running the `quasidev` command.

  lampshade_before_after.png  sample_meshes/lampshade.ply before and after `quasidev approximate`
                              (defaults), both coloured by |K| on one scale
                              (scripts/render_before_after.py)
  lampshade_pattern.png       that result beside its pattern from `quasidev flatten --svg`
                              (scripts/flatten_compare.py's picture)
  spot_segments.png           a closed mesh (spot) after `quasidev segment --max-error 30`,
                              one colour per patch (scripts/render.py)
  spot_before_after.png       spot before and after `quasidev segment --max-error 30` then
                              `quasidev approximate --seams free`, one |K| scale
The spot pictures need classic_spot_lowres_crane.ply (Keenan Crane's Spot, public domain) in the
folder given by --meshes or the environment variable QD_MESHES; without it they are skipped with
a message. Needs numpy, Pillow, matplotlib, pymeshlab (the Hausdorff distance in the titles) and
rsvg-convert (scripts/setup.sh installs them).

Usage: .venv/bin/python scripts/docs_figures.py [--quasidev PATH] [--meshes DIR] [--out DIR]
"""
from __future__ import annotations

import argparse
import os
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
SCRIPTS = ROOT / "scripts"
sys.path.insert(0, str(SCRIPTS))
from flatten_compare import picture  # noqa: E402

SPOT = "classic_spot_lowres_crane.ply"


def run(*cmd) -> None:
    print("+", " ".join(str(c) for c in cmd), flush=True)
    subprocess.run([str(c) for c in cmd], check=True)


def python(script: str, *args) -> None:
    run(sys.executable, SCRIPTS / script, *args)


def lampshade(quasidev: Path, out: Path, tmp: Path) -> None:
    mesh = ROOT / "sample_meshes" / "lampshade.ply"
    after, svg = tmp / "lampshade_dev.ply", tmp / "lampshade.svg"
    run(quasidev, "approximate", mesh, after, "--quiet")
    python("render_before_after.py", mesh, after, "-o", out / "lampshade_before_after.png",
           "--name", "sample_meshes/lampshade.ply", "--after-label", "after quasidev approximate")
    run(quasidev, "flatten", after, tmp / "lampshade_flat.ply", "--svg", svg, "--quiet")
    picture(after, svg, out / "lampshade_pattern.png")


def spot(quasidev: Path, meshes: Path, out: Path, tmp: Path) -> None:
    mesh = meshes / SPOT
    seg, after = tmp / "spot_seg.ply", tmp / "spot_dev.ply"
    run(quasidev, "segment", mesh, seg, "--max-error", "30", "--quiet")
    python("render.py", seg, "-o", out / "spot_segments.png", "--color", "patch",
           "--size", "560x420", "--labels", "quasidev segment --max-error 30 (colour = patch)")
    run(quasidev, "approximate", seg, after, "--seams", "free", "--quiet")
    python("render_before_after.py", mesh, after, "-o", out / "spot_before_after.png",
           "--name", "spot", "--after-label", "after segment, then approximate --seams free")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quasidev", type=Path, default=ROOT / "build" / "bin" / "quasidev")
    ap.add_argument("--meshes", type=Path, default=os.environ.get("QD_MESHES"),
                    help=f"folder holding {SPOT} (default: $QD_MESHES)")
    ap.add_argument("--out", type=Path, default=ROOT / "docs" / "tutorials")
    args = ap.parse_args()
    args.out.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory(prefix="docs-figures-") as d:
        lampshade(args.quasidev, args.out, Path(d))
        if args.meshes and (args.meshes / SPOT).is_file():
            spot(args.quasidev, args.meshes, args.out, Path(d))
        else:
            print(f"skipped the spot pictures: no {SPOT} in --meshes / $QD_MESHES", file=sys.stderr)


if __name__ == "__main__":
    main()
