#!/usr/bin/env bash
# Fails when a C++ file in the tree differs from what clang-format (.clang-format) would write.
set -euo pipefail
cd "$(dirname "$0")/.."
mapfile -t files < <(git ls-files -co --exclude-standard -- '*.cpp' '*.h' | grep -v '^third_party/' || true)
((${#files[@]})) || exit 0
clang-format --dry-run --Werror "${files[@]}"
