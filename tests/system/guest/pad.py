#!/usr/bin/env python3
"""Part of the system test inside the machine (guest/pad_stage): a game pad at the mast, made by
the kernel's uinput as a USB pad would appear: a left stick (ABS_X, ABS_Y, −32768..32767), a
D-pad (ABS_HAT0X/Y), A (BTN_SOUTH) and START, so that udev's input_id marks it a joystick and
the package's rule gives group azeltrack read access. It writes its event node to NODE_FILE,
then takes one command a line on stdin, each sent as the pad's events and a SYN_REPORT:
  abs CODE VALUE      an axis (0 ABS_X: the stick right is +32767)
  key CODE VALUE      a button (304 BTN_SOUTH), 1 pressed, 0 released
  quit                the pad unplugged (UI_DEV_DESTROY)
A command followed by `timed` then reads gpio-sim's LINES every 5 ms until all are 0 (at most
2 s) and writes the seconds since it was sent to NODE_FILE.off ("none" when they stayed on): a
figure the shell's polling could not give to better than a few tenths under emulation.
The structures and ioctls are linux/uinput.h's and linux/input.h's (x86_64 and arm64 layouts).
Usage: pad.py NODE_FILE SIM_DIR LINE..."""
import fcntl
import os
import struct
import sys
import time

EV_SYN, EV_KEY, EV_ABS = 0x00, 0x01, 0x03
ABS_X, ABS_Y, ABS_HAT0X, ABS_HAT0Y = 0x00, 0x01, 0x10, 0x11
BTN_SOUTH, BTN_START = 0x130, 0x13B
BUS_USB = 0x03


def iow(nr, size):
    """_IOW('U', nr, size): the write direction, the argument's size, uinput's 'U'."""
    return (1 << 30) | (size << 16) | (ord("U") << 8) | nr


UI_DEV_CREATE = (ord("U") << 8) | 1
UI_DEV_DESTROY = (ord("U") << 8) | 2
UI_DEV_SETUP = iow(3, 92)        # struct uinput_setup: input_id, name[80], ff_effects_max
UI_ABS_SETUP = iow(4, 28)        # struct uinput_abs_setup: code, pad, struct input_absinfo
UI_SET_EVBIT = iow(100, 4)
UI_SET_KEYBIT = iow(101, 4)
UI_SET_ABSBIT = iow(103, 4)
NAME = b"azeltrack system test pad"


def event(fd, kind, code, value):
    """struct input_event: a timeval (zero: the kernel stamps it), type, code, value."""
    os.write(fd, struct.pack("llHHi", 0, 0, kind, code, value))


def make_pad():
    fd = os.open("/dev/uinput", os.O_WRONLY | os.O_NONBLOCK)
    for kind in (EV_KEY, EV_ABS):
        fcntl.ioctl(fd, UI_SET_EVBIT, kind)
    for key in (BTN_SOUTH, BTN_START):
        fcntl.ioctl(fd, UI_SET_KEYBIT, key)
    axes = {ABS_X: (-32768, 32767, 128), ABS_Y: (-32768, 32767, 128),
            ABS_HAT0X: (-1, 1, 0), ABS_HAT0Y: (-1, 1, 0)}
    for code, (low, high, flat) in axes.items():
        fcntl.ioctl(fd, UI_SET_ABSBIT, code)
        fcntl.ioctl(fd, UI_ABS_SETUP, struct.pack("HHiiiiii", code, 0, 0, low, high, 16, flat, 0))
    fcntl.ioctl(fd, UI_DEV_SETUP, struct.pack("HHHH80sI", BUS_USB, 0x045E, 0x028E, 1, NAME, 0))
    fcntl.ioctl(fd, UI_DEV_CREATE)
    return fd


def node_of_pad():
    """/dev/input/eventN of the pad, once the kernel has made it."""
    for _ in range(100):
        for entry in sorted(os.listdir("/sys/class/input")):
            name = f"/sys/class/input/{entry}/device/name"
            if entry.startswith("event") and os.path.exists(name):
                with open(name, "rb") as f:
                    if f.read().strip() == NAME:
                        return f"/dev/input/{entry}"
        time.sleep(0.05)
    raise SystemExit("the pad's event node did not appear")


def lines_off_after(sim, lines, sent):
    """Seconds from `sent` until every line reads 0; None after 2 s."""
    while time.monotonic() - sent < 2.0:
        values = []
        for line in lines:
            with open(f"{sim}/sim_gpio{line}/value", encoding="ascii") as f:
                values.append(f.read().strip())
        if all(v == "0" for v in values):
            return time.monotonic() - sent
        time.sleep(0.005)
    return None


def report_off(path, sim, lines, sent):
    took = lines_off_after(sim, lines, sent)
    with open(path + ".new", "w", encoding="ascii") as f:
        f.write("none\n" if took is None else f"{took:.3f}\n")
    os.replace(path + ".new", path)


def main():
    sim, lines = sys.argv[2], sys.argv[3:]
    fd = make_pad()
    with open(sys.argv[1] + ".new", "w", encoding="ascii") as f:
        f.write(node_of_pad() + "\n")
    os.replace(sys.argv[1] + ".new", sys.argv[1])
    timed = False
    for line in sys.stdin:
        words = line.split()
        timed = words[-1:] == ["timed"]
        if not words or words[0] == "quit":
            break
        kind = EV_ABS if words[0] == "abs" else EV_KEY
        event(fd, kind, int(words[1]), int(words[2]))
        event(fd, EV_SYN, 0, 0)
        if timed:
            report_off(sys.argv[1] + ".off", sim, lines, time.monotonic())
    sent = time.monotonic()
    fcntl.ioctl(fd, UI_DEV_DESTROY)
    os.close(fd)
    if timed:
        report_off(sys.argv[1] + ".off", sim, lines, sent)
    return 0


if __name__ == "__main__":
    sys.exit(main())
