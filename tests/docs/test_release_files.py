"""The release files agree with each other and with the command: the version in CMakeLists.txt's
project(VERSION), the newest version in CHANGELOG.md, CITATION.cff's version and what
`quasidev --version` prints are one number; LICENSE is the GPL-3.0 text CITATION.cff names."""
import os
import pathlib
import re
import subprocess

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
QUASIDEV = pathlib.Path(os.environ.get("QD_BUILD_DIR", ROOT / "build")) / "bin" / "quasidev"


def cmake_version():
    return re.search(r"project\(\w+ VERSION ([0-9.]+)", (ROOT / "CMakeLists.txt").read_text()).group(1)


def test_changelog_newest_version_is_the_project_version():
    versions = re.findall(r"^## \[([0-9][0-9.]*)\]", (ROOT / "CHANGELOG.md").read_text(), flags=re.M)
    assert versions, "CHANGELOG.md has no '## [x.y.z]' heading"
    assert versions[0] == cmake_version()


def test_citation_names_the_project_version_and_the_licence():
    cff = (ROOT / "CITATION.cff").read_text()
    assert re.search(r"^version: ([0-9.]+)$", cff, flags=re.M).group(1) == cmake_version()
    assert re.search(r"^license: (\S+)$", cff, flags=re.M).group(1) == "GPL-3.0-or-later"
    assert "Least squares quasi-developable mesh approximation" in cff


def test_licence_is_the_gpl_3():
    text = (ROOT / "LICENSE").read_text()
    assert "GNU GENERAL PUBLIC LICENSE" in text and "Version 3, 29 June 2007" in text


@pytest.mark.skipif(not QUASIDEV.exists(), reason=f"{QUASIDEV} not built")
def test_the_command_prints_the_changelog_version():
    newest = re.search(r"^## \[([0-9.]+)\]", (ROOT / "CHANGELOG.md").read_text(), flags=re.M).group(1)
    out = subprocess.run([str(QUASIDEV), "--version"], capture_output=True, text=True, check=True).stdout
    assert out == f"quasidev {newest}\n"
