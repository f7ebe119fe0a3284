#!/usr/bin/env bash
# Builds the MeshLab 2020.09 plugin (libfilter_quasidev.so) against the installed MeshLab and
# installs it where MeshLab 2020.09 looks for plugins (docs/meshlab-notes.md "Where 2020.09
# looks for plugins"):
#   as root:     /usr/lib/x86_64-linux-gnu/meshlab/plugins/  (every user's meshlab/meshlabserver)
#   as a user:   a private prefix (default ~/.local/opt/meshlab2020) holding COPIES of meshlab and
#                meshlabserver (2020.09 only searches <dir of the real executable>/../lib/...), links
#                to the system library and plugins, our plugin, and the launchers
#                ~/.local/bin/meshlab2020 and ~/.local/bin/meshlabserver2020.
# --uninstall removes what the same options installed.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
SYSTEM_LIB=/usr/lib/x86_64-linux-gnu/meshlab
PLUGIN_NAME=libfilter_quasidev.so
MARKER=.installed-by-filter_quasidev

usage() {
  cat <<EOF
Usage: $0 [--system | --user] [--prefix DIR] [--bin-dir DIR] [--plugin FILE] [--build-dir DIR]
          [--uninstall]
  --system       install into $SYSTEM_LIB/plugins (default when run as root)
  --user         install into a private prefix (default when not root)
  --prefix DIR   private prefix for --user (default ~/.local/opt/meshlab2020)
  --bin-dir DIR  where --user puts the launchers meshlab2020, meshlabserver2020
                 (default ~/.local/bin; "none" for no launchers)
  --plugin FILE  install this plugin file instead of building one
  --build-dir D  build directory (default $ROOT/build); the plugin is D/bin/plugins/$PLUGIN_NAME
  --uninstall    remove the installed plugin (system) or the private prefix and launchers (user)
EOF
}
die() { echo "[install] FAILED: $*" >&2; exit 1; }
say() { echo "[install] $*"; }

mode=""; prefix="$HOME/.local/opt/meshlab2020"; bindir="$HOME/.local/bin"; plugin=""
build="$ROOT/build"; uninstall=0
while [ $# -gt 0 ]; do
  case "$1" in
    --system) mode=system ;;
    --user) mode=user ;;
    --prefix) prefix="$2"; shift ;;
    --bin-dir) bindir="$2"; shift ;;
    --plugin) plugin="$2"; shift ;;
    --build-dir) build="$2"; shift ;;
    --uninstall) uninstall=1 ;;
    -h|--help) usage; exit 0 ;;
    *) usage >&2; die "unknown option $1" ;;
  esac
  shift
done
[ -n "$mode" ] || { [ "$(id -u)" -eq 0 ] && mode=system || mode=user; }
[ -d "$SYSTEM_LIB/plugins" ] && [ -x /usr/bin/meshlabserver ] \
  || die "MeshLab 2020.09 is not installed (package meshlab; scripts/setup.sh installs it)"

# ---- uninstall --------------------------------------------------------------------------------
if [ $uninstall -eq 1 ]; then
  if [ "$mode" = system ]; then
    rm -f "$SYSTEM_LIB/plugins/$PLUGIN_NAME" || die "cannot remove $SYSTEM_LIB/plugins/$PLUGIN_NAME (root?)"
    say "removed $SYSTEM_LIB/plugins/$PLUGIN_NAME"
  else
    if [ -e "$prefix" ]; then
      [ -f "$prefix/$MARKER" ] || die "$prefix was not made by this script; not removing it"
      rm -rf "$prefix"
      say "removed $prefix"
    fi
    for launcher in meshlab2020 meshlabserver2020; do
      if [ "$bindir" != none ] && [ -L "$bindir/$launcher" ]; then
        rm -f "$bindir/$launcher"; say "removed $bindir/$launcher"
      fi
    done
  fi
  exit 0
fi

# ---- build (or take the given file) -----------------------------------------------------------
if [ -z "$plugin" ]; then
  [ -f "$ROOT/third_party/meshlab-2020.09/src/common/interfaces.h" ] \
    || die "MeshLab 2020.09 sources missing: run scripts/setup.sh first"
  say "building the plugin in $build"
  cmake -S "$ROOT" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null || die "cmake configure"
  cmake --build "$build" --target filter_quasidev -j2 >/dev/null || die "building filter_quasidev"
  plugin="$build/bin/plugins/$PLUGIN_NAME"
fi
[ -f "$plugin" ] || die "plugin $plugin not found"
# The plugin links SuiteSparse's CHOLMOD, which Debian's meshlab package does not pull in.
missing_libs="$(ldd "$plugin" 2>/dev/null | awk '/not found/ {print $1}' | tr '\n' ' ')"
[ -z "$missing_libs" ] || die "the plugin needs ${missing_libs}which this system lacks: install them (Debian: apt install libcholmod3 libopenblas0-pthread)"

# ---- install ----------------------------------------------------------------------------------
if [ "$mode" = system ]; then
  [ -w "$SYSTEM_LIB/plugins" ] || die "$SYSTEM_LIB/plugins is not writable: run as root or use --user"
  install -m 644 "$plugin" "$SYSTEM_LIB/plugins/$PLUGIN_NAME"
  say "installed $SYSTEM_LIB/plugins/$PLUGIN_NAME: meshlab and meshlabserver load it"
  exit 0
fi
if [ -e "$prefix" ] && [ ! -f "$prefix/$MARKER" ]; then
  die "$prefix exists and was not made by this script; choose another --prefix"
fi
libdir="$prefix/lib/x86_64-linux-gnu/meshlab"
mkdir -p "$prefix/bin" "$libdir/plugins"
touch "$prefix/$MARKER"
# Copies, not links: the plugin dir is derived from the resolved executable path
# (docs/meshlab-notes.md "Where 2020.09 looks for plugins").
# Re-copied on every run so the prefix follows upgrades of the meshlab package.
cp -f /usr/bin/meshlab /usr/bin/meshlabserver "$prefix/bin/"
ln -sfn "$SYSTEM_LIB/libmeshlab-common.so" "$libdir/libmeshlab-common.so"
find "$libdir/plugins" -maxdepth 1 -type l -delete
for so in "$SYSTEM_LIB"/plugins/*.so; do
  [ "$(basename "$so")" = "$PLUGIN_NAME" ] || ln -s "$so" "$libdir/plugins/"
done
install -m 644 "$plugin" "$libdir/plugins/$PLUGIN_NAME"
say "installed $libdir/plugins/$PLUGIN_NAME"
say "run MeshLab with it: $prefix/bin/meshlab  /  $prefix/bin/meshlabserver"
if [ "$bindir" != none ]; then
  mkdir -p "$bindir"
  ln -sfn "$prefix/bin/meshlab" "$bindir/meshlab2020"
  ln -sfn "$prefix/bin/meshlabserver" "$bindir/meshlabserver2020"
  say "launchers: $bindir/meshlab2020, $bindir/meshlabserver2020"
fi
