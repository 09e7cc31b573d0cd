#!/usr/bin/python3
"""Reference az/el of fixed ICRS sources from astropy, for azeltrack's oracle test.

Usage: /usr/bin/python3 astropy_oracle.py CASES.csv OUT.csv

CASES.csv columns (header line required):
    id, utc_iso, lat_deg, lon_deg, height_m, ra_deg, dec_deg
where utc_iso is the UTC instant as YYYY-MM-DDTHH:MM:SS.sss (not a Julian date: on a day ending
in a leap second astropy spreads a UTC JD fraction over 86401 s), the station is on the WGS84
ellipsoid (east longitude and north latitude positive) and RA/Dec are ICRS degrees.

OUT.csv columns: id, az_deg, alt_deg, az_nopm_deg, alt_nopm_deg, delta_ut1_utc_s
az from north through east, alt geometric (pressure = 0: no refraction). az_deg/alt_deg are
astropy's own result, with polar motion from its IERS table; the *_nopm_* pair is the same
transform with polar motion forced to zero (as azeltrack, which does not apply it), so that
everything else in the chain can be checked far below polar motion's ~0.6 arcsec.
delta_ut1_utc_s is the UT1 - UTC that astropy used for the instant (its bundled IERS-B table,
or the last value held past the table's end), so the caller can use the very same UT1.

Offline by design (see /work/shared/oracles/README.md section 3): astropy must not try to download
IERS-A or leap-second files, and degraded accuracy (dates past the bundled table) only warns.
Run with Debian's /usr/bin/python3, which sees python3-astropy (5.2.1).
"""
import csv
import sys
import warnings


def main(argv):
    if len(argv) != 3:
        sys.stderr.write("usage: astropy_oracle.py CASES.csv OUT.csv\n")
        return 2
    warnings.simplefilter("ignore")  # staleness/degraded-accuracy warnings: expected offline
    import numpy as np
    import astropy
    import astropy.units as u
    from astropy.coordinates import AltAz, EarthLocation, SkyCoord, erfa_astrom
    from astropy.time import Time
    from astropy.utils import iers

    iers.conf.auto_download = False
    iers.conf.iers_degraded_accuracy = "warn"

    with open(argv[1], newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.stderr.write("no cases\n")
        return 1

    def col(name):
        return np.array([float(r[name]) for r in rows])

    ids = [r["id"] for r in rows]
    t = Time([r["utc_iso"] for r in rows], format="isot", scale="utc")
    loc = EarthLocation.from_geodetic(lon=col("lon_deg") * u.deg, lat=col("lat_deg") * u.deg,
                                      height=col("height_m") * u.m, ellipsoid="WGS84")
    src = SkyCoord(ra=col("ra_deg") * u.deg, dec=col("dec_deg") * u.deg, frame="icrs")
    # One vectorised transform: obstime and location broadcast element by element.
    frame = AltAz(obstime=t, location=loc, pressure=0 * u.hPa)
    altaz = src.transform_to(frame)
    dut1 = np.asarray(t.delta_ut1_utc)  # filled from the IERS table by the UT1 conversion above

    # astropy 5.2's ICRS -> AltAz path takes polar motion from erfa_astrom.get_polar_motion
    # (ErfaAstrom.apco); replacing it with zeros gives the chain without polar motion.
    with_pm = erfa_astrom.get_polar_motion
    erfa_astrom.get_polar_motion = lambda time: (np.zeros(time.shape), np.zeros(time.shape))
    try:
        altaz_nopm = src.transform_to(AltAz(obstime=t, location=loc, pressure=0 * u.hPa))
    finally:
        erfa_astrom.get_polar_motion = with_pm

    with open(argv[2], "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(["id", "az_deg", "alt_deg", "az_nopm_deg", "alt_nopm_deg", "delta_ut1_utc_s"])
        for i, ident in enumerate(ids):
            w.writerow([ident] + [repr(float(x[i])) for x in (
                altaz.az.deg, altaz.alt.deg, altaz_nopm.az.deg, altaz_nopm.alt.deg, dut1)])
    sys.stderr.write("astropy %s: %d cases\n" % (astropy.__version__, len(ids)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
