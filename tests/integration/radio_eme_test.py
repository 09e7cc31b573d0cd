#!/usr/bin/env python3
"""EME Doppler on the rig (docs/radio.md) against the sky engine's conformance oracle: Hamlib's
dummy rig (`rigctld -m 1`) kept on frequency by `azeltrack serve`, read back with
`rigctl -m 2 -r 127.0.0.1:PORT f`, must stand on the dial plus the Moon's echo Doppler as
swetest (Swiss Ephemeris' own program) gives it, within 1 Hz:

 1  own echo (`eme_mode = "self"`) at 1296.1 and 10368.1 MHz: rig RX = dial − 2·f·ṙ/c
 2  full DX Doppler (`eme_mode = "dx"`, `[sky] dx_grid = "JO65MR"`) at 1296.1 and 10368.1 MHz:
    rig RX = dial − f·(ṙ + ṙ_DX)/c

ṙ is the Moon's topocentric range rate, the oracle of tests/conformance/swetest_oracle_test.cpp:
the slope at the instant of a least-squares cubic through swetest's distance (`-topo`, column
`w`) sampled every 10 s over ±2 min. Both programs run at the same TT and UT1: the daemon's
DUT1 is (TAI−UTC) + 32.184 s − swetest's ΔT, and swetest is given UT1 (`-bj… -ut`), as in the
conformance test. The four daemons run side by side from the same fixed instant
(daemon_harness.FIXED_UTC, `serve --utc-start`), each with its own rigctld; the instant each RX
was computed for is the state's `radio.at_unix_s`.

Usage: radio_eme_test.py AZELTRACK"""
import datetime
import os
import shutil
import subprocess
import sys
import tempfile

import numpy

from daemon_harness import (FIXED_UTC, Checks, free_port, http_json, station_toml, stop_at_exit,
                            wait_until)

BIN = os.path.realpath(sys.argv[1])
TMP = tempfile.mkdtemp(prefix="azt-radio-eme-")
check = Checks()
procs = []
stop_at_exit(procs, TMP)

C_KM_S = 299792.458
TAI_MINUS_UTC_S = 37.0  # since 2017-01-01 (IERS Bulletin C), so at FIXED_UTC
TT_MINUS_TAI_S = 32.184
DX_GRID = "JO65MR"
CASES = [  # name, dial MHz, eme_mode, DX grid
    ("own echo 1296", 1296.1, "self", None),
    ("own echo 10368", 10368.1, "self", None),
    ("DX 1296", 1296.1, "dx", DX_GRID),
    ("DX 10368", 10368.1, "dx", DX_GRID),
]

if shutil.which("rigctld") is None or shutil.which("swetest") is None:
    print("skip: Hamlib's rigctld (libhamlib-utils) or swetest is not installed")
    sys.exit(77)


def unix_to_jd(unix_s):
    return 2440587.5 + unix_s / 86400.0


def swetest(args):
    out = subprocess.run(["swetest"] + args, capture_output=True, text=True, timeout=20,
                         check=True).stdout
    return out


def swetest_delta_t_s(unix_s):
    """swetest's ΔT = TT − UT1 (s) at an instant, from its `-pq` line."""
    line = next(x for x in swetest([f"-bj{unix_to_jd(unix_s):.9f}", "-ut", "-pq", "-eswe", "-head",
                                    "-ep"]).splitlines() if "Delta T" in x)
    return float(line.split()[2].rstrip("s"))


def moon_range_rate_km_s(ut1_unix_s, lat_deg, lon_deg, height_m):
    """The Moon's topocentric range rate (km/s) at a UT1 instant: the cubic fit's slope."""
    steps = numpy.arange(-12, 13) * 10.0
    out = swetest([f"-bj{unix_to_jd(ut1_unix_s + steps[0]):.9f}", "-ut", "-p1", "-eswe",
                   f"-topo{lon_deg:.9f},{lat_deg:.9f},{height_m:.3f}", "-fw", "-head", "-ep",
                   "-n25", "-s10s"])
    dist_km = [float(x) for x in out.split()]
    if len(dist_km) != 25:
        sys.exit(f"swetest gave {len(dist_km)} distances: {out}")
    return numpy.polyfit(steps, dist_km, 3)[-2]


def grid_centre(grid):
    """The centre of a 6-character Maidenhead locator (lat, lon)."""
    g = grid.upper()
    lon = (ord(g[0]) - 65) * 20 - 180 + int(g[2]) * 2 + (ord(g[4]) - 65) * 5 / 60 + 2.5 / 60
    lat = (ord(g[1]) - 65) * 10 - 90 + int(g[3]) + (ord(g[5]) - 65) * 2.5 / 60 + 1.25 / 60
    return lat, lon


def rig_frequency(port):
    out = subprocess.run(["rigctl", "-m", "2", "-r", f"127.0.0.1:{port}", "f"],
                         capture_output=True, text=True, timeout=5, check=True)
    return float(out.stdout.split()[0])


def state(base):
    return http_json(base, "GET", "/api/state")[1]


# One DUT1 for the run: ΔT moves by milliseconds a year.
FIXED_UNIX_S = datetime.datetime.fromisoformat(FIXED_UTC.replace("Z", "+00:00")).timestamp()
DELTA_T_S = swetest_delta_t_s(FIXED_UNIX_S)
DUT1_S = TAI_MINUS_UTC_S + TT_MINUS_TAI_S - DELTA_T_S


def start(name, dial_mhz, mode, dx_grid):
    rig_port, web_port = free_port(), free_port()
    procs.append(subprocess.Popen(["rigctld", "-m", "1", "-T", "127.0.0.1", "-t", str(rig_port)],
                                  stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL))
    config = os.path.join(TMP, f"{name.replace(' ', '_')}.toml")
    with open(config, "w", encoding="utf-8") as f:
        f.write(station_toml(web_port=web_port))
        f.write(f"[sky]\ndut1_s = {DUT1_S:.6f}\n" + (f'dx_grid = "{dx_grid}"\n' if dx_grid else ""))
        f.write(f'[radio]\nrigctld = "127.0.0.1:{rig_port}"\ndoppler = "eme"\n'
                f'eme_mode = "{mode}"\ndial_mhz = {dial_mhz}\n')
    log = open(os.path.join(TMP, f"{name.replace(' ', '_')}.log"), "w", encoding="utf-8")
    procs.append(subprocess.Popen([BIN, "serve", "--config", config, "--utc-start", FIXED_UTC],
                                  stdout=log, stderr=subprocess.STDOUT))
    return rig_port, f"http://127.0.0.1:{web_port}"


def written(rig_port, base):
    """(rig Hz, the state's radio) once the RX is written: the state read just before or after
    the rig that matches it (the rig may be rewritten between the two reads)."""
    if not wait_until(lambda: state(base)["radio"]["rx_hz"] is not None, 15):
        sys.exit(f"no RX written: {state(base)['radio']}")
    before = state(base)
    rig_hz = rig_frequency(rig_port)
    after = state(base)
    radio = before["radio"] if abs(before["radio"]["rx_hz"] - rig_hz) < 0.5 else after["radio"]
    return rig_hz, radio, after


started = [(case, *start(*case)) for case in CASES]
for (name, dial_mhz, mode, dx_grid), rig_port, base in started:
    rig_hz, radio, st = written(rig_port, base)
    check(radio["link"] == "up" and radio["eme_mode"] == mode, f"{name}: {radio}")
    check(abs(radio["rx_hz"] - rig_hz) < 0.5, f"{name}: the rig reads back rx_hz: {rig_hz}, {radio}")
    ut1 = radio["at_unix_s"] + DUT1_S
    f_hz = dial_mhz * 1e6
    station = st["station"]
    rate = moon_range_rate_km_s(ut1, station["lat_deg"], station["lon_deg"], station["alt_m"])
    if dx_grid:
        lat, lon = grid_centre(dx_grid)
        rate_dx = moon_range_rate_km_s(ut1, lat, lon, 0.0)
        doppler_hz = -f_hz * (rate + rate_dx) / C_KM_S
    else:
        doppler_hz = -2.0 * f_hz * rate / C_KM_S
    expected = f_hz + doppler_hz
    print(f"{name}: rig {rig_hz:.0f} Hz, dial + swetest's Doppler {expected:.2f} Hz "
          f"(Doppler {doppler_hz:+.2f} Hz, azeltrack's {radio['rx_correction_hz']:+.2f} Hz, at "
          f"{radio['at']}): rig − oracle {rig_hz - expected:+.2f} Hz, correction − oracle "
          f"{radio['rx_correction_hz'] - doppler_hz:+.2f} Hz")
    check(abs(rig_hz - expected) <= 1.0, f"{name}: rig {rig_hz} vs dial + Doppler {expected:.2f}")
sys.exit(check.summary("radio_eme"))
