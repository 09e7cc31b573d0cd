#!/usr/bin/python3
"""WSJT-X's Astronomical Data, re-implemented from its published source for azeltrack's oracle
test (docs/eme.md): the Moon and the Sun from astropy (Debian python3-astropy, offline), the EME
quantities from the formulas of WSJT-X's lib/astro.f90 (WSJTX/wsjtx on GitHub, subroutine astro):

  - "Compute spatial polarization offset": xx = sin(lat)cos(El) - cos(lat)cos(Az)sin(El),
    yy = cos(lat)sin(Az), poloffset = atan2(yy, xx), per station;
  - poloffset = mod(poloffset2 - poloffset1 + 720, 180), minus 180 above 90;
    x1 = max(|cos(2 poloffset)|, 0.056234), xnr = -20 log10(x1)  (MNR);
  - coord(0, 0, -1.570796, 1.161639, RA, Dec) -> ecliptic longitude el; longecl_half =
    nint(el/2), 180 outside 1..180; t144 = nt144(longecl_half);
    tsky = (t144 - 2.7)(144 MHz / f)^2.6 + 2.7;
  - dBMoon = -40 log10(dist / 356903); tr = 80; tskymin = 13 (408 MHz / f)^2.6;
    dgrd = -10 log10((tsky + tr)/(tskymin + tr)) + dBMoon.
The Sun's separation is astropy's; the lit fraction is from the phase angle at the Moon between
the Sun and the observer (vectors, not the elongation formula azeltrack uses).

The echo widths (WSJT-X's Width and DxWid) follow three files; line numbers are those of
WSJTX/wsjtx at commit c04dd8d (May 2026; the three files unchanged since July 2022):
  - lib/ephem.f90, subroutine ephem, lines 27-31 and 73: the Moon's topocentric apparent RA/Dec
    (true equator and equinox of date) one minute before the instant (jj=1) and at it (jj=2),
    each handed to libration() with the UTC Julian date;
  - lib/libration.f90, subroutine libration, lines 12-35: the optical libration of Meeus,
    Astronomical Algorithms ch. 53 (no physical libration; W without Meeus's nutation term): RA/Dec
    precessed to J2000 (sla_PRECES) and turned into ecliptic longitude and latitude of date
    (sla_EQECL); I = 1.54242 deg, F = 93.2720993 + 483202.0175273 T - 0.0034029 T^2 deg,
    Omega = 2.182439196 - 33.7570446085 T + 3.6236526e-5 T^2 rad, W = lambda - Omega,
    A = atan2(sin W cos beta cos I - sin beta sin I, cos W cos beta), l = A - F,
    b = asin(-sin W cos beta sin I - sin beta cos I);
  - lib/astro0.f90, subroutine astro0, lines 25-47: dl, db = the change of l, b over that
    minute in degrees, for the station (1) and the DX (2); width1 = 0.5*6741*f_GHz*2*sqrt(dl1^2 +
    db1^2) (self echo), width2 = 0.5*6741*f_GHz*sqrt((dl1 + dl2)^2 + (db1 + db2)^2) (DX echo).
Here the RA/Dec are astropy's TETE seen from the station. sla_PRECES to J2000 followed by
sla_EQECL's own precession back to the date cancel (but for EQECL being handed jd - 2400000 as
an MJD, half a day's precession, 0.07"), so the ecliptic of date is reached by one rotation
through the IAU 1976 mean obliquity (sla_ECMAT), as EQECL applies it.

Usage: /usr/bin/python3 eme_oracle.py CASES.csv OUT.csv
CASES.csv: id,utc_iso,lat1_deg,lon1_deg,height1_m,lat2_deg,lon2_deg,height2_m,freq_mhz
OUT.csv:   id,az1_deg,el1_deg,par1_deg,par2_deg,dpol_deg,mnr_db,ecl_lon_deg,tsky_k,dgrd_db,
           sun_sep_deg,illumination,dist1_km,width1_hz,width2_hz
"""
import csv
import math
import sys
import warnings

# WSJT-X lib/astro.f90 `nt144`: sky temperature at 144 MHz (K) in 2-degree ecliptic bins.
NT144 = [
    234, 246, 257, 267, 275, 280, 283, 286, 291, 298, 305, 313, 322, 331, 341, 351, 361, 369,
    376, 381, 383, 382, 379, 374, 370, 366, 363, 361, 363, 368, 376, 388, 401, 415, 428, 440,
    453, 467, 487, 512, 544, 579, 607, 618, 609, 588, 563, 539, 512, 482, 450, 422, 398, 379,
    363, 349, 334, 319, 302, 282, 262, 242, 226, 213, 205, 200, 198, 197, 196, 197, 200, 202,
    204, 205, 204, 203, 202, 201, 203, 206, 212, 218, 223, 227, 231, 236, 240, 243, 247, 257,
    276, 301, 324, 339, 346, 344, 339, 331, 323, 316, 312, 310, 312, 317, 327, 341, 358, 375,
    392, 407, 422, 437, 451, 466, 480, 494, 511, 530, 552, 579, 612, 653, 702, 768, 863, 1008,
    1232, 1557, 1966, 2385, 2719, 2924, 3018, 3038, 2986, 2836, 2570, 2213, 1823, 1461, 1163,
    939, 783, 677, 602, 543, 494, 452, 419, 392, 373, 360, 353, 350, 350, 350, 350, 350, 350,
    348, 344, 337, 329, 319, 307, 295, 284, 276, 272, 272, 273, 274, 274, 271, 266, 260, 252,
    245, 238, 231]
RAD = 57.2957795


def poloffset(lat, az, el):
    xx = math.sin(lat / RAD) * math.cos(el / RAD) - math.cos(lat / RAD) * math.cos(az / RAD) * \
        math.sin(el / RAD)
    yy = math.cos(lat / RAD) * math.sin(az / RAD)
    return RAD * math.atan2(yy, xx)


def ecliptic_longitude(ra_deg, dec_deg):
    """coord() with the ecliptic pole at RA -90 deg, Dec 1.161639 rad: a rotation about the
    equinox direction by the pole's colatitude."""
    eps = math.pi / 2 - 1.161639
    x = math.cos(dec_deg / RAD) * math.cos(ra_deg / RAD)
    y = math.cos(dec_deg / RAD) * math.sin(ra_deg / RAD)
    z = math.sin(dec_deg / RAD)
    ye = y * math.cos(eps) + z * math.sin(eps)
    return (math.degrees(math.atan2(ye, x))) % 360.0


def wrap_pi(x):
    """x (radians, numpy) wrapped into [-pi, pi)."""
    import numpy as np
    return np.mod(x + np.pi, 2.0 * np.pi) - np.pi


def optical_libration(jd_utc, ra_rad, dec_rad):
    """WSJT-X lib/libration.f90 (Meeus ch. 53) on numpy arrays: the sub-observer point (l, b) in
    radians for topocentric apparent RA/Dec of date at UTC Julian date jd_utc."""
    import numpy as np
    t = (jd_utc - 2451545.0) / 36525.0
    # sla_ECMAT: the IAU 1976 mean obliquity of date, arcseconds.
    eps = np.radians((84381.448 - 46.8150 * t - 0.00059 * t * t + 0.001813 * t ** 3) / 3600.0)
    x = np.cos(dec_rad) * np.cos(ra_rad)
    y = np.cos(dec_rad) * np.sin(ra_rad)
    z = np.sin(dec_rad)
    lam = np.arctan2(y * np.cos(eps) + z * np.sin(eps), x)
    beta = np.arcsin(-y * np.sin(eps) + z * np.cos(eps))
    inc = np.radians(1.54242)
    f = np.radians(np.mod(93.2720993 + 483202.0175273 * t - 0.0034029 * t * t, 360.0))
    omega = 2.182439196 - 33.7570446085 * t + 3.6236526e-5 * t * t
    w = lam - omega
    a = np.arctan2(np.sin(w) * np.cos(beta) * np.cos(inc) - np.sin(beta) * np.sin(inc),
                   np.cos(w) * np.cos(beta))
    lon = wrap_pi(a - f)  # libration.f90 lines 33-34 fold 'round the back' angles
    lat = np.arcsin(-np.sin(w) * np.cos(beta) * np.sin(inc) - np.sin(beta) * np.cos(inc))
    return lon, lat


def libration_change_deg(t, loc):
    """ephem.f90: (dl, db) in degrees over the minute before each instant, seen from loc."""
    import numpy as np
    import astropy.units as u
    from astropy.coordinates import TETE, get_body
    points = []
    for ti in (t - 60.0 * u.s, t):
        tete = get_body("moon", ti, loc).transform_to(TETE(obstime=ti, location=loc))
        points.append(optical_libration(ti.utc.jd1 + ti.utc.jd2, tete.ra.rad, tete.dec.rad))
    dl = np.degrees(wrap_pi(points[1][0] - points[0][0]))
    return dl, np.degrees(points[1][1] - points[0][1])


def echo_widths_hz(change1, change2, freq_mhz):
    """astro0.f90 lines 39-47: self and DX echo widths (Hz) from each station's (dl, db)."""
    import numpy as np
    (dl1, db1), (dl2, db2) = change1, change2
    hz_per_deg_min = 0.5 * 6741.0 * freq_mhz / 1000.0
    return (hz_per_deg_min * 2.0 * np.hypot(dl1, db1),
            hz_per_deg_min * np.hypot(dl1 + dl2, db1 + db2))


def nint(x):
    return int(math.floor(x + 0.5)) if x >= 0 else -int(math.floor(-x + 0.5))


def main(argv):
    warnings.simplefilter("ignore")
    import numpy as np
    import astropy.units as u
    from astropy.coordinates import AltAz, EarthLocation, TETE, get_body
    from astropy.time import Time
    from astropy.utils import iers
    iers.conf.auto_download = False
    iers.conf.iers_degraded_accuracy = "warn"

    with open(argv[1], newline="") as f:
        rows = list(csv.DictReader(f))
    col = lambda name: np.array([float(r[name]) for r in rows])  # noqa: E731
    t = Time([r["utc_iso"] for r in rows], format="isot", scale="utc")
    places = []
    for n in ("1", "2"):
        loc = EarthLocation.from_geodetic(lon=col(f"lon{n}_deg") * u.deg,
                                          lat=col(f"lat{n}_deg") * u.deg,
                                          height=col(f"height{n}_m") * u.m, ellipsoid="WGS84")
        moon = get_body("moon", t, loc)
        altaz = moon.transform_to(AltAz(obstime=t, location=loc, pressure=0 * u.hPa))
        places.append((loc, moon, altaz))
    width1, width2 = echo_widths_hz(libration_change_deg(t, places[0][0]),
                                    libration_change_deg(t, places[1][0]), col("freq_mhz"))
    loc1, moon1, altaz1 = places[0]
    tete1 = moon1.transform_to(TETE(obstime=t, location=loc1))
    sun1 = get_body("sun", t, loc1)
    sep = moon1.separation(sun1).deg
    m = moon1.cartesian.xyz.to(u.km).value
    s = sun1.cartesian.xyz.to(u.km).value
    to_sun, to_obs = s - m, -m
    cos_i = np.sum(to_sun * to_obs, axis=0) / (np.linalg.norm(to_sun, axis=0) *
                                              np.linalg.norm(to_obs, axis=0))
    with open(argv[2], "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["id", "az1_deg", "el1_deg", "par1_deg", "par2_deg", "dpol_deg", "mnr_db",
                    "ecl_lon_deg", "tsky_k", "dgrd_db", "sun_sep_deg", "illumination", "dist1_km",
                    "width1_hz", "width2_hz"])
        for i, r in enumerate(rows):
            az1, el1 = altaz1.az.deg[i], altaz1.alt.deg[i]
            az2, el2 = places[1][2].az.deg[i], places[1][2].alt.deg[i]
            p1 = poloffset(float(r["lat1_deg"]), az1, el1)
            p2 = poloffset(float(r["lat2_deg"]), az2, el2)
            dpol = math.fmod(p2 - p1 + 720.0, 180.0)
            if dpol > 90.0:
                dpol -= 180.0
            mnr = -20.0 * math.log10(max(abs(math.cos(2 * dpol / RAD)), 0.056234))
            lon = ecliptic_longitude(tete1.ra.deg[i], tete1.dec.deg[i])
            half = nint(lon / 2.0)
            if half < 1 or half > 180:
                half = 180
            freq = float(r["freq_mhz"]) * 1e6
            tsky = (NT144[half - 1] - 2.7) * (144.0e6 / freq) ** 2.6 + 2.7
            dist = altaz1.distance.to(u.km).value[i]
            dbmoon = -40.0 * math.log10(dist / 356903.0)
            tskymin = 13.0 * (408.0e6 / freq) ** 2.6
            dgrd = -10.0 * math.log10((tsky + 80.0) / (tskymin + 80.0)) + dbmoon
            w.writerow([r["id"], az1, el1, p1, p2, dpol, mnr, lon, tsky, dgrd, sep[i],
                        (1.0 + cos_i[i]) / 2.0, dist, width1[i], width2[i]])
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
