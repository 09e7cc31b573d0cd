#!/usr/bin/env bash
# House style, checked by the test command (docs/architecture.md, "Rules that hold everywhere"):
# no source file over 500 lines, clang-format on every first-party C++ file, clang-tidy (naming,
# function size, bugprone, performance) on the core and the program.
# Usage: lint.sh SOURCE_DIR BUILD_DIR
set -euo pipefail
src=${1:?usage: lint.sh SOURCE_DIR BUILD_DIR}
build=${2:?usage: lint.sh SOURCE_DIR BUILD_DIR}
cd "$src"
# Citations and file lengths first: greps and counts of the tracked files, well under a second.
"$src/tests/lint/check_citations.sh" "$src"
"$src/tests/lint/check_file_length.sh" "$src"
"$src/tests/lint/check_kind_switches.sh" "$src"
mapfile -t files < <(find core platform apps tests bench fuzz firmware -name '*.cpp' -o -name '*.hpp' | sort)
[ ${#files[@]} -gt 10 ] || { echo "lint: found only ${#files[@]} files" >&2; exit 1; }
clang-format --dry-run --Werror "${files[@]}"
echo "lint: clang-format clean on ${#files[@]} files"
mapfile -t tidy < <(find core/src platform/*/src apps -name '*.cpp' | sort)
# GCC-only flags in compile_commands.json (-Wno-restrict) are unknown to clang: ignore them.
out=$(python3 "$src/tests/lint/tidy_cache.py" --source "$src" --build "$build" --jobs "$(nproc)" \
  "${tidy[@]}" -- --quiet --warnings-as-errors='*' --extra-arg=-Wno-unknown-warning-option 2>&1) || {
  printf '%s\n' "$out" | grep -E 'warning:|error:|tidy_cache:' | sort -u >&2
  echo "lint: clang-tidy found problems" >&2
  exit 1
}
# The cache's count, also for scripts/test's closing table.
printf '%s\n' "$out" | grep '^tidy_cache:' | tee "$build/tidy_cache.txt"
echo "lint: clang-tidy clean on ${#tidy[@]} files"
