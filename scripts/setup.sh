#!/usr/bin/env bash
# Installs everything the project needs on Debian 12 (idempotent; fast when already done):
#   1. Debian packages for building (compiler, CMake, Qt5, Eigen, GLEW, SuiteSparse, GoogleTest,
#      nanoflann, CLI11, nlohmann-json; clang and its libFuzzer for tests/cli/run_sanitizers.sh)
#      and running (meshlab 2020.09, Xvfb, xdotool, ImageMagick, Mesa, python3-venv; debootstrap
#      and pkgconf for the MeshLab 2025.07 GUI test; rsvg-convert for the README's pattern picture,
#      scripts/flatten_compare.py);
#   2. the MeshLab source trees whose headers the plugins compile against, from Debian's source
#      packages (pinned by sha256), into third_party/meshlab-2020.09 and third_party/meshlab-2025.07;
#   3. the Python venv .venv with every scripts/requirements-*.txt;
#   4. scripts/setup_pymeshlab.sh if present (pymeshlab 2025.07 side);
#   5. scripts/setup_sid_chroot.sh: the Debian sid chroot third_party/sid-chroot in which the
#      MeshLab 2025.07 GUI test runs (made once, ~1 min and ~490 MB; skipped when complete).
# Run as root (CI) or as a user with sudo. Fails loudly, naming the step that failed.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
THIRD="$ROOT/third_party"
VENV="$ROOT/.venv"

say() { echo "[setup] $*"; }
die() { echo "[setup] FAILED: $*" >&2; exit 1; }

if [ "$(id -u)" -eq 0 ]; then SUDO=(); else
  command -v sudo >/dev/null || die "not root and no sudo: run this script as root"
  SUDO=(sudo)
fi

# ---- 1. Debian packages ---------------------------------------------------------------------
PACKAGES=(cmake g++ make ninja-build qtbase5-dev libqt5opengl5-dev libglew-dev
          libeigen3-dev libsuitesparse-dev libopenblas0-pthread libgtest-dev libnanoflann-dev
          libcli11-dev nlohmann-json3-dev
          meshlab xvfb xauth xdotool imagemagick libgl1-mesa-dri python3-venv
          ca-certificates debian-archive-keyring xz-utils clang libclang-rt-14-dev
          debootstrap pkgconf librsvg2-bin)
missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  say "installing Debian packages: ${missing[*]}"
  "${SUDO[@]}" apt-get update || die "apt-get update"
  "${SUDO[@]}" env DEBIAN_FRONTEND=noninteractive apt-get -o DPkg::Lock::Timeout=600 install -y \
      --no-install-recommends "${missing[@]}" || die "apt-get install ${missing[*]}"
else
  say "Debian packages: all ${#PACKAGES[@]} present"
fi

# ---- 2. MeshLab sources from Debian's source packages ---------------------------------------
# name of the orig tarball | sha256 | apt source spec | target dir
SOURCES=(
  "meshlab_2020.09+dfsg1.orig.tar.xz|d6715352ff65caffdec0292858d4263eb0c3cbbf3b1e5c2e2bab218e3f234630|meshlab=2020.09+dfsg1-2|meshlab-2020.09"
  "meshlab_2025.07~dfsg.orig.tar.xz|d22c98d362f2a284e481af8dbfc272b2222f5b9c67b3cf8bec57d1c3161886f4|meshlab=2025.07~dfsg-4|meshlab-2025.07"
)
mkdir -p "$THIRD"
# A private deb-src list: the system's /etc/apt configuration stays untouched (MESHLAB.md §1).
APTDIR="$THIRD/.apt"
APT_OPTS=(-o "Dir::Etc::SourceParts=$APTDIR" -o "Dir::Etc::SourceList=/dev/null"
          -o "Dir::State::Lists=$APTDIR/lists" -o "Dir::Cache=$APTDIR/cache"
          -o "APT::Sandbox::User=root")
apt_ready=0
prepare_source_apt() {
  [ $apt_ready -eq 1 ] && return
  mkdir -p "$APTDIR/lists/partial" "$APTDIR/cache/archives/partial"
  cat > "$APTDIR/debian-src.sources" <<'EOF'
Types: deb-src
URIs: http://deb.debian.org/debian
Suites: bookworm sid
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
EOF
  say "updating the private deb-src index (bookworm + sid)"
  apt-get "${APT_OPTS[@]}" update >/dev/null || die "apt-get update of the private deb-src list ($APTDIR)"
  apt_ready=1
}
for entry in "${SOURCES[@]}"; do
  IFS='|' read -r tarball sha spec dir <<<"$entry"
  if [ -f "$THIRD/$dir/.sha256" ] && [ "$(cat "$THIRD/$dir/.sha256")" = "$sha" ]; then
    say "$dir: present (sha256 verified at extraction)"
    continue
  fi
  if [ ! -f "$THIRD/$tarball" ] || ! echo "$sha  $THIRD/$tarball" | sha256sum -c --status; then
    prepare_source_apt
    say "downloading $spec from Debian's source packages"
    # The sid .dsc may be 404 while the orig tarball is available (MESHLAB.md §1): only the
    # orig tarball is needed, so the exit status is judged by its checksum below.
    (cd "$THIRD" && apt-get "${APT_OPTS[@]}" source --download-only "$spec" >/dev/null 2>&1) || true
  fi
  [ -f "$THIRD/$tarball" ] || die "could not download $tarball ($spec) from deb.debian.org"
  echo "$sha  $THIRD/$tarball" | sha256sum -c --status \
    || die "sha256 mismatch for $tarball: expected $sha, got $(sha256sum "$THIRD/$tarball" | cut -d' ' -f1)"
  say "extracting $tarball to third_party/$dir"
  rm -rf "$THIRD/$dir.tmp" && mkdir -p "$THIRD/$dir.tmp"
  tar -xJf "$THIRD/$tarball" -C "$THIRD/$dir.tmp" --strip-components=1 || die "extracting $tarball"
  echo "$sha" > "$THIRD/$dir.tmp/.sha256"
  rm -rf "${THIRD:?}/$dir" && mv "$THIRD/$dir.tmp" "$THIRD/$dir"
done
[ -f "$THIRD/meshlab-2020.09/src/common/interfaces.h" ] || die "third_party/meshlab-2020.09 lacks src/common/interfaces.h"

# ---- 3. Python venv -------------------------------------------------------------------------
if [ ! -x "$VENV/bin/python" ]; then
  say "creating the Python venv $VENV"
  python3 -m venv "$VENV" || die "python3 -m venv $VENV"
fi
shopt -s nullglob
for req in "$ROOT"/scripts/requirements-*.txt; do
  plan=$("$VENV/bin/python" -m pip install --disable-pip-version-check --dry-run -r "$req" 2>&1) \
    || die "pip cannot resolve ${req#"$ROOT"/}: $(tail -3 <<<"$plan")"
  if grep -q "Would install" <<<"$plan"; then
    say "pip install -r ${req#"$ROOT"/}"
    "$VENV/bin/python" -m pip install --disable-pip-version-check -q -r "$req" || die "pip install -r $req"
  else
    say "python requirements ${req#"$ROOT"/}: satisfied"
  fi
done

# ---- 4. pymeshlab side ----------------------------------------------------------------------
if [ -f "$ROOT/scripts/setup_pymeshlab.sh" ]; then
  say "running scripts/setup_pymeshlab.sh"
  bash "$ROOT/scripts/setup_pymeshlab.sh" || die "scripts/setup_pymeshlab.sh"
fi
# ---- 5. the sid chroot with MeshLab 2025.07 ------------------------------------------------
say "running scripts/setup_sid_chroot.sh"
bash "$ROOT/scripts/setup_sid_chroot.sh" || die "scripts/setup_sid_chroot.sh"
say "done: build with  cmake -S $ROOT -B $ROOT/build -DCMAKE_BUILD_TYPE=Release && cmake --build $ROOT/build -j2"
