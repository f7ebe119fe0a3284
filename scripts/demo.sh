#!/usr/bin/env bash
# The main job, end to end: installs only what the demo needs (scripts/setup.sh --demo), builds
# the MeshLab 2020.09 plugin, runs "Quasi-Developable Approximation" through the real
# meshlabserver (a private MeshLab prefix in out/, so nothing system-wide changes) on a bundled
# sample with every parameter at its default, and renders the mesh before and after, both
# coloured by |Gaussian curvature| on one shared scale. Says how long each step took.
# Usage: scripts/demo.sh [MESH.ply [SCRIPT.mlx]]   (default: sample_meshes/lampshade.ply, default.mlx)
# Output: out/<mesh>_quasidev.ply (moved vertices, per-vertex curvature + colour, patch ids),
#         out/<mesh>_quasidev.log (the filter's log), out/<mesh>_before_after.png.
# Env: QD_BUILD_DIR overrides the build directory (default build/).
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
MESH="$(realpath "${1:-$ROOT/sample_meshes/lampshade.ply}")"
SCRIPT="$(realpath "${2:-$ROOT/sample_meshes/default.mlx}")"
OUT="$ROOT/out"
BUILD="${QD_BUILD_DIR:-$ROOT/build}"
NAME="$(basename "$MESH" .ply)"
say() { echo "[demo] $*"; }
die() { echo "[demo] FAILED: $*" >&2; exit 1; }

START=$SECONDS
TIMES=()
# step LABEL COMMAND...: runs the command, says how long it took and keeps that for the summary.
step() {
  local label="$1" t0=$SECONDS
  shift
  say "$label ..."
  "$@"
  TIMES+=("$label: $((SECONDS - t0)) s")
  say "$label: $((SECONDS - t0)) s"
}

[ -f "$MESH" ] || die "no mesh $MESH"
[ -f "$SCRIPT" ] || die "no filter script $SCRIPT"

step "set up (scripts/setup.sh --demo)" bash "$ROOT/scripts/setup.sh" --demo

build_plugin() {
  # A fresh build directory is configured without the tests (GoogleTest is a test-only
  # package); an existing one keeps its settings.
  local tests=()
  [ -f "$BUILD/CMakeCache.txt" ] || tests=(-DQD_BUILD_TESTS=OFF)
  cmake -S "$ROOT" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release "${tests[@]}" >/dev/null || die "cmake configure"
  cmake --build "$BUILD" --target filter_quasidev -j2 >/dev/null || die "building the plugin"
}
step "build the MeshLab 2020.09 plugin" build_plugin

install_plugin() {
  mkdir -p "$OUT"
  bash "$ROOT/scripts/install_plugin.sh" --user --prefix "$OUT/meshlab2020" --bin-dir none \
       --plugin "$BUILD/bin/plugins/libfilter_quasidev.so" >/dev/null \
    || die "installing into $OUT/meshlab2020"
}
step "install it into a private MeshLab in out/meshlab2020" install_plugin

RESULT="$OUT/${NAME}_quasidev.ply"
LOG="$OUT/${NAME}_quasidev.log"
run_meshlabserver() {
  rm -f "$RESULT"
  if ! HOME="$OUT" xvfb-run -a -s "-screen 0 1024x768x24" "$OUT/meshlab2020/bin/meshlabserver" \
         -i "$MESH" -o "$RESULT" -m vc vq fq -s "$SCRIPT" >"$LOG" 2>&1; then
    grep -E "failed:|Problem with filter" "$LOG" >&2 || tail -5 "$LOG" >&2
    die "meshlabserver (log: $LOG)"
  fi
  grep -E "^LOG: [0-9]+ (patch|total)" "$LOG" | sed 's/^LOG: [0-9]* /[demo]   /'
}
step "meshlabserver: $(basename "$MESH") with $(basename "$SCRIPT")" run_meshlabserver

PNG="$OUT/${NAME}_before_after.png"
step "render the picture" "$ROOT/.venv/bin/python" "$ROOT/scripts/render_before_after.py" \
  "$MESH" "$RESULT" -o "$PNG" --name "$NAME" --after-label "after the filter in meshlabserver"

say "times: ${TIMES[*]/%/;} total $((SECONDS - START)) s"
say "result mesh: $RESULT"
say "log:         $LOG"
say "picture:     $PNG"
