#!/usr/bin/env bash
# Installs the pymeshlab side of the project into the shared venv <repo>/.venv (idempotent):
# the pinned pymeshlab wheel (MeshLab 2025.07 core, double precision, "2025.07d") whose
# pymeshlab/lib/libmeshlab-common.so the 2025.07d plugin links against, plus the test deps.
# Called by scripts/setup.sh; can also be run alone. Only adds packages to the venv.
# Env: QD_VENV overrides the venv path.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
VENV="${QD_VENV:-$ROOT/.venv}"
PACKAGES=("pymeshlab==2025.7.post1" "pytest" "numpy")

say() { echo "[setup_pymeshlab] $*"; }
die() { echo "[setup_pymeshlab] FAILED: $*" >&2; exit 1; }

if [ ! -x "$VENV/bin/python" ]; then
  say "creating the Python venv $VENV"
  python3 -m venv "$VENV" || die "python3 -m venv $VENV (Debian: apt-get install python3-venv)"
fi
PY="$VENV/bin/python"

# Offline check first, so a complete venv needs no network.
installed() {
  "$PY" - "$@" <<'PYEOF' 2>/dev/null
import sys
from importlib.metadata import version
for spec in sys.argv[1:]:
    name, _, pin = spec.partition("==")
    if not version(name) or (pin and version(name) != pin):
        sys.exit(1)
PYEOF
}
if installed "${PACKAGES[@]}"; then
  say "already installed: ${PACKAGES[*]}"
else
  say "pip install ${PACKAGES[*]}"
  "$PY" -m pip install --disable-pip-version-check -q "${PACKAGES[@]}" \
    || die "pip install ${PACKAGES[*]} (PyPI reachable? pymeshlab 2025.7.post1 needs glibc >= 2.35, x86_64)"
fi

# The plugin build needs the wheel's own libmeshlab-common.so (filter_quasidev/meshlab/plugin2025.cmake).
LIB="$("$PY" -c 'import os, pymeshlab; print(os.path.join(os.path.dirname(pymeshlab.__file__), "lib"))' 2>/dev/null)" \
  || die "the venv's pymeshlab does not import: $PY -c 'import pymeshlab'"
[ -f "$LIB/libmeshlab-common.so" ] || die "pymeshlab wheel without lib/libmeshlab-common.so at $LIB"
say "pymeshlab ready: $LIB/libmeshlab-common.so"
