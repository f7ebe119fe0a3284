#!/usr/bin/env bash
# The test command: installs what is missing (scripts/setup.sh), builds everything with
# warnings as errors, then runs the unit tests (ctest) and the integration tests (pytest:
# the quasidev command, meshlabserver 2020.09 and the MeshLab GUI under Xvfb, pymeshlab 2025.07).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DQD_WERROR=ON
cmake --build build -j2
(cd build && ctest --output-on-failure -j2)
QD_BUILD_DIR="$PWD/build" .venv/bin/python -m pytest -q -p no:cacheprovider tests
