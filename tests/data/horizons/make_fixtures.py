#!/usr/bin/python3
"""Writes the JPL Horizons fixtures of tests/unit/horizons_test.cpp.

Run with Debian's python (python3-erfa): /usr/bin/python3 tests/data/horizons/make_fixtures.py
It writes, next to itself:
  moon_vectors_csv_kms.txt   EPHEM_TYPE='VECTORS', CSV_FORMAT='YES', VEC_TABLE='3', OUT_UNITS='KM-S',
                             REF_SYSTEM='ICRF', REF_PLANE='FRAME', CENTER='500@399', 10-minute steps
                             over one TDB day (145 nodes)
  moon_vectors_text_aud.txt  the same query with CSV_FORMAT='NO', VEC_TABLE='2', OUT_UNITS='AU-D',
                             hourly steps over six hours (labelled "X =" lines, VEC_LABELS='YES')
  observer_north.txt         EPHEM_TYPE='OBSERVER', CSV_FORMAT='YES', ANG_FORMAT='DEG',
                             QUANTITIES='4,20', a topocentric site, 10-minute steps

The layout follows real Horizons API output line by line (astroquery's test data
astroquery/jplhorizons/tests/data/ceres_vectors.txt and ceres_ephemerides.txt, and API v1.2 output
with "Reference frame : ICRF"); the headers are abridged (the object data block and most of the
column-meaning footer are left out) but every line kept is written as Horizons writes it.

The numbers are not Horizons'. The vector tables hold ERFA's Moon (erfa.moon98: geocentric GCRS,
which is ICRF-aligned, au and au/day at a TT instant used as TDB), so the test can check the
interpolation against eraMoon98 itself. The observer table is a synthetic track (azimuth sweeping
through north at 1 deg per 10 minutes, elevation a smooth arc, range changing at the listed range
rate): it exercises the parser and the azimuth unwrap, not astronomy.
"""

import math
import os

import erfa

HERE = os.path.dirname(os.path.abspath(__file__))
AU_KM = 149597870.7
C_KM_S = 299792.458
START_JD1 = 2460735.5  # 2025-Mar-01 00:00 (TDB for the vectors, UTC for the observer table)
STARS = "*" * 79
MONTHS = "Jan Feb Mar Apr May Jun Jul Aug Sep Oct Nov Dec".split()


def calendar(jd1, jd2, decimals):
    """Horizons' calendar form: 2025-Mar-01 00:10:00.0000 (seconds with `decimals` digits)."""
    y, m, d, fd = erfa.jd2cal(jd1, jd2)
    total = round(float(fd) * 86400.0, decimals)
    hh = int(total // 3600)
    mm = int((total - hh * 3600) // 60)
    ss = total - hh * 3600 - mm * 60
    width = 3 + decimals if decimals else 2
    return f"{int(y):04d}-{MONTHS[int(m) - 1]}-{int(d):02d} {hh:02d}:{mm:02d}:{ss:0{width}.{decimals}f}"


def moon_state(jd2):
    pv = erfa.moon98(START_JD1, jd2)
    return [float(v) for v in pv[0]], [float(v) for v in pv[1]]


def vectors_header(units, fmt, step, stop):
    return [
        "API VERSION: 1.2",
        "API SOURCE: NASA/JPL Horizons API",
        "",
        STARS,
        " Revised: July 31, 2013             Moon / (Earth)                          301",
        " (object data block abridged for this fixture)",
        STARS,
        "",
        "",
        STARS,
        "Ephemeris / API_USER Sat Mar  1 00:00:00 2025 Pasadena, USA      / Horizons",
        STARS,
        "Target body name: Moon (301)                      {source: DE441}",
        "Center body name: Earth (399)                     {source: DE441}",
        "Center-site name: BODY CENTER",
        STARS,
        "Start time      : A.D. 2025-Mar-01 00:00:00.0000 TDB",
        f"Stop  time      : A.D. {stop} TDB",
        f"Step-size       : {step}",
        STARS,
        "Center geodetic : 0.0, 0.0, 0.0                   {E-lon(deg),Lat(deg),Alt(km)}",
        "Center cylindric: 0.0, 0.0, 0.0                   {E-lon(deg),Dxy(km),Dz(km)}",
        "Center radii    : 6378.137, 6378.137, 6356.752 km {Equator_a, b, pole_c}",
        f"Output units    : {units}",
        "Calendar mode   : Mixed Julian/Gregorian",
        "Output type     : GEOMETRIC cartesian states",
        f"Output format   : {fmt}",
        "Reference frame : ICRF",
        STARS,
    ]


VECTORS_FOOTER = [
    STARS,
    " ",
    "TIME",
    "",
    "  Barycentric Dynamical Time (\"TDB\" or T_eph) output was requested.",
    " (rest of the footer abridged for this fixture)",
    STARS,
]


def write_csv_kms():
    names = ["JDTDB", "Calendar Date (TDB)", "X", "Y", "Z", "VX", "VY", "VZ", "LT", "RG", "RR"]
    widths = [17, 30] + [22] * 9
    columns = "".join(f"{n:>{w}}," + ("" if i == len(names) - 1 else " ")
                      for i, (n, w) in enumerate(zip(names, widths)))
    lines = vectors_header("KM-S", "3 (position, velocity, LT, range, range-rate)",
                           "10 minutes", "2025-Mar-02 00:00:00.0000")
    lines += [columns, "*" * len(columns), "$$SOE"]
    for k in range(145):
        jd2 = k / 144.0
        p, v = moon_state(jd2)
        pk = [x * AU_KM for x in p]
        vk = [x * AU_KM / 86400.0 for x in v]
        rg = math.sqrt(sum(x * x for x in pk))
        rr = sum(a * b for a, b in zip(pk, vk)) / rg
        lt = rg / C_KM_S
        values = pk + vk + [lt, rg, rr]
        row = f"{START_JD1 + jd2:.9f}, A.D. {calendar(START_JD1, jd2, 4)}, "
        row += ", ".join(f"{x: .15E}" for x in values) + ","
        lines.append(row)
    lines += ["$$EOE"] + VECTORS_FOOTER
    return lines


def write_text_aud():
    lines = vectors_header("AU-D", "2 (position and velocity)", "60 minutes",
                           "2025-Mar-01 06:00:00.0000")
    lines += ["JDTDB", "   X     Y     Z", "   VX    VY    VZ", STARS, "$$SOE"]
    for k in range(7):
        jd2 = k / 24.0
        p, v = moon_state(jd2)
        lines.append(f"{START_JD1 + jd2:.9f} = A.D. {calendar(START_JD1, jd2, 4)} TDB ")
        lines.append(f" X ={p[0]: .15E} Y ={p[1]: .15E} Z ={p[2]: .15E}")
        lines.append(f" VX={v[0]: .15E} VY={v[1]: .15E} VZ={v[2]: .15E}")
    lines += ["$$EOE"] + VECTORS_FOOTER
    return lines


def observer_header():
    return [
        "API VERSION: 1.2",
        "API SOURCE: NASA/JPL Horizons API",
        "",
        STARS,
        "Ephemeris / API_USER Sat Mar  1 00:00:00 2025 Pasadena, USA      / Horizons",
        STARS,
        "Target body name: Synthetic probe (-999)           {source: fixture}",
        "Center body name: Earth (399)                     {source: DE441}",
        "Center-site name: (user defined site below)",
        STARS,
        "Start time      : A.D. 2025-Mar-01 00:00:00.0000 UT",
        "Stop  time      : A.D. 2025-Mar-01 02:00:00.0000 UT",
        "Step-size       : 10 minutes",
        STARS,
        "Target pole/equ : (undefined)",
        "Target radii    : (undefined)",
        "Center geodetic : 350.123400, 48.765400, 0.3120000 {E-lon(deg),Lat(deg),Alt(km)}",
        "Center cylindric: 350.123400, 4210.12, 4773.45     {E-lon(deg),Dxy(km),Dz(km)}",
        "Center pole/equ : ITRF93                          {East-longitude positive}",
        "Center radii    : 6378.137, 6378.137, 6356.752 km {Equator_a, b, pole_c}",
        "Atmos refraction: NO (AIRLESS)",
        "RA format       : DEG",
        "Time format     : BOTH",
        "EOP file        : eop.250301.p250524",
        "Units conversion: 1 au= 149597870.700 km, c= 299792.458 km/s, 1 day= 86400.0 s",
        "Table format    : Comma Separated Values (spreadsheet)",
        STARS,
    ]


def write_observer():
    columns = (" Date__(UT)__HR:MN:SC.fff, Date_________JDUT, , ,  Azi_(a-app), Elev_(a-app),"
               "             delta,     deldot,")
    lines = observer_header() + [STARS + "*" * 30, columns, STARS + "*" * 30, "$$SOE"]
    for k in range(13):
        jd2 = k / 144.0
        minutes = 10.0 * k
        az = (354.0 + minutes / 10.0) % 360.0
        el = 20.0 + 10.0 * math.sin(math.pi * minutes / 120.0)
        deldot = -1.5 + 0.01 * minutes
        # delta is the integral of deldot (km/s) over the elapsed seconds.
        delta_km = 2.5e6 + 60.0 * (-1.5 * minutes + 0.005 * minutes * minutes)
        sun = "*" if k < 6 else " "
        moon = "m" if k % 4 == 0 else " "
        lines.append(f" {calendar(START_JD1, jd2, 3)}, {START_JD1 + jd2:.9f}, {sun}, {moon}, "
                     f"{az:12.6f}, {el:11.6f}, {delta_km / AU_KM:17.14f}, {deldot:10.7f},")
    lines += ["$$EOE", STARS + "*" * 30, "Column meaning:", " ", " (abridged for this fixture)",
              " ", " 'delta,     deldot,' =",
              "   Apparent range (\"delta\", light-time aberrated) and range-rate (\"delta-dot\")",
              "of the target center relative to the observer. A positive \"deldot\" means the",
              "target center is moving away from the observer, negative indicates movement",
              "toward the observer.  Units: AU and KM/S", " ", STARS]
    return lines


def main():
    for name, lines in (("moon_vectors_csv_kms.txt", write_csv_kms()),
                        ("moon_vectors_text_aud.txt", write_text_aud()),
                        ("observer_north.txt", write_observer())):
        with open(os.path.join(HERE, name), "w", encoding="ascii") as out:
            out.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
