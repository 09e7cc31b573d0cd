#!/usr/bin/env bash
# The Debian 12 machine the system test boots (issue 28): a root file system made by mmdebstrap
# from Debian's packages alone (systemd, udev, Debian's kernel and initramfs, chrony, the GPIO and
# I2C tools, and what the azeltrack package depends on, so that `apt install ./azeltrack.deb`
# needs no network), and the kernel's GPIO simulator built as a module for that kernel. No
# prebuilt image is downloaded.
#
# Debian's 6.1 kernel does not build gpio-sim (# CONFIG_GPIO_SIM is not set) nor the interrupt
# simulator it needs (CONFIG_IRQ_SIM), so the module is built here from linux-source-6.1's
# gpio-sim.c and irq_sim.c against the image kernel's headers, with the one call irq_sim.c
# makes that 6.1 does not export (irq_to_desc) replaced by its exported equivalent
# (generic_handle_irq): round3-notes §5.2 has the finding. The module is GPL-2.0 code of the
# kernel: built here, never committed.
#
# The result is cached in CACHE_DIR/KEY/, the key being a hash of this script, the package list
# and the kernel's ABI: root.img (raw ext4), vmlinuz, initrd.img, gpio-sim.ko.
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

# The kernel: the ABI whose headers this machine has (install-deps --test installs
# linux-headers-ARCH), so that the module is built for exactly the image's kernel.
kernel_flavour=$arch
[ "$arch" = arm64 ] && kernel_flavour=arm64
abi=$(dpkg-query -W -f='${Depends}' "linux-headers-$kernel_flavour" 2>/dev/null |
  grep -o "linux-headers-[0-9][^ ,]*" | head -1 | sed 's/^linux-headers-//')
[ -n "$abi" ] || { say "linux-headers-$kernel_flavour is not installed (scripts/install-deps --test)"; exit 1; }

# Runtime dependencies of the packages under test, preinstalled: the machine has no network.
depends=$(for d in "${debs[@]}"; do dpkg-deb -f "$d" Depends; done | tr ',' '\n' |
  sed 's/([^)]*)//g; s/|.*//; s/[[:space:]]//g' | grep -v -e '^$' -e '^azeltrack$' | sort -u |
  tr '\n' ',')
recommends=chrony,swe-basic-data
tools=systemd,systemd-sysv,udev,kmod,dbus,initramfs-tools,linux-image-$abi,gpiod,i2c-tools,curl,procps,python3,e2fsprogs,iproute2
include="$tools,$recommends,${depends%,}"
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

# initramfs-tools' MODULES=most gives virtio_blk and ext4 to the initramfs; root on /dev/vda.
mmdebstrap --variant=minbase --architecture="$arch" --include="$include" \
  --customize-hook='echo azt-system-test > "$1/etc/hostname"' \
  --customize-hook='echo "/dev/vda / ext4 rw,errors=remount-ro 0 1" > "$1/etc/fstab"' \
  --customize-hook='chroot "$1" passwd -d root' \
  --customize-hook="copy-in $here/guest/azt-payload.service /etc/systemd/system" \
  --customize-hook='chroot "$1" systemctl enable azt-payload.service' \
  bookworm "$work/root" >"$work/mmdebstrap.log" 2>&1 ||
  { tail -30 "$work/mmdebstrap.log" >&2; say "mmdebstrap failed"; exit 1; }

say "building gpio-sim.ko for $abi from linux-source-6.1"
mkdir -p "$work/gpio-sim"
tar -xJf /usr/src/linux-source-6.1.tar.xz -C "$work" --wildcards \
  '*/drivers/gpio/gpio-sim.c' '*/drivers/gpio/gpiolib.h' '*/kernel/irq/irq_sim.c'
src=$work/linux-source-6.1
cp "$src/drivers/gpio/gpio-sim.c" "$work/gpio-sim/gpio-sim-core.c"
cp "$src/drivers/gpio/gpiolib.h" "$work/gpio-sim/"
sed 's/handle_simple_irq(irq_to_desc(\([a-z_]*\)))/generic_handle_irq(\1)/' \
  "$src/kernel/irq/irq_sim.c" >"$work/gpio-sim/irq_sim.c"
grep -q 'generic_handle_irq(' "$work/gpio-sim/irq_sim.c" ||
  { say "irq_sim.c changed: the irq_to_desc call to replace is not there"; exit 1; }
printf 'obj-m := gpio-sim.o\ngpio-sim-y := gpio-sim-core.o irq_sim.o\n' >"$work/gpio-sim/Kbuild"
make -s -C "/usr/src/linux-headers-$abi" M="$work/gpio-sim" modules >"$work/kbuild.log" 2>&1 ||
  { cat "$work/kbuild.log" >&2; say "gpio-sim did not build"; exit 1; }

mkdir -p "$out.part"
cp "$work/gpio-sim/gpio-sim.ko" "$out.part/"
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
