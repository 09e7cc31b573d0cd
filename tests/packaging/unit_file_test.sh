#!/usr/bin/env bash
# packaging/azeltrack.service passes `systemd-analyze verify` with ExecStart pointing at the built
# binary, is a notify service with a watchdog, and its ExecStart line is a command the binary
# accepts.
# Usage: unit_file_test.sh SOURCE_DIR AZELTRACK
set -uo pipefail
src=${1:?usage: unit_file_test.sh SOURCE_DIR AZELTRACK}
bin=$(realpath "${2:?usage: unit_file_test.sh SOURCE_DIR AZELTRACK}")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
source "$src/tests/cli/lib.sh"
unit="$src/packaging/azeltrack.service"

sed "s|/usr/local/bin/azeltrack|$bin|" "$unit" >"$tmp/azeltrack.service"
if out=$(systemd-analyze verify "$tmp/azeltrack.service" 2>&1); then ok; else bad "verify: $out"; fi
for line in 'Type=notify' 'WatchdogSec=' 'ExecStart=/usr/local/bin/azeltrack serve --config ' \
  'RuntimeDirectory=azeltrack' 'ConfigurationDirectory=azeltrack' 'Restart=on-failure'; do
  grep -q "^$line" "$unit" && ok || bad "unit file lacks '$line'"
done
# The ExecStart arguments parse: with its config path swapped for a file of a future schema, the
# daemon gets as far as reading that file and refuses it (exit 2), so nothing starts.
exec_args=$(sed -n 's|^ExecStart=/usr/local/bin/azeltrack ||p' "$unit")
printf 'schema_version = 99\n' >"$tmp/future.toml"
# shellcheck disable=SC2086  # the unit's arguments, split as systemd splits them
"$bin" ${exec_args//\/etc\/azeltrack\/azeltrack.toml/$tmp/future.toml} >/dev/null 2>"$tmp/err"
rc=$?
[ $rc -eq 2 ] && grep -q 'schema_version 99' "$tmp/err" && ok ||
  bad "ExecStart arguments: rc=$rc $(cat "$tmp/err")"
finish
