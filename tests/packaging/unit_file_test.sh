#!/usr/bin/env bash
# debian/azeltrack.service, the unit the package installs: `systemd-analyze verify` passes with
# ExecStart pointing at the built binary; it is a notify service with a watchdog running as its
# own user with its settings in the state folder; its ExecStart arguments are a command the
# binary accepts; and `systemd-analyze security --offline` rates its exposure at most 3.0 (the
# score parsed from the tool's closing line), with the sandbox settings the daemon relies on.
# Usage: unit_file_test.sh SOURCE_DIR AZELTRACK
set -uo pipefail
src=${1:?usage: unit_file_test.sh SOURCE_DIR AZELTRACK}
bin=$(realpath "${2:?usage: unit_file_test.sh SOURCE_DIR AZELTRACK}")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
source "$src/tests/cli/lib.sh"
unit="$src/debian/azeltrack.service"

sed "s|/usr/bin/azeltrack|$bin|" "$unit" >"$tmp/azeltrack.service"
if out=$(systemd-analyze verify --man=no "$tmp/azeltrack.service" 2>&1); then ok; else bad "verify: $out"; fi
for line in 'Type=notify' 'WatchdogSec=' 'ExecStart=/usr/bin/azeltrack serve --config /var/lib/azeltrack/azeltrack.toml --update-inbox /var/lib/azeltrack/update --update-status /var/lib/azeltrack-update/status' \
  'StateDirectory=azeltrack' 'RuntimeDirectory=azeltrack' 'Restart=on-failure' 'User=azeltrack' \
  'CapabilityBoundingSet=$' 'DevicePolicy=closed' 'ProtectSystem=strict'; do
  grep -q "^$line" "$unit" && ok || bad "unit file lacks '$line'"
done
# What the daemon needs must survive the sandbox: netlink (the interface list), adjtimex (the
# kernel clock's verdict), the serial, GPIO, SPI and I2C devices.
grep -q '^RestrictAddressFamilies=.*AF_NETLINK' "$unit" && ok || bad "netlink not allowed"
grep -q '^SystemCallFilter=@system-service adjtimex' "$unit" && ok || bad "adjtimex not allowed"
for dev in char-ttyUSB char-ttyACM char-gpiochip char-spi char-i2c; do
  grep -q "^DeviceAllow=$dev rw" "$unit" && ok || bad "device $dev not allowed"
done

# The update helper's units (docs/packaging.md): the path unit watches the daemon's inbox, the
# service runs the helper once; both verify, and the inbox is the one the daemon's ExecStart names.
sed "s|/usr/libexec/azeltrack/azeltrack-update|$src/packaging/update/azeltrack-update|" \
  "$src/debian/azeltrack.azeltrack-update.service" >"$tmp/azeltrack-update.service"
cp "$src/debian/azeltrack.azeltrack-update.path" "$tmp/azeltrack-update.path"
if out=$(systemd-analyze verify --man=no "$tmp/azeltrack-update.path" "$tmp/azeltrack-update.service" 2>&1); then
  ok
else
  bad "verify the update units: $out"
fi
grep -qx 'PathExists=/var/lib/azeltrack/update/request.deb' "$tmp/azeltrack-update.path" && ok ||
  bad "the path unit does not watch the daemon's inbox"
grep -qx 'Type=oneshot' "$tmp/azeltrack-update.service" && ! grep -q '^\[Install\]' "$tmp/azeltrack-update.service" &&
  ok || bad "the helper is a oneshot started by its path unit only"
grep -q 'dh_installsystemd -pazeltrack --restart-after-upgrade azeltrack.service$' "$src/debian/rules" &&
  grep -q 'dh_installsystemd -pazeltrack --name=azeltrack-update --restart-after-upgrade azeltrack-update.path$' "$src/debian/rules" &&
  ok || bad "debian/rules must name the units the maintainer scripts restart (never the helper's service)"

# The exposure score: "→ Overall exposure level for azeltrack.service: 1.7 OK".
report=$(systemd-analyze security --offline=true --no-pager "$tmp/azeltrack.service" 2>&1)
score=$(printf '%s\n' "$report" | sed -n 's/.*Overall exposure level for azeltrack.service: \([0-9.]*\) .*/\1/p')
if [ -z "$score" ]; then
  bad "no exposure score in: $(printf '%s\n' "$report" | tail -3)"
elif awk -v s="$score" 'BEGIN { exit !(s <= 3.0) }'; then
  echo "exposure score $score (at most 3.0)"
  ok
else
  bad "exposure score $score is above 3.0"
fi

# The ExecStart arguments parse: with its config path swapped for a file of a future schema, the
# daemon gets as far as reading that file and refuses it (exit 2), so nothing starts.
exec_args=$(sed -n 's|^ExecStart=/usr/bin/azeltrack ||p' "$unit")
printf 'schema_version = 99\n' >"$tmp/future.toml"
# shellcheck disable=SC2086  # the unit's arguments, split as systemd splits them
"$bin" ${exec_args//\/var\/lib\/azeltrack\/azeltrack.toml/$tmp/future.toml} >/dev/null 2>"$tmp/err"
rc=$?
[ $rc -eq 2 ] && grep -q 'schema_version 99' "$tmp/err" && ok ||
  bad "ExecStart arguments: rc=$rc $(cat "$tmp/err")"
finish
