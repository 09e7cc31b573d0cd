#!/usr/bin/env bash
# Fails if a room of the program includes a room above it, or a header by a bare name
# (docs/architecture.md). The rooms, from the ground up; each may include only rooms to its
# left (and itself), the core and the platform libraries. main.cpp, at the root, may include any.
# Usage: check_rooms.sh APP_DIR
set -euo pipefail
app=${1:?usage: check_rooms.sh APP_DIR}
rooms=(common config satellites elements antenna station hands schedule radio calibration console daemon cli)
status=0
checked=0
for ((i = 0; i < ${#rooms[@]}; i++)); do
  room=${rooms[$i]}
  [ -d "$app/$room" ] || { echo "rooms: $app/$room is missing" >&2; status=1; continue; }
  above=("${rooms[@]:$((i + 1))}")
  for file in "$app/$room"/*.cpp "$app/$room"/*.hpp; do
    [ -e "$file" ] || continue
    checked=$((checked + 1))
    while IFS= read -r line; do
      header=${line#*\"}
      header=${header%%\"*}
      target=${header%%/*}
      if [ "$target" = "$header" ]; then
        echo "rooms: $file includes \"$header\" by a bare name: write it from the app root" >&2
        status=1
      fi
      for up in "${above[@]}"; do
        if [ "$target" = "$up" ]; then
          echo "rooms: $file ($room) includes \"$header\": $up is above $room" >&2
          status=1
        fi
      done
    done < <(grep -E '^#[[:space:]]*include[[:space:]]*"' "$file" | grep -v '"azt/' || true)
  done
done
stray=$(find "$app" -maxdepth 1 \( -name '*.cpp' -o -name '*.hpp' \) ! -name main.cpp)
if [ -n "$stray" ]; then
  echo "rooms: files outside every room: $stray" >&2
  status=1
fi
if [ "$checked" -lt 20 ]; then
  echo "rooms: only $checked files found under $app: wrong directory?" >&2
  status=1
fi
[ $status -eq 0 ] && echo "rooms: $checked files in ${#rooms[@]} rooms, no include runs up"
exit $status
