#!/usr/bin/env python3
"""MeshLab's filter on the sweep's smooth members that auto leaves above 10 % of their curvature.

Reads a table of scripts/robustness_sweep.py (its JSON), makes again every smooth member (no
jitter) where auto removed less than --floor % of G_ABD, and runs on it our default (`quasidev`
with no options) and MeshLab's "Make mesh developable" (pymeshlab's
apply_coord_developability_of_mesh, topology kept) at each --evals. Both are measured identically,
with scripts/tradeoff.py's functions: G_ABD removed (%) and Hausdorff / bounding-box diagonal.
So the members we miss are set beside what the other filter reaches on them.

Writes OUT/robustness_meshlab.md and OUT/robustness_meshlab.json.

Usage: .venv/bin/python scripts/robustness_meshlab.py [--sweep docs/robustness_sweep.json]
         [--floor 90] [--evals 400 2000 8000] [--quasidev PATH] [--out DIR]
"""
from __future__ import annotations

import argparse
import json
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mesh_family  # noqa: E402
import tradeoff  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def figures(fig: dict) -> str:
    if "error" in fig:
        return "error: " + fig["error"]
    return f"{fig['reduction']:.1f} ({fig['hausdorff_rel']:.1e})"


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--sweep", default=os.path.join(ROOT, "docs", "robustness_sweep.json"))
    ap.add_argument("--floor", type=float, default=90.0, help="auto's share on smooth members (%%)")
    ap.add_argument("--evals", type=int, nargs="+", default=[400, 2000, 8000],
                    help="MeshLab's maxfunevals (400 is its default)")
    ap.add_argument("--quasidev", default=tradeoff.DEFAULT_QUASIDEV)
    ap.add_argument("--out", default=os.path.join(ROOT, "docs"))
    args = ap.parse_args()
    with open(args.sweep) as f:
        rows = json.load(f)["rows"]
    missed = [r for r in rows if r["smooth"] and r["auto"].get("reduction", 0) < args.floor]
    results = []
    with tempfile.TemporaryDirectory() as tmp:
        for row in missed:
            member = mesh_family.Member.from_name(row["member"])
            path = os.path.join(tmp, member.name + ".ply")
            mesh_family.write_ply(path, *mesh_family.make(member))
            before = tradeoff.input_figures(path)
            ours = tradeoff.run_ours(args.quasidev, path, [], before, tmp)
            theirs = {n: tradeoff.run_meshlab(path, dict(tradeoff.THEIRS_KEEP_TOPOLOGY, maxfunevals=n), before)
                      for n in args.evals}
            results.append({"member": member.name, "faces": before["faces"], "ours": ours,
                            "meshlab": {str(n): fig for n, fig in theirs.items()}})
            print(member.name, figures(ours), " ".join(figures(f) for f in theirs.values()), flush=True)
    beaten = sum(1 for r in results if all("error" in f or f["reduction"] < r["ours"].get("reduction", 0)
                                           for f in r["meshlab"].values()))
    head = ["member", "faces", "ours, default"] + [f"MeshLab, {n} evaluations" for n in args.evals]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for r in results:
        cells = [r["member"], str(r["faces"]), figures(r["ours"])] + [figures(f) for f in r["meshlab"].values()]
        lines.append("| " + " | ".join(cells) + " |")
    command = " ".join([".venv/bin/python scripts/robustness_meshlab.py", *sys.argv[1:]])
    os.makedirs(args.out, exist_ok=True)
    with open(os.path.join(args.out, "robustness_meshlab.md"), "w") as f:
        f.write("# The smooth members below the floor, beside MeshLab's filter\n\n"
                f"Made by `{command}` from "
                f"`{os.path.relpath(args.sweep, ROOT)}`: the {len(results)} smooth members where auto "
                f"removed less than {args.floor:g} % of G_ABD. Each cell: G_ABD removed (%) and, in "
                "brackets, Hausdorff / bounding-box diagonal, both measured by scripts/tradeoff.py's "
                "functions (so ours may differ a little from the sweep's own report). MeshLab's filter "
                "keeps the topology (edge flips and collapses off). "
                f"Ours removes more than MeshLab at every evaluation count on {beaten} of "
                f"{len(results)}.\n\n" + "\n".join(lines) + "\n")
    with open(os.path.join(args.out, "robustness_meshlab.json"), "w") as f:
        json.dump({"sweep": os.path.relpath(args.sweep, ROOT), "floor": args.floor, "evals": args.evals,
                   "rows": results}, f, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main())
