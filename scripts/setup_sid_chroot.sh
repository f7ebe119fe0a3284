#!/usr/bin/env bash
# Makes the Debian sid chroot in which the real MeshLab 2025.07 GUI runs for the tests
# (tests/meshlab/test_gui_2025.py; docs/meshlab-notes.md "The MeshLab 2025.07 GUI in a sid
# chroot"): Debian 12 ships only MeshLab 2020.09, sid ships meshlab 2025.07~dfsg-4 (Qt 5). Called by scripts/setup.sh; can also be run alone (as root, or
# it asks sudo when there is work to do).
#
#   debootstrap --variant=minbase sid, then apt-get install --no-install-recommends the pinned
#   meshlab + the four libraries without which MeshLab 2025.07 opens its blocking "Unable to load
#   the following plugins" dialog + a font (so the dialogs have text on screenshots).
#
# Idempotent: skipped when <chroot>/.qd-complete holds this script's SPEC. Built in <chroot>.tmp
# and renamed when complete, so an interrupted run leaves no half chroot behind the marker.
# Every mount (debootstrap's own /proc and /sys, /proc for dpkg) happens inside a private mount
# namespace (unshare -m) that dies with the command: nothing stays mounted in the clone, whatever
# happens, so `rm -rf` of the clone always works.
# If sid no longer has the pinned meshlab, the chroot is not made and <chroot>.unavailable says
# why: the GUI test then skips naming the version (never passes silently); setup goes on.
# Env: QD_SID_CHROOT overrides the path (default <repo>/third_party/sid-chroot),
#      QD_SID_MIRROR the Debian mirror.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
CHROOT="${QD_SID_CHROOT:-$ROOT/third_party/sid-chroot}"
MIRROR="${QD_SID_MIRROR:-http://deb.debian.org/debian}"
MESHLAB_VERSION="2025.07~dfsg-4"
PACKAGES=("meshlab=$MESHLAB_VERSION" libmuparser2v5 libqhull-r8.0 lib3ds-1-3 libopenctm1
          fonts-dejavu-core)
SPEC="sid minbase; ${PACKAGES[*]}; no docs"
MARKER="$CHROOT/.qd-complete"
UNAVAILABLE="$CHROOT.unavailable"
TMP="$CHROOT.tmp"

say() { echo "[setup_sid_chroot] $*"; }
die() { echo "[setup_sid_chroot] FAILED: $*" >&2; exit 1; }

if [ -f "$MARKER" ] && [ "$(cat "$MARKER")" = "$SPEC" ]; then
  say "present: ${CHROOT#"$ROOT"/} (meshlab $MESHLAB_VERSION)"
  exit 0
fi
if [ -f "$UNAVAILABLE" ] && grep -qF "meshlab $MESHLAB_VERSION " "$UNAVAILABLE"; then
  echo "[setup_sid_chroot] WARNING: $(cat "$UNAVAILABLE") (found earlier; delete $UNAVAILABLE to look again)" >&2
  exit 0
fi
if [ "$(id -u)" -ne 0 ]; then   # debootstrap and chroot need root
  command -v sudo >/dev/null || die "not root and no sudo: run this script as root"
  exec sudo env QD_SID_CHROOT="$CHROOT" QD_SID_MIRROR="$MIRROR" bash "$0" "$@"
fi
command -v debootstrap >/dev/null || die "debootstrap missing (apt-get install debootstrap)"

# Refuses to delete a directory something is mounted in (rm -rf would descend into /dev, /proc).
remove_tree() {
  local dir="$1"
  [ -e "$dir" ] || return 0
  local real; real="$(realpath "$dir")"
  if awk -v d="$real" '$5 == d || index($5, d "/") == 1 {found=1} END {exit !found}' /proc/self/mountinfo; then
    die "something is mounted under $real (see findmnt -R $real): unmount it, then rerun"
  fi
  rm -rf "$dir"
}

start=$(date +%s)
remove_tree "$TMP"
remove_tree "$CHROOT"
rm -f "$UNAVAILABLE"
mkdir -p "$(dirname "$CHROOT")"

say "debootstrap --variant=minbase sid from $MIRROR"
unshare --mount --propagation private \
  debootstrap --variant=minbase sid "$TMP" "$MIRROR" > "$TMP.log" 2>&1 \
  || die "debootstrap (log: $TMP.log): $(tail -3 "$TMP.log")"
rm -f "$TMP.log"

# No documentation, manual pages or translations: a third of the installed size.
cat > "$TMP/etc/dpkg/dpkg.cfg.d/01-qd-nodoc" <<'EOF'
path-exclude=/usr/share/doc/*
path-exclude=/usr/share/man/*
path-exclude=/usr/share/info/*
path-exclude=/usr/share/locale/*
path-exclude=/usr/share/lintian/*
EOF
# The mirror this runs against may serve a sid Release file past its Valid-Until date (seen:
# "Release file ... is expired"); the signatures are still checked.
echo 'Acquire::Check-Valid-Until "false";' > "$TMP/etc/apt/apt.conf.d/01-qd-no-valid-until"
mkdir -p "$TMP/qd"   # where the tests bind their working directory
mkdir -p -m 1777 "$TMP/tmp/.X11-unix"   # where they bind the host's X sockets

# Runs a command in the chroot with /proc mounted, in a private mount namespace.
in_chroot() {
  unshare --mount --propagation private sh -c 'mount -t proc proc "$1/proc" && shift && exec chroot "$@"' \
    sh "$TMP" "$TMP" env DEBIAN_FRONTEND=noninteractive LC_ALL=C.UTF-8 "$@"
}

say "apt-get update in the chroot"
in_chroot apt-get update -q >/dev/null || die "apt-get update in the sid chroot"
available=$(in_chroot apt-cache madison meshlab | awk '{print $3}' | paste -sd ' ')
if ! grep -qwF -- "$MESHLAB_VERSION" <<<"$available"; then
  msg="Debian sid no longer has meshlab $MESHLAB_VERSION (it has: ${available:-none}); update MESHLAB_VERSION in scripts/setup_sid_chroot.sh"
  echo "[setup_sid_chroot] WARNING: $msg; the MeshLab 2025.07 GUI test will be skipped" >&2
  remove_tree "$TMP"
  echo "$msg" > "$UNAVAILABLE"
  exit 0
fi
say "apt-get install --no-install-recommends ${PACKAGES[*]}"
in_chroot apt-get install -y -q --no-install-recommends "${PACKAGES[@]}" > "$TMP.log" 2>&1 \
  || die "apt-get install in the sid chroot (log: $TMP.log): $(tail -5 "$TMP.log")"
rm -f "$TMP.log"
in_chroot apt-get clean
rm -rf "$TMP"/var/lib/apt/lists/* "$TMP"/var/cache/apt/*.bin
[ -x "$TMP/usr/bin/meshlab" ] || die "no /usr/bin/meshlab in the chroot after apt-get install"

echo "$SPEC" > "$TMP/.qd-complete"
mv "$TMP" "$CHROOT"
say "made ${CHROOT#"$ROOT"/} in $(( $(date +%s) - start )) s, $(du -sh "$CHROOT" | cut -f1)"
