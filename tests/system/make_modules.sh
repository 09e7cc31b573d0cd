#!/usr/bin/env bash
# The kernel modules the system test's board needs that Debian's kernel does not build, made for
# the image's kernel from Debian's linux-source-6.1 (GPL-2.0 code of the kernel: built here, never
# committed), cached beside the image it is for:
# - gpio-sim, the kernel's GPIO simulator, with the interrupt simulator it needs. Debian's 6.1
#   builds neither (# CONFIG_GPIO_SIM is not set, nor CONFIG_IRQ_SIM); irq_sim.c's one call 6.1
#   does not export (irq_to_desc) is replaced by its exported equivalent (generic_handle_irq):
#   round3-notes §5.2 has the finding.
# - i2c-stub, where the kernel lacks it (Debian's arm64 6.1: # CONFIG_I2C_STUB is not set; its
#   amd64 kernel has it as a module).
# For this machine's architecture the modules are built against the headers installed here; for
# another (arm64) inside the image's root, mounted read-only, with its own gcc and headers run
# through qemu-user (binfmt_misc), as they would be built on a Pi.
#
# Usage: make_modules.sh ARCH IMAGE_DIR   prints the modules' folder on stdout.
set -euo pipefail
arch=${1:?usage: make_modules.sh ARCH IMAGE_DIR}
image=${2:?usage: make_modules.sh ARCH IMAGE_DIR}
say() { echo "system test: $*" >&2; }
abi=$(cat "$image/abi")
key=$( (cat "$0"; echo "$arch $abi") | sha256sum | cut -c1-16)
out="$image/modules-$key"
if [ -f "$out/done" ]; then
  echo "$out"
  exit 0
fi
work=$(mktemp -d)
mnt=$work/root
cleanup() {
  mountpoint -q "$mnt/tmp" && umount "$mnt/tmp"
  mountpoint -q "$mnt/dev" && umount "$mnt/dev"
  mountpoint -q "$mnt" && umount "$mnt"
  rm -rf "$work"
}
trap cleanup EXIT
mkdir -p "$work/src/modules" "$mnt"
say "building gpio-sim.ko (and i2c-stub.ko where missing) for $abi from linux-source-6.1"
tar -xJf /usr/src/linux-source-6.1.tar.xz -C "$work/src" --wildcards \
  '*/drivers/gpio/gpio-sim.c' '*/drivers/gpio/gpiolib.h' '*/kernel/irq/irq_sim.c' \
  '*/drivers/i2c/i2c-stub.c'
src=$work/src/linux-source-6.1
mods=$work/src/modules
cp "$src/drivers/gpio/gpio-sim.c" "$mods/gpio-sim-core.c"
cp "$src/drivers/gpio/gpiolib.h" "$mods/"
sed 's/handle_simple_irq(irq_to_desc(\([a-z_]*\)))/generic_handle_irq(\1)/' \
  "$src/kernel/irq/irq_sim.c" >"$mods/irq_sim.c"
grep -q 'generic_handle_irq(' "$mods/irq_sim.c" ||
  { say "irq_sim.c changed: the irq_to_desc call to replace is not there"; exit 1; }
printf 'obj-m := gpio-sim.o\ngpio-sim-y := gpio-sim-core.o irq_sim.o\n' >"$mods/Kbuild"
mount -o loop,ro "$image/root.img" "$mnt"
if grep -q '^# CONFIG_I2C_STUB is not set' "$mnt/boot/config-$abi"; then
  cp "$src/drivers/i2c/i2c-stub.c" "$mods/"
  echo 'obj-m += i2c-stub.o' >>"$mods/Kbuild"
fi
if [ "$arch" = "$(dpkg --print-architecture)" ]; then
  make -s -C "/usr/src/linux-headers-$abi" M="$mods" modules >"$work/kbuild.log" 2>&1
else
  mount -t tmpfs tmpfs "$mnt/tmp"
  mount --bind /dev "$mnt/dev"
  cp -r "$mods" "$mnt/tmp/modules"
  chroot "$mnt" make -s -C "/usr/src/linux-headers-$abi" M=/tmp/modules modules \
    >"$work/kbuild.log" 2>&1 && cp "$mnt"/tmp/modules/*.ko "$mods/"
fi || { cat "$work/kbuild.log" >&2; say "the modules did not build"; exit 1; }
mkdir -p "$out.part"
cp "$mods"/*.ko "$out.part/"
touch "$out.part/done"
rm -rf "$out"
mv "$out.part" "$out"
for old in "$image"/modules-*; do
  [ "$old" = "$out" ] || rm -rf "$old"
done
echo "$out"
