#!/usr/bin/env bash
# The main job: installs what is missing (scripts/setup.sh), builds the MeshLab 2020.09 plugin,
# runs "Quasi-Developable Approximation" through the real meshlabserver (a private MeshLab prefix
# in out/, so nothing system-wide changes) on a bundled sample with every parameter at its
# default, and renders a before/after PNG.
# Usage: scripts/demo.sh [MESH.ply [SCRIPT.mlx]]   (default: sample_meshes/lampshade.ply, default.mlx)
# Output: out/<mesh>_quasidev.ply (moved vertices, per-vertex curvature + colour, patch ids),
#         out/<mesh>_quasidev.log (the filter's log), out/<mesh>_before_after.png.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
MESH="$(realpath "${1:-$ROOT/sample_meshes/lampshade.ply}")"
SCRIPT="$(realpath "${2:-$ROOT/sample_meshes/default.mlx}")"
OUT="$ROOT/out"
BUILD="${QD_BUILD_DIR:-$ROOT/build}"   # build directory (env QD_BUILD_DIR overrides)
NAME="$(basename "$MESH" .ply)"
die() { echo "[demo] FAILED: $*" >&2; exit 1; }

[ -f "$MESH" ] || die "no mesh $MESH"
[ -f "$SCRIPT" ] || die "no filter script $SCRIPT"
bash "$ROOT/scripts/setup.sh"
echo "[demo] building the plugin in $BUILD"
cmake -S "$ROOT" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release >/dev/null || die "cmake configure"
cmake --build "$BUILD" --target filter_quasidev -j2 >/dev/null || die "building the plugin"
mkdir -p "$OUT"
bash "$ROOT/scripts/install_plugin.sh" --user --prefix "$OUT/meshlab2020" --bin-dir none \
     --plugin "$BUILD/bin/plugins/libfilter_quasidev.so" >/dev/null || die "installing into $OUT/meshlab2020"

RESULT="$OUT/${NAME}_quasidev.ply"
LOG="$OUT/${NAME}_quasidev.log"
echo "[demo] meshlabserver: $(basename "$MESH") with $(basename "$SCRIPT")"
rm -f "$RESULT"
if ! HOME="$OUT" xvfb-run -a -s "-screen 0 1024x768x24" "$OUT/meshlab2020/bin/meshlabserver" \
       -i "$MESH" -o "$RESULT" -m vc vq fq -s "$SCRIPT" >"$LOG" 2>&1; then
  grep -E "failed:|Problem with filter" "$LOG" >&2 || tail -5 "$LOG" >&2
  die "meshlabserver (log: $LOG)"
fi
grep -E "^LOG: [0-9]+ (patch|total)" "$LOG" | sed 's/^LOG: [0-9]* /[demo]   /'

PNG="$OUT/${NAME}_before_after.png"
"$ROOT/.venv/bin/python" "$ROOT/scripts/render.py" "$MESH" "$RESULT" -o "$PNG" \
    --title "Quasi-Developable Approximation (MeshLab 2020.09): $NAME" \
    --labels "input,after the filter (colour = Gaussian curvature)" || die "rendering $PNG"
echo "[demo] result mesh: $RESULT"
echo "[demo] log:         $LOG"
echo "[demo] picture:     $PNG"
