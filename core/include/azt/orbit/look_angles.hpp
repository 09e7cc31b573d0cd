#pragma once
// Where a satellite is seen from a station (docs/satellites.md), by the common convention
// (Vallado's teme2ecef, also skyfield's and most trackers'): the TEME state from SGP4 is turned to
// the Earth-fixed frame by GMST 1982 of UT1 (no equation of the equinoxes, no polar motion), then
// seen from a WGS-84 site. Geometric: no light time, no refraction (a satellite's refraction is
// the caller's choice, as for any target).

#include <array>

#include "azt/astro/observer.hpp"
#include "azt/astro/time_scales.hpp"

namespace azt::orbit {

struct LookAngles {
  double az_deg = 0.0;  ///< 0..360, from north through east
  double el_deg = 0.0;
  double range_km = 0.0;
  double range_rate_km_s = 0.0;  ///< positive: receding
};

/// `r_km`, `v_km_s`: the TEME state at UT1 `ut1`.
LookAngles look_angles(const std::array<double, 3>& r_km, const std::array<double, 3>& v_km_s,
                       const astro::JulianDate& ut1, const astro::Observer& site);

}  // namespace azt::orbit
