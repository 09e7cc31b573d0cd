#!/usr/bin/env bash
# The Debian 12 machine the system test boots (docs/packaging.md): a root file system made by
# mmdebstrap from Debian's packages alone (systemd, udev, Debian's kernel and initramfs, chrony, the
# GPIO and I2C tools, and what the azeltrack package depends on, so that `apt install
# ./azeltrack.deb` needs no network). No prebuilt image is downloaded.
#
# The kernel modules the board needs that Debian's kernel lacks (gpio-sim; i2c-stub on arm64)
# are make_modules.sh's, built against this image's kernel; for another architecture than this
# machine's the root gets that kernel's headers, make and gcc for it.
#
# The result is cached in CACHE_DIR/KEY/, the key being a hash of this script, the package list
# and the kernel's ABI: root.img (raw ext4), vmlinuz, initrd.img, abi (the kernel's ABI).
#
# Usage: make_image.sh ARCH CACHE_DIR DEB…   prints the folder of the image on stdout. The DEBs
# (azeltrack's and the panel's) name the dependencies to preinstall; the panel's brings cage and
# cog, as `apt install` of it would on a Pi.
set -euo pipefail
arch=${1:?usage: make_image.sh ARCH CACHE_DIR DEB...}
cache_dir=${2:?usage: make_image.sh ARCH CACHE_DIR DEB...}
shift 2
debs=("$@")
say() { echo "system test: $*" >&2; }

# The kernel: for this machine's architecture, the ABI whose headers this machine has
# (install-deps --test installs linux-headers-ARCH), so that the module is built for exactly the
# image's kernel; for another, the archive's current one, its headers going into the root.
native=$(dpkg --print-architecture)
if [ "$arch" = "$native" ]; then
  abi=$(dpkg-query -W -f='${Depends}' "linux-headers-$arch" 2>/dev/null |
    grep -o "linux-headers-[0-9][^ ,]*" | head -1 | sed 's/^linux-headers-//')
  [ -n "$abi" ] || { say "linux-headers-$arch is not installed (scripts/install-deps --test)"; exit 1; }
else
  meta=$(apt-cache show "linux-image-$arch:$arch" 2>/dev/null || true)
  abi=$(grep -m1 '^Depends:' <<<"$meta" | grep -o "linux-image-[0-9][^ ,]*" | sed 's/^linux-image-//')
  [ -n "$abi" ] || { say "no linux-image-$arch:$arch in apt (scripts/install-deps --cross $arch)"; exit 1; }
  # mmdebstrap and the module's build run that architecture's programs through qemu-user, as
  # systemd-binfmt registers them on a machine with qemu-user-static.
  cpu=$(case "$arch" in arm64) echo aarch64 ;; armhf) echo arm ;; *) echo "$arch" ;; esac)
  misc=/proc/sys/fs/binfmt_misc
  [ -e "$misc/register" ] || mount -t binfmt_misc binfmt_misc "$misc"
  [ -e "$misc/qemu-$cpu" ] || cat "/usr/lib/binfmt.d/qemu-$cpu.conf" >"$misc/register"
fi

# Runtime dependencies of the packages under test, preinstalled: the machine has no network.
depends=$(for d in "${debs[@]}"; do dpkg-deb -f "$d" Depends; done | tr ',' '\n' |
  sed 's/([^)]*)//g; s/|.*//; s/[[:space:]]//g' | grep -v -e '^$' -e '^azeltrack$' | sort -u |
  tr '\n' ',')
recommends=chrony,swe-basic-data
tools=systemd,systemd-sysv,udev,kmod,dbus,initramfs-tools,linux-image-$abi,gpiod,i2c-tools,curl,procps,python3,e2fsprogs,iproute2
include="$tools,$recommends,${depends%,}"
[ "$arch" = "$native" ] || include="$include,linux-headers-$abi,make"
here=$(dirname "$0")
key=$( (cat "$0" "$here/guest/azt-payload.service"; echo "$arch $abi $include") | sha256sum | cut -c1-16)
out="$cache_dir/$arch-$key"
if [ -f "$out/done" ]; then
  echo "$out"
  exit 0
fi
say "making the $arch image (kernel $abi; cached as $out)"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/root"

# initramfs-tools' MODULES=most gives virtio_blk and ext4 to the initramfs. The root is found by
# its label: on arm64's -M virt the virtio-mmio disks are not named in command-line order.
mmdebstrap --variant=minbase --architecture="$arch" --include="$include" \
  --customize-hook='echo azt-system-test > "$1/etc/hostname"' \
  --customize-hook='echo "LABEL=azt-root / ext4 rw,errors=remount-ro 0 1" > "$1/etc/fstab"' \
  --customize-hook='chroot "$1" passwd -d root' \
  --customize-hook="copy-in $here/guest/azt-payload.service /etc/systemd/system" \
  --customize-hook='chroot "$1" systemctl enable azt-payload.service' \
  bookworm "$work/root" >"$work/mmdebstrap.log" 2>&1 ||
  { tail -30 "$work/mmdebstrap.log" >&2; say "mmdebstrap failed"; exit 1; }

mkdir -p "$out.part"
echo "$abi" >"$out.part/abi"
cp "$work"/root/boot/vmlinuz-* "$out.part/vmlinuz"
cp "$work"/root/boot/initrd.img-* "$out.part/initrd.img"
# 3 GiB, sparse: the root is about 1 GiB; the rest is room for the test's installs and journal.
mke2fs -q -t ext4 -L azt-root -d "$work/root" "$out.part/root.img" 3G >&2
touch "$out.part/done"
rm -rf "$out"
mv "$out.part" "$out"
# Older images of this architecture (another package list, kernel or script): 870 MB each.
for old in "$cache_dir/$arch"-*; do
  [ "$old" = "$out" ] || rm -rf "$old"
done
echo "$out"
