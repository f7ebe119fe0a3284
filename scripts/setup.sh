#!/usr/bin/env bash
# Installs what the project needs on Debian 12 (idempotent; fast when already done).
#   scripts/setup.sh --demo   only what scripts/demo.sh needs:
#     1. Debian packages to build the engine, the command and the MeshLab 2020.09 plugin (compiler,
#        CMake, Qt5, Eigen, GLEW, SuiteSparse, nanoflann, CLI11, nlohmann-json, libnest2d with
#        Boost.Geometry and NLopt for the marker, cairo for the printable PDF) and to run it
#        (meshlab 2020.09, Xvfb, Mesa, python3-venv);
#     2. the MeshLab 2020.09 source tree whose headers the plugin compiles against, and the
#        Clipper source compiled into the engine, from Debian's source packages (pinned by
#        sha256), into third_party/meshlab-2020.09 and third_party/polyclipping-6.4.2;
#     3. the Python venv .venv with scripts/requirements-render.txt (the demo's picture).
#   scripts/setup.sh          all of the above, plus what only the tests and the docs need:
#     4. Debian packages: GoogleTest, clang and its libFuzzer (tests/cli/run_sanitizers.sh),
#        clang-tidy (scripts/clang_tidy.sh), clang-format (scripts/check_format.sh),
#        xdotool and ImageMagick (GUI tests), debootstrap and pkgconf (the MeshLab 2025.07 GUI
#        test), rsvg-convert (scripts/flatten_compare.py's pattern picture), python3-dev (the
#        headers `pip install .` builds the Python package against, tests/python/run.sh);
#     5. the MeshLab 2025.07 source tree (third_party/meshlab-2025.07);
#     6. every other scripts/requirements-*.txt into .venv (tests, docs site) and
#        scripts/setup_pymeshlab.sh (the pymeshlab 2025.07 wheel);
#     7. scripts/setup_sid_chroot.sh: the Debian sid chroot third_party/sid-chroot in which the
#        MeshLab 2025.07 GUI test runs (made once, ~1 min and ~490 MB; skipped when complete).
# Run as root (CI) or as a user with sudo. Fails loudly, naming the step that failed; says how
# long each step took.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
THIRD="$ROOT/third_party"
VENV="$ROOT/.venv"

say() { echo "[setup] $*"; }
die() { echo "[setup] FAILED: $*" >&2; exit 1; }

DEMO_ONLY=0
case "${1:-}" in
  --demo) DEMO_ONLY=1 ;;
  "") ;;
  *) die "unknown option $1 (usage: scripts/setup.sh [--demo])" ;;
esac

if [ "$(id -u)" -eq 0 ]; then SUDO=(); else
  command -v sudo >/dev/null || die "not root and no sudo: run this script as root"
  SUDO=(sudo)
fi

# timed LABEL COMMAND...: runs the command and says how long it took.
timed() {
  local label="$1" t0=$SECONDS
  shift
  "$@"
  say "$label: $((SECONDS - t0)) s"
}

# ---- Debian packages ------------------------------------------------------------------------
# What the demo needs: build the engine, the command and the MeshLab 2020.09 plugin, and run it.
DEMO_PACKAGES=(cmake g++ make qtbase5-dev libqt5opengl5-dev libglew-dev
               libeigen3-dev libsuitesparse-dev libopenblas0-pthread libnanoflann-dev
               libcli11-dev nlohmann-json3-dev libnest2d-dev libboost-dev libnlopt-cxx-dev
               libcairo2-dev
               meshlab xvfb xauth libgl1-mesa-dri python3-venv
               ca-certificates debian-archive-keyring xz-utils)
# What only the tests need (see the header).
TEST_PACKAGES=(ninja-build libgtest-dev xdotool imagemagick clang libclang-rt-14-dev clang-tidy
               clang-format debootstrap pkgconf librsvg2-bin python3-dev)
install_packages() {
  local missing=() p
  for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  if [ ${#missing[@]} -eq 0 ]; then
    say "Debian packages: all $# present"
    return
  fi
  say "installing Debian packages: ${missing[*]}"
  "${SUDO[@]}" apt-get update || die "apt-get update"
  "${SUDO[@]}" env DEBIAN_FRONTEND=noninteractive apt-get -o DPkg::Lock::Timeout=600 install -y \
      --no-install-recommends "${missing[@]}" || die "apt-get install ${missing[*]}"
}

# ---- MeshLab sources from Debian's source packages ------------------------------------------
# name of the orig tarball | sha256 | apt source spec | target dir
SOURCE_2020="meshlab_2020.09+dfsg1.orig.tar.xz|d6715352ff65caffdec0292858d4263eb0c3cbbf3b1e5c2e2bab218e3f234630|meshlab=2020.09+dfsg1-2|meshlab-2020.09"
SOURCE_2025="meshlab_2025.07~dfsg.orig.tar.xz|d22c98d362f2a284e481af8dbfc272b2222f5b9c67b3cf8bec57d1c3161886f4|meshlab=2025.07~dfsg-4|meshlab-2025.07"
# Clipper (polygon offsets for the seam allowance, and libnest2d's geometry), compiled into the
# engine: Debian ships it only as a shared library, which the pymeshlab wheel does not have.
SOURCE_CLIPPER="libpolyclipping_6.4.2.orig.tar.bz2|69a2fadc3c0b6c06c3f77e92067b65e28e398a75d1260e9114c283a04e76c463|libpolyclipping=6.4.2-7|polyclipping-6.4.2"
# A private deb-src list: the system's /etc/apt configuration stays untouched
# (docs/meshlab-notes.md, "MeshLab's sources").
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
fetch_source() {
  local tarball sha spec dir
  IFS='|' read -r tarball sha spec dir <<<"$1"
  mkdir -p "$THIRD"
  if [ -f "$THIRD/$dir/.sha256" ] && [ "$(cat "$THIRD/$dir/.sha256")" = "$sha" ]; then
    say "$dir: present (sha256 verified at extraction)"
    return
  fi
  if [ ! -f "$THIRD/$tarball" ] || ! echo "$sha  $THIRD/$tarball" | sha256sum -c --status; then
    prepare_source_apt
    say "downloading $spec from Debian's source packages"
    # The sid .dsc may be 404 while the orig tarball is available (docs/meshlab-notes.md): only
    # the orig tarball is needed, so the exit status is judged by its checksum below.
    (cd "$THIRD" && apt-get "${APT_OPTS[@]}" source --download-only "$spec" >/dev/null 2>&1) || true
  fi
  [ -f "$THIRD/$tarball" ] || die "could not download $tarball ($spec) from deb.debian.org"
  echo "$sha  $THIRD/$tarball" | sha256sum -c --status \
    || die "sha256 mismatch for $tarball: expected $sha, got $(sha256sum "$THIRD/$tarball" | cut -d' ' -f1)"
  say "extracting $tarball to third_party/$dir"
  rm -rf "$THIRD/$dir.tmp" && mkdir -p "$THIRD/$dir.tmp"
  tar -xaf "$THIRD/$tarball" -C "$THIRD/$dir.tmp" --strip-components=1 || die "extracting $tarball"
  echo "$sha" > "$THIRD/$dir.tmp/.sha256"
  rm -rf "${THIRD:?}/$dir" && mv "$THIRD/$dir.tmp" "$THIRD/$dir"
}

# ---- Python venv ----------------------------------------------------------------------------
pip_requirements() {
  local req="$1" plan
  if [ ! -x "$VENV/bin/python" ]; then
    say "creating the Python venv $VENV"
    python3 -m venv "$VENV" || die "python3 -m venv $VENV"
  fi
  plan=$("$VENV/bin/python" -m pip install --disable-pip-version-check --dry-run -r "$req" 2>&1) \
    || die "pip cannot resolve ${req#"$ROOT"/}: $(tail -3 <<<"$plan")"
  if grep -q "Would install" <<<"$plan"; then
    say "pip install -r ${req#"$ROOT"/}"
    "$VENV/bin/python" -m pip install --disable-pip-version-check -q -r "$req" || die "pip install -r $req"
  else
    say "python requirements ${req#"$ROOT"/}: satisfied"
  fi
}

# ---- 1-3: what the demo needs ---------------------------------------------------------------
timed "Debian packages for the demo" install_packages "${DEMO_PACKAGES[@]}"
timed "MeshLab 2020.09 source" fetch_source "$SOURCE_2020"
[ -f "$THIRD/meshlab-2020.09/src/common/interfaces.h" ] || die "third_party/meshlab-2020.09 lacks src/common/interfaces.h"
timed "Clipper source" fetch_source "$SOURCE_CLIPPER"
[ -f "$THIRD/polyclipping-6.4.2/cpp/clipper.cpp" ] || die "third_party/polyclipping-6.4.2 lacks cpp/clipper.cpp"
timed "Python venv for the demo" pip_requirements "$ROOT/scripts/requirements-render.txt"
if [ $DEMO_ONLY -eq 1 ]; then
  say "done (the demo's needs; scripts/setup.sh without --demo adds what the tests need)"
  exit 0
fi

# ---- 4-7: what only the tests and the docs need ---------------------------------------------
timed "Debian packages for the tests" install_packages "${TEST_PACKAGES[@]}"
timed "MeshLab 2025.07 source" fetch_source "$SOURCE_2025"
shopt -s nullglob
for req in "$ROOT"/scripts/requirements-*.txt; do
  [ "$req" = "$ROOT/scripts/requirements-render.txt" ] && continue
  timed "Python ${req#"$ROOT"/}" pip_requirements "$req"
done
timed "pymeshlab (scripts/setup_pymeshlab.sh)" bash "$ROOT/scripts/setup_pymeshlab.sh"
timed "sid chroot (scripts/setup_sid_chroot.sh)" bash "$ROOT/scripts/setup_sid_chroot.sh"
say "done: build with  cmake -S $ROOT -B $ROOT/build -DCMAKE_BUILD_TYPE=Release && cmake --build $ROOT/build -j2"
