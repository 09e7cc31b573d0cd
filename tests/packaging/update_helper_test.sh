#!/usr/bin/env bash
# The root update helper against what the daemon's user can leave in its inbox (issue 27 §2):
# a FIFO (it had held the helper in "checking" until its 20-minute start timeout), a folder (it
# was refused but left there, so the path unit started the helper again and again), a symbolic
# link, a hard link to a root-owned file, a file over 64 MiB, and bytes that are no package.
# Each must be refused with its reason within seconds, and the inbox left empty. The helper runs
# as it does under systemd (as root, reading the request as the daemon's user, here `nobody`),
# with its folders moved to a scratch folder; nothing is installed (every case is refused first).
# Usage: update_helper_test.sh SOURCE_DIR
set -uo pipefail
src=${1:?usage: update_helper_test.sh SOURCE_DIR}
helper="$src/packaging/update/azeltrack-update"
if [ "$(id -u)" -ne 0 ]; then
  echo "update_helper_test: needs root (the helper runs as root and reads as another user)" >&2
  exit 77
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
bin=/bin/false
source "$src/tests/cli/lib.sh"
inbox="$tmp/inbox" state="$tmp/state"
mkdir -p "$inbox" "$state"
chown nobody "$inbox"
chmod 0711 "$tmp"  # the daemon's user reaches its inbox, as under /var/lib/azeltrack

# case NAME EXPECTED_REASON: runs the helper on what the caller left at request.deb.
case_() {
  local name=$1 reason=$2 started elapsed phase message
  started=$(date +%s%N)
  AZT_UPDATE_INBOX=$inbox AZT_UPDATE_STATE=$state AZT_UPDATE_USER=nobody \
    timeout 30 "$helper" >/dev/null 2>"$tmp/helper.err"
  local rc=$?
  elapsed=$(( ($(date +%s%N) - started) / 1000000 ))
  phase=$(sed -n 's/^phase=//p' "$state/status" 2>/dev/null)
  message=$(sed -n 's/^message=//p' "$state/status" 2>/dev/null)
  [ "$rc" -eq 0 ] && ok || bad "$name: the helper exited $rc: $(cat "$tmp/helper.err")"
  [ "$elapsed" -lt 5000 ] && ok || bad "$name: the helper took $elapsed ms"
  [ "$phase" = refused ] && ok || bad "$name: phase '$phase' ($message), not refused"
  [[ $message == *"$reason"* ]] && ok || bad "$name: the reason '$message' lacks '$reason'"
  [ -z "$(ls -A "$inbox")" ] && ok || bad "$name: the inbox keeps $(ls -A "$inbox")"
  [ ! -e "$state/package.deb" ] && ok || bad "$name: the helper's copy was left behind"
  echo "update_helper_test: $name: refused in $elapsed ms: $message"
}

mkfifo "$inbox/request.deb" && chown nobody "$inbox/request.deb"
case_ fifo "not a regular file"

mkdir -p "$inbox/request.deb/inside" && chown -R nobody "$inbox/request.deb"
case_ folder "not a regular file"

echo "secret of root" >"$tmp/root-file" && chmod 0644 "$tmp/root-file"
ln -s "$tmp/root-file" "$inbox/request.deb"
case_ "symbolic link" "symbolic link"
[ "$(cat "$tmp/root-file")" = "secret of root" ] && ok || bad "the link's target was changed"

ln "$tmp/root-file" "$inbox/request.deb"  # as root: protected_hardlinks stops the user itself
case_ "hard link to a root-owned file" "links"
[ -f "$tmp/root-file" ] && ok || bad "the hard link's other name was removed"

truncate -s $((64 * 1024 * 1024 + 1)) "$inbox/request.deb" && chown nobody "$inbox/request.deb"
case_ "over 64 MiB" "over 64 MiB"

head -c 4096 /dev/urandom >"$inbox/request.deb" && chown nobody "$inbox/request.deb"
case_ "no package" "not a valid Debian package"

finish
