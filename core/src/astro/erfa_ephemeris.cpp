#include "azt/astro/erfa_ephemeris.hpp"

#include <erfa.h>

namespace azt::astro {
namespace {

PosVel to_posvel(const double pv[2][3]) {
  PosVel out;
  for (std::size_t i = 0; i < 3; ++i) {
    out.pos_au[i] = pv[0][i];
    out.vel_au_d[i] = pv[1][i];
  }
  return out;
}

}  // namespace

Result<EarthSun> ErfaEphemeris::earth_sun(const JulianDate& tt) const {
  double helio[2][3];
  double bary[2][3];
  // Status 1 only warns that the date is outside 1900–2100, where accuracy degrades gently.
  if (eraEpv00(tt.jd1, tt.jd2, helio, bary) < 0) return fail("eraEpv00 failed");
  EarthSun out;
  out.earth_bary = to_posvel(bary);
  // Sun = Earth(bary) − Earth(helio): both at the same TT.
  for (std::size_t i = 0; i < 3; ++i) {
    out.sun_bary.pos_au[i] = bary[0][i] - helio[0][i];
    out.sun_bary.vel_au_d[i] = bary[1][i] - helio[1][i];
  }
  return out;
}

Result<PosVel> ErfaEphemeris::moon_geocentric(const JulianDate& tt) const {
  double pv[2][3];
  eraMoon98(tt.jd1, tt.jd2, pv);  // GCRS, geometric, au and au/day
  return to_posvel(pv);
}

}  // namespace azt::astro
