#!/usr/bin/env bash
# The root update helper against what the daemon's user can leave in its inbox
# (docs/reliability.md "Hardening, round three" row 2):
# a FIFO (it had held the helper in "checking" until its 20-minute start timeout), a folder (it
# was refused but left there, so the path unit started the helper again and again), a symbolic
# link, a hard link to a root-owned file, a file over 64 MiB, and bytes that are no package; and
# (§1) a package named azeltrack, version 99:0, with a root postinst, handed over unsigned,
# signed by a key the station does not trust, changed after signing, or with a trusted-keys
# folder the daemon's user could write. Each must be refused with its reason within seconds, the
# postinst never run, and the inbox left empty. (A package signed by a trusted key installs in
# the upgrade test's root: tests/packaging/upgrade_test.py.) The helper runs
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
inbox="$tmp/inbox" state="$tmp/state" keys="$tmp/keys"
mkdir -p "$inbox" "$state"
"$src/packaging/update/azeltrack-update-keys" --dir "$keys" \
  add "$src/tests/data/software/signing/test-key.asc" >/dev/null
chown nobody "$inbox"
chmod 0711 "$tmp"  # the daemon's user reaches its inbox, as under /var/lib/azeltrack

# case NAME EXPECTED_REASON: runs the helper on what the caller left at request.deb.
case_() {
  local name=$1 reason=$2 started elapsed phase message
  started=$(date +%s%N)
  AZT_UPDATE_INBOX=$inbox AZT_UPDATE_STATE=$state AZT_UPDATE_USER=nobody AZT_UPDATE_KEYS=$keys \
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

# The attack of §1: any "azeltrack" of a higher version with a root postinst.
export GNUPGHOME="$tmp/gnupg"
mkdir -m 0700 "$GNUPGHOME"
gpg --batch --quiet --import "$src/tests/data/software/signing/test-key.secret.asc" 2>/dev/null
gpg --batch --quiet --passphrase '' --quick-gen-key 'someone else <other@example.invalid>' \
  ed25519 sign never 2>/dev/null
other=$(gpg --batch --with-colons --list-secret-keys other@example.invalid |
  awk -F: '$1 == "fpr" { print $10; exit }')
root_deb="$tmp/root.deb"
mkdir -p "$tmp/pkg/DEBIAN"
printf 'Package: azeltrack\nVersion: 99:0\nArchitecture: %s\nMaintainer: x <x@example.invalid>\nDescription: not azeltrack\n' \
  "$(dpkg --print-architecture)" >"$tmp/pkg/DEBIAN/control"
printf '#!/bin/sh\ntouch %s/postinst-ran\n' "$tmp" >"$tmp/pkg/DEBIAN/postinst"
chmod 0755 "$tmp/pkg/DEBIAN/postinst"
dpkg-deb --root-owner-group -b "$tmp/pkg" "$root_deb" >/dev/null

# offer FILE: leaves FILE as the daemon would, in the inbox as the daemon's user's.
offer() { cp "$1" "$inbox/request.deb" && chown nobody "$inbox/request.deb"; }

offer "$root_deb"
case_ "unsigned azeltrack 99:0" "not signed"

cp "$root_deb" "$tmp/other.deb" && debsigs --sign=origin --default-key="$other" "$tmp/other.deb" 2>/dev/null
offer "$tmp/other.deb"
case_ "signed by an untrusted key" "$other, which this station does not trust"

# A trusted signature moved onto another valid package (its postinst changed after signing):
# debsigs signs the members before it, so the archive is whole but the signature does not match.
cp "$root_deb" "$tmp/signed.deb"
debsigs --sign=origin --default-key=FC4892F01AAC91A16E33CF6BD790D49363F83F75 "$tmp/signed.deb" 2>/dev/null
(cd "$tmp" && ar x signed.deb _gpgorigin)
printf '#!/bin/sh\ntouch %s/postinst-ran\necho changed\n' "$tmp" >"$tmp/pkg/DEBIAN/postinst"
dpkg-deb --root-owner-group -b "$tmp/pkg" "$tmp/changed.deb" >/dev/null
(cd "$tmp" && ar q changed.deb _gpgorigin)
offer "$tmp/changed.deb"
case_ "changed after signing" "does not verify"

cp "$root_deb" "$tmp/trusted.deb"
debsigs --sign=origin --default-key=FC4892F01AAC91A16E33CF6BD790D49363F83F75 "$tmp/trusted.deb" 2>/dev/null
chmod o+w "$keys/policies"
offer "$tmp/trusted.deb"
case_ "trusted keys others may write" "not root's alone"
chmod o-w "$keys/policies"
[ ! -e "$tmp/postinst-ran" ] && ok || bad "a refused package's postinst ran"

finish
