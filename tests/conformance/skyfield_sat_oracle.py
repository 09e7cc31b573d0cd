#!/usr/bin/python3
"""Reference satellite look angles and pass times from skyfield + sgp4 (Debian, offline).

Usage:
  /usr/bin/python3 skyfield_sat_oracle.py look CASES.csv OUT.csv
      CASES: id, line1, line2, utc_iso, lat_deg, lon_deg, height_m
      OUT:   id, az_deg, alt_deg, range_km, range_rate_km_s, dut1_s   (nan when SGP4 fails)
  /usr/bin/python3 skyfield_sat_oracle.py passes CASES.csv OUT.csv
      CASES: id, line1, line2, from_iso, hours, lat_deg, lon_deg, height_m, min_el_deg
      OUT:   id, kind, t_s, alt_deg, az_deg, dut1_s   kind: rise | culminate | set; t_s after from

skyfield's geometric topocentric position (sat - topos).at(t), no light time, no refraction,
no polar motion (the default timescale has none): the convention of azeltrack (docs/satellites.md).
find_events() rise and set times are refined here by bisection on skyfield's own elevation,
because its raw event times run up to ~12 s late; dut1_s is the UT1 - UTC skyfield used, so the
caller can use the same UT1.
"""
import csv
import math
import sys


def refine(f, a, b, tol_days):
    """Bisection for a sign change of f on [a, b] (floats, TT Julian days)."""
    fa = f(a)
    for _ in range(200):
        if b - a < tol_days:
            break
        m = (a + b) / 2.0
        fm = f(m)
        if (fm > 0) == (fa > 0):
            a, fa = m, fm
        else:
            b = m
    return (a + b) / 2.0


def main(argv):
    if len(argv) != 4 or argv[1] not in ("look", "passes"):
        sys.stderr.write(__doc__)
        return 2
    from skyfield.api import EarthSatellite, load, wgs84

    ts = load.timescale(builtin=True)
    with open(argv[2], newline="") as f:
        rows = list(csv.DictReader(f))
    out = open(argv[3], "w", newline="")
    w = csv.writer(out, lineterminator="\n")
    if argv[1] == "look":
        w.writerow(["id", "az_deg", "alt_deg", "range_km", "range_rate_km_s", "dut1_s"])
        for r in rows:
            sat = EarthSatellite(r["line1"], r["line2"], ts=ts)
            site = wgs84.latlon(float(r["lat_deg"]), float(r["lon_deg"]), float(r["height_m"]))
            t = ts.from_datetime(__import__("datetime").datetime.fromisoformat(r["utc_iso"] + "+00:00"))
            topo = (sat - site).at(t)
            if getattr(topo, "message", None) or not all(math.isfinite(x) for x in topo.position.km):
                w.writerow([r["id"], "nan", "nan", "nan", "nan", repr(float(t.dut1))])
                continue
            alt, az, dist, _alt_rate, _az_rate, range_rate = topo.frame_latlon_and_rates(site)
            w.writerow([r["id"], repr(float(az.degrees)), repr(float(alt.degrees)),
                        repr(float(dist.km)), repr(float(range_rate.km_per_s)),
                        repr(float(t.dut1))])
    else:
        w.writerow(["id", "kind", "t_s", "alt_deg", "az_deg", "dut1_s"])
        import datetime
        for r in rows:
            sat = EarthSatellite(r["line1"], r["line2"], ts=ts)
            site = wgs84.latlon(float(r["lat_deg"]), float(r["lon_deg"]), float(r["height_m"]))
            t0 = ts.from_datetime(datetime.datetime.fromisoformat(r["from_iso"] + "+00:00"))
            t1 = t0 + float(r["hours"]) / 24.0
            min_el = float(r["min_el_deg"])
            diff = sat - site

            def alt_at(tt):
                return diff.at(ts.tt_jd(tt)).altaz()[0].degrees - min_el

            times, events = sat.find_events(site, t0, t1, altitude_degrees=min_el)
            for t, e in zip(times, events):
                tt = t.tt
                if e in (0, 2):
                    # The true crossing lies within a minute of skyfield's (late) event time.
                    a, b = tt - 60.0 / 86400.0, tt + 60.0 / 86400.0
                    if (alt_at(a) > 0) == (alt_at(b) > 0):
                        continue  # no clean bracket (a grazing pass): not compared
                    tt = refine(alt_at, a, b, 1e-4 / 86400.0)
                alt, az, _ = diff.at(ts.tt_jd(tt)).altaz()
                w.writerow([r["id"], ("rise", "culminate", "set")[e],
                            repr((tt - t0.tt) * 86400.0), repr(float(alt.degrees)),
                            repr(float(az.degrees)), repr(float(t0.dut1))])
    out.close()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
