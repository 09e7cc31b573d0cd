"""The satellite Doppler oracle of the radio tests (docs/radio.md "Satellite Doppler"): the ISS of
tests/data/sat/iss_2024.tle seen from FN06HE through python3-skyfield, its range rate at any
instant, and the rig's frequencies it implies by the exact classical forms: heard f/(1 + ṙ/c),
sent f/(1 − ṙ/c), ṙ positive receding. Shared by radio_satellite_test.py (the rig through
rigctld) and radio_hamlib_test.py (the rig through libhamlib)."""
import datetime
import math
import os
import sys

from skyfield.api import EarthSatellite, load, wgs84

HERE = os.path.dirname(os.path.realpath(__file__))
TLE = os.path.join(HERE, "..", "data", "sat", "iss_2024.tle")
C_KM_S = 299792.458
GRID = "FN06HE"


def locator_centre(grid):
    """The centre of a six-character Maidenhead square (lat, lon) in degrees."""
    g = grid.upper()
    lon = -180 + (ord(g[0]) - 65) * 20 + int(g[2]) * 2 + (ord(g[4]) - 65) / 12 + 1 / 24
    lat = -90 + (ord(g[1]) - 65) * 10 + int(g[3]) + (ord(g[5]) - 65) / 24 + 1 / 48
    return lat, lon


ts = load.timescale()
_name, _line1, _line2 = open(TLE, encoding="utf-8").read().splitlines()[:3]
ISS = EarthSatellite(_line1, _line2, _name, ts)
LAT, LON = locator_centre(GRID)
SITE = wgs84.latlon(LAT, LON, 0.0)


def skyfield_time(unix_s):
    return ts.from_datetime(datetime.datetime.fromtimestamp(unix_s, datetime.timezone.utc))


def range_rate_km_s(unix_s):
    """d|r|/dt of the satellite seen from the site (the same in any frame)."""
    seen = (ISS - SITE).at(skyfield_time(unix_s))
    r = seen.position.km
    v = seen.velocity.km_per_s
    return sum(a * b for a, b in zip(r, v)) / math.sqrt(sum(a * a for a in r))


def heard_hz(f_hz, unix_s):
    return f_hz / (1 + range_rate_km_s(unix_s) / C_KM_S)


def sent_hz(f_hz, unix_s):
    return f_hz / (1 - range_rate_km_s(unix_s) / C_KM_S)


def high_pass():
    """(rise, set) in Unix seconds of the first pass after the elements' epoch above 40°."""
    t0 = ISS.epoch
    t, events = ISS.find_events(SITE, t0, t0 + 1.0, altitude_degrees=0.0)
    rise, peak = None, 0.0
    for ti, e in zip(t, events):
        if e == 0:
            rise = ti
        elif e == 1 and rise is not None:
            peak = (ISS - SITE).at(ti).altaz()[0].degrees
        elif e == 2 and rise is not None and peak > 40.0:
            return rise.utc_datetime().timestamp(), ti.utc_datetime().timestamp()
    sys.exit("no pass above 40° within a day of the elements' epoch")


def ut1_minus_utc_s(unix_s):
    """UT1 − UTC at an instant, for the daemon's [sky] dut1_s: the two then compare Doppler, not
    Earth orientations (0.16 s of UT1 moves the site 75 m: up to 1.5 Hz at 435 MHz)."""
    return float(skyfield_time(unix_s).dut1)


def iso(unix_s):
    return datetime.datetime.fromtimestamp(unix_s, datetime.timezone.utc).strftime(
        "%Y-%m-%dT%H:%M:%SZ")
