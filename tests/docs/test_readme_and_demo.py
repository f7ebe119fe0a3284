"""What a newcomer meets first: the README stays short and its links lead somewhere, no file a
user reads names a developer's machine path, and scripts/demo.sh installs only what the demo
needs (scripts/setup.sh --demo), not the test-only extras. The docs site itself is checked by
`mkdocs build --strict` in scripts/test.sh (broken links, pages missing from the nav)."""
import pathlib
import re

ROOT = pathlib.Path(__file__).resolve().parents[2]
README = ROOT / "README.md"
MACHINE_PATH = "/" + "work" + "/"  # the developers' folder, spelt so this file does not contain it


def test_readme_is_short():
    lines = README.read_text().splitlines()
    assert len(lines) <= 160, f"README.md has {len(lines)} lines; move detail into docs/"


def test_readme_links_exist():
    for target in re.findall(r"\]\(([^)#\s]+)(?:#[^)]*)?\)", README.read_text()):
        if re.match(r"[a-z]+:", target):
            continue
        assert (ROOT / target).exists(), f"README.md links to {target}, which does not exist"


def test_no_machine_paths_in_what_users_read():
    files = [README, ROOT / "mkdocs.yml", ROOT / "CHANGELOG.md", ROOT / "CITATION.cff",
             *sorted(f for f in (ROOT / "docs").rglob("*") if f.suffix in (".md", ".json"))]
    for path in files:
        assert MACHINE_PATH not in path.read_text(), f"{path.relative_to(ROOT)} names a machine path"


def array(script: str, name: str) -> set[str]:
    body = re.search(rf"^{name}=\((.*?)\)", script, flags=re.M | re.S).group(1)
    return set(body.split())


def test_demo_installs_only_what_it_needs():
    demo = (ROOT / "scripts" / "demo.sh").read_text()
    assert re.search(r"scripts/setup\.sh\"? --demo", demo), "demo.sh must call scripts/setup.sh --demo"
    setup = (ROOT / "scripts" / "setup.sh").read_text()
    demo_packages, test_packages = array(setup, "DEMO_PACKAGES"), array(setup, "TEST_PACKAGES")
    test_only = {"clang", "libclang-rt-14-dev", "debootstrap", "libgtest-dev", "xdotool"}
    assert test_only <= test_packages and not (test_only & demo_packages)
    assert {"meshlab", "xvfb", "cmake", "g++"} <= demo_packages
    demo_part = setup[setup.index("# ---- 1-3"):setup.index("# ---- 4-7")]
    for extra in ("TEST_PACKAGES", "SOURCE_2025", "setup_pymeshlab.sh", "setup_sid_chroot.sh"):
        assert extra not in demo_part, f"scripts/setup.sh --demo runs {extra}, which only the tests need"
