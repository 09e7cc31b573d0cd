#!/usr/bin/env bash
# A short, bounded run of one fuzz target from a seed corpus (fuzz/corpus/<target>/). A libFuzzer
# build (clang, the fuzz preset) runs for at most RUNS executions and SECONDS seconds on a copy of
# the seeds, so new inputs never land in the source tree; a standalone build (AZT_FUZZ_STANDALONE,
# any compiler) replays each seed once, one per process. Any failed invariant aborts the target
# and fails this test; the failing input is printed as hex and kept in the work directory, which
# is then left in place.
# Usage: fuzz_run.sh BIN RUNS SECONDS [SEED_DIR]
set -uo pipefail
usage="usage: fuzz_run.sh BIN RUNS SECONDS [SEED_DIR]"
bin=${1:?$usage}
runs=${2:?$usage}
seconds=${3:?$usage}
seeds=${4:-}
[ -x "$bin" ] || { echo "fuzz_run: no executable $bin" >&2; exit 1; }
bin=$(realpath "$bin")  # the run below changes directory
tmp=$(mktemp -d)
mkdir -p "$tmp/corpus"
if [ -n "$seeds" ]; then
  [ -d "$seeds" ] || { echo "fuzz_run: no seed directory $seeds" >&2; exit 1; }
  cp "$seeds"/* "$tmp/corpus/" 2>/dev/null || true
fi
name=$(basename "$bin")

# (Into a file first: with pipefail, grep -q closing the pipe early would fail the pipeline.)
"$bin" -help=1 >"$tmp/help" 2>&1
if grep -q -i libfuzzer "$tmp/help"; then
  # -seed fixes the run; inputs up to 1 KiB reach past every line and datagram bound.
  (cd "$tmp" && "$bin" -seed=1 -runs="$runs" -max_total_time="$seconds" -max_len=1024 \
    -timeout=10 -artifact_prefix="$tmp/" -print_final_stats=1 "$tmp/corpus") >"$tmp/log" 2>&1
  rc=$?
  grep -E 'stat::(number_of_executed_units|average_exec_per_sec)' "$tmp/log" |
    sed "s/^/$name: /"
else
  shopt -s nullglob
  files=("$tmp"/corpus/*)
  if [ ${#files[@]} -eq 0 ]; then
    echo "fuzz_run: a standalone build replays seeds: give a non-empty SEED_DIR" >&2
    rm -rf "$tmp"
    exit 1
  fi
  # One input per run, so a failure names its input.
  rc=0
  for file in "${files[@]}"; do
    if ! "$bin" "$file" >>"$tmp/log" 2>&1; then
      rc=1
      cp "$file" "$tmp/crash-$(basename "$file")"
    fi
  done
  echo "$name: replayed ${#files[@]} seeds"
fi
if [ $rc -ne 0 ]; then
  tail -n 40 "$tmp/log" >&2
  for crash in "$tmp"/crash-* "$tmp"/leak-* "$tmp"/timeout-* "$tmp"/oom-*; do
    [ -f "$crash" ] || continue
    echo "fuzz_run: $name failed on $crash:" >&2
    od -A d -t x1z -v "$crash" | head -n 40 >&2
  done
  echo "fuzz_run: work directory kept: $tmp" >&2
  echo "0 passed, 1 failed"
  exit 1
fi
rm -rf "$tmp"
echo "1 passed, 0 failed"
