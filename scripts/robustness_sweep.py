#!/usr/bin/env python3
"""Robustness sweep: `quasidev approximate` on a generated family (scripts/mesh_family.py).

For every member (base x bump amplitude x wavelength x jitter x resolution x seed x irregular
triangulation) it runs each
developability term (--terms, default curve, defect, both, auto) from the same input with the same
options, reads the JSON report, and tabulates the G_ABD reduction, the iterations and the
largest move (AE); its JSON also keeps each run's stop reason, engine time and factorisations.
A member passes when auto is within --margin percentage points of the best single term and, for
smooth members (no jitter), removes at least --smooth-floor %.

Writes OUT/robustness_sweep.md and OUT/robustness_sweep.json; exit status 1 when a member fails.

Usage: .venv/bin/python scripts/robustness_sweep.py [--quick] [--out DIR] [--quasidev PATH]
         [--bases ...] [--amplitudes ...] [--wavelengths ...] [--jitters ...]
         [--resolutions ...] [--seeds ...] [--irregular ...] [--terms ...]
         [-- extra quasidev options]
"""
from __future__ import annotations

import argparse
import concurrent.futures
import dataclasses
import itertools
import json
import os
import subprocess
import sys
import tempfile

import numpy as np
from plyfile import PlyData

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mesh_family  # noqa: E402
import ply_columns  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT_QUASIDEV = os.path.join(ROOT, "build", "bin", "quasidev")
FULL = dict(bases=list(mesh_family.BASES), amplitudes=[0.5, 1, 2, 4], wavelengths=[0.08, 0.16],
            jitters=[0, 0.05, 0.2], resolutions=[1, 2], seeds=[1], irregular=[0])  # 240 members
QUICK = dict(bases=list(mesh_family.BASES), amplitudes=[1, 3], wavelengths=[0.12],
             jitters=[0, 0.05, 0.2], resolutions=[1], seeds=[1], irregular=[0])
SINGLE = ("curve", "defect", "both")


def positions(path: str) -> np.ndarray:
    return ply_columns.positions(PlyData.read(path))


def flipped_faces(V0, V1, F) -> int:
    """Faces whose normal turned against the input's (or vanished)."""
    def cross(V):
        return np.cross(V[F[:, 1]] - V[F[:, 0]], V[F[:, 2]] - V[F[:, 0]])
    return int(np.count_nonzero(np.einsum("ij,ij->i", cross(V0), cross(V1)) <= 0))


def run(quasidev: str, mesh: str, term: str, extra: list[str], tmp: str, V, F) -> dict:
    out, rep = os.path.join(tmp, f"{term}.ply"), os.path.join(tmp, f"{term}.json")
    cmd = [quasidev, "approximate", mesh, out, "--developability", term, "--report", rep,
           "--quiet", "--no-progress", *extra]
    proc = subprocess.run(cmd, capture_output=True, text=True)
    if proc.returncode != 0:
        return {"error": proc.stderr.strip()}
    r = json.load(open(rep, encoding="utf-8"))
    p = r["patches"][0]
    chosen = p["developability"]  # "defect ×30" where auto kept its stronger rows (group_run.h)
    kept = next((c for c in p.get("candidates", []) if c["kept"]), {})
    factor = kept.get("defect_weight_factor", 1)
    if factor != 1:
        chosen += f" ×{factor:g}"
    return {"reduction": r["abd_reduction"], "iterations": p["iterations"],
            "stop": p["stop_reason"], "max_move_ae": r["total_after"]["max_disp"] / r["average_edge"],
            "mean_move_ae": r["total_after"]["mean_disp"] / r["average_edge"],
            "chosen": chosen, "stronger_weight": r["parameters"]["defect_weight"] * factor,
            "bounded_by": kept.get("bounded_by"),
            "time_ms": r["time_ms"],
            "factorizations": r["factorizations"],
            "flipped": flipped_faces(V, positions(out), F)}


def run_member(quasidev: str, terms: list[str], extra: list[str], member: mesh_family.Member) -> dict:
    with tempfile.TemporaryDirectory() as tmp:
        mesh = os.path.join(tmp, "in.ply")
        V, F = mesh_family.make(member)
        mesh_family.write_ply(mesh, V, F, member.name)
        row = {"member": member.name, **dataclasses.asdict(member), "smooth": member.smooth,
               "faces": int(len(F))}
        for term in terms:
            row[term] = run(quasidev, mesh, term, extra, tmp, V, F)
        kept = row.get("auto", {}).get("chosen", "")
        if "×" in kept:  # auto's stronger rows, run alone: what auto's cost is measured against
            row[kept] = run(quasidev, mesh, "defect",
                            [*extra, "--defect-weight", f"{row['auto']['stronger_weight']:g}"], tmp, V, F)
    return row


def sweep(members, terms, quasidev=DEFAULT_QUASIDEV, extra=(), jobs=os.cpu_count() or 1) -> list[dict]:
    """One row per member (in order): its figures under each term."""
    with concurrent.futures.ThreadPoolExecutor(jobs) as pool:
        return list(pool.map(lambda m: run_member(quasidev, list(terms), list(extra), m), members))


def verdict(row: dict, margin: float, floor: float) -> str:
    """'' when the member passes, else why not."""
    if "auto" not in row:
        return ""
    if "error" in row["auto"]:
        return "auto failed: " + row["auto"]["error"]
    singles = [row[t]["reduction"] for t in SINGLE if t in row and "error" not in row[t]]
    auto = row["auto"]["reduction"]
    why = []
    if singles and auto < max(singles) - margin:
        why.append(f"auto {auto:.1f} % < best single {max(singles):.1f} % - {margin:g}")
    if row["smooth"] and auto < floor:
        why.append(f"auto {auto:.1f} % < {floor:g} % on a smooth member")
    return "; ".join(why)


def table(rows: list[dict], terms: list[str], margin: float, floor: float) -> list[str]:
    head = "| member | faces | " + " | ".join(f"{t} (% / it. / move AE)" for t in terms)
    head += " | auto chose | verdict |"
    lines = [head, "|" + "---|" * (len(terms) + 4)]
    for row in rows:
        cells = []
        for t in terms:
            c = row[t]
            cells.append(c["error"][:40] if "error" in c else
                         f"{c['reduction']:.1f} / {c['iterations']} / {c['max_move_ae']:.2f}")
        chose = row.get("auto", {}).get("chosen", "")
        v = verdict(row, margin, floor) or "pass"
        lines.append(f"| {row['member']} | {row['faces']} | " + " | ".join(cells) + f" | {chose} | {v} |")
    return lines


def main() -> int:
    argv = sys.argv[1:]
    extra = []
    if "--" in argv:
        extra = argv[argv.index("--") + 1:]
        argv = argv[:argv.index("--")]
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="a smaller family")
    ap.add_argument("--quasidev", default=DEFAULT_QUASIDEV)
    ap.add_argument("--out", default=None, help="folder for robustness.md and .json")
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--terms", nargs="+", default=["curve", "defect", "both", "auto"])
    ap.add_argument("--margin", type=float, default=2.0, help="auto vs best single term (points)")
    ap.add_argument("--smooth-floor", type=float, default=90.0, help="auto on smooth members (%%)")
    for key, values in FULL.items():
        ap.add_argument("--" + key, nargs="+", type=str if key == "bases" else float, default=None)
    args = ap.parse_args(argv)
    args.extra = extra
    grid = QUICK if args.quick else FULL
    axes = {k: getattr(args, k) or grid[k] for k in FULL}
    members = [mesh_family.Member(b, a, w, j, int(r), int(s), i)
               for b, a, w, j, r, s, i in itertools.product(*(axes[k] for k in FULL))]
    rows = sweep(members, args.terms, args.quasidev, args.extra, args.jobs)
    lines = table(rows, args.terms, args.margin, args.smooth_floor)
    failed = [r for r in rows if verdict(r, args.margin, args.smooth_floor)]
    summary = f"{len(rows) - len(failed)} of {len(rows)} members pass"
    ratios = sorted(r["auto"]["time_ms"] / r[r["auto"]["chosen"]]["time_ms"] for r in rows
                    if "auto" in r and "error" not in r["auto"] and r["auto"]["chosen"] in r
                    and "error" not in r[r["auto"]["chosen"]] and r[r["auto"]["chosen"]]["time_ms"] > 0)
    if ratios:
        summary += (f"; auto's engine time over that of the term it kept, run alone: median "
                    f"{ratios[len(ratios) // 2]:.2f}, worst {ratios[-1]:.2f}")
    stronger = sum(1 for r in rows if "×" in r.get("auto", {}).get("chosen", ""))
    if stronger:
        summary += (f"; auto kept the stronger angle-defect rows on {stronger} members (measured "
                    "against those rows run alone)")
    print("\n".join(lines))
    print(summary)
    if args.out:
        os.makedirs(args.out, exist_ok=True)
        cmd = "scripts/robustness_sweep.py " + " ".join(sys.argv[1:])
        with open(os.path.join(args.out, "robustness_sweep.md"), "w", encoding="utf-8") as f:
            f.write(f"Made by `{cmd}`. {summary}.\n\n" + "\n".join(lines) + "\n")
        with open(os.path.join(args.out, "robustness_sweep.json"), "w", encoding="utf-8") as f:
            json.dump({"command": cmd, "rows": rows}, f, indent=1)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
