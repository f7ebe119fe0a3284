#!/usr/bin/env bash
# Runs clang-tidy (the checks of .clang-tidy) on every source file of the core engine,
# filter_quasidev/core/**/*.cpp, with the compile commands of a build folder; fails on any finding.
#   scripts/clang_tidy.sh [BUILD_DIR]   (default build/, configured with
#                                        -DCMAKE_EXPORT_COMPILE_COMMANDS=ON, as scripts/test.sh does)
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${1:-$ROOT/build}"
[ -f "$BUILD/compile_commands.json" ] \
  || { echo "clang_tidy.sh: no $BUILD/compile_commands.json (configure with -DCMAKE_EXPORT_COMPILE_COMMANDS=ON)" >&2; exit 1; }
command -v run-clang-tidy >/dev/null || { echo "clang_tidy.sh: run-clang-tidy missing (Debian package clang-tidy)" >&2; exit 1; }

t0=$SECONDS
# run-clang-tidy takes the files as regular expressions over the compile database's paths.
run-clang-tidy -quiet -j 2 -p "$BUILD" "$ROOT/filter_quasidev/core/.*\.cpp$"
echo "clang-tidy: core clean ($((SECONDS - t0)) s)"
