#!/usr/bin/python3
"""The Moon windows of docs/eme.md: `azeltrack moon-windows` against an independent computation with
astropy (Debian python3-astropy, offline): both stations' airless Moon elevation every 5 minutes
over the span, the common windows where both are above their limits (edges interpolated between
samples), compared window by window: start and end within 60 s, the same number of windows. Three
station pairs, 30 days each, from seeded dates.

Usage: /usr/bin/python3 moon_windows_oracle.py AZELTRACK"""
import json
import subprocess
import sys
import warnings

PAIRS = [  # own grid, DX grid, own min el, DX min el, start
    ("FN06HE", "JO62QM", 0.0, 0.0, "2025-03-01T00:00:00Z"),
    ("QF56OD", "IO91WM", 10.0, 5.0, "2026-07-15T06:30:00Z"),
    ("KP20LE", "PM95VQ", 3.0, 15.0, "2030-11-02T18:00:00Z"),
]
STEP_S = 300.0  # linear between 5-minute samples: the edges to a few seconds
BAR_S = 60.0


def grid_centre(grid):
    """Maidenhead square centre (lat, lon), written here rather than taken from azeltrack."""
    g = grid.upper()
    lon = (ord(g[0]) - 65) * 20 - 180 + int(g[2]) * 2
    lat = (ord(g[1]) - 65) * 10 - 90 + int(g[3])
    if len(g) >= 6:
        lon += (ord(g[4]) - 65) * (2 / 24) + 1 / 24
        lat += (ord(g[5]) - 65) * (1 / 24) + 1 / 48
    else:
        lon += 1
        lat += 0.5
    return lat, lon


def astropy_windows(own, dx, min_el, dx_min_el, start, days):
    warnings.simplefilter("ignore")
    import numpy as np
    import astropy.units as u
    from astropy.coordinates import AltAz, EarthLocation, get_body
    from astropy.time import Time
    from astropy.utils import iers
    iers.conf.auto_download = False
    iers.conf.iers_degraded_accuracy = "warn"
    t0 = Time(start.replace("Z", ""), format="isot", scale="utc")
    offsets = np.arange(0.0, days * 86400.0 + STEP_S, STEP_S)
    t = t0 + offsets * u.s
    margins = []
    for grid, limit in ((own, min_el), (dx, dx_min_el)):
        lat, lon = grid_centre(grid)
        loc = EarthLocation.from_geodetic(lon=lon * u.deg, lat=lat * u.deg, height=0 * u.m)
        alt = get_body("moon", t, loc).transform_to(AltAz(obstime=t, location=loc,
                                                          pressure=0 * u.hPa)).alt.deg
        margins.append(alt - limit)
    margin = np.minimum(margins[0], margins[1])  # > 0: both see the Moon
    windows, open_at = [], (0.0 if margin[0] > 0 else None)
    for i in range(1, len(offsets)):
        a, b = margin[i - 1], margin[i]
        if (a > 0) == (b > 0):
            continue
        edge = offsets[i - 1] + STEP_S * a / (a - b)  # linear between the samples
        if b > 0:
            open_at = edge
        elif open_at is not None:
            windows.append((open_at, edge))
            open_at = None
    if open_at is not None:
        windows.append((open_at, offsets[-1]))
    return t0, windows


def main(argv):
    from datetime import datetime
    failures, worst = 0, 0.0
    for own, dx, min_el, dx_min_el, start in PAIRS:
        out = subprocess.run([argv[1], "moon-windows", "--grid", own, "--dx-grid", dx, "--from",
                              start, "--days", "30", "--min-el", str(min_el), "--dx-min-el",
                              str(dx_min_el), "--json"], capture_output=True, text=True, check=True)
        ours = json.loads(out.stdout)["windows"]
        t0, ref = astropy_windows(own, dx, min_el, dx_min_el, start, 30)
        base = datetime.fromisoformat(start.replace("Z", "+00:00")).timestamp()
        rel = [(datetime.fromisoformat(w["start"].replace("Z", "+00:00")).timestamp() - base,
                datetime.fromisoformat(w["end"].replace("Z", "+00:00")).timestamp() - base)
               for w in ours]
        if len(rel) != len(ref):
            print(f"FAIL {own}-{dx}: {len(rel)} windows, astropy {len(ref)}")
            failures += 1
            continue
        for (s, e), (rs, re_) in zip(rel, ref):
            d = max(abs(s - rs), abs(e - re_))
            worst = max(worst, d)
            if d > BAR_S:
                print(f"FAIL {own}-{dx}: window at +{s:.0f} s: start {s - rs:+.1f} s, "
                      f"end {e - re_:+.1f} s")
                failures += 1
        print(f"{own}-{dx} from {start}: {len(rel)} windows, edges within "
              f"{max((max(abs(s - rs), abs(e - re_)) for (s, e), (rs, re_) in zip(rel, ref)), default=0):.1f} s")
    print(f"measure: moon-windows vs astropy: worst edge {worst:.1f} s (bar {BAR_S:.0f} s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
