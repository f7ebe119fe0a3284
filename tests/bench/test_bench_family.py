"""scripts/bench_family.py (issue 28) on the shipped garments, one run each: every member runs,
the worst, median and best members are ordered and are members' figures, the re-cut members
have the panels the table says, and the generated members are reproducible from their seeds.
Timings themselves are not asserted (benchmarks, not timed tests)."""
import glob
import json
import os
import subprocess
import sys

import numpy as np
import pytest
from plyfile import PlyData

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import bench_family  # noqa: E402
import mesh_family  # noqa: E402
from ply_columns import column  # noqa: E402

BUILD = os.environ.get("QD_BUILD_DIR", os.path.join(ROOT, "build"))
SHIRT = os.path.join(ROOT, "tests", "data", "garment_shirt_initial_diffavatar.ply")


@pytest.fixture(scope="module")
def family(tmp_path_factory):
    if not os.path.exists(os.path.join(BUILD, "bin", "qd_bench")):
        pytest.fail(f"{BUILD}/bin/qd_bench is missing: build the project first")
    out = tmp_path_factory.mktemp("family")
    env = {k: v for k, v in os.environ.items() if k != "QD_SHARED_MESHES"}  # the shipped meshes only
    subprocess.run([sys.executable, os.path.join(ROOT, "scripts", "bench_family.py"), "--quick", "--runs", "1",
                    "--families", "garments", "--build", BUILD, "--out", str(out), "--cache", str(out / "cache")],
                   check=True, capture_output=True, env=env, timeout=120)
    with open(out / "benchmark-family.json") as f:
        return out, json.load(f)["families"]["garments"], (out / "benchmark-family.md").read_text()


def test_every_member_runs_and_the_summary_is_ordered(family):
    _, fam, text = family
    rows = fam["members"]
    # 2 shipped garments as found and draped, the shirt re-cut 4 ways
    assert len(rows) == 8 and all("error" not in r for r in rows), [r.get("error") for r in rows]
    for r in rows:
        assert 5000 <= r["faces"] <= 8000 and r["iterations"] >= 1 and r["ms"]["engine"] > 0
        assert f"| {r['member']} | {r['what']} | {r['faces']} |" in text
    s = fam["summary"]
    engine = [r["ms"]["engine"] for r in rows]
    assert s["worst"]["engine_ms"] == max(engine) >= s["median"]["engine_ms"] >= s["best"]["engine_ms"] == min(engine)
    assert sorted(engine)[len(engine) // 2] == s["median"]["engine_ms"]
    assert s["whole_process_ms"] > 0 and f"| worst | {s['worst']['member']} |" in text


def test_recut_members_have_the_panels_the_table_says(family):
    out, fam, text = family
    recut = [r for r in fam["members"] if "asked" in r]
    assert sorted(r["asked"] for r in recut) == bench_family.PANELS
    for r in recut:
        ids = np.unique(np.round(column(PlyData.read(out / "cache" / r["file"]), "face", "quality")))
        assert len(ids) == r["patches"] == r["panels"] and 2 <= r["panels"] <= 8
        assert f"| {r['patches']} (asked {r['asked']}) |" in text


def test_generated_members_are_reproducible_from_their_seeds(tmp_path):
    def draped(folder, seed):
        os.makedirs(tmp_path / folder)
        with open(bench_family.draped(SHIRT, 0.2, 0.02, seed, str(tmp_path / folder)), "rb") as f:
            return f.read()

    def tube(name, seed):
        spec = mesh_family.Tube(3000, 3, amplitude=0.02, jitter=0.1, closed=False, seed=seed)
        mesh_family.write_ply(tmp_path / name, *mesh_family.make_tube(spec), spec.name)
        return (tmp_path / name).read_bytes()

    assert draped("a", 11) == draped("b", 11) != draped("c", 12)
    assert tube("a.ply", 1) == tube("b.ply", 1) != tube("c.ply", 2)
    V, F, patch = bench_family.read_garment(SHIRT)
    V2, F2, patch2 = bench_family.read_garment(bench_family.draped(SHIRT, 0.2, 0.02, 11, str(tmp_path / "a")))
    assert np.array_equal(F2, F) and np.array_equal(patch2, patch) and len(np.unique(patch)) == 5
    assert np.abs(V2 - V).max() > 0  # the drape moves the garment and keeps its faces and panels


def test_subdivision_keeps_area_and_patch_ids():
    V, F, patch = bench_family.read_garment(SHIRT)
    V2, F2, patch2 = mesh_family.subdivide(V, F, patch)

    def areas(V, F):
        return 0.5 * np.linalg.norm(np.cross(V[F[:, 1]] - V[F[:, 0]], V[F[:, 2]] - V[F[:, 0]]), axis=1)

    assert len(F2) == 4 * len(F) and np.array_equal(patch2, np.repeat(patch, 4))
    assert np.allclose(areas(V2, F2).reshape(-1, 4).sum(axis=1), areas(V, F), rtol=1e-9)
    # every edge gets one midpoint: V + E vertices, all used
    edges = np.unique(np.sort(np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]]), axis=1), axis=0)
    assert len(V2) == len(V) + len(edges) == len(np.unique(F2))


def last_level_cache_bytes() -> int:
    """The largest cache of the first CPU (sysfs), 0 where it is not known."""
    units = {"K": 1 << 10, "M": 1 << 20, "G": 1 << 30}
    sizes = []
    for path in glob.glob("/sys/devices/system/cpu/cpu0/cache/index*/size"):
        with open(path) as f:
            size = f.read().strip()
        sizes.append(int(size[:-1]) * units[size[-1]] if size[-1] in units else int(size))
    return max(sizes, default=0)


def test_flops_and_bytes_bound_every_member(family):
    _, fam, text = family
    rates = fam["rates"]
    assert rates["dense_gflops"] > 0.1 and rates["memory_gbs"] > 0.1
    cache = last_level_cache_bytes()
    for r in fam["members"]:
        assert (r["factorization_gflop"] > 0) == (r["factorizations"] > 0)
        assert r["solve_gb"] > 0
        # per thread, a sparse factorisation runs no faster than a dense product, and a solve
        # whose bytes do not fit in the cache reads no faster than a sum streams (a garment's
        # solves read 2-4 MB each, from the cache; with another job streaming beside the test
        # they ran at 2.1 times the memory rate it measured)
        assert r["factorization_gflop"] / (r["ms"]["factorization"] / 1000) < 2 * rates["dense_gflops"]
        if r["solve_gb"] * 1e9 / r["solves"] > cache:
            assert r["solve_gb"] / (r["ms"]["solve"] / 1000) < 2 * rates["memory_gbs"]
        floor = bench_family.floor_ms(r, rates)
        assert 0 < floor["flops"] and 0 < floor["memory"] and floor["total"] < r["ms"]["engine"]
    worst = next(r for r in fam["members"] if r["member"] == fam["summary"]["worst"]["member"])
    floor = bench_family.floor_ms(worst, rates)
    assert f"its factorisations take {worst['factorization_gflop']:.3f} GFlop, {floor['flops']:.1f} ms" in text
    assert f"its solves read at least {worst['solve_gb']:.3f} GB, {floor['memory']:.1f} ms" in text


def test_a_family_not_run_is_kept_from_the_last_run(family, tmp_path):
    _, fam, _ = family
    path = tmp_path / "benchmark-family.json"
    old_1m = dict(fam, members=fam["members"][:1])
    path.write_text(json.dumps({"families": {"1M": old_1m, "garments": dict(fam, members=[])}}))
    merged = bench_family.with_earlier({"garments": fam}, str(path))
    assert list(merged) == ["1M", "garments"]
    assert merged["1M"] == old_1m and merged["garments"] is fam  # the new run replaces its own
    assert list(bench_family.with_earlier({"garments": fam}, str(tmp_path / "none.json"))) == ["garments"]
