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
# Idempotent: skipped when <chroot>/.qd-complete holds this script's SPEC. Made and used by the
# recipe of scripts/chroot_lib.sh (built in <chroot>.tmp and renamed when complete; every mount
# in a private mount namespace, so nothing stays mounted in the clone).
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
UNAVAILABLE="$CHROOT.unavailable"
TMP="$CHROOT.tmp"
# shellcheck source=scripts/chroot_lib.sh
source "$ROOT/scripts/chroot_lib.sh"

say() { echo "[setup_sid_chroot] $*"; }
die() { echo "[setup_sid_chroot] FAILED: $*" >&2; exit 1; }

if chroot_complete "$CHROOT" "$SPEC"; then
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
start=$(date +%s)
rm -f "$UNAVAILABLE"
say "debootstrap --variant=minbase sid from $MIRROR"
chroot_bootstrap sid "$CHROOT" "$MIRROR"
# The mirror this runs against may serve a sid Release file past its Valid-Until date (seen:
# "Release file ... is expired"); the signatures are still checked.
echo 'Acquire::Check-Valid-Until "false";' > "$TMP/etc/apt/apt.conf.d/01-qd-no-valid-until"
mkdir -p "$TMP/qd"   # where the tests bind their working directory
mkdir -p -m 1777 "$TMP/tmp/.X11-unix"   # where they bind the host's X sockets

say "apt-get update in the chroot"
chroot_run "$TMP" -- apt-get update -q >/dev/null || die "apt-get update in the sid chroot"
available=$(chroot_run "$TMP" -- apt-cache madison meshlab | awk '{print $3}' | paste -sd ' ')
if ! grep -qwF -- "$MESHLAB_VERSION" <<<"$available"; then
  msg="Debian sid no longer has meshlab $MESHLAB_VERSION (it has: ${available:-none}); update MESHLAB_VERSION in scripts/setup_sid_chroot.sh"
  echo "[setup_sid_chroot] WARNING: $msg; the MeshLab 2025.07 GUI test will be skipped" >&2
  chroot_remove "$TMP"
  echo "$msg" > "$UNAVAILABLE"
  exit 0
fi
say "apt-get install --no-install-recommends ${PACKAGES[*]}"
chroot_install "$TMP" "${PACKAGES[@]}"
[ -x "$TMP/usr/bin/meshlab" ] || die "no /usr/bin/meshlab in the chroot after apt-get install"

chroot_seal "$CHROOT" "$SPEC"
say "made ${CHROOT#"$ROOT"/} in $(( $(date +%s) - start )) s, $(du -sh "$CHROOT" | cut -f1)"
