#!/usr/bin/env bash
# `azeltrack config check|get|set`, and the kill -9 loop of the reliability plan (R23): a `config
# set` killed at a random moment (200 times) never leaves a configuration that fails to load or
# holds anything but the old or the new value.
# Usage: config_cli_test.sh path/to/azeltrack [ITERATIONS]
set -uo pipefail
bin=$(realpath "${1:?usage: config_cli_test.sh AZELTRACK [ITERATIONS]}")
iterations=${2:-200}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
source "$(dirname "$0")/lib.sh"
src=$(cd "$(dirname "$0")/../.." && pwd)
cfg="$tmp/azeltrack.toml"
cp "$src/examples/sim.toml" "$cfg"

"$bin" config check --config "$cfg" >"$tmp/out" 2>"$tmp/err" && grep -q valid "$tmp/out" && ok ||
  bad "check: $(cat "$tmp/err")"
[ "$("$bin" config get --config "$cfg" control.window_deg)" = "0.1" ] && ok || bad "get window_deg"
[ "$("$bin" config get --config "$cfg" park.2.name)" = '"stow"' ] && ok || bad "get park.2.name"
"$bin" config set --config "$cfg" target.name '"sun"' && ok || bad "set target.name"
[ "$("$bin" config get --config "$cfg" target.name)" = '"sun"' ] && ok || bad "target not saved"
grep -q '^name = "moon"' "$cfg.bak" && ok || bad "no .bak with the previous target"

# Refusals: exit 2, one line naming the key, file unchanged.
before=$(cat "$cfg")
expect_usage_error "window out of range" config set --config "$cfg" control.window_deg 3.0
grep -q 'window_deg' "$tmp/err" && ok || bad "error does not name the key: $(cat "$tmp/err")"
expect_usage_error "unknown key" config set --config "$cfg" control.speed 1
expect_usage_error "not TOML" config set --config "$cfg" target.name sun
expect_usage_error "grid contradicts lat/lon" config set --config "$cfg" station.grid '"JO65"' 
expect_usage_error "missing key" config get --config "$cfg" control.nothing
expect_usage_error "no such file" config check --config "$tmp/none.toml"
[ "$(cat "$cfg")" = "$before" ] && ok || bad "a refused change altered the file"

# A corrupt primary: check falls back to the backup and says so loudly.
cp "$cfg" "$tmp/good"
head -c 100 "$tmp/good" >"$cfg"
printf '\n[[[\n' >>"$cfg"
"$bin" config check --config "$cfg" >/dev/null 2>"$tmp/err" && grep -q 'using backup' "$tmp/err" &&
  ok || bad "corrupt primary: $(cat "$tmp/err")"
cp "$tmp/good" "$cfg"
rm -f "$cfg.bak"

# The kill -9 loop: alternate two values; kill each writer after a random 0–9 ms (a save takes ~5 ms).
old=0.1
"$bin" config set --config "$cfg" control.window_deg "$old"
torn=0
kept_old=0
took_new=0
for i in $(seq "$iterations"); do
  if [ $((i % 2)) -eq 0 ]; then new=0.1; else new=0.2; fi
  "$bin" config set --config "$cfg" control.window_deg "$new" 2>/dev/null &
  writer=$!
  sleep "0.00$((RANDOM % 10))"
  kill -9 "$writer" 2>/dev/null
  wait "$writer" 2>/dev/null
  got=$("$bin" config get --config "$cfg" control.window_deg 2>"$tmp/err")
  if [ $? -ne 0 ] || { [ "$got" != "$old" ] && [ "$got" != "$new" ]; } || [ -s "$tmp/err" ]; then
    torn=$((torn + 1))
    echo "iteration $i: got '$got' (old $old, new $new): $(cat "$tmp/err")" >&2
  fi
  if [ "$got" = "$new" ]; then took_new=$((took_new + 1)); else kept_old=$((kept_old + 1)); fi
  old=$got
  rm -f "$cfg".tmp.* "$cfg".bak.tmp.*  # a killed writer's temp files are expected debris
done
[ "$torn" -eq 0 ] && ok || bad "$torn of $iterations loads after kill -9 were torn or failed"
# The kills must land on both sides of the rename, or the loop proved nothing.
[ "$kept_old" -gt 0 ] && [ "$took_new" -gt 0 ] && ok ||
  bad "kills never split the save: $kept_old kept the old value, $took_new the new"
echo "config kill -9 loop: $iterations iterations, $torn bad loads," \
  "$kept_old killed before the rename, $took_new after"
finish
