#!/usr/bin/env bash
# Regenerates what is made from the parameter declarations (filter_quasidev/params/*_params.cpp)
# after a parameter was added, renamed or changed: the reference pages docs/reference/*.md and
# the parameter lists of the .mlx samples in sample_meshes/ (their values kept, a new parameter
# at its default: scripts/update_mlx.py). Run it from a configured build (build/, or $QD_BUILD_DIR);
# the tests fail until it has run.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD="${QD_BUILD_DIR:-build}"
cmake --build "$BUILD" --target qd_reference -j2
"$BUILD/bin/qd_reference" --write docs/reference
"$BUILD/bin/qd_reference" --json > "$BUILD/parameters.json"
python3 scripts/update_mlx.py "$BUILD/parameters.json" sample_meshes/*.mlx
