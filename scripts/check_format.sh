#!/usr/bin/env bash
# Fails when a C++ source of ours is not as clang-format (the repository's .clang-format) would
# write it; names the files. Run `clang-format -i FILE` to fix one. third_party/ is not ours.
set -euo pipefail
cd "$(dirname "$0")/.."
mapfile -t files < <(git ls-files '*.cpp' '*.h' | grep -v '^third_party/')
clang-format --dry-run -Werror "${files[@]}"
echo "clang-format: ${#files[@]} files as .clang-format writes them"
