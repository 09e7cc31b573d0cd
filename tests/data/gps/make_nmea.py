#!/usr/bin/env python3
"""Writes the NMEA logs the GPS tests replay through gpsfake (docs/gps.md), u-blox M8N style:
RMC, GGA, GSA, GSV and TXT, one fix a second. Deterministic (a fixed seed), so the logs in this
folder are what this script prints; run it again after a change:
    python3 tests/data/gps/make_nmea.py tests/data/gps
Each log's true mean position is written beside it in a .json file for the tests to compare.
The time test imports write_live() for a log that starts at a given UTC second (now).
"""
import json
import math
import random
import sys
from datetime import datetime, timedelta, timezone

START = datetime(2025, 3, 14, 0, 0, 0, tzinfo=timezone.utc)
SITE = (46.18958, -79.39375, 301.0)  # FN06HE, the example station's grid square
SATS = [(2, 67, 45), (5, 41, 120), (12, 23, 300), (13, 55, 210), (15, 12, 80), (18, 33, 250),
        (20, 71, 10), (25, 18, 160), (26, 9, 330), (29, 48, 275), (31, 27, 30), (10, 5, 190)]


def checksum(body):
    c = 0
    for ch in body.encode("ascii"):
        c ^= ch
    return f"${body}*{c:02X}\r\n"


def lat_text(lat):
    d = int(abs(lat))
    return f"{d:02d}{(abs(lat) - d) * 60:08.5f},{'N' if lat >= 0 else 'S'}"


def lon_text(lon):
    d = int(abs(lon))
    return f"{d:03d}{(abs(lon) - d) * 60:08.5f},{'E' if lon >= 0 else 'W'}"


SENTENCES_PER_FIX = 6  # RMC, GGA, GSA and three GSV: gpsfake -c 1/6 plays a fix a second


def cycle(t, pos, mode, used):
    """One second of sentences: mode 3 (3D), 2 (2D) or 1 (no fix); `used` satellites in use."""
    hms = t.strftime("%H%M%S") + ".00"
    dmy = t.strftime("%d%m%y")
    lat, lon, alt = pos
    ok = mode > 1
    out = []
    if ok:
        out.append(checksum(f"GNRMC,{hms},A,{lat_text(lat)},{lon_text(lon)},0.012,,{dmy},,,A"))
        alt_text = f"{alt:.1f},M,-34.6,M" if mode == 3 else ",M,,M"
        out.append(checksum(f"GNGGA,{hms},{lat_text(lat)},{lon_text(lon)},1,{used:02d},0.94,"
                            f"{alt_text},,"))
    else:
        out.append(checksum(f"GNRMC,{hms},V,,,,,,,{dmy},,,N"))
        out.append(checksum(f"GNGGA,{hms},,,,,0,00,99.99,,,,,,"))
    prns = ",".join(f"{p:02d}" for p, _, _ in SATS[:used]) + "," * (12 - used)
    out.append(checksum(f"GNGSA,A,{mode},{prns},1.65,0.94,1.36"))
    groups = [SATS[i:i + 4] for i in range(0, len(SATS), 4)]
    for i, g in enumerate(groups):
        sats = ",".join(f"{p:02d},{el:02d},{az:03d},{30 + p % 15:02d}" for p, el, az in g)
        out.append(checksum(f"GPGSV,{len(groups)},{i + 1},{len(SATS):02d},{sats}"))
    return out


def offset(pos, north_m, east_m):
    lat, lon, alt = pos
    return (lat + north_m / 111195.0, lon + east_m / (111195.0 * math.cos(math.radians(lat))), alt)


def fixes(rng, seconds, centre, mode=3, used=8, t0=0, start=START):
    lines, seen = [], []
    for s in range(seconds):
        p = offset(centre, rng.gauss(0, 1.5), rng.gauss(0, 1.5))
        p = (p[0], p[1], centre[2] + rng.gauss(0, 2.0))
        # Rounded as the sentence carries it: the mean the tests expect is of what gpsd reads.
        p = (round(p[0] * 6e6) / 6e6, round(p[1] * 6e6) / 6e6, round(p[2], 1))
        lines += cycle(start + timedelta(seconds=t0 + s), p, mode, used)
        if mode == 3:
            seen.append(p)
    return lines, seen


def mean(points):
    return [sum(p[i] for p in points) / len(points) for i in range(3)] if points else None


def write_live(path, start_unix_s, seconds):
    """A good 3D fix a second from the whole UTC second start_unix_s on, for a time chain."""
    start = datetime.fromtimestamp(start_unix_s, tz=timezone.utc)
    lines, _ = fixes(random.Random(15), seconds, SITE, start=start)
    with open(path, "w", encoding="ascii", newline="") as f:
        f.writelines(lines)


def main(folder):
    rng = random.Random(15)
    txt = [checksum("GNTXT,01,01,02,u-blox AG - www.u-blox.com"),
           checksum("GNTXT,01,01,02,HW UBX-M8030 00080000")]
    logs = {}
    # A cold start: 40 s without a fix first, so a client that connects while gpsfake already
    # replays (gpsfake does not wait for one) still sees every good fix.
    acquiring, _ = fixes(rng, 40, SITE, mode=1, used=0)
    good, seen = fixes(rng, 60, SITE, t0=40)
    logs["good_fix"] = (txt + acquiring + good, mean(seen))
    none, _ = fixes(rng, 20, SITE, mode=1, used=0)
    logs["no_fix"] = (txt + none, None)
    two, _ = fixes(rng, 20, SITE, mode=2, used=3)
    logs["fix_2d"] = (txt + two, None)
    first, seen_a = fixes(rng, 30, SITE)
    moved = offset(SITE, 400.0, 300.0)  # 500 m away
    second, seen_b = fixes(rng, 30, moved, t0=30)
    logs["position_jump"] = (txt + first + second, {"before": mean(seen_a), "after": mean(seen_b)})
    garbage = []
    junk = ["$GNGGA,garbage*00\r\n", "\x00\xff\xfe\x01 binary noise\r\n",
            "$GNRMC,000000.00,A,99999.99999,N,99999.99999,W,0,,140325,,,A*3C\r\n",
            "no dollar sign at all\r\n"]
    for s in range(20):
        cyc, _ = fixes(rng, 1, SITE, t0=s)
        garbage += cyc + [junk[s % len(junk)]]
    logs["garbage"] = (txt + garbage, None)
    for name, (lines, truth) in logs.items():
        with open(f"{folder}/{name}.nmea", "w", encoding="latin-1", newline="") as f:
            f.write(f"# {name}: written by make_nmea.py (docs/gps.md), one fix a second\n")
            f.writelines(lines)
        with open(f"{folder}/{name}.json", "w", encoding="ascii") as f:
            json.dump({"mean": truth}, f, indent=1)
            f.write("\n")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else ".")
