#!/usr/bin/env bash
# `azeltrack seq-sim`: the configured chain's transitions in virtual time, checked from outside.
# Usage: seq_sim_test.sh path/to/azeltrack
set -uo pipefail
bin=$(realpath "${1:?usage: seq_sim_test.sh AZELTRACK}")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
source "$(dirname "$0")/lib.sh"

printf '[station]\ngrid = "FN06HE"\n[sequencer]\noutputs = ["preamp", "trx_relay", "amplifier", "radio"]\ndelays_ms = [20, 30, 40]\ndebounce_ms = 5\ntx_timeout_s = 2\n' >"$tmp/a.toml"
"$bin" seq-sim --config "$tmp/a.toml" --ptt "0:down,1000:up,1100:down,4000:up" --json >"$tmp/out" 2>"$tmp/err" || bad "seq-sim failed: $(cat "$tmp/err")"
python3 - "$tmp/out" <<'PY' && ok || bad "seq-sim transitions: $(cat "$tmp/out")"
import json, sys
rows = [json.loads(l) for l in open(sys.argv[1])]
got = [(r["t_ms"], r["line"], r["state"]) for r in rows]
want = [(5, "preamp", "on"), (25, "trx_relay", "on"), (55, "amplifier", "on"), (95, "radio", "on"),
        (1005, "radio", "off"), (1045, "amplifier", "off"), (1075, "trx_relay", "off"),
        (1095, "preamp", "off"),
        (1105, "preamp", "on"), (1125, "trx_relay", "on"), (1155, "amplifier", "on"),
        (1195, "radio", "on"),
        # the 2 s time-out, counted from the debounced press at 1105
        (3105, "radio", "off"), (3145, "amplifier", "off"), (3175, "trx_relay", "off"),
        (3195, "preamp", "off")]
sys.exit(0 if got == want else 1)
PY
printf '[station]\ngrid = "FN06HE"\n[sequencer]\ntx_timeout_s = 0\n' >"$tmp/off.toml"
expect_usage_error "time-out off" seq-sim --config "$tmp/off.toml" --ptt 0:down
grep -q 'tx_timeout_s' "$tmp/err" && ok || bad "error does not name the key: $(cat "$tmp/err")"
expect_usage_error "bad ptt" seq-sim --config "$tmp/a.toml" --ptt "0:pressed"
expect_usage_error "times going back" seq-sim --config "$tmp/a.toml" --ptt "10:down,5:up"
finish
