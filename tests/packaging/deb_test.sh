#!/usr/bin/env bash
# The built package (scripts/package): its files are the program, the unit, the system user, the
# state folder, the udev rules, the chrony snippet and sources link, the hub firmware, the manual
# page and the docs; the settings are no conffile (dpkg ships nothing under /var/lib/azeltrack,
# so an upgrade never asks about them); the version is the program's own; and lintian reports
# nothing (its only overrides are explained in debian/azeltrack.lintian-overrides).
# With PANEL_DEB, the touch panel's package too: its unit, user and folder, enabled at install,
# depending on the daemon's package, cage and cog; lintian clean.
# Usage: deb_test.sh SOURCE_DIR DEB [PANEL_DEB]
set -uo pipefail
src=${1:?usage: deb_test.sh SOURCE_DIR DEB [PANEL_DEB]}
deb=${2:?usage: deb_test.sh SOURCE_DIR DEB [PANEL_DEB]}
panel=${3:-}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
source "$src/tests/cli/lib.sh"

# The project's release key (packaging/keys/azeltrack-release.asc), whose signed updates the
# update helper installs (docs/packaging.md, "Signed updates").
release_key=5A33A3747E83ECC0CD2795FE2124FFC9F62C5588
dpkg-deb -c "$deb" | awk '{ print $6 }' | sed 's|^\./|/|' >"$tmp/files"
for f in /usr/bin/azeltrack /lib/systemd/system/azeltrack.service \
  /usr/lib/sysusers.d/azeltrack.conf /usr/lib/tmpfiles.d/azeltrack.conf \
  /lib/udev/rules.d/70-azeltrack.rules /etc/chrony/conf.d/azeltrack.conf \
  /etc/chrony/sources.d/azeltrack.sources /usr/share/azeltrack/firmware/encoder-hub.hex \
  /usr/share/azeltrack/firmware/encoder-hub.elf /usr/share/man/man1/azeltrack.1.gz \
  /usr/share/doc/azeltrack/README.md /usr/share/doc/azeltrack/copyright \
  /usr/share/doc/azeltrack/examples/station.toml /usr/libexec/azeltrack/azeltrack-update \
  /lib/systemd/system/azeltrack-update.path /lib/systemd/system/azeltrack-update.service \
  /usr/sbin/azeltrack-update-keys /usr/share/man/man8/azeltrack-update-keys.8.gz \
  "/etc/azeltrack/update-keys/policies/$release_key/azeltrack.pol" \
  "/etc/azeltrack/update-keys/keyrings/$release_key/azeltrack.gpg"; do
  grep -qx "$f" "$tmp/files" && ok || bad "the package lacks $f"
done
# Every manual under docs/ is in the package, uncompressed (the units' Documentation= links).
for md in "$src"/docs/*.md; do
  name=$(basename "$md")
  grep -qx "/usr/share/doc/azeltrack/$name" "$tmp/files" && ok || bad "docs: $name missing"
done
# Nothing else: no test binaries, benchmarks or fuzzers, no hub-sim.
extra=$(grep -Ev '/$' "$tmp/files" | grep -E '^/usr/(bin|sbin|lib)/' |
  grep -Evx '/usr/(bin/azeltrack|sbin/azeltrack-update-keys)|/usr/lib/(sysusers|tmpfiles)\.d/azeltrack\.conf')
[ -z "$extra" ] && ok || bad "unexpected programs or libraries: $extra"
grep -q '^/var/lib' "$tmp/files" && bad "the package ships files under /var/lib" || ok

dpkg-deb -e "$deb" "$tmp/control"
expected_conffiles="/etc/azeltrack/update-keys/keyrings/$release_key/azeltrack.gpg
/etc/azeltrack/update-keys/policies/$release_key/azeltrack.pol
/etc/chrony/conf.d/azeltrack.conf"
[ "$(sort "$tmp/control/conffiles")" = "$expected_conffiles" ] && ok ||
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
# It reports the package's version (what the console's Software page shows and compares).
deb_version=$(dpkg-deb -f "$deb" Version)
"${run[@]}" "$tmp/root/usr/bin/azeltrack" --version >"$tmp/version" 2>&1 && grep -q "$cmake_version" "$tmp/version" &&
  grep -qx "azeltrack $deb_version" "$tmp/version" &&
  ok || bad "azeltrack --version from the package $deb_version: $(cat "$tmp/version")"
depends=$(dpkg-deb -f "$deb" Depends)
for lib in liberfa1 libhamlib4 libsodium23 libsystemd0 libgpiod2 libevdev2 libcurl4 acl tzdata; do
  grep -q "$lib" <<<"$depends" && ok || bad "Depends lacks $lib: $depends"
done

# lintian: no error, warning or information line (overrides are reported only with --show-overrides).
lintian --info --no-tag-display-limit "$deb" >"$tmp/lintian" 2>&1
lintian_rc=$?
tags=$(grep -E '^[EWIPX]: ' "$tmp/lintian")
[ "$lintian_rc" -eq 0 ] && [ -z "$tags" ] && ok || bad "lintian ($lintian_rc): $tags"

if [ -n "$panel" ]; then
  dpkg-deb -c "$panel" | awk '{ print $6 }' | sed 's|^\./|/|' >"$tmp/panel-files"
  for f in /lib/systemd/system/azeltrack-panel.service /usr/lib/sysusers.d/azeltrack-panel.conf \
    /usr/lib/tmpfiles.d/azeltrack-panel.conf; do
    grep -qx "$f" "$tmp/panel-files" && ok || bad "the panel package lacks $f"
  done
  panel_depends=$(dpkg-deb -f "$panel" Depends)
  for dep in "azeltrack (>= $deb_version)" cage cog; do
    grep -qF "$dep" <<<"$panel_depends" && ok || bad "the panel's Depends lacks $dep: $panel_depends"
  done
  [ "$(dpkg-deb -f "$panel" Architecture)" = all ] && ok || bad "the panel package is not arch all"
  dpkg-deb -e "$panel" "$tmp/panel-control"
  grep -q "deb-systemd-helper enable 'azeltrack-panel.service'" "$tmp/panel-control/postinst" && ok ||
    bad "the panel's postinst does not enable its unit"
  grep -q 'userdel azeltrack-panel' "$tmp/panel-control/postrm" && ok || bad "purge keeps the panel's user"
  lintian --info --no-tag-display-limit "$panel" >"$tmp/lintian-panel" 2>&1
  lintian_rc=$?
  tags=$(grep -E '^[EWIPX]: ' "$tmp/lintian-panel")
  [ "$lintian_rc" -eq 0 ] && [ -z "$tags" ] && ok || bad "lintian on the panel ($lintian_rc): $tags"
fi
finish
