#!/usr/bin/env bash
# A short, bounded fuzzing run of the EncoderHub decoder target (fuzz/hub_decoder_fuzz.cpp) from
# a seed corpus this script writes: valid frames of both versions, garbage before a frame, empty
# frames, an overlong run, a truncated frame, an axis error. A libFuzzer build runs for a bounded number of
# executions and seconds; a standalone build (AZT_FUZZ_STANDALONE, any compiler) replays the
# corpus once. Any failed invariant aborts the target and fails this test.
# Usage: fuzz_smoke.sh path/to/hub_decoder_fuzz [RUNS] [SECONDS]
set -uo pipefail
bin=${1:?usage: fuzz_smoke.sh HUB_DECODER_FUZZ [RUNS] [SECONDS]}
bin=$(realpath "$bin")  # the run below changes directory
runs=${2:-200000}
seconds=${3:-20}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/corpus"

# Frames as tests/unit/proto/hub_frame_test.cpp derives them (seed 000 layout, standard COBS).
seed_frame='\x03\xcc\x04\x02\x08\x01\x00'           # az 12 bits 2048, el 12 bits 1024
crc_frame='\x03\xcc\x04\x02\x08\x02\x6c\x00'        # the same with its CRC-8/AUTOSAR byte
sixteen='\x01\x05\x12\x34\xff\xff\x00'              # 16/16 bits: EncBITS nibbles 0
printf '%b' "$seed_frame" >"$tmp/corpus/seed"
printf '%b' "$crc_frame" >"$tmp/corpus/crc8"
printf '%b' "$sixteen$seed_frame$crc_frame" >"$tmp/corpus/three"
printf '%b' "\xde\xad\xbe\xef\x00$seed_frame" >"$tmp/corpus/garbage"
printf '%b' "\x00\x00$crc_frame\x00" >"$tmp/corpus/empty"
head -c 300 /dev/zero | tr '\0' 'Z' >"$tmp/corpus/overlong"
printf '%b' "\x00$seed_frame" >>"$tmp/corpus/overlong"
printf '\x03\xcc\x04\x08\x01\x00\x06\x8c\x04\x01\x08\x01\x00' >"$tmp/corpus/truncated_bad_nibble"
# A CRC-8 frame whose el axis reports error 2 (nibble 1): no angle (a smoke once found it).
printf '\x00\x02\x01\x02\x02\x01\x02\xfc\x00' >"$tmp/corpus/axis_error"

# (Into a file first: with pipefail, grep -q closing the pipe early would fail the pipeline.)
"$bin" -help=1 >"$tmp/help" 2>&1
if grep -q -i libfuzzer "$tmp/help"; then
  # -seed fixes the run; the work directory keeps crash-* files out of the source tree.
  (cd "$tmp" && "$bin" -seed=1 -runs="$runs" -max_total_time="$seconds" -max_len=128 \
    -print_final_stats=1 "$tmp/corpus") >"$tmp/log" 2>&1
  rc=$?
  grep -E 'stat::(number_of_executed_units|average_exec_per_sec)' "$tmp/log"
else
  "$bin" "$tmp"/corpus/* >"$tmp/log" 2>&1
  rc=$?
  cat "$tmp/log"
fi
if [ $rc -ne 0 ]; then
  tail -n 40 "$tmp/log" >&2
  echo "0 passed, 1 failed"
  exit 1
fi
echo "1 passed, 0 failed"
