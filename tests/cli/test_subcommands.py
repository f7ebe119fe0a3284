"""The command's subcommands: `quasidev approximate IN OUT [options]` is the same job as
`quasidev IN OUT [options]`, --help lists the subcommands and each option's default, --version
prints the CMake project's version, and bad values given through a subcommand are named."""
import json
import pathlib
import re
import sys

import pytest

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from test_quasidev_cli import BINARY, REPO, SAMPLES, assert_clean_failure, run  # noqa: E402

pytestmark = pytest.mark.skipif(not BINARY.exists(), reason=f"{BINARY} not built")

# Figures that depend on the clock, or name the output file.
UNSTABLE = {"time_ms", "stage_ms", "log", "output"}


def stable(report):
    if isinstance(report, dict):
        return {k: stable(v) for k, v in report.items() if k not in UNSTABLE}
    if isinstance(report, list):
        return [stable(v) for v in report]
    return report


@pytest.mark.parametrize("options", [[], ["--seam-mode", "free", "--max-iter", "3"]],
                         ids=["defaults", "free-seams"])
def test_subcommand_form_equals_the_old_form(options, tmp_path):
    mesh = REPO / "sample_meshes" / "patches.ply"
    outputs = {}
    for form, prefix in (("old", []), ("sub", ["approximate"])):
        out, report = tmp_path / f"{form}.ply", tmp_path / f"{form}.json"
        r = run(*prefix, mesh, out, "--report", report, *options)
        assert r.returncode == 0, r.stderr
        outputs[form] = (out.read_bytes(), stable(json.loads(report.read_text())),
                         re.sub(r"[0-9.]+ ms", "", r.stdout), r.stderr)
    assert outputs["sub"] == outputs["old"]


def test_version_is_the_project_version():
    cmake = (REPO / "CMakeLists.txt").read_text()
    version = re.search(r"project\(\w+ VERSION ([0-9.]+)", cmake).group(1)
    for args in (["--version"], ["approximate", "--version"]):
        r = run(*args)
        assert r.returncode == 0 and r.stdout == f"quasidev {version}\n", r.stdout


def test_help_lists_the_subcommands_and_the_defaults():
    top = run("--help")
    assert top.returncode == 0
    assert re.search(r"^Subcommands:\napproximate\n", top.stdout, re.M), top.stdout
    sub = run("approximate", "--help")
    assert sub.returncode == 0
    assert "Usage: quasidev approximate [OPTIONS] INPUT OUTPUT" in sub.stdout
    for option, default in (("--tolerance-ae,--tolerance X", "1"), ("--max-iter N", "30"),
                            ("--weight X", "30"), ("--developability NAME", "auto"),
                            ("--seam-mode,--seams NAME", "fixed"),
                            ("--target-mode,--targets NAME", "reproject-then-refit"),
                            ("--output-quality,--quality NAME", "curvature"), ("--threads N", "0"),
                            ("--defect-weight X", "0.03")):
        entry = sub.stdout[sub.stdout.index(option):]
        entry = " ".join(entry[:entry.index("\n  --", 1)].split())
        assert f"default {default})" in entry, entry


@pytest.mark.parametrize("option,value,hint", [("--seam-mode", "sometimes", "fixed|free"),
                                               ("--max-iter", "0", "whole number from 1"),
                                               ("--tolerance-ae", "-1", "greater than 0"),
                                               ("--developability", "paper", "curve|defect")])
def test_bad_value_through_the_subcommand_names_option_and_value(option, value, hint, tmp_path):
    out = tmp_path / "out.ply"
    r = run("approximate", SAMPLES[0], out, option, value)
    assert_clean_failure(r, out, status=2)
    assert option in r.stderr and value in r.stderr and hint in r.stderr, r.stderr


def test_unknown_option_and_missing_files_through_the_subcommand(tmp_path):
    out = tmp_path / "out.ply"
    r = run("approximate", SAMPLES[0], out, "--frobnicate")
    assert_clean_failure(r, out, status=2)
    assert "unknown option '--frobnicate'" in r.stderr
    r = run("approximate", SAMPLES[0])
    assert_clean_failure(r, out, status=2)
    assert "expected INPUT and OUTPUT, got 1" in r.stderr


def test_progress_line_through_the_subcommand(tmp_path):
    r = run("approximate", SAMPLES[0], tmp_path / "o.ply", "--progress")
    assert r.returncode == 0, r.stderr
    progress = [l for l in r.stderr.splitlines() if l.startswith("quasidev: ")]
    assert progress and progress[-1].startswith("quasidev: 100%")
