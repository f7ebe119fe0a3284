#!/usr/bin/env bash
# The test command: installs what is missing (scripts/setup.sh: the demo's needs plus the
# test-only extras), builds the docs site (mkdocs build --strict: a broken link or a page
# missing from mkdocs.yml fails), checks that the C++ sources are as clang-format writes them
# (scripts/check_format.sh), builds everything with warnings as errors, runs clang-tidy on
# the core (scripts/clang_tidy.sh), then runs the unit tests (ctest) and the integration tests
# (pytest: the quasidev command, meshlabserver 2020.09, the MeshLab GUIs 2020.09 and 2025.07
# (the latter in the sid chroot of scripts/setup_sid_chroot.sh) under Xvfb, pymeshlab 2025.07),
# the quasidev Python package installed with `pip install .` into its own venv and tested there
# (tests/python/run.sh), its wheel repaired by auditwheel and run in a Debian 12 chroot without
# SuiteSparse or OpenBLAS (scripts/test_wheel.sh),
# and last the engine and command tests again under ASan + UBSan with 60 s of libFuzzer per fuzz
# target (tests/cli/run_sanitizers.sh, in build-asan/, which later runs reuse).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
NO_MKDOCS_2_WARNING=1 .venv/bin/mkdocs build --strict --quiet --site-dir build/site
bash scripts/check_format.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DQD_WERROR=ON -DQD_BUILD_TESTS=ON -DCMAKE_EXPORT_COMPILE_COMMANDS=ON
cmake --build build -j2
bash scripts/clang_tidy.sh build
(cd build && ctest --output-on-failure -j2)
QD_BUILD_DIR="$PWD/build" .venv/bin/python -m pytest -q -rs -p no:cacheprovider tests \
  --ignore=tests/python  # -rs: say why a test skipped; tests/python needs the package's venv
QD_BUILD_DIR="$PWD/build" bash tests/python/run.sh "$PWD/build/python-venv"
QD_WHEEL_VENV="$PWD/build/python-venv" bash scripts/test_wheel.sh
bash tests/cli/run_sanitizers.sh "$PWD/build-asan"
