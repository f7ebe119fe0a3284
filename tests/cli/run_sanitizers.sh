#!/usr/bin/env bash
# Builds the engine and command tests with AddressSanitizer + UndefinedBehaviorSanitizer and runs
# them: the core unit tests (if present), the command's unit tests, its end-to-end pytest suite
# against the sanitized binary, and bounded fuzz runs of the readers and the engine.
# Any sanitizer report aborts the process, so it fails the run.
# Usage: tests/cli/run_sanitizers.sh [BUILD_DIR]   (default: build-asan beside the sources)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
repo="$(cd "$here/../.." && pwd)"
build="${1:-$repo/build-asan}"
flags="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer -O1 -g"
cmake -S "$repo" -B "$build" -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS="$flags" >/dev/null
targets=(qd_cli_tests quasidev qd_fuzz_mesh_readers qd_fuzz_engine)
known_targets="$(cmake --build "$build" --target help)"
if [[ "$known_targets" == *qd_core_tests* ]]; then targets+=(qd_core_tests); fi
cmake --build "$build" -j2 --target "${targets[@]}"
export ASAN_OPTIONS=halt_on_error=1:abort_on_error=1:detect_leaks=1
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
failed=()
step() {  # runs one check, remembers a failure, goes on with the others
  echo "== $*"
  "$@" || failed+=("$*")
}
pytest="$repo/.venv/bin/pytest"
[[ -x "$pytest" ]] || pytest="$(command -v pytest)"
if [[ -x "$build/bin/qd_core_tests" ]]; then step "$build/bin/qd_core_tests" --gtest_brief=1; fi
step "$build/bin/qd_cli_tests" --gtest_brief=1
step "$build/bin/qd_fuzz_mesh_readers" "$here/fuzz/seeds" 200000 30
step "$build/bin/qd_fuzz_engine" "$here/fuzz/engine_seeds" 2000 60
step env QD_BUILD_DIR="$build" "$pytest" -q -p no:cacheprovider "$here"
if ((${#failed[@]})); then
  echo "sanitized runs FAILED: ${failed[*]}"
  exit 1
fi
echo "sanitized runs passed"
