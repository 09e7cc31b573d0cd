#!/usr/bin/env bash
# packaging/chrony/azeltrack.conf (docs/time.md) as chronyd itself reads it (`chronyd -p` parses
# the file and prints the directives it understood, changing nothing): every directive accepted,
# the GPS refclock on gpsd's shared memory unit 0, serving the LAN, holdover and the RTC; and the
# PPS line left commented (chronyd refuses to start when /dev/pps0 is missing).
# Usage: chrony_conf_test.sh SOURCE_DIR
set -u
conf="$1/packaging/chrony/azeltrack.conf"
fails=0
check() {  # check WHAT COMMAND...
  local what="$1"; shift
  if "$@"; then echo "ok: $what"; else echo "FAIL: $what"; fails=$((fails + 1)); fi
}
parsed=$(chronyd -p -f "$conf" 2>&1)
rc=$?
check "chronyd -p accepts every directive (rc $rc): $parsed" test "$rc" -eq 0
directives=$(grep -Ecv '^[[:space:]]*(#|$)' "$conf")
check "every directive is understood ($directives in the file)" \
  test "$(printf '%s\n' "$parsed" | grep -c .)" -eq "$directives"
check "the GPS from gpsd's SHM 0, refid GPS" grep -Eq '^refclock SHM 0 refid GPS ' <<<"$parsed"
check "the LAN may ask" grep -q '^allow 192.168.0.0/16' <<<"$parsed"
check "holdover at stratum 10" grep -q '^local stratum 10' <<<"$parsed"
check "the RTC kept" grep -q '^rtcsync' <<<"$parsed"
check "the PPS line is there, commented" grep -q '^#refclock PPS /dev/pps0 lock GPS' "$conf"
echo "chrony_conf: $fails failed"
exit $((fails > 0))
