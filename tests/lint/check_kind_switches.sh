#!/usr/bin/env bash
# Fails, naming each line, where C++ compares a drive or sensor kind with == or != instead of
# switching on it. A switch over a closed set without `default` is checked by the compiler
# (-Wswitch, an error under -Werror): a new kind of drive or sensor then fails the build at every
# place that has to say what it does, where an `if (kind == Relay) … else` would quietly treat the
# new kind as the else (docs/architecture.md, "Adding a drive"; issue: a missed branch would drive
# an H-bridge). Predicates such as read_by_hub() and sends_setpoint() are switches themselves.
# Usage: check_kind_switches.sh SOURCE_DIR
set -euo pipefail
src=${1:?usage: check_kind_switches.sh SOURCE_DIR}
cd "$src"
pattern='[!=]=[[:space:]]*([a-z_]+::)*(AxisDriveKind|AxisSensorKind|DriveKind)::'
if found=$(git ls-files -z -- '*.cpp' '*.hpp' | xargs -0 grep -nE "$pattern"); then
  echo "kind switches: compare a drive or sensor kind with == or != (switch on it instead):" >&2
  echo "$found" >&2
  exit 1
fi
echo "kind switches: no drive or sensor kind compared with == or !="
