#!/usr/bin/env bash
# Side-by-side rotctld-protocol server benchmark: Debian's Hamlib `rotctld -m 1` (dummy rotator)
# against `azeltrack serve`, driven by bench/rotctld_load. Builds nothing.
#
# Usage: bench/rotctld_compare.sh BUILD_DIR
#   BUILD_DIR must hold bench/rotctld_load; azeltrack is optional (skipped with
#   "azeltrack serve not available" when missing, without `serve`, or not listening within 5 s).
#   BENCH_SECONDS (default 5) sets the measured seconds per load, after a 1 s warm-up.
# Per server: 1 and 50 closed-loop clients, then RSS and thread count with 200 idle connections
# plus 1 active client, then SIGTERM and the exit status. Progress on stderr, the Markdown table
# on stdout.
set -euo pipefail

if [[ $# -ne 1 ]]; then
  echo "usage: $0 BUILD_DIR" >&2
  exit 2
fi
build_dir=$1
load="$build_dir/bench/rotctld_load"
azeltrack="$build_dir/azeltrack"
run_s=${BENCH_SECONDS:-5}
idle_clients=200
start_timeout_tenths=50

if [[ ! -x $load ]]; then
  echo "$load: not found or not executable (build the rotctld_load target first)" >&2
  exit 2
fi

tmp=$(mktemp -d)
children=()

# forget PID: drop a reaped child, so cleanup never signals a recycled pid.
forget() {
  local pid kept=()
  for pid in "${children[@]}"; do
    [[ $pid == "$1" ]] || kept+=("$pid")
  done
  children=("${kept[@]}")
}

cleanup() {
  local pid
  for pid in "${children[@]}"; do
    if kill -0 "$pid" 2>/dev/null; then
      kill -TERM "$pid" 2>/dev/null || true
    fi
  done
  for pid in "${children[@]}"; do
    wait "$pid" 2>/dev/null || true
  done
  rm -rf "$tmp"
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM

# Two distinct free loopback ports (both sockets stay bound until both are known).
read -r port_rotctld port_azeltrack < <(
  python3 -c 'import socket
socks = [socket.socket() for _ in range(2)]
for s in socks:
    s.bind(("127.0.0.1", 0))
print(*(s.getsockname()[1] for s in socks))'
)

# wait_for_port PID PORT: 0 once PORT accepts connections, 1 if PID died or 5 s passed.
wait_for_port() {
  local pid=$1 port=$2 i
  for ((i = 0; i < start_timeout_tenths; i++)); do
    kill -0 "$pid" 2>/dev/null || return 1
    if (: <"/dev/tcp/127.0.0.1/$port") 2>/dev/null; then
      return 0
    fi
    sleep 0.1
  done
  return 1
}

# status_field PID FIELD: a /proc/PID/status field (VmRSS in kB, Threads), or "?".
status_field() {
  if [[ ! -r /proc/$1/status ]]; then
    echo "?"
    return
  fi
  awk -v f="$2:" '$1 == f { print $2; found = 1 } END { if (!found) print "?" }' \
    "/proc/$1/status"
}

# trim TEXT: TEXT without leading and trailing blanks.
trim() {
  local s=$1
  s=${s#"${s%%[![:space:]]*}"}
  s=${s%"${s##*[![:space:]]}"}
  printf '%s' "$s"
}

declare -A result

# run_load SERVER PORT CLIENTS: one closed-loop run; stores req/s, latency and errors.
run_load() {
  local server=$1 port=$2 clients=$3 row out="$tmp/load.out"
  # In the background, so that a signal's trap runs at once rather than after the load.
  "$load" --port "$port" --clients "$clients" --seconds "$run_s" --warmup 1 \
    --label "$server" >"$out" &
  local load_pid=$!
  children+=("$load_pid")
  wait "$load_pid"
  forget "$load_pid"
  row=$(<"$out")
  echo "$row" >&2
  local _ rps p50 p99 max errors
  IFS="|" read -r _ _ _ rps p50 p99 max errors _ <<<"$row"
  result[$server,$clients,rps]=$(trim "$rps")
  result[$server,$clients,lat]="$(trim "$p50") / $(trim "$p99") / $(trim "$max")"
  result[$server,$clients,errors]=$(trim "$errors")
}

# measure_idle SERVER PID PORT: RSS and threads while idle_clients idle + 1 active are connected.
measure_idle() {
  local server=$1 pid=$2 port=$3 log="$tmp/idle-$3.log" i
  "$load" --port "$port" --clients 1 --idle "$idle_clients" --seconds 4 --warmup 0 \
    --label "$server idle" >"$log" 2>&1 &
  local load_pid=$!
  children+=("$load_pid")
  for ((i = 0; i < 150; i++)); do
    grep -qs 'idle connections open' "$log" && break
    kill -0 "$load_pid" 2>/dev/null || break
    sleep 0.1
  done
  sleep 1
  result[$server,rss_idle]=$(status_field "$pid" VmRSS)
  result[$server,threads_idle]=$(status_field "$pid" Threads)
  wait "$load_pid" || true
  forget "$load_pid"
  cat "$log" >&2
}

# stop_server SERVER PID: SIGTERM, up to 5 s to exit, then SIGKILL; records how it ended.
stop_server() {
  local server=$1 pid=$2 i status=0
  kill -TERM "$pid" 2>/dev/null || true
  for ((i = 0; i < 50; i++)); do
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.1
  done
  if kill -0 "$pid" 2>/dev/null; then
    kill -KILL "$pid" 2>/dev/null || true
    wait "$pid" 2>/dev/null || true
    forget "$pid"
    result[$server,exit]="SIGKILL (still running 5 s after SIGTERM)"
    return
  fi
  wait "$pid" 2>/dev/null || status=$?
  forget "$pid"
  if ((status > 128)); then
    result[$server,exit]="killed by signal $((status - 128))"
  else
    result[$server,exit]="exit $status"
  fi
}

# bench_server SERVER PID PORT: the whole sequence against one running server.
bench_server() {
  local server=$1 pid=$2 port=$3
  result[$server,rss_start]=$(status_field "$pid" VmRSS)
  run_load "$server" "$port" 1
  run_load "$server" "$port" 50
  measure_idle "$server" "$pid" "$port"
  stop_server "$server" "$pid"
  result[$server,ok]=1
}

servers=("rotctld -m 1" "azeltrack serve")

if command -v rotctld >/dev/null; then
  rotctld -m 1 -T 127.0.0.1 -t "$port_rotctld" >"$tmp/rotctld.log" 2>&1 &
  rotctld_pid=$!
  children+=("$rotctld_pid")
  if wait_for_port "$rotctld_pid" "$port_rotctld"; then
    bench_server "rotctld -m 1" "$rotctld_pid" "$port_rotctld"
  else
    echo "rotctld did not start:" >&2
    cat "$tmp/rotctld.log" >&2
  fi
else
  echo "rotctld not installed (apt install libhamlib-utils)" >&2
fi

azeltrack_help=""
if [[ -x $azeltrack ]]; then
  azeltrack_help=$(timeout 5 "$azeltrack" --help 2>&1 || true)
fi
serve_re='(^|[^[:alnum:]_-])serve([^[:alnum:]_-]|$)'
if [[ $azeltrack_help =~ $serve_re ]]; then
  config="$tmp/azeltrack.toml"
  # The simulated antenna tracking the Moon, so the control tick does real work under the load.
  printf '[station]\ngrid = "FN06HE"\n[target]\nname = "moon"\n[rotctld]\nbind = "127.0.0.1"\nport = %s\n[pstrotator]\nport = 0\n[web]\nport = 0\n' \
    "$port_azeltrack" >"$config"
  "$azeltrack" serve --config "$config" >"$tmp/azeltrack.log" 2>&1 &
  azeltrack_pid=$!
  children+=("$azeltrack_pid")
  if wait_for_port "$azeltrack_pid" "$port_azeltrack"; then
    bench_server "azeltrack serve" "$azeltrack_pid" "$port_azeltrack"
    # The daemon logs its control-tick lateness over the whole run (all loads) when it stops.
    result["azeltrack serve",tick]=$(grep -o 'late p50.*overruns' "$tmp/azeltrack.log" || echo "?")
  else
    if kill -0 "$azeltrack_pid" 2>/dev/null; then
      echo "azeltrack serve not available (not listening on port $port_azeltrack within 5 s)"
    else
      echo "azeltrack serve not available (exited before listening; its log follows on stderr)"
    fi
    tail -n 20 "$tmp/azeltrack.log" >&2
    kill -TERM "$azeltrack_pid" 2>/dev/null || true
    wait "$azeltrack_pid" 2>/dev/null || true
    forget "$azeltrack_pid"
  fi
else
  echo "azeltrack serve not available ($azeltrack missing or without a serve subcommand)"
fi

# cell SERVER KEY: a stored result, or "n/a" for a server that was not measured.
cell() {
  if [[ -n ${result[$1,ok]:-} ]]; then
    echo "${result[$1,$2]:-?}"
  else
    echo "n/a"
  fi
}

row() {
  local title=$1 key=$2 server
  local line="| $title |"
  for server in "${servers[@]}"; do
    line+=" $(cell "$server" "$key") |"
  done
  echo "$line"
}

read -r load1 load5 _ </proc/loadavg
echo
echo "rotctld protocol, loopback, ${run_s} s per load after 1 s warm-up, p + P alternating;"
echo "$(nproc) CPUs, load average ${load1} ${load5} at the end (other work skews the numbers)"
echo
echo "| | ${servers[0]} | ${servers[1]} |"
echo "|---|---:|---:|"
for clients in 1 50; do
  row "$clients client(s): requests/s" "$clients,rps"
  row "$clients client(s): p50 / p99 / max µs" "$clients,lat"
  row "$clients client(s): errors" "$clients,errors"
done
row "VmRSS after start, kB" rss_start
row "VmRSS with $idle_clients idle + 1 active client, kB" rss_idle
row "threads with $idle_clients idle + 1 active client" threads_idle
row "after SIGTERM" exit
row "control tick (20 Hz) lateness over the run" tick
