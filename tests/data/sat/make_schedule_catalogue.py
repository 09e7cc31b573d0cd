#!/usr/bin/python3
"""Writes schedule_catalogue.tle: the 20-satellite catalogue of the schedule's skyfield proof
(tests/conformance/schedule_skyfield_test.py).

Run: /usr/bin/python3 tests/data/sat/make_schedule_catalogue.py

Two element sets are real, copied unchanged: ISS (ZARYA) of iss_2024.tle and NOAA 19 of
../omm/catalogue.tle (CelesTrak, 1 March 2024). The other eighteen are DERIVED, not real objects:
the shapes of real LEO families (the ISS's 51.6°, SO-50's 64.6°, sun-synchronous CubeSats at
97.5°, the NOAA weather satellites at 99°, RS-44's 82.5°, FO-29's eccentric 98.6°) with the
inclination, RAAN, mean anomaly and mean motion varied, at one common epoch (2024-03-01 12:00
UTC), NORAD numbers 90001-90018 and names that say "DERIVED". Their drag terms are those of the
real satellite of the family. Checksums are computed here (tle_text.py).
"""

import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from tle_text import element_lines  # noqa: E402

EPOCH = "24061.50000000"

# Family: name, inclination, eccentricity, argument of perigee, mean motion, and the drag fields
# (ndot, nddot, bstar) of the real satellite it is shaped after.
FAMILIES = {
    "ISS": (51.64, 0.00067, 130.5, 15.498, " .00016717", " 00000-0", " 30119-3"),
    "SO50": (64.55, 0.00310, 62.9, 14.757, " .00000053", " 00000-0", " 28045-4"),
    "SSO": (97.58, 0.00120, 122.1, 14.823, " .00000395", " 00000-0", " 54209-4"),
    "NOAA": (99.05, 0.00140, 290.0, 14.200, " .00000227", " 00000-0", " 14581-3"),
    "RS44": (82.53, 0.02167, 331.1, 12.797, " .00000017", " 00000-0", " 28663-4"),
    "FO29": (98.58, 0.03511, 51.2, 13.531, "-.00000049", " 00000-0", "-15585-4"),
}

# The derived satellites: family, then the changes to inclination, mean motion (rev/day), and
# the RAAN and mean anomaly (degrees).
DERIVED = [
    ("ISS", 0.00, +0.010, 30.0, 10.0),
    ("ISS", +0.40, -0.030, 140.0, 200.0),
    ("ISS", -0.30, +0.020, 260.0, 95.0),
    ("SO50", 0.00, 0.000, 300.0, 40.0),
    ("SO50", +0.10, +0.020, 60.0, 250.0),
    ("SO50", -0.20, -0.040, 180.0, 130.0),
    ("SSO", 0.00, 0.000, 20.0, 300.0),
    ("SSO", +0.10, +0.150, 95.0, 60.0),
    ("SSO", -0.20, +0.300, 170.0, 180.0),
    ("SSO", +0.30, -0.100, 245.0, 15.0),
    ("SSO", 0.00, +0.050, 320.0, 270.0),
    ("NOAA", 0.00, 0.000, 50.0, 120.0),
    ("NOAA", +0.10, +0.060, 130.0, 330.0),
    ("NOAA", -0.15, -0.050, 210.0, 75.0),
    ("RS44", 0.00, 0.000, 180.0, 27.8),
    ("RS44", +0.20, +0.040, 40.0, 210.0),
    ("FO29", 0.00, 0.000, 148.8, 312.0),
    ("FO29", -0.10, +0.030, 290.0, 100.0),
]


def real_sets():
    with open(os.path.join(HERE, "iss_2024.tle")) as f:
        iss = f.read().splitlines()[0:3]
    with open(os.path.join(HERE, "..", "omm", "catalogue.tle")) as f:
        lines = f.read().splitlines()
    noaa = lines[lines.index("NOAA 19"):lines.index("NOAA 19") + 3]
    return [iss, noaa]


def derived_sets():
    out = []
    for k, (family, d_incl, d_n, raan, ma) in enumerate(DERIVED, start=1):
        incl, ecc, argp, n, ndot, nddot, bstar = FAMILIES[family]
        name = "DERIVED %s-%02d" % (family, k)
        l1, l2 = element_lines(90000 + k, "24900%s" % chr(ord("A") + k - 1), EPOCH, ndot, nddot,
                               bstar, incl + d_incl, raan, ecc, argp, ma, n + d_n, rev=1000 + k)
        out.append([name, l1, l2])
    return out


def main():
    sets = real_sets() + derived_sets()
    assert len(sets) == 20
    with open(os.path.join(HERE, "schedule_catalogue.tle"), "w") as f:
        for s in sets:
            f.write("\n".join(s) + "\n")


if __name__ == "__main__":
    main()
