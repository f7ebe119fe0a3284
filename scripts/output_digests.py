"""Fingerprint every output file of the three jobs, to show that a refactoring changed nothing.

Runs `quasidev approximate`, `segment` and `flatten` (with its SVG, plain and AAMA DXF and
marker files) on the bundled samples, the test data and, with --shared DIR, the shared meshes,
and writes the SHA-256 of each output file. JSON reports are fingerprinted without their
timings and paths (`time_ms`, `*_ms`, `input`, `output`), which differ run to run.

    python scripts/output_digests.py --build build --out before.json
    ... change the code, rebuild ...
    python scripts/output_digests.py --build build --compare before.json

--compare exits with 1 and names each file whose digest differs.
"""
from __future__ import annotations

import argparse
import hashlib
import json
import pathlib
import subprocess
import sys
import tempfile

REPO = pathlib.Path(__file__).resolve().parent.parent

# Meshes whose patches are panels: flatten runs on them as they are.
PANELLED = ("cone_panels.ply", "draped_panels.ply", "patches.ply",
            "garment_shirt_initial_diffavatar.ply", "garment_shirt_initial_diffavatar.obj",
            "garment_tee4panel_gpg.ply", "garment_tee_gcd_0AZKWACRSY.ply")
APPROXIMATE_VARIANTS = {"default": [], "free_seams": ["--seams", "free", "--max-iter", "5"],
                        "defect": ["--developability", "defect", "--max-iter", "5"]}


def _report_digest(path: pathlib.Path) -> str:
    def strip(value):
        if isinstance(value, dict):
            return {k: strip(v) for k, v in value.items()
                    if k not in ("input", "output", "time_ms", "log") and not k.endswith("_ms")}
        if isinstance(value, list):
            return [strip(v) for v in value]
        return value
    text = json.dumps(strip(json.loads(path.read_text())), sort_keys=True)
    return hashlib.sha256(text.encode()).hexdigest()


def _digests(folder: pathlib.Path) -> dict[str, str]:
    out = {}
    for path in sorted(folder.iterdir()):
        if path.suffix == ".json":
            out[path.name] = _report_digest(path)
        else:
            out[path.name] = hashlib.sha256(path.read_bytes()).hexdigest()
    return out


def _run(binary: pathlib.Path, args: list[str], folder: pathlib.Path) -> dict[str, str]:
    folder.mkdir(parents=True)
    r = subprocess.run([str(binary), *args, "--quiet", "--report", str(folder / "report.json")],
                       cwd=folder, capture_output=True, text=True)
    digests = _digests(folder)
    digests["exit"] = str(r.returncode)
    return digests


def _inputs(shared: pathlib.Path | None) -> list[pathlib.Path]:
    meshes = sorted((REPO / "sample_meshes").glob("*.ply")) + sorted((REPO / "tests" / "data").glob("*.*"))
    meshes = [m for m in meshes if m.suffix in (".ply", ".obj")]
    if shared:
        meshes += sorted(shared.glob("*.ply")) + sorted((shared / "obj").glob("*.obj"))
    return meshes


def fingerprint(binary: pathlib.Path, shared: pathlib.Path | None) -> dict[str, dict[str, str]]:
    result = {}
    with tempfile.TemporaryDirectory() as tmp:
        work = pathlib.Path(tmp)
        for mesh in _inputs(shared):
            key = f"{mesh.parent.name}/{mesh.name}"
            for name, extra in APPROXIMATE_VARIANTS.items():
                job = f"approximate {name} {key}"
                result[job] = _run(binary, ["approximate", str(mesh), "out.ply", *extra],
                                   work / str(len(result)))
            result[f"segment {key}"] = _run(binary, ["segment", str(mesh), "out.ply"],
                                            work / str(len(result)))
            if mesh.name in PANELLED:
                pattern = ["--svg", "p.svg", "--dxf", "p.dxf"]
                result[f"flatten {key}"] = _run(binary, ["flatten", str(mesh), "out.ply", *pattern],
                                                work / str(len(result)))
                cutting = ["--seam-allowance", "0.01", "--grain-direction", "longest", "--unit", "cm",
                           "--dxf-style", "aama", "--marker", "2", "--marker-svg", "m.svg",
                           "--marker-dxf", "m.dxf"]
                result[f"flatten cutting-room {key}"] = _run(
                    binary, ["flatten", str(mesh), "out.ply", *pattern, *cutting],
                    work / str(len(result)))
            print(f"{key}: done", file=sys.stderr)
    return result


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", type=pathlib.Path, default=REPO / "build")
    ap.add_argument("--shared", type=pathlib.Path, help="also the meshes of this folder (../shared/meshes)")
    ap.add_argument("--out", type=pathlib.Path, help="write the digests here")
    ap.add_argument("--compare", type=pathlib.Path, help="compare with digests written before")
    args = ap.parse_args()
    now = fingerprint(args.build / "bin" / "quasidev", args.shared)
    if args.out:
        args.out.write_text(json.dumps(now, indent=1, sort_keys=True) + "\n")
    if not args.compare:
        return 0
    before = json.loads(args.compare.read_text())
    changed = [f"{job}: {name}" for job in sorted(set(before) | set(now))
               for name in sorted(set(before.get(job, {})) | set(now.get(job, {})))
               if before.get(job, {}).get(name) != now.get(job, {}).get(name)]
    for line in changed:
        print(f"changed: {line}")
    print(f"{sum(len(v) for v in now.values())} files compared, {len(changed)} changed")
    return 1 if changed else 0


if __name__ == "__main__":
    sys.exit(main())
