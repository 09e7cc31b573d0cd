#!/usr/bin/env bash
# The built package (scripts/package): its files are the program, the unit, the system user, the
# state folder, the udev rules, the chrony snippet and sources link, the hub firmware, the manual
# page and the docs; the settings are no conffile (dpkg ships nothing under /var/lib/azeltrack,
# so an upgrade never asks about them); the version is the program's own; and lintian reports
# nothing (its only overrides are explained in debian/azeltrack.lintian-overrides).
# Usage: deb_test.sh SOURCE_DIR DEB
set -uo pipefail
src=${1:?usage: deb_test.sh SOURCE_DIR DEB}
deb=${2:?usage: deb_test.sh SOURCE_DIR DEB}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
source "$src/tests/cli/lib.sh"

dpkg-deb -c "$deb" | awk '{ print $6 }' | sed 's|^\./|/|' >"$tmp/files"
for f in /usr/bin/azeltrack /lib/systemd/system/azeltrack.service \
  /usr/lib/sysusers.d/azeltrack.conf /usr/lib/tmpfiles.d/azeltrack.conf \
  /lib/udev/rules.d/60-azeltrack.rules /etc/chrony/conf.d/azeltrack.conf \
  /etc/chrony/sources.d/azeltrack.sources /usr/share/azeltrack/firmware/encoder-hub.hex \
  /usr/share/azeltrack/firmware/encoder-hub.elf /usr/share/man/man1/azeltrack.1.gz \
  /usr/share/doc/azeltrack/README.md.gz /usr/share/doc/azeltrack/copyright \
  /usr/share/doc/azeltrack/examples/station.toml; do
  grep -qx "$f" "$tmp/files" && ok || bad "the package lacks $f"
done
# Every manual under docs/ is in the package (compressed or not).
for md in "$src"/docs/*.md; do
  name=$(basename "$md")
  grep -Eqx "/usr/share/doc/azeltrack/$name(\\.gz)?" "$tmp/files" && ok || bad "docs: $name missing"
done
# Nothing else: no test binaries, benchmarks or fuzzers, no hub-sim.
extra=$(grep -Ev '/$' "$tmp/files" | grep -E '^/usr/(bin|sbin|lib)/' |
  grep -Evx '/usr/bin/azeltrack|/usr/lib/(sysusers|tmpfiles)\.d/azeltrack\.conf')
[ -z "$extra" ] && ok || bad "unexpected programs or libraries: $extra"
grep -q '^/var/lib' "$tmp/files" && bad "the package ships files under /var/lib" || ok

dpkg-deb -e "$deb" "$tmp/control"
[ "$(cat "$tmp/control/conffiles")" = "/etc/chrony/conf.d/azeltrack.conf" ] && ok ||
  bad "conffiles: $(cat "$tmp/control/conffiles")"
grep -q 'deb-systemd-invoke $_dh_action' "$tmp/control/postinst" && ok ||
  bad "the postinst does not (re)start the unit"
grep -q 'rm -rf /var/lib/azeltrack' "$tmp/control/postrm" && ok || bad "purge keeps the settings"

# The package's version is the program's: debian/changelog and CMake's project() agree.
deb_version=$(dpkg-deb -f "$deb" Version)
cmake_version=$(sed -n 's/^project(azeltrack VERSION \([0-9.]*\).*/\1/p' "$src/CMakeLists.txt")
case "$deb_version" in
  "$cmake_version" | "$cmake_version"+*) ok ;;
  *) bad "package version $deb_version, program version $cmake_version" ;;
esac

# The packaged program runs (its shared libraries are what Depends names: dpkg-shlibdeps).
dpkg-deb -x "$deb" "$tmp/root"
# Another architecture's program runs under qemu-user, with that architecture's libraries from
# multiarch (scripts/install-deps --cross).
run=()
deb_arch=$(dpkg-deb -f "$deb" Architecture)
if [ "$deb_arch" != "$(dpkg --print-architecture)" ]; then
  run=("qemu-$(dpkg-architecture -a "$deb_arch" -qDEB_HOST_GNU_CPU 2>/dev/null)-static")
fi
"${run[@]}" "$tmp/root/usr/bin/azeltrack" --version >"$tmp/version" 2>&1 && grep -q "$cmake_version" "$tmp/version" &&
  ok || bad "azeltrack --version from the package: $(cat "$tmp/version")"
depends=$(dpkg-deb -f "$deb" Depends)
for lib in liberfa1 libhamlib4 libsodium23 libsystemd0 libgpiod2 acl tzdata; do
  grep -q "$lib" <<<"$depends" && ok || bad "Depends lacks $lib: $depends"
done

# lintian: no error, warning or information line (overrides are reported only with --show-overrides).
lintian --info --no-tag-display-limit "$deb" >"$tmp/lintian" 2>&1
lintian_rc=$?
tags=$(grep -E '^[EWIPX]: ' "$tmp/lintian")
[ "$lintian_rc" -eq 0 ] && [ -z "$tags" ] && ok || bad "lintian ($lintian_rc): $tags"
finish
