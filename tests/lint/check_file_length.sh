#!/usr/bin/env bash
# Fails, listing each with its length, where a tracked source file (C and C++, JavaScript, Python,
# shell, CSS, HTML, CMake) is longer than 500 lines: the house rule is one concept per file, named
# for what it holds (docs/architecture.md, "Rules that hold everywhere"), and a file that long
# holds several. A file can be let off for a while by a line of EXCEPTIONS (by default
# tests/lint/file_length_exceptions.txt): its path, then why; lines that start with # are
# comments. An exception for a file that is no longer over the limit, or no longer tracked, fails
# too, so the list only ever shrinks. Only the files git tracks are read, so build directories are
# never counted. Runs in well under a second; lint.sh runs it after check_citations.sh.
# Usage: check_file_length.sh SOURCE_DIR [EXCEPTIONS]
set -euo pipefail
src=${1:?usage: check_file_length.sh SOURCE_DIR [EXCEPTIONS]}
exceptions=${2:-$src/tests/lint/file_length_exceptions.txt}
limit=500
if ! git -C "$src" rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  echo "file length: $src is not a git work tree, so its tracked files are unknown: not checked" >&2
  exit 0
fi

# The exceptions' paths (first word of each line that is neither blank nor a comment).
declare -A excepted=()
if [ -f "$exceptions" ]; then
  while read -r path _; do
    case "$path" in '' | '#'*) continue ;; esac
    excepted[$path]=1
  done <"$exceptions"
fi

cd "$src"
mapfile -d '' -t files < <(git ls-files -z -- '*.cpp' '*.hpp' '*.h' '*.c' '*.js' '*.py' '*.sh' \
  '*.css' '*.html' '*.cmake' '*CMakeLists.txt')
[ ${#files[@]} -gt 0 ] || { echo "file length: no tracked source files in $src" >&2; exit 1; }

# wc prints "LINES PATH" for each file, then a total when it read more than one.
declare -A length=()
while read -r n path; do
  length[$path]=$n
done < <(printf '%s\0' "${files[@]}" | wc -l --files0-from=- | head -n "${#files[@]}")

too_long=()
for path in "${files[@]}"; do
  n=${length[$path]:-0}
  if [ "$n" -gt "$limit" ] && [ -z "${excepted[$path]:-}" ]; then
    too_long+=("$path: $n lines")
  fi
done
stale=()
for path in "${!excepted[@]}"; do
  n=${length[$path]:-}
  if [ -z "$n" ]; then
    stale+=("$path: an exception, but not a tracked source file")
  elif [ "$n" -le "$limit" ]; then
    stale+=("$path: an exception, but $n lines")
  fi
done

if [ ${#too_long[@]} -gt 0 ] || [ ${#stale[@]} -gt 0 ]; then
  [ ${#too_long[@]} -eq 0 ] || printf '%s\n' "${too_long[@]}" | sort
  [ ${#stale[@]} -eq 0 ] || printf '%s\n' "${stale[@]}" | sort
  [ ${#too_long[@]} -eq 0 ] ||
    echo "file length: split the files above along their concepts (at most $limit lines each)" >&2
  [ ${#stale[@]} -eq 0 ] || echo "file length: remove the stale exceptions above from $exceptions" >&2
  exit 1
fi
echo "file length: ${#files[@]} tracked source files of at most $limit lines" \
  "(${#excepted[@]} excepted in $(basename "$exceptions"))"
