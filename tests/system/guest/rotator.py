#!/usr/bin/env python3
"""Part of the system test inside the machine: the rotator behind the Pi's header (guest/board
makes the header; guest/run installs this as azt-rotator.service, before azeltrack). Two motors
run while their relay lines are energised (gpio-sim lines 6 AZ CW, 7 AZ CCW, 8 EL UP, 9 EL DOWN,
read from the simulator's `value` files) at a fixed speed, and each axis's pot is the voltage its
ADS1115 converts: the angle as the 15-bit code of the daemon's pot_calibration, written to the
i2c-stub chip's Conversion register (0x00) as the SMBus word the chip would send (its first
byte, the code's high byte, low in the word). The daemon reads it through i2c-dev as a Pi reads
an ADS1115; nothing here talks to the daemon. The azimuth also has a reed and a home switch, both
to ground (closed: the line pulled down, as the daemon's pull-up then reads it low), on lines 12
and 13: the reed is closed for the first half of each of its counts, the home switch at and below
its angle (guest/pulses counts them).

Usage: rotator.py SIM_DIR I2C_DEV [--once]   (--once: write the start angles and exit)"""
import ctypes
import fcntl
import os
import sys
import time

I2C_SLAVE = 0x0703
I2C_SMBUS = 0x0720
I2C_SMBUS_WRITE = 0
I2C_SMBUS_WORD_DATA = 3

# Each axis: its chip, its relay lines (+, -), its speed, its start and the daemon's
# pot_calibration (guest/run sets the same numbers: code = c0 + deg * (c1 - c0) / span).
AXES = {
    "az": {"addr": 0x48, "plus": 6, "minus": 7, "deg_s": 5.0, "deg": 100.0, "span": 450.0},
    "el": {"addr": 0x49, "plus": 8, "minus": 9, "deg_s": 4.0, "deg": 10.0, "span": 180.0},
}
CODE_0, CODE_1 = 1000, 25000
REED, HOME = 12, 13
COUNTS_PER_DEG, HOME_DEG = 0.5, 120.0  # guest/pulses sets the same counts_per_deg and home_deg
STATE = "/run/azt-rotator"  # the angles, for the test's log: "az el"


class SmbusData(ctypes.Union):
    _fields_ = [("byte", ctypes.c_uint8), ("word", ctypes.c_uint16),
                ("block", ctypes.c_uint8 * 34)]


class SmbusCall(ctypes.Structure):
    _fields_ = [("read_write", ctypes.c_uint8), ("command", ctypes.c_uint8),
                ("size", ctypes.c_uint32), ("data", ctypes.POINTER(SmbusData))]


def write_code(fd, addr, code):
    """The ADS1115's Conversion register holds `code` (its two bytes high first on the wire)."""
    u = code & 0xFFFF
    data = SmbusData()
    data.word = (u >> 8) | ((u & 0xFF) << 8)
    fcntl.ioctl(fd, I2C_SLAVE, addr)
    fcntl.ioctl(fd, I2C_SMBUS, SmbusCall(I2C_SMBUS_WRITE, 0x00, I2C_SMBUS_WORD_DATA,
                                         ctypes.pointer(data)))


def code_of(axis):
    return round(CODE_0 + axis["deg"] * (CODE_1 - CODE_0) / axis["span"])


def relay(sim, line):
    with open(f"{sim}/sim_gpio{line}/value", encoding="ascii") as f:
        return f.read().strip() == "1"


def set_closed(sim, line, closed):
    """A switch to ground: closed pulls the line down. Written every turn, since a consumer's
    request sets the pull to its own bias (a rewrite of the same pull makes no edge)."""
    with open(f"{sim}/sim_gpio{line}/pull", "w", encoding="ascii") as f:
        f.write("pull-down" if closed else "pull-up")


def switches(sim):
    az = AXES["az"]["deg"]
    set_closed(sim, REED, (az * COUNTS_PER_DEG) % 1.0 < 0.5)
    set_closed(sim, HOME, az <= HOME_DEG)


def publish(fd, sim):
    switches(sim)
    for axis in AXES.values():
        write_code(fd, axis["addr"], code_of(axis))
    with open(STATE + ".new", "w", encoding="ascii") as f:
        f.write(f"{AXES['az']['deg']:.2f} {AXES['el']['deg']:.2f}\n")
    os.replace(STATE + ".new", STATE)


def main():
    sim, dev = sys.argv[1], sys.argv[2]
    fd = os.open(dev, os.O_RDWR)
    publish(fd, sim)
    if "--once" in sys.argv:
        return 0
    last = time.monotonic()
    while True:
        time.sleep(0.02)
        now = time.monotonic()
        dt, last = now - last, now
        for axis in AXES.values():
            direction = relay(sim, axis["plus"]) - relay(sim, axis["minus"])
            axis["deg"] += direction * axis["deg_s"] * dt
        publish(fd, sim)


if __name__ == "__main__":
    sys.exit(main())
