#!/usr/bin/python3
"""Writes schedule_scenario.tle and schedule_scenario.json: three satellites whose passes over a
station are placed to the second around an instant T0, for the daemon's schedule test.

Run: /usr/bin/python3 tests/data/sat/make_schedule_scenario.py [--t0 ISO] [--lat DEG --lon DEG
     --alt M] [--out-dir DIR]
The defaults write the committed files next to this script (T0 2024-03-01T12:00:00Z, the station
of examples/sim.toml). A test that needs the passes near another instant (the daemon's own "now")
can run it with --t0 and --out-dir: it takes a few seconds. Shifting the TLE epochs of the
committed files instead would not do: the Earth turns under the orbits.

The passes, over a 0 deg geometric horizon (skyfield's (sat - site).at(t).altaz(): no refraction,
no light time - azeltrack's pass search, core/src/orbit/passes.cpp, with `[satellites] mask`
"0"), seconds after T0:
    A  AOS  +20 (+-5)   LOS +110 (+-15)
    B  AOS  +45 (+-5)   LOS  +80 (+-10)    inside A's pass
    C  AOS +165 (+-15)  LOS +235 (+-30)
and no other pass of A, B or C from T0 - 600 s to T0 + 900 s. They are low grazing passes.

How: each satellite starts from a real element set (A and B: ISS (ZARYA) of iss_2024.tle; C:
NOAA 19 of ../omm/catalogue.tle) with its epoch moved to T0 - 3 h and a new NORAD number (99901-3):
the RAAN and the mean anomaly are then tuned by Newton's method on SGP4 (python3-sgp4, through
skyfield) until the pass's middle and length are those above (a first guess puts the satellite
over a ground point beside the site at the right time by spherical geometry). The mean motion
stays the real one. The guesses are chosen so that a mount at 1.5 deg/s can follow: B rises
within 30 deg of azimuth of where A is then (the take-over is a short move), C within 90 deg of
A's LOS point; when a guess fails (another --t0 or site) others are swept, then the other base
set. Checksums are computed (tle_text.py). The json lists each pass as skyfield finds it (AOS,
TCA and LOS to 0.1 s - AOS and LOS bisected to 0.01 s -, max elevation, azimuths at AOS and
LOS), the station, T0 and skyfield's UT1-UTC there (give it to azeltrack as [sky] dut1_s: with
0 the grazing B pass moves by about 0.1 s), so a test can assert against them.
"""
import argparse
import datetime
import json
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "..", "conformance"))
from tle_text import element_lines  # noqa: E402
from schedule_skyfield_oracle import SkyPasses  # noqa: E402

# name, NORAD, base element set, target AOS and LOS (s after T0), and the first guess tried
# (azimuth of the ground point, descending): guesses that put B beside A in the sky (the
# antenna can follow the take-over) and C within reach of A's LOS for the default T0 and site.
TARGETS = [
    ("AZT SCENARIO A", 99901, "iss", 20.0, 110.0, (180.0, False)),
    ("AZT SCENARIO B", 99902, "iss", 45.0, 80.0, (180.0, False)),
    ("AZT SCENARIO C", 99903, "noaa19", 165.0, 235.0, (90.0, True)),
]
# B's AOS within this of where A is then, C's within this of A's LOS point (degrees of azimuth):
# a mount at 1.5 deg/s gets there in time.
NEAR_DEG = {"AZT SCENARIO B": 30.0, "AZT SCENARIO C": 90.0}
BEFORE_S, AFTER_S = 600.0, 900.0  # the window that holds no other pass
EPOCH_BEFORE_T0_D = 0.125


def base_sets():
    with open(os.path.join(HERE, "iss_2024.tle")) as f:
        iss = f.read().splitlines()[1:3]
    with open(os.path.join(HERE, "..", "omm", "catalogue.tle")) as f:
        lines = f.read().splitlines()
    k = lines.index("NOAA 19")
    return {"iss": iss, "noaa19": lines[k + 1:k + 3]}


def fields(line1, line2):
    """The numbers and the drag fields of a real element set."""
    return {"ndot": line1[33:43], "nddot": line1[44:52], "bstar": line1[53:61],
            "incl": float(line2[8:16]), "ecc": float("0." + line2[26:33]),
            "argp": float(line2[34:42]), "n": float(line2[52:63])}


def epoch_field(t):
    """YYDDD.DDDDDDDD of a UTC datetime."""
    start = datetime.datetime(t.year, 1, 1, tzinfo=datetime.timezone.utc)
    day = (t - start).total_seconds() / 86400.0 + 1.0
    return "%02d%012.8f" % (t.year % 100, day)


class Tuner:
    """One satellite's elements as a function of (RAAN, mean anomaly)."""

    def __init__(self, ts, site, t0, base, norad, epoch):
        self.ts, self.site, self.t0, self.base = ts, site, t0, base
        self.norad, self.epoch = norad, epoch

    def lines(self, raan, ma):
        b = self.base
        return element_lines(self.norad, "24999" + "ABC"[(self.norad - 99901) % 3], self.epoch,
                             b["ndot"], b["nddot"], b["bstar"], b["incl"], raan, b["ecc"],
                             b["argp"], ma, b["n"])

    def satellite(self, raan, ma, name="tuning"):
        from skyfield.api import EarthSatellite
        l1, l2 = self.lines(raan, ma)
        return EarthSatellite(l1, l2, name, self.ts)

    def window(self, raan, ma, horizon_deg=0.0):
        start = self.ts.tt_jd(self.t0.tt - BEFORE_S / 86400.0)
        return SkyPasses(self.ts, self.satellite(raan, ma), self.site, start,
                         BEFORE_S + AFTER_S, horizon_deg)

    def first_guess(self, mid_s, az_deg, descending, ground_km=2000.0):
        """RAAN and mean anomaly that put the satellite over the ground point ground_km from the
        site in azimuth az_deg at T0 + mid_s, ascending or descending there (circular orbit,
        spherical Earth): a start for Newton's method, which finds the pass near it."""
        b = self.base
        lat = math.radians(self.site.latitude.degrees)
        lon = math.radians(self.site.longitude.degrees)
        d, az = ground_km / 6371.0, math.radians(az_deg)
        lat_p = math.asin(math.sin(lat) * math.cos(d) + math.cos(lat) * math.sin(d) * math.cos(az))
        lon_p = lon + math.atan2(math.sin(az) * math.sin(d) * math.cos(lat),
                                 math.cos(d) - math.sin(lat) * math.sin(lat_p))
        inc = math.radians(b["incl"])
        u = math.asin(max(-1.0, min(1.0, math.sin(lat_p) / math.sin(inc))))
        if descending:
            u = math.pi - u
        dlon = math.atan2(math.cos(inc) * math.sin(u), math.cos(u))
        t = self.ts.tt_jd(self.t0.tt + mid_s / 86400.0)
        raan = math.degrees(lon_p + math.radians(t.gmst * 15.0) - dlon)
        # The mean anomaly at the epoch: back along the orbit by the time from the epoch.
        ma = math.degrees(u) - b["argp"] - 360.0 * b["n"] * (mid_s / 86400.0 + EPOCH_BEFORE_T0_D)
        return raan % 360.0, ma % 360.0

    def peak(self, x, mid_s):
        """(time of the highest point near T0 + mid_s - that instant, its elevation's signed
        square root): near a grazing pass's top the elevation is a parabola in time, so the
        square root of the highest elevation is proportional to the pass's length."""
        centre = BEFORE_S + mid_s
        tca, max_el = self.window(*x).peak(centre - 400.0, centre + 400.0, tol_s=0.01)
        return tca - centre, math.copysign(math.sqrt(abs(max_el)), max_el)

    def pass_near(self, x, mid_s):
        """The pass around the highest point near T0 + mid_s, seconds after T0."""
        sp = self.window(*x)
        centre = BEFORE_S + mid_s
        tca, _ = sp.peak(centre - 400.0, centre + 400.0, tol_s=0.01)
        p = sp.around_peak(tca, 0.01)
        return {k: (v - BEFORE_S if k in ("aos", "los", "tca") else v) for k, v in p.items()}


def newton(f, x, goal, steps=(0.01, 0.01), iterations=40, tol=(0.05, 0.05)):
    """2-D Newton's method with a finite-difference Jacobian and a damped step."""
    for _ in range(iterations):
        y = f(x)
        r = (y[0] - goal[0], y[1] - goal[1])
        if abs(r[0]) < tol[0] and abs(r[1]) < tol[1]:
            return x
        cols = []
        for k in range(2):
            xk = list(x)
            xk[k] += steps[k]
            yk = f(xk)
            cols.append(((yk[0] - y[0]) / steps[k], (yk[1] - y[1]) / steps[k]))
        a, c = cols[0]
        b, d = cols[1]
        det = a * d - b * c
        if det == 0.0:
            raise RuntimeError("singular Jacobian")
        dx = ((d * r[0] - b * r[1]) / det, (-c * r[0] + a * r[1]) / det)
        scale = min(1.0, 1.0 / max(abs(dx[0]), abs(dx[1]), 1e-12))  # at most 1 deg a step
        x = [x[0] - scale * dx[0], x[1] - scale * dx[1]]
    raise RuntimeError("no convergence: residual %r" % (r,))


def tune(tuner, aos_s, los_s, az_deg, descending):
    """A pass of 3 deg at the right time first; then the length, from the square root of the
    highest elevation (proportional to it), and the middle, corrected for the pass's asymmetry."""
    mid, length = 0.5 * (aos_s + los_s), los_s - aos_s
    x = list(tuner.first_guess(mid, az_deg, descending))
    x = newton(lambda v: tuner.peak(v, mid), x, (0.0, math.sqrt(3.0)), tol=(0.5, 0.01))
    for _ in range(12):
        p = tuner.pass_near(x, mid)
        if abs(p["los"] - p["aos"] - length) < 0.3 and abs(p["aos"] - aos_s) < 0.3:
            return x
        root = math.sqrt(p["max_el"]) * length / (p["los"] - p["aos"])
        asymmetry = 0.5 * (p["aos"] + p["los"]) - p["tca"]
        x = newton(lambda v: tuner.peak(v, mid), x, (-asymmetry, root), steps=(0.002, 0.002),
                   tol=(0.02, 1e-4))
    raise RuntimeError("%s: the pass does not settle" % tuner.norad)


def iso(t0, s):
    t = t0 + datetime.timedelta(seconds=round(s, 1))
    return t.strftime("%Y-%m-%dT%H:%M:%S.") + "%dZ" % (t.microsecond // 100000)


def az_gap(a, b):
    return abs((a - b + 180.0) % 360.0 - 180.0)


def place(tuners, name, aos_s, los_s, guess, near):
    """The tuner and elements of the first guess that gives the pass alone in the quiet window,
    with its AOS near the azimuth `near` (None: anywhere): the preferred base and guess first,
    then a sweep of ground points, then the other base."""
    sweep = [(float(az), d) for d in (False, True) for az in range(0, 360, 45)]
    for k, tuner in enumerate(tuners):
        for az, descending in ([guess] if k == 0 else []) + sweep:
            try:
                x = tune(tuner, aos_s, los_s, az, descending)
            except RuntimeError:
                continue
            sp = tuner.window(*x)
            passes = sp.find(tol_s=0.01)
            if len(passes) != 1:
                continue  # another pass in the quiet window
            aos_az = float(sp.look(passes[0]["aos"])[0])
            if near is None or az_gap(aos_az, near) <= NEAR_DEG[name]:
                return tuner, x, sp, passes[0]
    raise SystemExit("%s: no element set gives the pass (try another --t0 or site)" % name)


def describe(name, norad, lines, sp, p, t0_dt):
    """The json entry of one satellite: its elements and its pass, seconds after T0."""
    s = {k: p[k] - BEFORE_S for k in ("aos", "tca", "los")}
    entry = {"name": name, "norad": norad, "line1": lines[0], "line2": lines[1],
             "pass": {"aos": iso(t0_dt, s["aos"]), "tca": iso(t0_dt, s["tca"]),
                      "los": iso(t0_dt, s["los"]), "aos_s": round(s["aos"], 1),
                      "tca_s": round(s["tca"], 1), "los_s": round(s["los"], 1),
                      "max_el_deg": round(p["max_el"], 3),
                      "aos_az_deg": round(float(sp.look(p["aos"])[0]), 2),
                      "los_az_deg": round(float(sp.look(p["los"])[0]), 2)}}
    print("%s: AOS %+.1f s az %.1f, LOS %+.1f s az %.1f, max el %.3f deg" %
          (name, s["aos"], entry["pass"]["aos_az_deg"], s["los"], entry["pass"]["los_az_deg"],
           p["max_el"]))
    return entry


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--t0", default="2024-03-01T12:00:00Z")
    ap.add_argument("--lat", type=float, default=46.189)
    ap.add_argument("--lon", type=float, default=-79.393)
    ap.add_argument("--alt", type=float, default=300.0)
    ap.add_argument("--out-dir", default=HERE)
    a = ap.parse_args()
    from skyfield.api import load, wgs84

    ts = load.timescale(builtin=True)
    t0_dt = datetime.datetime.fromisoformat(a.t0.replace("Z", "+00:00"))
    t0 = ts.from_datetime(t0_dt)
    site = wgs84.latlon(a.lat, a.lon, a.alt)
    epoch = epoch_field(t0_dt - datetime.timedelta(days=EPOCH_BEFORE_T0_D))
    bases = base_sets()
    tle, sats, sky_a = [], [], None
    for name, norad, base, aos_s, los_s, guess in TARGETS:
        tuners = [Tuner(ts, site, t0, fields(*bases[b]), norad, epoch)
                  for b in [base] + [b for b in bases if b != base]]
        near = None
        if sky_a is not None:  # B beside A at B's AOS; C within reach of A's LOS
            when = aos_s if name.endswith("B") else sats[0]["pass"]["los_s"]
            near = float(sky_a.look(when + BEFORE_S)[0])
        tuner, x, sp, p = place(tuners, name, aos_s, los_s, guess, near)
        lines = tuner.lines(*x)
        tle += [name, lines[0], lines[1]]
        sats.append(describe(name, norad, lines, sp, p, t0_dt))
        sky_a = sky_a or sp
    doc = {"about": "tests/data/sat/make_schedule_scenario.py: passes over a 0 deg geometric "
                    "horizon (skyfield, [sky] dut1_s as below), seconds after t0; no other pass "
                    "of these satellites from t0-600 s to t0+900 s",
           "t0": t0_dt.strftime("%Y-%m-%dT%H:%M:%SZ"),
           "site": {"lat_deg": a.lat, "lon_deg": a.lon, "alt_m": a.alt},
           "horizon_deg": 0.0, "dut1_s": round(float(t0.dut1), 4),
           "quiet_window_s": [-BEFORE_S, AFTER_S], "satellites": sats}
    with open(os.path.join(a.out_dir, "schedule_scenario.tle"), "w") as f:
        f.write("\n".join(tle) + "\n")
    with open(os.path.join(a.out_dir, "schedule_scenario.json"), "w") as f:
        json.dump(doc, f, indent=2)
        f.write("\n")


if __name__ == "__main__":
    main()
