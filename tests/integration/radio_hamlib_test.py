#!/usr/bin/env python3
"""The rig through libhamlib directly (docs/radio.md "Through rigctld or directly"): `azeltrack
serve` with `[radio] model = 1`, Hamlib's dummy rig opened in the daemon's own process, held to the
oracles the rigctld path is held to.

 1  satellite Doppler on the ISS pass of radio_satellite_test.py (the same skyfield oracle,
    satellite_doppler_oracle.py): an FM bird (145.800 down, 437.800 up) early in the pass and near
    its closest approach, where the range rate changes fastest, and an inverting transponder
    (435.850 down, 145.950 up, the dial read through libhamlib each cycle: track the knob) in
    between. /api/state radio says link "up", and rx_hz and tx_hz are the nominal frequencies
    corrected for skyfield's range rate at the instants the state gives for them (`at_unix_s`,
    `tx_at_unix_s`) within 5 Hz, the tolerance of the rigctld path
 2  EME, own echo at 1296 MHz: rx_hz is the dial plus the state's Moon echo Doppler within 1 Hz,
    as radio_test.py holds the rigctld path to
 3  a rig that cannot be opened (model 1020, the FT-817, on a device that does not exist; Hamlib
    tries it for 2 s each time): the state's link says "down: rig_open of model 1020 (Yaesu
    FT-817) at … failed: …", the log says so once across the retries, `/api/state` answers within
    0.5 s throughout and the control tick is never late by more than 100 ms (the daemon's tick
    statistics when it stops): rig_open waits on the rig's worker thread, not on the loop

The dummy rig is in the daemon, so nothing outside can read it back as rigctl reads rigctld's;
the state's rx_hz and tx_hz are what the rig acknowledged (rig_set_freq and rig_set_split_freq
returned RIG_OK), and the component test (tests/component/hamlib_rig_test.cpp) reads the same rig
back through libhamlib.

Usage: radio_hamlib_test.py AZELTRACK"""
import os
import re
import subprocess
import sys
import tempfile
import time

from daemon_harness import Checks, FIXED_UTC, free_port, http_json, wait_until, stop_at_exit
from satellite_doppler_oracle import (GRID, TLE, heard_hz, high_pass, iso, range_rate_km_s,
                                      sent_hz, ut1_minus_utc_s)

BIN = os.path.realpath(sys.argv[1])
TMP = tempfile.mkdtemp(prefix="azt-radio-hamlib-")
TOLERANCE_HZ = 5.0
DIAL_MHZ = 1296.1  # [sky] band "1296" is 1296.100 MHz: the state's moon figures are at the dial
MISSING = "/nonexistent/azt-test-rig"
check = Checks()
procs = []
stop_at_exit(procs, TMP)

FM = {"downlink_mhz": 145.800, "uplink_mhz": 437.800, "mode": "fm"}
INVERTING = {"downlink_mhz": 435.850, "uplink_mhz": 145.950, "mode": "linear_inverting"}
WEB = free_port()
BASE = f"http://127.0.0.1:{WEB}"
# A console password already set, so that no start spends an Argon2 hash on writing one (the
# console is only read here).
PASSWORD = "$argon2id$v=19$m=65536,t=3,p=1$YXp0LXRlc3Qtc2FsdA$bm90LWEtcmVhbC1oYXNoLWF0LWFsbA"


def config_text(radio, extra=""):
    return (f'schema_version = 2\n[station]\ngrid = "{GRID}"\n'
            f'[rotctld]\nport = 0\n[pstrotator]\nport = 0\n'
            f'[web]\nport = {WEB}\npassword_hash = "{PASSWORD}"\n{extra}[radio]\n{radio}')


def satellite_config(transmitter, dut1_s):
    return config_text(
        'model = 1\ndoppler = "satellite"\n'
        f'[[satellites.transmitter]]\nnorad = "25544"\n'
        f'downlink_mhz = {transmitter["downlink_mhz"]}\n'
        f'uplink_mhz = {transmitter["uplink_mhz"]}\nmode = "{transmitter["mode"]}"\n',
        f'[target]\nname = "sat:25544"\n[sky]\ndut1_s = {dut1_s!r}\n[satellites]\nfile = "{TLE}"\n')


def radio_state():
    return http_json(BASE, "GET", "/api/state")[1]["radio"]


class Daemon:
    """`azeltrack serve` on a configuration, at a UTC instant."""

    def __init__(self, name, text, utc):
        self.config = os.path.join(TMP, f"{name}.toml")
        with open(self.config, "w", encoding="utf-8") as f:
            f.write(text)
        self.log_path = os.path.join(TMP, f"{name}.log")
        with open(self.log_path, "w", encoding="utf-8") as log:
            self.proc = subprocess.Popen([BIN, "serve", "--config", self.config, "--utc-start", utc],
                                         stdout=log, stderr=subprocess.STDOUT)
        procs.append(self.proc)
        self.serving = wait_until(lambda: http_json(BASE, "GET", "/api/state")[0] == 200, 10, 0.05)
        if not self.serving:
            print(self.log(), file=sys.stderr)

    def log(self):
        with open(self.log_path, encoding="utf-8") as f:
            return f.read()

    def stop(self):
        self.proc.terminate()
        self.proc.wait(10)


def satellite_instant(label, transmitter, unix_s, dut1_s):
    daemon = Daemon(transmitter["mode"], satellite_config(transmitter, dut1_s), iso(unix_s))
    both = daemon.serving and wait_until(lambda: radio_state()["tx_hz"] is not None, 5, 0.05)
    radio = radio_state() if daemon.serving else {}
    daemon.stop()
    if not check(both, f"1: {label}: both legs written: {radio}\n{daemon.log()}"):
        return
    check(radio["link"] == "up", f"1: {label}: link {radio['link']}")
    want_rx = heard_hz(transmitter["downlink_mhz"] * 1e6, radio["at_unix_s"])
    want_tx = sent_hz(transmitter["uplink_mhz"] * 1e6, radio["tx_at_unix_s"])
    rx_error, tx_error = radio["rx_hz"] - want_rx, radio["tx_hz"] - want_tx
    print(f"1: {label} {transmitter['mode']:16} {iso(radio['at_unix_s'])} ṙ "
          f"{range_rate_km_s(radio['at_unix_s']):+.4f} km/s: RX {radio['rx_hz']:.0f} "
          f"({rx_error:+.2f} Hz), TX {radio['tx_hz']:.0f} ({tx_error:+.2f} Hz)")
    check(abs(rx_error) <= TOLERANCE_HZ, f"1: {label}: RX {rx_error:+.2f} Hz from skyfield")
    check(abs(tx_error) <= TOLERANCE_HZ, f"1: {label}: TX {tx_error:+.2f} Hz from skyfield")
    check("radio: Hamlib rig model 1: link up" in daemon.log(),
          f"1: {label}: the log names the rig\n{daemon.log()}")


def eme_own_echo():
    daemon = Daemon("eme", config_text(f'model = 1\ndoppler = "eme"\neme_mode = "self"\n'
                                       f"dial_mhz = {DIAL_MHZ}\n", '[sky]\nband = "1296"\n'),
                    FIXED_UTC)
    written = daemon.serving and wait_until(lambda: radio_state()["rx_hz"] is not None, 5, 0.05)
    state = http_json(BASE, "GET", "/api/state")[1] if daemon.serving else {}
    daemon.stop()
    if not check(written, f"2: the RX written: {state.get('radio')}\n{daemon.log()}"):
        return
    radio, echo_hz = state["radio"], state["moon"]["echo_doppler_hz"]
    expected = DIAL_MHZ * 1e6 + echo_hz
    print(f"2: rx_hz {radio['rx_hz']:.0f} at {radio['at']}, dial + echo {expected:.1f} "
          f"(echo {echo_hz:+.2f} Hz)")
    check(radio["link"] == "up" and radio["doppler"] == "eme", f"2: link and source: {radio}")
    check(abs(radio["rx_hz"] - expected) <= 1.0, f"2: dial + echo {expected:.1f} vs {radio}")


def missing_rig():
    daemon = Daemon("missing", config_text(f'model = 1020\ndevice = "{MISSING}"\n'), FIXED_UTC)
    down = daemon.serving and wait_until(lambda: radio_state()["link"].startswith("down"), 5, 0.05)
    link = radio_state()["link"] if daemon.serving else ""
    # The console asked every 0.1 s for 3 s more, through the retries (0.5 s apart, then 2 s in
    # rig_open each): the slowest answer says whether the loop ever waited for the rig.
    slowest_s, end = 0.0, time.monotonic() + 3.0
    while daemon.serving and time.monotonic() < end:
        asked = time.monotonic()
        radio_state()
        slowest_s = max(slowest_s, time.monotonic() - asked)
        time.sleep(0.1)
    daemon.stop()
    text = daemon.log()
    print(f"3: link: {link}; the slowest /api/state {slowest_s * 1e3:.0f} ms")
    check(slowest_s < 0.5, f"3: the console answered throughout: slowest {slowest_s:.2f} s")
    check(down and link.startswith(f"down: rig_open of model 1020 (Yaesu FT-817) at {MISSING} "
                                   "failed: "), f"3: the state says why: {link!r}")
    lines = [line for line in text.splitlines() if "radio: Hamlib rig model 1020" in line]
    check(len(lines) == 1 and "link down" in lines[0], f"3: said once: {lines}")
    found = re.search(r"late p50 [\d.]+ ms p99 ([\d.]+) ms max ([\d.]+) ms", text)
    if check(found is not None, f"3: the tick statistics at stop\n{text}"):
        print(f"3: tick lateness p99 {found.group(1)} ms, max {found.group(2)} ms over the "
              "failing rig_opens (each 2 s)")
        check(float(found.group(2)) < 100.0, f"3: the tick was never held: {found.group(0)}")


started = time.monotonic()
rise, setting = high_pass()
peak = (rise + setting) / 2
DUT1_S = ut1_minus_utc_s(peak)
print(f"pass {iso(rise)} to {iso(setting)} over {GRID}")
satellite_instant("early", FM, rise + 60, DUT1_S)
satellite_instant("transponder", INVERTING, peak - 120, DUT1_S)
satellite_instant("closest", FM, peak - 20, DUT1_S)
eme_own_echo()
missing_rig()
print(f"took {time.monotonic() - started:.1f} s")
sys.exit(check.summary("radio_hamlib"))
