#include "azt/astro/swiss_ephemeris.hpp"

extern "C" {
#include <swephexp.h>
}

#include <string>

namespace azt::astro {
namespace {

// Geometric barycentric/geocentric cartesian states in the ICRS, exactly what the shared
// reduction in sky.cpp expects (equatorial: libswe defaults to ecliptic): no light time, no
// aberration, no deflection, no precession.
constexpr int32 kGeometricIcrs = SEFLG_SWIEPH | SEFLG_EQUATORIAL | SEFLG_J2000 | SEFLG_ICRS |
                                 SEFLG_XYZ | SEFLG_TRUEPOS | SEFLG_NOABERR | SEFLG_NOGDEFL |
                                 SEFLG_SPEED;

Result<PosVel> calc(const JulianDate& tt, int body, int32 flags) {
  double xx[6];
  char err[AS_MAXCH] = {0};
  // libswe takes one double: the split is summed here, costing ~20 µs of precision in 2026,
  // 1e-10 of a Moon step — far below the data's own accuracy.
  const int32 got = swe_calc(tt.jd1 + tt.jd2, body, flags, xx, err);
  if (got < 0) return fail(std::string("Swiss Ephemeris: ") + err);
  if ((got & SEFLG_SWIEPH) == 0) {
    return fail(
        "Swiss Ephemeris data files not found (libswe fell back to its Moshier theory); "
        "install swe-basic-data or set the ephemeris path");
  }
  PosVel out;
  for (std::size_t i = 0; i < 3; ++i) {
    out.pos_au[i] = xx[i];
    out.vel_au_d[i] = xx[i + 3];
  }
  return out;
}

}  // namespace

Result<SwissEphemeris> SwissEphemeris::open(const std::string& ephe_path) {
  swe_set_ephe_path(ephe_path.empty() ? nullptr : ephe_path.c_str());
  SwissEphemeris ephemeris;
  // 2451545.0 = J2000.0: inside every data file's range, so a failure means missing files.
  auto probe = ephemeris.moon_geocentric(JulianDate{2451545.0, 0.0});
  if (!probe) return probe.error();
  return ephemeris;
}

Result<EarthSun> SwissEphemeris::earth_sun(const JulianDate& tt) const {
  auto earth = calc(tt, SE_EARTH, kGeometricIcrs | SEFLG_BARYCTR);
  if (!earth) return earth.error();
  auto sun = calc(tt, SE_SUN, kGeometricIcrs | SEFLG_BARYCTR);
  if (!sun) return sun.error();
  return EarthSun{*earth, *sun};
}

Result<PosVel> SwissEphemeris::moon_geocentric(const JulianDate& tt) const {
  return calc(tt, SE_MOON, kGeometricIcrs);
}

}  // namespace azt::astro
