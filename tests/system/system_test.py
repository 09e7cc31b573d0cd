#!/usr/bin/env python3
"""The Debian package on a real system (docs/packaging.md): a Debian 12 machine under qemu, made
from Debian's packages by make_image.sh (cached outside the clone), boots with its own kernel,
systemd and udev and no network; a payload disk carries the packages and the test (guest/run), which
installs, runs, crashes, hangs, updates, reboots and purges azeltrack as a user would on a Pi and
reports each step on the second serial port. This prints one line per step with its figure, the
accelerator and the wall time, then "N passed, M failed".

Exit status 0 when every step passed, 77 when it cannot run here (not root), 1 otherwise.

Usage (as root): system_test.py DEB_N DEB_N_PLUS_1 --panel PANEL_DEB_N [--cache-dir DIR]
                [--arch amd64|arm64]
KVM is used when AZT_SYSTEM_ACCEL=kvm (nested KVM fails on the reference machine); TCG else.
arm64 is qemu-system-aarch64's -M virt under TCG, the packages being the arm64 ones."""
import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
SIGNING = os.path.join(HERE, "..", "data", "software", "signing")
TEST_KEY = "FC4892F01AAC91A16E33CF6BD790D49363F83F75"  # tests/data/software/signing
QEMU = {"amd64": "qemu-system-x86_64", "arm64": "qemu-system-aarch64"}


def log(text):
    print(f"system test: {text}", file=sys.stderr, flush=True)


def sign(deb, out):
    """`deb` with the tests' key's origin signature (the key the guest trusts, as an operator
    adds their own with azeltrack-update-keys)."""
    shutil.copy(deb, out)
    with tempfile.TemporaryDirectory() as home:
        quiet = {"env": dict(os.environ, GNUPGHOME=home), "check": True, "capture_output": True}
        subprocess.run(["gpg", "--batch", "--import",
                        os.path.join(SIGNING, "test-key.secret.asc")], **quiet)
        subprocess.run(["debsigs", "--sign=origin", f"--default-key={TEST_KEY}", out], **quiet)


def make_payload(work, modules, debs, broken_udev):
    """The payload disk: the test, the packages (N, the panel's, and N+1 signed), the key."""
    payload = os.path.join(work, "payload")
    os.makedirs(os.path.join(payload, "debs"))
    if broken_udev:
        open(os.path.join(payload, "break-udev"), "w", encoding="ascii").close()
    for name in ("run", "pulses", "gamepad", "pad.py", "gpio_watch.py", "board", "rotator.py",
                 "rotctld_p.py"):
        shutil.copy(os.path.join(HERE, "guest", name), payload)
    shutil.copy(debs.deb_n, os.path.join(payload, "debs", "azeltrack_N.deb"))
    shutil.copy(debs.panel, os.path.join(payload, "debs", "azeltrack-panel.deb"))
    sign(debs.deb_n1, os.path.join(payload, "debs", "azeltrack_N1_signed.deb"))
    shutil.copy(os.path.join(SIGNING, "test-key.asc"), payload)
    for module in os.listdir(modules):  # gpio-sim.ko, and i2c-stub.ko where the kernel lacks it
        shutil.copy(os.path.join(modules, module), payload)
    img = os.path.join(work, "payload.img")
    subprocess.run(["mke2fs", "-q", "-t", "ext4", "-L", "azt-payload", "-d", payload, img, "64M"],
                   check=True)
    return img


def qemu_command(arch, image, overlay, payload, work, accel):
    """The machine: Debian's kernel booted directly, the root and the payload on virtio disks,
    the kernel's console on the first serial port and the test's results on a second channel
    (a second UART on a PC; on arm64's -M virt, which has one PL011, a virtio serial port).
    arm64 runs a Cortex-A72, a Raspberry Pi 4's core."""
    console = os.path.join(work, "console.log")
    results = os.path.join(work, "results.log")
    common = ["-accel", accel, "-m", "1536", "-smp", "2", "-display", "none",
              "-monitor", "none", "-nic", "none",
              "-kernel", os.path.join(image, "vmlinuz"),
              "-initrd", os.path.join(image, "initrd.img"),
              "-drive", f"file={overlay},if=virtio,format=qcow2",
              "-drive", f"file={payload},if=virtio,format=raw,readonly=on"]
    boot = "root=LABEL=azt-root rw quiet systemd.show_status=0"
    if arch == "arm64":
        return ["qemu-system-aarch64", "-M", "virt", "-cpu", "cortex-a72", *common,
                "-append", f"{boot} console=ttyAMA0", "-serial", f"file:{console}",
                "-device", "virtio-serial-device",
                "-chardev", f"file,id=results,path={results}",
                "-device", "virtserialport,chardev=results,name=azt.results"]
    return ["qemu-system-x86_64", *common, "-append", f"{boot} console=ttyS0",
            "-serial", f"file:{console}", "-serial", f"file:{results}"]


def follow(qemu, results_path, started, timeout_s):
    """Prints each result line as the guest writes it; returns them all when qemu exits."""
    seen = 0
    lines = []
    while True:
        done = qemu.poll() is not None
        if os.path.exists(results_path):
            with open(results_path, encoding="utf-8", errors="replace") as f:
                text = f.read()
            new = text.splitlines()[seen:] if text.endswith("\n") or done else \
                text.splitlines()[seen:-1]
            for line in new:
                print(f"  [{time.monotonic() - started:5.0f} s] {line.strip()}", flush=True)
            seen += len(new)
            lines += new
        if done:
            return lines
        if time.monotonic() - started > timeout_s:
            qemu.kill()
            qemu.wait()
            lines.append(f"STEP FAIL timeout: the machine was still running after {timeout_s} s")
            return lines
        time.sleep(0.5)


def expect_gpio_refused(steps):
    """With the wrong group in the udev rule the device must not be the daemon's: the ACL step
    and the daemon's start on the lines fail. Those failures become this run's passes."""
    out = []
    for line in steps:
        name = line.split()[2].rstrip(":")
        if name in ("gpio_acl", "gpio_start"):
            ok = line.startswith("STEP FAIL ")
            out.append(f"STEP {'ok' if ok else 'FAIL'} {name}_refused: " +
                       ("failed as it must: " if ok else "passed with a broken rule: ") + line)
        elif not name.startswith("gpio_") or name in ("gpio_module", "gpio_config"):
            out.append(line)
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("deb_n")
    ap.add_argument("deb_n1")
    ap.add_argument("--panel", required=True, help="the azeltrack-panel package of version N")
    ap.add_argument("--cache-dir", default=os.path.expanduser("~/.cache/azeltrack/system"))
    ap.add_argument("--arch", default="amd64")
    ap.add_argument("--timeout", type=int, help="seconds (default 900; arm64, emulated: 3600)")
    ap.add_argument("--broken-udev", action="store_true",
                    help="the proof: with the package's udev rule naming the wrong group, the "
                         "GPIO step must fail (and only the install and GPIO steps run)")
    args = ap.parse_args()
    if os.geteuid() != 0:
        print("system test: skipped: mmdebstrap and mke2fs -d of a root tree need root")
        return 77
    accel = os.environ.get("AZT_SYSTEM_ACCEL", "tcg")
    t0 = time.monotonic()
    image = subprocess.run([os.path.join(HERE, "make_image.sh"), args.arch, args.cache_dir,
                            args.deb_n, args.panel], check=True, capture_output=False,
                           stdout=subprocess.PIPE, text=True).stdout.strip()
    modules = subprocess.run([os.path.join(HERE, "make_modules.sh"), args.arch, image],
                             check=True, stdout=subprocess.PIPE, text=True).stdout.strip()
    log(f"image ready in {time.monotonic() - t0:.0f} s: {image}")
    with tempfile.TemporaryDirectory(prefix="azt-system-") as work:
        payload = make_payload(work, modules, args, args.broken_udev)
        overlay = os.path.join(work, "root.qcow2")
        subprocess.run(["qemu-img", "create", "-q", "-f", "qcow2", "-F", "raw", "-b",
                        os.path.join(image, "root.img"), overlay], check=True)
        log(f"booting ({QEMU[args.arch]}, {accel}); one line per step")
        started = time.monotonic()
        qemu = subprocess.Popen(qemu_command(args.arch, image, overlay, payload, work, accel),
                                stdin=subprocess.DEVNULL)
        timeout_s = args.timeout or (900 if args.arch == "amd64" else 3600)
        lines = follow(qemu, os.path.join(work, "results.log"), started, timeout_s)
        wall = time.monotonic() - started
        steps = [l for l in lines if l.startswith("STEP ")]
        if args.broken_udev:
            steps = expect_gpio_refused(steps)
        failed = [l for l in steps if not l.startswith("STEP ok ")]
        passed = len(steps) - len(failed)
        if not any(l.strip() == "DONE" for l in lines):
            failed.append("the test did not finish (the machine's console's last lines above)")
            with open(os.path.join(work, "console.log"), encoding="utf-8",
                      errors="replace") as f:
                print("".join(f.readlines()[-40:]), file=sys.stderr)
    print(f"system test: {args.arch} under {accel}, machine wall time {wall:.0f} s "
          f"(image {started - t0:.0f} s)")
    for line in failed:
        print(f"  failed: {line}")
    print(f"{passed} passed, {len(failed)} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
