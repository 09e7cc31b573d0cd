#!/usr/bin/python3
"""python3-sgp4 / skyfield side of bench/sat_bench.cpp (Debian, offline).

Usage: /usr/bin/python3 sat_bench.py CATALOGUE.tle LAT LON FROM_ISO DAYS
Prints: propagations_per_s <n>  (python-sgp4's Satrec.sgp4 on the first satellite, TEME)
        pass_search_s <s> <passes>  (skyfield find_events for every satellite over DAYS)
"""
import datetime
import sys
import time


def main(argv):
    from sgp4.api import Satrec, jday
    from skyfield.api import EarthSatellite, load, wgs84

    lines = [l.rstrip("\n") for l in open(argv[1]) if l.strip()]
    sets = [(lines[i], lines[i + 1], lines[i + 2]) for i in range(0, len(lines), 3)]
    lat, lon = float(argv[2]), float(argv[3])
    start = datetime.datetime.fromisoformat(argv[4] + "+00:00")
    days = float(argv[5])

    sat = Satrec.twoline2rv(sets[0][1], sets[0][2])
    jd, fr = jday(start.year, start.month, start.day, start.hour, start.minute, start.second)
    n = 20000
    t0 = time.perf_counter()
    for i in range(n):
        sat.sgp4(jd, fr + i / 1440.0)
    print("propagations_per_s %.1f" % (n / (time.perf_counter() - t0)))

    ts = load.timescale(builtin=True)
    site = wgs84.latlon(lat, lon)
    t_start = ts.from_datetime(start)
    t_end = t_start + days
    t0 = time.perf_counter()
    passes = 0
    for name, l1, l2 in sets:
        s = EarthSatellite(l1, l2, name, ts)
        _, events = s.find_events(site, t_start, t_end, altitude_degrees=0.0)
        passes += int((events == 0).sum())
    print("pass_search_s %.3f %d" % (time.perf_counter() - t0, passes))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
