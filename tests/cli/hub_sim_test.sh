#!/usr/bin/env bash
# hub-sim | azeltrack hub decode (docs/encoder-hub.md): the real firmware on a simulated ATmega328P,
# its bytes through a pipe into the daemon's decoder, as `hub-sim … --seconds 1 | azeltrack hub
# decode` is documented to print the positions given; then through a pseudo-terminal, as a hub
# on a serial port is read.
# Usage: hub_sim_test.sh path/to/azeltrack path/to/hub-sim path/to/encoder-hub.elf
set -uo pipefail
bin=${1:?usage: hub_sim_test.sh AZELTRACK HUB_SIM ELF}
sim=${2:?}
elf=${3:?}
py=/usr/bin/python3
root=$(cd "$(dirname "$0")/../.." && pwd)
tmp=$(mktemp -d)
pids=()
trap 'kill "${pids[@]}" 2>/dev/null; rm -rf "$tmp"' EXIT
# shellcheck source=lib.sh
source "$(dirname "$0")/lib.sh"

# check DESCRIPTION PYTHON_EXPR FILE: `j` is the decoder's JSON lines, `f` the frames among them.
check() {
  if "$py" -c "import json,sys; j=[json.loads(l) for l in open(sys.argv[1])]; f=[x for x in j if 'version' in x]; sys.exit(0 if ($2) else 1)" "$3"; then
    ok
  else
    bad "$1: $2 is false for $(head -c 400 "$3")"
  fi
}

# AS5045-class on both axes (no jumpers): 1024 and 512 of 4096 are 90° and 45°.
"$sim" --elf "$elf" --az-raw 1024 --el-raw 512 --seconds 1 | "$bin" hub decode >"$tmp/a.json"
check "one second of frames" "len(f) >= 48" "$tmp/a.json"
check "90° and 45°, every frame" "all(x['az_deg'] == 90.0 and x['el_deg'] == 45.0 for x in f)" "$tmp/a.json"
check "nothing rejected" "j[-1]['counters']['rejected'] == 0" "$tmp/a.json"

# Generic SSI, 16-bit Gray and 9-bit binary, at their largest counts.
"$sim" --elf "$elf" --az-code gray --az-bits 16 --az-raw 65535 --el-code binary --el-bits 9 \
  --el-raw 511 --seconds 0.2 | "$bin" hub decode >"$tmp/b.json"
check "16-bit Gray and 9-bit binary" "f and all(x['az_raw'] == 65535 and x['az_bits'] == 16 and x['el_raw'] == 511 and x['el_bits'] == 9 for x in f)" "$tmp/b.json"

# A disconnected encoder: no angle for that axis, the reason instead, the other axis intact.
"$sim" --elf "$elf" --az-raw 1024 --el-raw 512 --fault open --fault-axis el --seconds 0.2 |
  "$bin" hub decode >"$tmp/c.json"
check "open encoder reported" "f and all(x['el_deg'] is None and x['el_error'] == 'no encoder answers' and x['az_deg'] == 90.0 for x in f)" "$tmp/c.json"

# Bad arguments are one-line usage errors.
"$sim" --elf "$tmp/nothing.elf" --az-raw 1 --el-raw 1 --seconds 0.1 >/dev/null 2>"$tmp/err"
[ $? -eq 2 ] && grep -q "nothing.elf" "$tmp/err" && ok || bad "a missing ELF: $(cat "$tmp/err")"
"$sim" --elf "$elf" --az-code gray --az-bits 9 --az-raw 512 --el-raw 1 >/dev/null 2>"$tmp/err"
[ $? -eq 2 ] && ok || bad "a count past 2^bits: $(cat "$tmp/err")"

# Through a pseudo-terminal, in real time, read as a serial port is.
"$sim" --elf "$elf" --az-raw 2048 --el-raw 1024 --seconds 8 --pty "$tmp/hub" &
pids+=($!)
for _ in $(seq 50); do [ -e "$tmp/hub" ] && break; sleep 0.1; done
timeout 4 "$bin" hub decode --await-delimiter <"$tmp/hub" >"$tmp/d.json" 2>/dev/null
check "frames from the pty" "len(f) >= 5 and all(x['az_deg'] == 180.0 and x['el_deg'] == 90.0 for x in f)" "$tmp/d.json"

# The firmware in the loop of the daemon: [sim] hub = "firmware" reads the simulated antenna
# through the ELF beside the program (build/firmware/), and rotctld reports its angles.
port=$("$py" -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])')
cat >"$tmp/fw.toml" <<TOML
schema_version = 2
[station]
grid = "FN06HE"
[target]
name = "stop"
[rotctld]
port = $port
[pstrotator]
port = 0
[web]
port = 0
[sim]
hub = "firmware"
[sim.az]
start_deg = 100.0
[sim.el]
start_deg = 20.0
TOML
"$bin" serve --config "$tmp/fw.toml" --run-for 6 >"$tmp/fw.log" 2>&1 &
pids+=($!)
# Until the daemon answers with a position (it has none before the first frames): at most 5 s.
got=""
for _ in $(seq 50); do
  got=$(rotctl -m 2 -r "127.0.0.1:$port" p 2>/dev/null | tr '\n' ' ')
  [[ "$got" =~ ^-?[0-9.]+\ -?[0-9.]+ ]] && break
  sleep 0.1
done
grep -q "read by the EncoderHub firmware" "$tmp/fw.log" && ok || bad "serve did not say it reads the firmware: $(cat "$tmp/fw.log")"
"$py" -c "import sys; a, e = map(float, sys.argv[1].split()[:2]); sys.exit(0 if abs(a - 100) < 0.1 and abs(e - 20) < 0.1 else 1)" "$got" &&
  ok || bad "rotctld through the firmware: '$got'"

# azeltrack simulate with the firmware in the loop: the same slew and Moon as the plain model,
# 50 frames a second from the AVR, the same accuracy within an encoder step (360/4096°).
sed 's/^hub = "model"/hub = "firmware"/' "$root/examples/sim.toml" >"$tmp/simfw.toml"
for kind in model firmware; do
  cfg="$root/examples/sim.toml"
  [ "$kind" = firmware ] && cfg="$tmp/simfw.toml"
  "$bin" simulate --config "$cfg" --scenario slew --to-az 300 --to-el 30 --json >"$tmp/slew-$kind.json" ||
    bad "simulate slew ($kind) failed"
  "$bin" simulate --config "$cfg" --scenario moon --from 2025-03-14T02:00:00Z --hours 0.1 --json \
    >"$tmp/moon-$kind.json" || bad "simulate moon ($kind) failed"
done
compare() {
  "$py" - "$tmp/$1-model.json" "$tmp/$1-firmware.json" "$2" <<'PY' && ok || bad "simulate $1 with the firmware: $(cat "$tmp/$1-firmware.json")"
import json, sys
m, f = (json.load(open(p)) for p in sys.argv[1:3])
sys.exit(0 if eval(sys.argv[3]) else 1)
PY
}
compare slew "f['hub']['kind'] == 'firmware' and m['hub']['kind'] == 'model' and f['faults'] == [] and f['slew_time_s'] is not None and abs(f['slew_time_s'] - m['slew_time_s']) < 1.0"
compare moon "f['faults'] == [] and f['hub']['rejected'] == 0 and f['hub']['frames_ok'] >= 0.1*3600*49.9 and f['max_error_deg'] <= m['max_error_deg'] + 360/4096"

finish
