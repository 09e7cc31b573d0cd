#!/usr/bin/env python3
"""Satellite Doppler on the rig (docs/radio.md) against python3-skyfield: `azeltrack serve` tracking
the ISS of tests/data/sat/iss_2024.tle from FN06HE with `[radio] doppler = "satellite"`, and
Hamlib's rigctld with its dummy rig.

 1  ten instants across a high pass (one daemon start each, `--utc-start`): the VFOs read back with
    `rigctl -m 2 … f` and `i` are the state's rx_hz and tx_hz, and each is the transmitter's
    nominal frequency corrected for skyfield's range rate at the instant the state gives for it
    (`at_unix_s`, `tx_at_unix_s`) within 5 Hz: an FM bird (145.800 down, 437.800 up) at four of
    them, an inverting and a non-inverting transponder (435.850 down, 145.950 up) at three each,
    so each leg is checked at 145 and at 435 MHz
 2  at the second and third instants the dial is turned up 20 kHz (`rigctl … F`): on the
    inverting transponder the uplink moves down by as much, on the other up by as much (in the
    satellite's frame, within 5 Hz: the rig's frequencies taken back through skyfield's range
    rates)

The oracle uses the exact classical forms: heard f/(1 + ṙ/c), sent f/(1 − ṙ/c), ṙ positive
receding. The first-order forms f·(1 ∓ ṙ/c) differ from them by f·(ṙ/c)², 0.24 Hz at 435 MHz at
7 km/s: inside the tolerance either way, so the 5 Hz checks the range rate and the instant, not the
choice of form (tests/unit/orbit/link_doppler_test.cpp checks that).

rigctld runs in VFO mode (`-o`): Hamlib 4.5.4's rigctl reads `i` from a plain-mode rigctld with
`f`, the main VFO, so only in VFO mode does `rigctl … i currVFO` show the split frequency (the
daemon's plain-mode conversation is radio_test.py's). Both VFOs are read in one rigctl run (50 ms),
so that near the closest approach, where the daemon writes every 200 ms cycle, the state read
before or after still says what the rig holds.

Usage: radio_satellite_test.py AZELTRACK"""
import datetime
import os
import subprocess
import sys
import tempfile
import time

from daemon_harness import Checks, free_port, http_json, wait_until, stop_at_exit
from satellite_doppler_oracle import (C_KM_S, GRID, LAT, LON, TLE, heard_hz, high_pass, iso,
                                      range_rate_km_s, sent_hz, ut1_minus_utc_s)

BIN = os.path.realpath(sys.argv[1])
TMP = tempfile.mkdtemp(prefix="azt-radio-sat-")
TOLERANCE_HZ = 5.0
TURN_HZ = 20000.0
check = Checks()
procs = []

FM = {"downlink_mhz": 145.800, "uplink_mhz": 437.800, "mode": "fm"}
INVERTING = {"downlink_mhz": 435.850, "uplink_mhz": 145.950, "mode": "linear_inverting"}
LINEAR = {"downlink_mhz": 435.850, "uplink_mhz": 145.950, "mode": "linear"}


stop_at_exit(procs, TMP)


def write_config(path, web, rig, transmitter, dut1_s):
    """The daemon's UT1 is skyfield's at the pass, so that the two compare Doppler, not Earth
    orientations (0.16 s of UT1 moves the site 75 m: up to 1.5 Hz at 435 MHz)."""
    with open(path, "w", encoding="utf-8") as f:
        f.write(f'schema_version = 2\n[station]\ngrid = "{GRID}"\n[target]\nname = "sat:25544"\n'
                f'[sky]\ndut1_s = {dut1_s!r}\n'
                f'[rotctld]\nport = 0\n[pstrotator]\nport = 0\n[web]\nport = {web}\n'
                f'[satellites]\nfile = "{TLE}"\n'
                f'[radio]\nrigctld = "127.0.0.1:{rig}"\ndoppler = "satellite"\n'
                f'[[satellites.transmitter]]\nnorad = "25544"\n'
                f'downlink_mhz = {transmitter["downlink_mhz"]}\n'
                f'uplink_mhz = {transmitter["uplink_mhz"]}\nmode = "{transmitter["mode"]}"\n')


RIG = free_port()
WEB = free_port()
BASE = f"http://127.0.0.1:{WEB}"
procs.append(subprocess.Popen(["rigctld", "-m", "1", "-o", "-T", "127.0.0.1", "-t", str(RIG)],
                              stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL))


def rigctl(*args):
    """The answers of one `rigctl` run. Against a VFO-mode rigctld every command takes a VFO,
    `currVFO` here (the main VFO; `i` answers for the split's TX VFO)."""
    out = subprocess.run(["rigctl", "-m", "2", "-r", f"127.0.0.1:{RIG}", *args],
                         capture_output=True, text=True, timeout=5, check=True)
    return out.stdout.split()


def radio_state():
    return http_json(BASE, "GET", "/api/state")[1]["radio"]


class Daemon:
    """`azeltrack serve` at a UTC instant with one transmitter, until the rig has both legs."""

    def __init__(self, transmitter, utc_unix_s):
        config = os.path.join(TMP, f"{transmitter['mode']}.toml")
        # Once per transmitter: the first start adds a console password (an Argon2 hash, slow).
        if not os.path.exists(config):
            write_config(config, WEB, RIG, transmitter, DUT1_S)
        self.log = os.path.join(TMP, "daemon.log")
        with open(self.log, "w", encoding="utf-8") as log:
            self.proc = subprocess.Popen([BIN, "serve", "--config", config, "--utc-start",
                                          iso(utc_unix_s)], stdout=log, stderr=subprocess.STDOUT)
        procs.append(self.proc)
        self.ready = wait_until(lambda: radio_state()["tx_hz"] is not None, 10, 0.05)
        if not self.ready:
            print(open(self.log, encoding="utf-8").read(), file=sys.stderr)

    def stop(self):
        self.proc.terminate()
        self.proc.wait(10)


def daemon_unix_s():
    utc = http_json(BASE, "GET", "/api/state")[1]["utc"]
    return datetime.datetime.fromisoformat(utc.replace("Z", "+00:00")).timestamp()


last_sample = []  # for a failure's message


def sample(wanted=lambda rx, tx, rx_at, tx_at: True):
    """(rig RX, rig TX, RX instant, TX instant): the rig's VFOs, each with the state that says
    it was written (read before and after the rig, since the daemon writes every cycle it must),
    the first that is `wanted`; None if none was within 5 s."""
    end = time.monotonic() + 5.0
    while time.monotonic() < end:
        before = radio_state()
        rx, tx = (float(hz) for hz in rigctl("f", "currVFO", "i", "currVFO"))
        after = radio_state()
        rx_at = [s["at_unix_s"] for s in (before, after) if s["rx_hz"] == rx]
        tx_at = [s["tx_at_unix_s"] for s in (before, after) if s["tx_hz"] == tx]
        if rx_at and tx_at:
            last_sample[:] = [rx, tx, rx_at[-1], tx_at[-1]]
            if wanted(*last_sample):
                return tuple(last_sample)
        time.sleep(0.05)
    return None


def compare_with_skyfield(n, transmitter, got):
    """Checks both VFOs of instant `n` against the oracle; keeps the largest difference a band."""
    rx, tx, rx_at, tx_at = got
    want_rx = heard_hz(transmitter["downlink_mhz"] * 1e6, rx_at)
    want_tx = sent_hz(transmitter["uplink_mhz"] * 1e6, tx_at)
    print(f"1: {iso(rx_at)} {transmitter['mode']:16} ṙ {range_rate_km_s(rx_at):+.4f} km/s: "
          f"RX {rx:.0f} ({rx - want_rx:+.2f} Hz), TX {tx:.0f} ({tx - want_tx:+.2f} Hz)")
    for leg, error, hz in (("RX", rx - want_rx, rx), ("TX", tx - want_tx, tx)):
        band = f"{leg} {hz / 1e6:.0f}"
        worst[band] = max(worst.get(band, 0.0), abs(error))
        check(abs(error) <= TOLERANCE_HZ, f"1: instant {n} {leg}: {error:+.2f} Hz from skyfield")


def turn_the_dial(transmitter, before, sign):
    """Turns the dial up TURN_HZ from `before` (a sample); checks the uplink moves sign·as much."""
    label = f"2: {transmitter['mode']}"
    dial_hz = before[0] + TURN_HZ
    rigctl("F", "currVFO", str(int(dial_hz)))
    took = float(rigctl("f", "currVFO")[0])
    turned_by = daemon_unix_s()  # the daemon's clock: the turn was before this
    check(abs(took - dial_hz) < 1000, f"{label}: the rig took the turn: {took:.0f}")
    # Both legs written for the new place: an RX near the turned dial (a dial written over would
    # never be), and a TX computed after the daemon read the dial, which is within a cycle of
    # the turn (0.2 s; 0.5 s allowed).
    after = sample(lambda rx, tx, rx_at, tx_at: abs(rx - dial_hz) < 1000 and
                   tx_at >= turned_by + 0.5)
    if not check(after is not None, f"{label}: the turned dial {dial_hz:.0f} kept and both legs "
                                    f"rewritten: the last seen {last_sample}"):
        return
    rx, tx, rx_at, tx_at = after
    down = transmitter["downlink_mhz"] * 1e6
    up = transmitter["uplink_mhz"] * 1e6
    # The place in the passband, in the satellite's frame, from the rig's frequencies.
    moved_down = rx * (1 + range_rate_km_s(rx_at) / C_KM_S) - down
    moved_up = tx * (1 - range_rate_km_s(tx_at) / C_KM_S) - up
    # The dial is read some time after the turn: its place is what the turned dial means at the
    # range rate then, which has moved since the last write before the turn.
    drift_hz = down * abs(range_rate_km_s(rx_at) - range_rate_km_s(before[2])) / C_KM_S
    print(f"{label}: dial +{TURN_HZ:.0f} Hz: downlink moved {moved_down:+.2f} Hz, uplink "
          f"{moved_up:+.2f} Hz (satellite frame; Doppler drift since the turn {drift_hz:.1f} Hz)")
    check(abs(moved_down - TURN_HZ) <= TOLERANCE_HZ + drift_hz,
          f"{label}: the downlink follows the dial: {moved_down:+.2f}")
    check(abs(moved_up - sign * moved_down) <= TOLERANCE_HZ,
          f"{label}: the uplink moves {sign:+d}× the downlink: {moved_up:+.2f} vs {moved_down:+.2f}")


started = time.monotonic()
rise, setting = high_pass()
DUT1_S = ut1_minus_utc_s((rise + setting) / 2)
print(f"pass {iso(rise)} to {iso(setting)} over {GRID} ({LAT:.4f}, {LON:.4f}), "
      f"UT1-UTC {DUT1_S:.4f} s")

# 1 (and 2 early in the pass, where the Doppler drifts least while the dial is read).
worst = {}
DIAL_TURNED = {1: -1, 2: +1}  # instant: which way the uplink must move
for n in range(10):
    transmitter = (FM, INVERTING, LINEAR)[n % 3]
    daemon = Daemon(transmitter, rise + 30 + n * (setting - rise - 60) / 9)
    got = sample() if daemon.ready else None
    if check(got is not None, f"1: instant {n}: the rig's VFOs and the state agree"):
        compare_with_skyfield(n, transmitter, got)
        if n in DIAL_TURNED:
            turn_the_dial(transmitter, got, DIAL_TURNED[n])
    daemon.stop()
print("1: largest differences from skyfield: " +
      ", ".join(f"{band} MHz {e:.2f} Hz" for band, e in sorted(worst.items())))
print(f"took {time.monotonic() - started:.1f} s")
sys.exit(check.summary("radio_satellite"))
