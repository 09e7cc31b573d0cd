#!/usr/bin/env bash
# azeltrack serve driven by real programs: Hamlib's rotctl over TCP (-m 2) and over the daemon's
# pseudo-terminals (-m 603 GS-232B, -m 601 GS-232A, -m 202 EasyComm II, -m 901 SPID Rot2Prog),
# a PstRotator UDP client, and the hamlib backend driving Debian's `rotctld -m 1`. Every move is
# checked on the simulated antenna's read-back position, polled with a deadline (no fixed sleeps).
# Usage: daemon_clients_test.sh path/to/azeltrack
set -uo pipefail
bin=$(realpath "${1:?usage: daemon_clients_test.sh AZELTRACK}")
tmp=$(mktemp -d)
pids=()
cleanup() {
  for p in "${pids[@]}"; do kill "$p" 2>/dev/null; done
  wait 2>/dev/null
  if [ -n "${KEEP_TMP:-}" ]; then echo "kept $tmp" >&2; else rm -rf "$tmp"; fi
}
trap cleanup EXIT
source "$(dirname "$0")/../cli/lib.sh"

free_port() {
  python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])'
}

# A fast simulated antenna (20°/s) so that moves take seconds; ptys in the scratch directory.
write_config() {  # write_config FILE RPORT UPORT [extra toml]
  cat >"$1" <<TOML
schema_version = 2
[station]
grid = "FN06HE"
[control]
window_deg = 0.1
[geometry]
az_min_deg = 0.0
az_max_deg = 450.0
el_min_deg = 0.0
el_max_deg = 90.0
[mount.az]
max_rate_deg_s = 20.0
[mount.el]
max_rate_deg_s = 20.0
[sim.az]
start_deg = 180.0
[sim.el]
start_deg = 10.0
[target]
name = "stop"
[rotctld]
port = $2
[pstrotator]
port = $3
reply_port = $(( $3 + 1 ))
[web]
port = 0
${4:-}
TOML
}

start_daemon() {  # start_daemon CONFIG LOG PORT: waits (≤ 10 s) until rotctld answers
  "$bin" serve --config "$1" >"$2" 2>&1 &
  daemon_pid=$!
  pids+=("$daemon_pid")
  for _ in $(seq 100); do
    # ready when the position is known (the first hub frame arrives with the first tick)
    if rotctl -m 2 -r "127.0.0.1:$3" p >/dev/null 2>&1; then return 0; fi
    kill -0 "$daemon_pid" 2>/dev/null || break
    sleep 0.1
  done
  bad "daemon did not start: $(cat "$2")"
  return 1
}

# send_lines PORT: stdin to the daemon's rotctld, half-close, print everything it answers.
send_lines() {
  timeout 5 python3 -c '
import socket, sys
s = socket.create_connection(("127.0.0.1", int(sys.argv[1])), timeout=4)
s.sendall(sys.stdin.buffer.read()); s.shutdown(socket.SHUT_WR)
while True:
    data = s.recv(4096)
    if not data: break
    sys.stdout.buffer.write(data)
' "$1"
}

position() { rotctl -m 2 -r "127.0.0.1:$1" p 2>/dev/null | tr '\n' ' '; }

# wait_at PORT AZ EL TOL: polls the read-back position (≤ 30 s) until within TOL on both axes.
wait_at() {
  local pos
  for _ in $(seq 150); do
    pos=$(position "$1")
    if python3 - "$2" "$3" "$4" $pos <<'PY'; then return 0; fi
import sys
az, el, tol = map(float, sys.argv[1:4])
try:
    a, e = float(sys.argv[4]), float(sys.argv[5])
except (IndexError, ValueError):
    sys.exit(1)
d = abs((a - az + 180) % 360 - 180)
sys.exit(0 if d <= tol and abs(e - el) <= tol else 1)
PY
    sleep 0.2
  done
  echo "  last position: $pos (wanted $2 $3 ± $4)" >&2
  return 1
}

rport=$(free_port)
uport=$(free_port)
write_config "$tmp/a.toml" "$rport" "$uport" "
[[serial]]
protocol = \"gs232b\"
device = \"pty:$tmp/pty/gs232b\"
[[serial]]
protocol = \"gs232a\"
device = \"pty:$tmp/pty/gs232a\"
[[serial]]
protocol = \"easycomm2\"
device = \"pty:$tmp/pty/easycomm2\"
[[serial]]
protocol = \"spid\"
device = \"pty:$tmp/pty/spid\"
baud = 600
"
start_daemon "$tmp/a.toml" "$tmp/a.log" "$rport" || { finish; exit 1; }

# 1. rotctl -m 2: 100 set/get round trips in one connection, all answered.
args=()
for i in $(seq 0 99); do args+=(P "$((100 + i % 50)).5" "$((10 + i % 30)),25" p); done
if out=$(rotctl -m 2 -r "127.0.0.1:$rport" "${args[@]}" 2>&1); then
  n=$(grep -cE '^-?[0-9]+\.[0-9]{2}$' <<<"$out")
  [ "$n" -eq 200 ] && ok || bad "rotctl -m 2: $n of 200 position lines"
else
  bad "rotctl -m 2 set/get failed: $(tail -3 <<<"$out")"
fi
wait_at "$rport" 149.5 19.25 0.3 && ok || bad "rotctl -m 2: antenna did not reach 149.5/19.25"

# \dump_state as netrotctl reads it: protocol version 1, model 1, then the travel.
dump=$(printf '\\dump_state\n' | send_lines "$rport")
[ "$(sed -n 1p <<<"$dump")" = "1" ] && grep -q '^min_az=-180' <<<"$dump" && ok ||
  bad "dump_state: $dump"

# get_info as rotctl shows it (63 characters): the station's 6-character locator is not cut.
info=$(rotctl -m 2 -r "127.0.0.1:$rport" _ 2>&1)
grep -Eq '^azeltrack [^ ]+ at [A-R]{2}[0-9]{2}[a-x]{2}: ' <<<"$info" && ok || bad "get_info: $info"

# Strictness: trailing junk, NaN and out-of-range targets are RPRT -1 and move nothing.
for line in 'P 10 10 junk' 'P nan 10' 'P 500 10' 'P 10 95'; do
  reply=$(printf '%s\n' "$line" | send_lines "$rport")
  [ "$reply" = "RPRT -1" ] && ok || bad "'$line' answered '$reply'"
done
reply=$(printf 'X 1\n' | send_lines "$rport")
[ "$reply" = "RPRT -4" ] && ok || bad "unknown command answered '$reply'"

# 2. Serial protocols through Hamlib's own backends on the pseudo-terminals.
serial_move() {  # serial_move MODEL PTY AZ EL TOL [rotctl options]
  local model=$1 pty=$2 az=$3 el=$4 tol=$5; shift 5
  if ! timeout 20 rotctl -m "$model" -r "$pty" "$@" P "$az" "$el" >"$tmp/r.out" 2>&1; then
    bad "rotctl -m $model P $az $el: $(tail -2 "$tmp/r.out")"
    return
  fi
  wait_at "$rport" "$az" "$el" "$tol" && ok || bad "rotctl -m $model: antenna not at $az $el"
  # and its own read-back agrees
  local got
  got=$(timeout 20 rotctl -m "$model" -r "$pty" "$@" p 2>/dev/null | tr '\n' ' ')
  python3 -c "import sys; a,e=map(float,'$got'.split()[:2]); sys.exit(0 if abs(a-$az)<=$tol+1 and abs(e-$el)<=$tol+1 else 1)" \
    && ok || bad "rotctl -m $model p read '$got', wanted $az $el"
}
serial_move 603 "$tmp/pty/gs232b" 200 30 1.0
serial_move 601 "$tmp/pty/gs232a" 170 20 1.0
serial_move 202 "$tmp/pty/easycomm2" 123.4 45.6 0.3
serial_move 901 "$tmp/pty/spid" 210.5 15.5 0.6 -s 600

# One daemon per pty name: a second daemon (other ports) naming the same link refuses to start,
# naming the first one's pid, and the first one's link still leads to it.
write_config "$tmp/second.toml" "$(free_port)" 0 "
[[serial]]
protocol = \"gs232b\"
device = \"pty:$tmp/pty/gs232b\""
"$bin" serve --config "$tmp/second.toml" </dev/null >"$tmp/out" 2>"$tmp/err"
rc=$?
[ $rc -eq 2 ] && tail -1 "$tmp/err" | grep -q "in use by another azeltrack daemon (pid $daemon_pid)" &&
  ok || bad "second daemon: rc=$rc, $(cat "$tmp/err")"
serial_move 603 "$tmp/pty/gs232b" 190 25 1.0

# 3. PstRotator UDP: a target, then the AZ?/EL? replies on port+1.
pst=$(python3 - "$uport" <<'PY'
import socket, sys, time
port = int(sys.argv[1])
rx = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
rx.bind(("127.0.0.1", port + 1)); rx.settimeout(2.0)
tx = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
tx.sendto(b"<PST><AZIMUTH>140.000000.2</AZIMUTH><ELEVATION>25</ELEVATION></PST>", ("127.0.0.1", port))
time.sleep(0.2)
tx.sendto(b"<PST>AZ?</PST>", ("127.0.0.1", port))
try:
    print(rx.recv(100).decode().strip())
except OSError as e:
    print("no reply:", e)
PY
)
grep -qE '^AZ:[0-9]+\.[0-9]$' <<<"$pst" && ok || bad "PstRotator AZ? reply: '$pst'"
wait_at "$rport" 140 25 0.3 && ok || bad "PstRotator target not reached"

# 4. A continuous move stops by itself when its client falls silent (R11: ≤ 1 s + one tick).
exec 3<>"/dev/tcp/127.0.0.1/$rport"
printf 'M 16 50\n' >&3
read -r -t 2 reply <&3
[ "$reply" = "RPRT 0" ] && ok || bad "M answered '$reply'"
sleep 0.5  # moving now; then silence (the connection stays open)
python3 - "$rport" <<'PY' && ok || bad "continuous move did not stop after 1 s of silence"
import socket, sys, time
def pos():
    s = socket.create_connection(("127.0.0.1", int(sys.argv[1])))
    s.sendall(b"p\n"); data = b""
    while data.count(b"\n") < 2: data += s.recv(100)
    s.close(); return float(data.split()[0])
# the dead-man fires 1 s after the M; allow the soft stop (ramp 1 s at 20 deg/s) to settle
time.sleep(2.5)
a = pos(); time.sleep(1.0); b = pos()
sys.exit(0 if abs(((b - a + 180) % 360) - 180) < 0.2 else 1)
PY
exec 3<&-

# 5. SIGTERM: motors stopped, exit 0, pseudo-terminal links removed.
kill -TERM "$daemon_pid"
wait "$daemon_pid"
rc=$?
[ $rc -eq 0 ] && ok || bad "exit code after SIGTERM: $rc"
grep -q 'motors stopped' "$tmp/a.log" && ok || bad "no 'motors stopped' in the log"
[ ! -e "$tmp/pty/gs232b" ] && ok || bad "pty link left behind"

# 6. The hamlib backend drives Debian's rotctld -m 1 (the dummy rotator).
hport=$(free_port)
rotctld -m 1 -T 127.0.0.1 -t "$hport" >/dev/null 2>&1 &
pids+=($!)
for _ in $(seq 50); do rotctl -m 2 -r "127.0.0.1:$hport" _ >/dev/null 2>&1 && break; sleep 0.1; done
rport2=$(free_port)
write_config "$tmp/h.toml" "$rport2" 0 "
[antenna]
backend = \"hamlib\"
[hamlib]
model = 2
device = \"127.0.0.1:$hport\"
poll_s = 0.1
"
start_daemon "$tmp/h.toml" "$tmp/h.log" "$rport2" && {
  rotctl -m 2 -r "127.0.0.1:$rport2" P 20 10 >/dev/null 2>&1 && ok || bad "P to the hamlib daemon"
  wait_at "$hport" 20 10 0.5 && ok || bad "rotctld -m 1 was not driven to 20/10"
  wait_at "$rport2" 20 10 0.5 && ok || bad "daemon did not read the hamlib rotator back"
  kill -TERM "$daemon_pid"; wait "$daemon_pid"
}

# 7. Refusing to start, with the reason: a port in use, a bad key (named with its line).
write_config "$tmp/busy.toml" "$hport" 0
expect_usage_error "rotctld port in use" serve --config "$tmp/busy.toml"
grep -q "rotctld" "$tmp/err" && ok || bad "port-in-use error does not name rotctld: $(cat "$tmp/err")"
write_config "$tmp/bad.toml" "$rport" 0 "
[[serial]]
protocol = \"gs232c\"
device = \"pty:$tmp/x\""
expect_usage_error "unknown serial protocol" serve --config "$tmp/bad.toml"
grep -q 'line [0-9]*: \[serial#1\].protocol' "$tmp/err" && ok ||
  bad "error does not name the key and line: $(cat "$tmp/err")"
# A GPIO chip that does not exist (none on a build machine): the libgpiod adapter's error names
# the key and the chip, and nothing starts.
write_config "$tmp/nogpio.toml" "$rport" 0 "
[gpio]
chip = \"gpiochip-azt-missing\"
estop = 26"
expect_usage_error "missing GPIO chip" serve --config "$tmp/nogpio.toml"
grep -q '\[gpio\] estop (gpiochip-azt-missing line 26)' "$tmp/err" && ok ||
  bad "GPIO error does not name the key and the chip: $(cat "$tmp/err")"
write_config "$tmp/nospi.toml" "$rport" 0 "
[antenna]
backend = \"hardware\"
[hardware.az]
drive = \"pot\"
spi_device = \"$tmp/no-spidev\"
wiper_calibration = [0, 0.0, 255, 450.0]
sensor = \"mcp3008\"
adc_device = \"$tmp/no-spidev.1\"
pot_calibration = [0, 0.0, 1023, 450.0]
[hardware.el]
drive = \"pot\"
spi_device = \"$tmp/no-spidev.2\"
wiper_calibration = [0, 0.0, 255, 180.0]
sensor = \"mcp3008\"
adc_device = \"$tmp/no-spidev.3\"
pot_calibration = [0, 0.0, 1023, 90.0]"
expect_usage_error "missing spidev" serve --config "$tmp/nospi.toml"
grep -q '\[hardware.az\] adc_device: .*no-spidev.1: No such file' "$tmp/err" && ok ||
  bad "SPI error does not name the key and the device: $(cat "$tmp/err")"
printf 'schema_version = 99\n' >"$tmp/future.toml"
expect_usage_error "future schema" serve --config "$tmp/future.toml"

# 8. A first run without a file writes the commented default and starts on it.
timeout 20 "$bin" serve --config "$tmp/new/azeltrack.toml" --run-for 0.5 >"$tmp/first.log" 2>&1
rc=$?
[ $rc -eq 0 ] && grep -q '^\[antenna\]' "$tmp/new/azeltrack.toml" && ok ||
  bad "first run: rc=$rc $(tail -3 "$tmp/first.log")"

# 9. SIGHUP (a closed terminal) stops the motors and exits cleanly too.
rport3=$(free_port)
write_config "$tmp/hup.toml" "$rport3" 0
start_daemon "$tmp/hup.toml" "$tmp/hup.log" "$rport3" && {
  kill -HUP "$daemon_pid"
  wait "$daemon_pid"
  rc=$?
  [ $rc -eq 0 ] && grep -q 'SIGHUP: motors stopped' "$tmp/hup.log" && ok ||
    bad "SIGHUP: rc=$rc $(tail -2 "$tmp/hup.log")"
}

finish
