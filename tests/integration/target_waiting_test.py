#!/usr/bin/python3
"""Waiting, said plainly (docs/daemon.md "Who is in control"): a daemon started tracking the Moon
while it is below the horizon limit holds, shows no pointing error, and says when the Moon rises
through the limit (`target.waiting.until`) within 60 s of an independent moonrise computed with
astropy (Debian python3-astropy, offline: the Moon's airless topocentric altitude every 60 s,
the crossing interpolated). The daemon's clock starts at a fixed instant (--utc-start), so the
test is the same at any hour; the sky is airless on both sides ([atmosphere] refraction "none").
Usage: /usr/bin/python3 target_waiting_test.py AZELTRACK"""
import datetime
import os
import shutil
import subprocess
import sys
import tempfile
import warnings

from daemon_harness import Checks, free_port, http_json, wait_until

BIN = os.path.realpath(sys.argv[1])
TMP = tempfile.mkdtemp(prefix="azt-waiting-")
LAT, LON, LIMIT = 40.7, -74.0, 5.0
BAR_S = 60.0
check = Checks()


def moon_altitudes(start, seconds, step_s=60.0):
    warnings.simplefilter("ignore")
    import numpy as np
    import astropy.units as u
    from astropy.coordinates import AltAz, EarthLocation, get_body
    from astropy.time import Time
    from astropy.utils import iers
    iers.conf.auto_download = False
    iers.conf.iers_degraded_accuracy = "warn"
    offsets = np.arange(0.0, seconds + step_s, step_s)
    t = Time(start, format="datetime", scale="utc") + offsets * u.s
    loc = EarthLocation.from_geodetic(lon=LON * u.deg, lat=LAT * u.deg, height=0 * u.m)
    alt = get_body("moon", t, loc).transform_to(AltAz(obstime=t, location=loc,
                                                      pressure=0 * u.hPa)).alt.deg
    return offsets, alt


def below_start_and_rise():
    """A start (from a fixed date, in 3-hour steps) with the Moon below the limit, and the
    instant it rises through it after that (seconds after the start)."""
    start = datetime.datetime(2026, 3, 20, 0, 0, 0)
    for _ in range(16):
        offsets, alt = moon_altitudes(start, 2 * 86400)
        if alt[0] < LIMIT - 2.0:
            for i in range(1, len(alt)):
                if alt[i - 1] < LIMIT <= alt[i]:
                    f = (LIMIT - alt[i - 1]) / (alt[i] - alt[i - 1])
                    return start, offsets[i - 1] + f * (offsets[i] - offsets[i - 1])
        start += datetime.timedelta(hours=3)
    raise SystemExit("no start with the Moon below the limit found")


start, rise_s = below_start_and_rise()
web = free_port()
path = os.path.join(TMP, "station.toml")
with open(path, "w") as f:
    f.write(f"""schema_version = 2
[station]
lat_deg = {LAT}
lon_deg = {LON}
[atmosphere]
refraction = "none"
[geometry]
el_min_deg = {LIMIT}
[target]
name = "moon"
[rotctld]
port = 0
[pstrotator]
port = 0
[web]
port = {web}
""")
base = f"http://127.0.0.1:{web}"
log = open(os.path.join(TMP, "daemon.log"), "w")
proc = subprocess.Popen([BIN, "serve", "--config", path, "--utc-start",
                         start.strftime("%Y-%m-%dT%H:%M:%SZ")], stdout=log, stderr=log)


def state():
    return http_json(base, "GET", "/api/state")[1]


def waiting():
    try:
        return state()["target"].get("waiting")
    except (OSError, KeyError, TypeError, ValueError):
        return None


try:
    check(wait_until(lambda: (waiting() or {}).get("until"), 20),
          f"waiting with a rise time ({waiting()})")
    s = state()
    w = s["target"]["waiting"]
    until = datetime.datetime.strptime(w["until"][:19], "%Y-%m-%dT%H:%M:%S")
    expected = start + datetime.timedelta(seconds=rise_s)
    diff = (until - expected).total_seconds()
    print(f"target_waiting: until {w['until']}, astropy {expected.isoformat()}Z ({diff:+.1f} s)")
    check(abs(diff) <= BAR_S, f"until {w['until']} vs astropy {expected.isoformat()}Z: "
          f"{diff:+.1f} s (at most {BAR_S:.0f})")
    check(s["mode"] == "TRACK" and "below the horizon limit (5°)" in w["reason"],
          f"TRACK, and the reason names the limit: {s['mode']}, {w['reason']!r}")
    check(s["error_deg"] is None, f"no pointing error while waiting: {s['error_deg']}")
    check(abs(w["in_s"] - rise_s) <= BAR_S + 30, f"in_s counts down from the start: {w['in_s']}")
finally:
    proc.terminate()
    proc.wait(10)
    log.close()
    shutil.rmtree(TMP, ignore_errors=True)

sys.exit(check.summary("target_waiting"))
