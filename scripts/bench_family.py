#!/usr/bin/env python3
"""The benchmark families of issue 28: speed on every shape, judged by the worst member.

Two families of generated meshes with fixed seeds, each member run by bench/qd_bench (stage
times, CG iterations, factorisations, peak memory, G_ABD removed) with the quasidev defaults
except --max-iter 5:
  1M        about --size triangles each (default 1,000,000): closed and open cylinders and cones
            of several length / radius ratios and cell aspects, bumps of 0.005 to 0.05 radius,
            with and without jitter, a curved sheet, an upsampled draped garment and
            qd_bench's own noisy tube; one run each (--big-runs).
  garments  every garment of 5-8k triangles found (scripts/mesh_folders.py, and
            sample_meshes/draped_panels.ply), the same with drape noise, and re-cut into 2 to 8
            panels by `quasidev segment --target N`; --runs runs each (medians).
Per family: the worst member (most engine time), the median and the best, the targets on the
worst, and a per-member table, with the bound on each member: the factorisations' flops
(CHOLMOD's count, in the report) at the machine's dense rate (a one-thread matrix product,
measured at the start), and the bytes the solves must read (the factors once per triangular
pass, M once per CG product; in the report) at its memory rate (a one-thread sum of 512 MB),
each as the time it would take on every core. Writes
OUT/benchmark-family.md and .json and prints the markdown; a family not run this time is kept
from OUT/benchmark-family.json.

Usage: scripts/bench_family.py [--build DIR] [--families 1M garments] [--quick] [--size N]
                               [--runs R] [--big-runs R] [--cache DIR] [--out DIR]
  --quick   1M family at 100,000 triangles and fewer members in both families (a test).
  --cache   keep the generated meshes there (default: a temporary folder, removed at the end).
"""
from __future__ import annotations

import argparse
import json
import math
import os
import shlex
import subprocess
import sys
import tempfile
import time

import numpy as np
from plyfile import PlyData

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
import mesh_family  # noqa: E402
from bench import bench  # noqa: E402
from mesh_folders import SAMPLES, find_mesh, mesh_folders, missing  # noqa: E402
from ply_columns import column, faces, has, positions  # noqa: E402

ITERATIONS = 5
DRAPES = [(0.2, 0.02, 11), (0.5, 0.05, 12)]  # drape noise: amplitude AE, jitter AE, seed
PANELS = [2, 4, 6, 8]
SHARED_GARMENTS = ["garment_shirt_initial_diffavatar.ply", "garment_tee4panel_gpg.ply"]
TARGETS = {"1M": "end to end under 10 s and peak under 4 GB",
           "garments": "engine under 30 ms and the whole process under 0.1 s"}


def read_garment(path: str) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Vertices, triangles and per-face patch ids (face quality, else patch) of a PLY."""
    ply = PlyData.read(path)
    patch = next(p for p in ("quality", "patch") if has(ply, "face", p))
    return positions(ply), np.array(faces(ply), dtype=np.int64), np.round(column(ply, "face", patch))


def garments() -> list[str]:
    """Every garment of 5-8k triangles in the mesh folders, and the shipped draped panels."""
    found = {}
    for folder in mesh_folders():
        for name in sorted(os.listdir(folder)):
            if name.startswith("garment_") and name.endswith(".ply") and name not in found:
                if 5000 <= PlyData.read(os.path.join(folder, name))["face"].count <= 8000:
                    found[name] = os.path.join(folder, name)
    lost = [n for n in SHARED_GARMENTS if n not in found and find_mesh(n) is None]
    if lost:
        print(f"  skipping {missing(lost)}", file=sys.stderr)
    return list(found.values()) + [os.path.join(SAMPLES, "draped_panels.ply")]


def stem(path: str) -> str:
    return os.path.splitext(os.path.basename(path))[0]


def draped(src: str, amplitude: float, jitter: float, seed: int, cache: str) -> str:
    """src with drape noise (mesh_family.drape), patch ids kept; written once to the cache."""
    path = os.path.join(cache, f"{stem(src)}_drape{amplitude:g}_j{jitter:g}_s{seed}.ply")
    if not os.path.exists(path):
        V, F, patch = read_garment(src)
        V = mesh_family.drape(V, F, amplitude, jitter, seed)
        mesh_family.write_ply(path, V, F, f"{stem(src)} with drape noise", patch)
    return path


def upsampled(sources: list[str], size: int, seed: int, cache: str) -> str:
    """The garment whose 4-to-1 subdivision comes nearest `size` faces (in ratio), subdivided
    that often, patch ids kept, with drape noise of 0.3 AE and 0.05 AE jitter at the fine level."""
    def level(src):
        n = PlyData.read(src)["face"].count
        k = max(0, round(math.log(size / n, 4)))
        return abs(math.log(n * 4 ** k / size)), k
    src = min(sources, key=lambda s: level(s)[0])
    k = level(src)[1]
    path = os.path.join(cache, f"{stem(src)}_x{4 ** k}_s{seed}.ply")
    if not os.path.exists(path):
        V, F, patch = read_garment(src)
        for _ in range(k):
            V, F, patch = mesh_family.subdivide(V, F, patch)
        V = mesh_family.drape(V, F, 0.3, 0.05, seed)
        mesh_family.write_ply(path, V, F, f"{stem(src)} subdivided {k} times, drape noise", patch)
    return path


def tube(spec: mesh_family.Tube, cache: str) -> str:
    path = os.path.join(cache, spec.name + ".ply")
    if not os.path.exists(path):
        V, F = mesh_family.make_tube(spec)
        mesh_family.write_ply(path, V, F, spec.name)
    return path


def recut(quasidev: str, src: str, panels: int, cache: str) -> tuple[str, int]:
    """src re-cut by `quasidev segment --target panels`; the path and the panel count obtained."""
    path = os.path.join(cache, f"{stem(src)}_recut{panels}.ply")
    report = path + ".json"
    subprocess.run([quasidev, "segment", src, path, "--target", str(panels), "--quiet", "--report",
                    report], check=True, capture_output=True)
    with open(report) as f:
        return path, len(json.load(f)["patches"])


def big_family(a, cache: str) -> list[dict]:
    """The 1M members: (name, qd_bench mesh arguments, what it is)."""
    n = a.size
    T = mesh_family.Tube
    specs = [
        ("closed cylinder, length 3 r, bumps 0.02 r", T(n, 3, amplitude=0.02, seed=1)),
        ("closed cylinder, length 1 r, bumps 0.05 r, jitter 0.1 AE", T(n, 1, amplitude=0.05, jitter=0.1, seed=2)),
        ("closed cylinder, length 10 r, bumps 0.005 r", T(n, 10, amplitude=0.005, seed=3)),
        ("closed cylinder, length 3 r, cells 4:1 around:along, bumps 0.02 r, jitter 0.1 AE",
         T(n, 3, aspect=4, amplitude=0.02, jitter=0.1, seed=4)),
        ("closed cylinder, length 3 r, cells 1:4, bumps 0.005 r, jitter 0.1 AE",
         T(n, 3, aspect=0.25, amplitude=0.005, jitter=0.1, seed=5)),
        ("open cylinder (cut along a generator), length 3 r, bumps 0.02 r, jitter 0.1 AE",
         T(n, 3, amplitude=0.02, jitter=0.1, closed=False, seed=6)),
        ("closed cone (far radius 0.5 r), length 3 r, bumps 0.02 r", T(n, 3, taper=0.5, amplitude=0.02, seed=7)),
        ("open cone (far radius 0.5 r), length 1 r, cells 2:1, bumps 0.05 r",
         T(n, 1, aspect=2, taper=0.5, amplitude=0.05, closed=False, seed=8)),
        ("curved sheet (a quarter of a cylinder), length 3 r, bumps 0.02 r, jitter 0.1 AE",
         T(n, 3, sweep=0.25, amplitude=0.02, jitter=0.1, seed=9)),
    ]
    if a.quick:
        specs = [specs[i] for i in (0, 5, 6, 8)]
    members = [dict(member=s.name, what=w, args=["--mesh", tube(s, cache)]) for w, s in specs]
    garment = upsampled(garments(), n, 10, cache)
    members.append(dict(member=stem(garment), what="upsampled garment (4-to-1 subdivision), drape noise",
                        args=["--mesh", garment]))
    members.append(dict(member=f"tube{n}", what="qd_bench's noisy closed tube (docs/benchmark.md)",
                        args=["--tube", str(n)]))
    return members


def garment_family(a, quasidev: str, cache: str) -> list[dict]:
    sources = garments()
    drapes = DRAPES[:1] if a.quick else DRAPES
    members = [dict(member=stem(s), what="as found", args=["--mesh", s]) for s in sources]
    for s in sources:
        for amplitude, jitter, seed in drapes:
            members.append(dict(member=f"{stem(s)} drape {amplitude:g}",
                                what=f"drape noise {amplitude:g} AE, jitter {jitter:g} AE, seed {seed}",
                                args=["--mesh", draped(s, amplitude, jitter, seed, cache)]))
    for s in sources[:1] if a.quick else sources[:2]:
        for panels in PANELS if s == sources[0] else PANELS[::3]:
            path, got = recut(quasidev, s, panels, cache)
            members.append(dict(member=f"{stem(s)} re-cut {panels}", what=f"segment --target {panels}",
                                args=["--mesh", path], asked=panels, panels=got))
    return members


def machine_rates() -> dict:
    """One core's dense rate (GFlop/s of a 512 × 512 matrix product, OpenBLAS on one thread) and
    memory rate (GB/s of summing 512 MB), each the best of 5."""
    code = ("import time, numpy as np\n"
            "def best(f):\n"
            "    return min((lambda t: (f(), time.perf_counter() - t)[1])(time.perf_counter()) for _ in range(5))\n"
            "a, b = np.random.rand(512, 512), np.random.rand(512, 512)\n"
            "big = np.ones(64 * 1024 * 1024)\n"
            "print(2 * 512 ** 3 / best(lambda: a @ b) / 1e9, big.nbytes / best(big.sum) / 1e9)")
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS="1")
    out = subprocess.run([sys.executable, "-c", code], check=True, capture_output=True, text=True, env=env).stdout
    dense, memory = map(float, out.split())
    return dict(dense_gflops=dense, memory_gbs=memory)


def floor_ms(row: dict, rates: dict) -> dict:
    """What the member's factorisations and solves cannot beat on every core: their flops at the
    dense rate, their bytes at the memory rate (ms)."""
    cores = os.cpu_count() or 1
    flops = row["factorization_gflop"] / (rates["dense_gflops"] * cores) * 1000
    memory = row["solve_gb"] / (rates["memory_gbs"] * cores) * 1000
    return dict(flops=flops, memory=memory, total=flops + memory)


def run(build: str, members: list[dict], runs: int) -> list[dict]:
    rows = []
    for m in members:
        row = dict(member=m["member"], what=m["what"], file=os.path.basename(m["args"][1]))
        if "panels" in m:
            row.update(asked=m["asked"], panels=m["panels"])
        try:
            row.update(bench(build, m["args"], runs, iterations=ITERATIONS))
            print(f"  {m['member']}: {row['faces']} faces, engine {row['ms']['engine']:.1f} ms, "
                  f"end to end {row['ms']['end_to_end']:.1f} ms, {row['peak_mb']:.0f} MB",
                  file=sys.stderr, flush=True)
        except subprocess.CalledProcessError as e:
            row["error"] = e.stderr.strip()
            print(f"  {m['member']}: failed ({row['error']})", file=sys.stderr)
        rows.append(row)
    return rows


def whole_process(quasidev: str, mesh: str, runs: int) -> float:
    """Median wall clock (ms) of `quasidev approximate MESH OUT --max-iter 5` as a subprocess."""
    times = []
    with tempfile.TemporaryDirectory() as tmp:
        for _ in range(runs):
            t0 = time.perf_counter()
            subprocess.run([quasidev, "approximate", mesh, os.path.join(tmp, "out.ply"), "--max-iter",
                            str(ITERATIONS)], check=True, stdout=subprocess.DEVNULL)
            times.append(1000 * (time.perf_counter() - t0))
    return sorted(times)[len(times) // 2]


def summary(rows: list[dict]) -> dict:
    """The worst, median and best member by engine time (the median: the upper one)."""
    ran = sorted((r for r in rows if "error" not in r), key=lambda r: r["ms"]["engine"])
    pick = {"worst": ran[-1], "median": ran[len(ran) // 2], "best": ran[0]}
    return {k: dict(member=r["member"], engine_ms=r["ms"]["engine"], end_to_end_ms=r["ms"]["end_to_end"],
                    peak_mb=r["peak_mb"]) for k, r in pick.items()}


def targets(family: str, rows: list[dict], s: dict) -> list[tuple[str, float, float]]:
    """(what, measured, limit) on the worst members."""
    ran = [r for r in rows if "error" not in r]
    if family == "1M":
        return [("end to end of the slowest member (ms, in process)", max(r["ms"]["end_to_end"] for r in ran), 10000),
                ("peak memory of the largest member (MB)", max(r["peak_mb"] for r in ran), 4096)]
    return [("engine of the worst member (ms)", s["worst"]["engine_ms"], 30),
            ("end to end of the slowest member (ms, in process)", max(r["ms"]["end_to_end"] for r in ran), 100),
            (f"whole process of the worst member (ms, `quasidev approximate`, median of {s['runs']})",
             s["whole_process_ms"], 100)]


def member_table(rows: list[dict], rates: dict) -> str:
    head = ("| member | what | faces | patches | iterations | CG iterations | factorisations | "
            "factorisation GFlop | factorisation ms | GFlop/s | flop floor ms | solve GB | solve ms | "
            "GB/s | memory floor ms | engine ms | engine / floor | end to end ms | peak MB | G_ABD removed % |")
    lines = [head, "|" + "---|" * (head.count("|") - 1)]
    for r in rows:
        if "error" in r:
            lines.append(f"| {r['member']} | {r['what']} | failed: {r['error']} |" + " |" * 17)
            continue
        ms = r["ms"]
        patches = f"{r['patches']}" + (f" (asked {r['asked']})" if "asked" in r else "")
        gflop, gb, floor = r["factorization_gflop"], r["solve_gb"], floor_ms(r, rates)
        lines.append(f"| {r['member']} | {r['what']} | {r['faces']} | {patches} | {r['iterations']} | "
                     f"{r['cg_iterations']} | {r['factorizations']} | {gflop:.3f} | {ms['factorization']:.1f} | "
                     f"{gflop / max(ms['factorization'], 1e-9) * 1000:.1f} | {floor['flops']:.1f} | "
                     f"{gb:.3f} | {ms['solve']:.1f} | {gb / max(ms['solve'], 1e-9) * 1000:.1f} | "
                     f"{floor['memory']:.1f} | {ms['engine']:.1f} | {ms['engine'] / max(floor['total'], 1e-9):.0f} | "
                     f"{ms['end_to_end']:.1f} | {r['peak_mb']:.0f} | {r['abd_reduction']:.1f} |")
    return "\n".join(lines)


def family_text(name: str, fam: dict) -> str:
    s = fam["summary"]
    load = fam["load"]
    lines = [f"## Family {name} ({len(fam['members'])} members, {fam['runs']} run(s) each, medians)", "",
             f"Made by `{fam['command']}` (load average {load[0][0]:.2f} at the start, {load[1][0]:.2f} at "
             "the end).", "",
             "| | member | engine ms | end to end ms (in process) | peak MB |", "|---|---|---|---|---|"]
    lines += [f"| {k} | {s[k]['member']} | {s[k]['engine_ms']:.1f} | {s[k]['end_to_end_ms']:.1f} | "
              f"{s[k]['peak_mb']:.0f} |" for k in ("worst", "median", "best")]
    lines += ["", f"Targets ({TARGETS[name]}):", ""]
    lines += [f"- {what}: {got:.1f} against {limit:g}: **{'met' if got < limit else 'missed'}**"
              for what, got, limit in fam["targets"]]
    worst = next(r for r in fam["members"] if r["member"] == s["worst"]["member"])
    rates, floor = fam["rates"], floor_ms(worst, fam["rates"])
    lines += ["", f"The bound on the worst member: its factorisations take {worst['factorization_gflop']:.3f} GFlop, "
              f"{floor['flops']:.1f} ms on {os.cpu_count()} cores at the dense rate of {rates['dense_gflops']:.1f} "
              f"GFlop/s per core (a one-thread 512 × 512 matrix product on this machine), and its solves read "
              f"at least {worst['solve_gb']:.3f} GB, {floor['memory']:.1f} ms at the memory rate of "
              f"{rates['memory_gbs']:.1f} GB/s per core (a one-thread sum of 512 MB); the engine took "
              f"{worst['ms']['engine'] / max(floor['total'], 1e-9):.0f}× those {floor['total']:.1f} ms. Per "
              "member, GFlop/s and GB/s are the rates the factorisations and the solves ran at per thread."]
    return "\n".join(lines + ["", member_table(fam["members"], rates)])


def with_earlier(families: dict, path: str) -> dict:
    """The families just run, and those of the JSON at `path` not run this time, as their last
    run left them (each says its own command and load)."""
    earlier = {}
    if os.path.exists(path):
        with open(path) as f:
            earlier = {name: fam for name, fam in json.load(f)["families"].items() if "command" in fam}
    return {name: families.get(name) or earlier[name] for name in TARGETS if name in families or name in earlier}


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--families", nargs="+", choices=["1M", "garments"], default=["1M", "garments"])
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--size", type=int)
    ap.add_argument("--runs", type=int, default=11)
    ap.add_argument("--big-runs", type=int, default=1)
    ap.add_argument("--cache")
    ap.add_argument("--out", default=os.path.join(ROOT, "docs"))
    a = ap.parse_args()
    a.size = a.size or (100000 if a.quick else 1000000)
    quasidev = os.path.join(a.build, "bin", "quasidev")
    # The command as a user would type it: where the build, cache and output live is the machine's.
    args, skip = [], False
    for arg in sys.argv[1:]:
        if skip or arg in ("--build", "--cache", "--out"):
            skip = not skip
            continue
        args.append(arg)
    command = " ".join(["scripts/bench_family.py", shlex.join(args)]).strip()
    load = [os.getloadavg()]
    rates = machine_rates()
    print(f"per core: dense {rates['dense_gflops']:.1f} GFlop/s, memory {rates['memory_gbs']:.1f} GB/s",
          file=sys.stderr)
    with tempfile.TemporaryDirectory() as tmp:
        cache = a.cache or tmp
        os.makedirs(cache, exist_ok=True)
        families = {}
        for name in a.families:
            print(f"family {name}", file=sys.stderr)
            members = big_family(a, cache) if name == "1M" else garment_family(a, quasidev, cache)
            runs = a.big_runs if name == "1M" else a.runs
            rows = run(a.build, members, runs)
            s = summary(rows)
            if name == "garments":
                s["runs"] = a.runs
                worst = next(m for m in members if m["member"] == s["worst"]["member"])
                s["whole_process_ms"] = whole_process(quasidev, worst["args"][1], a.runs)
            families[name] = dict(runs=runs, members=rows, summary=s, targets=targets(name, rows, s),
                                  command=command, rates=rates)
    load.append(os.getloadavg())
    for name, fam in families.items():
        fam["load"] = load
    families = with_earlier(families, os.path.join(a.out, "benchmark-family.json"))
    report = "\n\n".join([
        "# Benchmark families (issue 28)",
        "Made by `scripts/bench_family.py` (each family's command below). Every member runs `qd_bench --mesh FILE -- --max-iter 5` (or `--tube N`): the quasidev "
        "defaults (developability auto) except 5 iterations, as scripts/bench.py does for the 1M tube "
        "and the garments. Milliseconds are medians over the runs; stage times are summed over patches "
        "and threads; end to end is qd_bench's read + engine + write in one process. The worst "
        "member is the one with the most engine time; the targets are checked on the worst member "
        "of each measure. Generated members have fixed seeds (scripts/mesh_family.py: Tube, drape, "
        "subdivide); radii (r) are the tube's, AE the average edge length.",
        *[family_text(name, fam) for name, fam in families.items()],
    ]) + "\n"
    print(report)
    os.makedirs(a.out, exist_ok=True)
    with open(os.path.join(a.out, "benchmark-family.md"), "w") as f:
        f.write(report)
    with open(os.path.join(a.out, "benchmark-family.json"), "w") as f:
        json.dump(dict(families=families), f, indent=1)
    return 0 if all("error" not in r for fam in families.values() for r in fam["members"]) else 1


if __name__ == "__main__":
    sys.exit(main())
