#!/usr/bin/env bash
# Builds the engine, the quasidev command and their tests with AddressSanitizer +
# UndefinedBehaviorSanitizer and runs them: the core unit tests, the command's unit tests, its
# end-to-end pytest suite against the sanitized binary, and the two fuzz targets (mesh readers,
# engine). Any sanitizer report aborts the process, so it fails the run.
#
# With clang (scripts/setup.sh installs clang and libclang-rt-14-dev) everything is built with
# clang and the fuzz targets are real libFuzzer binaries (tests/cli/fuzz/run_libfuzzer.sh);
# without it GCC builds them with the bounded mutation driver fuzz_driver.cpp.
#
# Usage: tests/cli/run_sanitizers.sh [BUILD_DIR]   (default: build-asan beside the sources; kept
#        between runs, so only changed files are rebuilt). QD_JOBS = parallel compile jobs (2);
#        QD_FUZZ_SECONDS = libFuzzer time per target (60).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
repo="$(cd "$here/../.." && pwd)"
build="${1:-$repo/build-asan}"
flags="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer -O1 -g"
config=(-DCMAKE_BUILD_TYPE=Debug -DQD_WERROR=ON)
fuzz_probe='extern "C" int LLVMFuzzerTestOneInput(const unsigned char*, unsigned long) { return 0; }'
if command -v clang++ >/dev/null &&
   clang++ -x c++ -fsanitize=fuzzer,address - -o /dev/null <<<"$fuzz_probe" 2>/dev/null; then
  compiler=clang++
  flags="$flags -fsanitize=fuzzer-no-link"
  config+=(-DQD_LIBFUZZER=ON)
else
  compiler=g++
  echo "clang with libFuzzer not found: GCC build, fuzz targets use the mutation driver"
fi
# A build directory made by the other compiler is started afresh.
if [[ -f "$build/CMakeCache.txt" ]] && ! grep -q "^CMAKE_CXX_COMPILER:.*/$compiler\$" "$build/CMakeCache.txt"; then
  rm -rf "$build"
fi
cmake -S "$repo" -B "$build" "${config[@]}" -DCMAKE_CXX_COMPILER="$compiler" \
      -DCMAKE_CXX_FLAGS="$flags" >/dev/null
targets=(qd_cli_tests quasidev qd_fuzz_mesh_readers qd_fuzz_engine)
known_targets="$(cmake --build "$build" --target help)"
if [[ "$known_targets" == *qd_core_tests* ]]; then targets+=(qd_core_tests); fi
cmake --build "$build" -j"${QD_JOBS:-2}" --target "${targets[@]}"
export ASAN_OPTIONS=halt_on_error=1:abort_on_error=1:detect_leaks=1
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
export LSAN_OPTIONS="suppressions=$here/lsan_suppressions.txt:print_suppressions=0"
failed=()
step() {  # runs one check, remembers a failure, goes on with the others
  echo "== $*"
  "$@" || failed+=("$*")
}
pytest="$repo/.venv/bin/pytest"
[[ -x "$pytest" ]] || pytest="$(command -v pytest)"
# Timing tests measure the optimised build; sanitized code is several times slower.
if [[ -x "$build/bin/qd_core_tests" ]]; then
  step "$build/bin/qd_core_tests" --gtest_brief=1 --gtest_filter='-*Timing*'
fi
step "$build/bin/qd_cli_tests" --gtest_brief=1
if [[ $compiler == clang++ ]]; then
  step bash "$here/fuzz/run_libfuzzer.sh" "$build" "${QD_FUZZ_SECONDS:-60}"
else
  step "$build/bin/qd_fuzz_mesh_readers" "$here/fuzz/seeds" 200000 30
  step "$build/bin/qd_fuzz_engine" "$here/fuzz/engine_seeds" 2000 60
fi
step env QD_BUILD_DIR="$build" "$pytest" -q -p no:cacheprovider "$here"
if ((${#failed[@]})); then
  echo "sanitized runs FAILED: ${failed[*]}"
  exit 1
fi
echo "sanitized runs passed"
