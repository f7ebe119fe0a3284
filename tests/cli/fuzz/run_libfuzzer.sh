#!/usr/bin/env bash
# Runs the libFuzzer targets that run_sanitizers.sh builds with clang (QD_LIBFUZZER=ON) for a
# bounded time each: qd_fuzz_mesh_readers from seeds/, qd_fuzz_engine from engine_seeds/. Inputs
# that reach new code are kept in BUILD_DIR/fuzz-corpus/TARGET for the next run. An input that
# crashes, leaks, hangs or runs out of memory is copied into the target's seed folder as
# regression-<sha1 prefix>: commit it, and from then on every fuzz run, the ctest replay of the
# seeds and the GCC mutation driver run it first, so the bug stays fixed.
# Usage: tests/cli/fuzz/run_libfuzzer.sh BUILD_DIR [SECONDS per target, default 60]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
build="$(cd "$1" && pwd)"
seconds="${2:-60}"
status=0
for pair in qd_fuzz_mesh_readers:seeds qd_fuzz_engine:engine_seeds; do
  target="${pair%%:*}"
  seeds="$here/${pair#*:}"
  corpus="$build/fuzz-corpus/$target"
  artifacts="$build/fuzz-artifacts/$target"
  log="$build/fuzz-$target.log"
  mkdir -p "$corpus" "$artifacts"
  rm -f "$artifacts"/*
  if "$build/bin/$target" -max_total_time="$seconds" -timeout=25 -rss_limit_mb=2048 \
       -print_final_stats=1 -artifact_prefix="$artifacts/" "$corpus" "$seeds" >"$log" 2>&1; then
    runs="$(awk '/stat::number_of_executed_units/ {print $2}' "$log")"
    echo "$target: $runs inputs in ${seconds} s, no crash ($(find "$corpus" -type f | wc -l) in its corpus)"
  else
    status=1
    tail -n 40 "$log"
    for found in "$artifacts"/*; do
      [[ -f "$found" ]] || continue
      keep="$seeds/regression-$(sha1sum "$found" | cut -c1-12)"
      cp "$found" "$keep"
      echo "$target: $(basename "$found") kept as tests/cli/fuzz/${keep#"$here/"}: commit it"
    done
  fi
done
exit "$status"
