#!/usr/bin/env bash
# The quasidev Python package's tests: makes the venv VENV (default build/python-venv) if it is
# missing, installs the package there with `pip install .` from the repository root, and runs
# tests/python with pytest against the installed package (the command to compare with is
# $QD_BUILD_DIR/bin/quasidev, default build/). The build runs without isolation, with the backend
# of tests/python/requirements.txt, so later runs reuse build/python/ (and ccache when it
# is installed). Extra CMake definitions: SKBUILD_CMAKE_DEFINE (scikit-build-core).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
VENV="${1:-$ROOT/build/python-venv}"
cd "$ROOT"
[ -x "$VENV/bin/python" ] || python3 -m venv "$VENV"
"$VENV/bin/pip" install -q -r tests/python/requirements.txt
launcher=()
if command -v ccache >/dev/null; then
  launcher=(--config-settings=cmake.define.CMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
CMAKE_BUILD_PARALLEL_LEVEL="${CMAKE_BUILD_PARALLEL_LEVEL:-2}" \
  "$VENV/bin/pip" install -q --no-build-isolation --force-reinstall --no-deps "${launcher[@]}" .
cd "$VENV"  # import the installed package, not a source tree
QD_BUILD_DIR="${QD_BUILD_DIR:-$ROOT/build}" "$VENV/bin/python" -m pytest -q -rs -p no:cacheprovider \
  "$ROOT/tests/python"
