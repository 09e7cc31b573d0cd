#!/usr/bin/env bash
# `azeltrack hub` as scripts meet it: encode -> decode round trips through a pipe (binary and
# --hex), garbage before a frame, rejection counters, exit codes and one-line errors.
# Usage: hub_cli_test.sh path/to/azeltrack
set -uo pipefail
bin=${1:?usage: hub_cli_test.sh AZELTRACK}
py=/usr/bin/python3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# shellcheck source=lib.sh
source "$(dirname "$0")/lib.sh"

# expect_text DESCRIPTION EXPECTED ARGS...: stdout is exactly EXPECTED (one line), exit 0.
expect_text() {
  local what=$1 expected=$2; shift 2
  local got
  if got=$("$bin" "$@" 2>"$tmp/err") && [ "$got" = "$expected" ]; then
    ok
  else
    bad "$what: got '$got', expected '$expected' $(cat "$tmp/err")"
  fi
}

# lines_check DESCRIPTION PYTHON_EXPR FILE: `j` is the list of JSON objects, one per line of FILE.
lines_check() {
  local what=$1 expr=$2 file=$3
  if "$py" -c "import json,sys; j=[json.loads(l) for l in open(sys.argv[1])]; sys.exit(0 if ($expr) else 1)" "$file"; then
    ok
  else
    bad "$what: $expr is false for $(head -c 600 "$file")"
  fi
}

# Frames worked out by hand in tests/unit/proto/hub_frame_test.cpp (seed 000 layout, standard COBS).
expect_text "seed frame, 12/12 bits" "03 cc 04 02 08 01 00" \
  hub encode --az-bits 12 --el-bits 12 --az-raw 2048 --el-raw 1024
expect_text "crc frame, 12/12 bits" "03 cc 04 02 08 02 6c 00" \
  hub encode --az-bits 12 --el-bits 12 --az-raw 2048 --el-raw 1024 --crc
expect_text "16 bits as nibble 0, hex raw" "01 05 12 34 ff ff 00" \
  hub encode --az-bits 16 --el-bits 16 --az-raw 0xffff --el-raw 0x1234

# Round trip through a pipe, as bytes.
if "$bin" hub encode --az-bits 16 --el-bits 9 --az-raw 65535 --el-raw 511 >"$tmp/hex" &&
   xxd -r -p "$tmp/hex" | "$bin" hub decode >"$tmp/out" 2>"$tmp/err"; then
  lines_check "binary round trip" \
    "len(j)==2 and j[0]['az_raw']==65535 and j[0]['az_bits']==16 and j[0]['el_raw']==511 and j[0]['el_bits']==9 and j[0]['version']=='seed' and abs(j[0]['az_deg']-(360-360/65536))<1e-12 and j[1]['counters']['frames_seed']==1 and j[1]['counters']['rejected']==0" \
    "$tmp/out"
else
  bad "binary round trip: $(cat "$tmp/err")"
fi

# Round trip of many readings, CRC version, as hex text; --accept crc8.
: >"$tmp/stream"
for r in "9 9 0 0" "9 16 511 65535" "12 12 2048 1024" "15 13 32767 8191" "16 16 0 0" "10 11 1 2"; do
  read -r az_bits el_bits az_raw el_raw <<<"$r"
  "$bin" hub encode --az-bits "$az_bits" --el-bits "$el_bits" --az-raw "$az_raw" --el-raw "$el_raw" \
    --crc >>"$tmp/stream" || bad "encode $r"
done
if "$bin" hub decode --hex --accept crc8 <"$tmp/stream" >"$tmp/out" 2>"$tmp/err"; then
  lines_check "hex round trip, six CRC frames" \
    "len(j)==7 and [(f['az_bits'],f['el_bits'],f['az_raw'],f['el_raw']) for f in j[:6]]==[(9,9,0,0),(9,16,511,65535),(12,12,2048,1024),(15,13,32767,8191),(16,16,0,0),(10,11,1,2)] and all(f['version']=='crc8' for f in j[:6]) and j[2]['az_deg']==180.0 and j[2]['el_deg']==90.0 and j[6]['counters']['frames_crc8']==6" \
    "$tmp/out"
else
  bad "hex round trip: $(cat "$tmp/err")"
fi

# Garbage, a delimiter, a valid frame; garbage glued to a frame costs that frame only.
{ printf 'de ad be ef 00\n'; "$bin" hub encode --az-bits 12 --el-bits 12 --az-raw 1 --el-raw 2;
  printf '42 42 '; "$bin" hub encode --az-bits 12 --el-bits 12 --az-raw 3 --el-raw 4;
  "$bin" hub encode --az-bits 12 --el-bits 12 --az-raw 5 --el-raw 6; } >"$tmp/garbage"
if "$bin" hub decode --hex <"$tmp/garbage" >"$tmp/out" 2>"$tmp/err"; then
  lines_check "garbage then frames" \
    "len(j)==3 and j[0]['az_raw']==1 and j[1]['az_raw']==5 and j[2]['counters']['wrong_length']==1 and j[2]['counters']['rejected']==2 and j[2]['counters']['frames_seed']==2" \
    "$tmp/out"
else
  bad "garbage then frames: $(cat "$tmp/err")"
fi

# A live stream joined mid-frame: --await-delimiter drops the partial first frame.
printf '\x04\x02\x08\x01\x00\x03\xcc\x04\x02\x08\x01\x00' | "$bin" hub decode --await-delimiter >"$tmp/out" 2>"$tmp/err"
lines_check "await delimiter" "len(j)==2 and j[1]['counters']['unsynced']==1 and j[1]['counters']['frames_seed']==1" "$tmp/out"

# A seed frame on a crc8-only decoder, a bad CRC, an unterminated tail.
printf '03 cc 04 02 08 01 00  03 cc 04 02 08 02 6d 00  03 cc\n' |
  "$bin" hub decode --hex --accept crc8 >"$tmp/out" 2>"$tmp/err"
lines_check "rejection counters" \
  "len(j)==1 and j[0]['counters']['wrong_version']==1 and j[0]['counters']['bad_crc']==1 and j[0]['counters']['rejected']==2 and j[0]['trailing_bytes']==2" \
  "$tmp/out"
# Azimuth nibble 8; elevation 512 at 9 bits.
printf '06 8c 04 01 08 01 00 03 99 02 02 02 01 00\n' | "$bin" hub decode --hex >"$tmp/out" 2>"$tmp/err"
lines_check "bad nibble, out of range" \
  "len(j)==1 and j[0]['counters']['bad_nibble']==1 and j[0]['counters']['out_of_range']==1" "$tmp/out"

expect_usage_error "bits below 9" hub encode --az-bits 8 --el-bits 12 --az-raw 0 --el-raw 0
expect_usage_error "bits above 16" hub encode --az-bits 12 --el-bits 17 --az-raw 0 --el-raw 0
expect_usage_error "raw too large for its bits" hub encode --az-bits 12 --el-bits 12 --az-raw 4096 --el-raw 0
expect_usage_error "negative raw" hub encode --az-bits 12 --el-bits 12 --az-raw -1 --el-raw 0
expect_usage_error "fractional raw" hub encode --az-bits 12 --el-bits 12 --az-raw 1.5 --el-raw 0
expect_usage_error "raw beyond 16 bits" hub encode --az-bits 16 --el-bits 12 --az-raw 65536 --el-raw 0
expect_usage_error "missing raw" hub encode --az-bits 12 --el-bits 12 --az-raw 1
expect_usage_error "unknown accept" hub decode --accept all
expect_usage_error "no hub subcommand" hub

# Malformed hex input is a failure of the run (exit 1), still one line on stderr.
printf '03 cz\n' | "$bin" hub decode --hex >"$tmp/out" 2>"$tmp/err"
rc=$?
if [ $rc -eq 1 ] && [ "$(wc -l <"$tmp/err")" -eq 1 ]; then ok; else bad "bad hex: rc=$rc $(cat "$tmp/err")"; fi

finish
