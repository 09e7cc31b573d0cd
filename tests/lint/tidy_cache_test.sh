#!/usr/bin/env bash
# The clang-tidy cache (tidy_cache.py) on a unit of two files with the project's .clang-tidy: a
# second run takes the unit from the cache; a finding put into the header is caught on that warm
# run (the key follows included content, not the .cpp alone); a corrupt or foreign entry is a
# miss, never a pass; a clone at another path shares the results.
# Usage: tidy_cache_test.sh SOURCE_DIR
set -euo pipefail
src=$(realpath "${1:?usage: tidy_cache_test.sh SOURCE_DIR}")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export AZT_TIDY_CACHE=$work/cache
failures=0
check() {  # check WHAT EXPECTED_STATUS EXPECTED_SUMMARY PROJECT
  local out rc=0
  out=$(cd "$4" && python3 "$src/tests/lint/tidy_cache.py" --source . --build build core/unit.cpp \
    -- --quiet --warnings-as-errors='*' 2>&1) || rc=$?
  if [ "$rc" -eq "$2" ] && grep -q "$3" <<<"$out"; then
    echo "ok: $1"
  else
    echo "FAILED: $1 (exit $rc, wanted $2 and '$3'):"; printf '%s\n' "$out"
    failures=$((failures + 1))
  fi
}
make_project() {  # make_project DIR: core/unit.cpp including core/thing.hpp, and its build
  mkdir -p "$1/core" "$1/build"
  cp "$src/.clang-tidy" "$1/"
  printf '#pragma once\ninline int twice(int value) { return 2 * value; }\n' >"$1/core/thing.hpp"
  printf '#include "thing.hpp"\nint four() { return twice(2); }\n' >"$1/core/unit.cpp"
  # The clone's path also in a flag, without a slash after it (dpkg-buildflags' prefix map).
  printf '[{"directory": "%s", "file": "%s", "command": "c++ -std=c++20 -ffile-prefix-map=%s=. -I%s -o unit.o -c %s"}]\n' \
    "$1/build" "$1/core/unit.cpp" "$1" "$1/core" "$1/core/unit.cpp" >"$1/build/compile_commands.json"
}
entry() { find "$AZT_TIDY_CACHE" -name '*.json' | head -1; }

a=$work/a
make_project "$a"
check "a clean unit runs on a cold cache" 0 "0 from the cache, 1 run, 0 with findings" "$a"
check "and comes from the cache on a warm one" 0 "1 from the cache, 0 run" "$a"
cp "$a/core/thing.hpp" "$work/thing.hpp"
printf 'inline int BadlyNamed(double value) { return (int)value; }\n' >>"$a/core/thing.hpp"
check "a finding added to the header is caught on the warm run" 1 "thing.hpp.*BadlyNamed" "$a"
cp "$work/thing.hpp" "$a/core/thing.hpp"
check "the header restored is clean from the cache again" 0 "1 from the cache" "$a"

head -c 40 "$(entry)" >"$work/cut" && cp "$work/cut" "$(entry)"
check "a truncated entry is a miss" 0 "0 from the cache, 1 run" "$a"
# A well-formed entry with a valid checksum, written for another key, under this unit's name.
python3 - "$(entry)" <<'PY'
import hashlib, json, sys
entry = json.load(open(sys.argv[1]))
body = dict(entry["body"], key="0" * 64)
check = hashlib.sha256(json.dumps(body, sort_keys=True).encode()).hexdigest()
json.dump({"body": body, "check": check}, open(sys.argv[1], "w"))
PY
check "a foreign entry is a miss" 0 "0 from the cache, 1 run" "$a"
sed -i 's/"result": "clean"/"result": "clear"/' "$(entry)"
check "an entry whose checksum does not match is a miss" 0 "0 from the cache, 1 run" "$a"

make_project "$work/b"
check "a clone at another path shares the result" 0 "1 from the cache, 0 run" "$work/b"
echo "tidy_cache_test: $failures failed"
[ "$failures" -eq 0 ]
