#!/usr/bin/env bash
# docs/man/azeltrack.1 stays true to the program: every subcommand `azeltrack --help` lists has its
# entry, the page names the program's version, and man(1) formats it without a warning.
# Usage: man_page_test.sh SOURCE_DIR AZELTRACK
set -uo pipefail
src=${1:?usage: man_page_test.sh SOURCE_DIR AZELTRACK}
bin=${2:?usage: man_page_test.sh SOURCE_DIR AZELTRACK}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
source "$src/tests/cli/lib.sh"
page="$src/docs/man/azeltrack.1"

subcommands=$("$bin" --help | awk '/^Subcommands:/ { on = 1; next } /^$/ { on = 0 } on { print $1 }')
[ "$(wc -w <<<"$subcommands")" -ge 10 ] && ok || bad "too few subcommands read from --help: $subcommands"
for cmd in $subcommands; do
  # In roff a hyphen is written \-.
  grep -qx "\\.B ${cmd//-/\\\\-}" "$page" && ok || bad "the man page has no entry for '$cmd'"
done
version=$("$bin" --version | grep -Eo '[0-9]+\.[0-9]+\.[0-9]+' | head -1)
grep -q "^\\.TH AZELTRACK 1 .*\"azeltrack $version\"" "$page" && ok ||
  bad "the man page's .TH does not name version $version"
MANWIDTH=80 man --warnings -l "$page" >"$tmp/out" 2>"$tmp/warnings"
[ -s "$tmp/out" ] && [ ! -s "$tmp/warnings" ] && ok || bad "man --warnings: $(cat "$tmp/warnings")"
finish
