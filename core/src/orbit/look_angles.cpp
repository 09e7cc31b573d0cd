#include "azt/orbit/look_angles.hpp"

#include <erfa.h>
#include <erfam.h>

#include <cmath>

namespace azt::orbit {
namespace {

/// The Earth's rotation rate, rad/s (Vallado's teme2ecef, length of day not modelled).
constexpr double kEarthRateRadS = 7.292115146706979e-5;

using Vec = std::array<double, 3>;

}  // namespace

LookAngles look_angles(const Vec& r_km, const Vec& v_km_s, const astro::JulianDate& ut1,
                       const astro::Observer& site) {
  // TEME -> pseudo Earth-fixed: a rotation by GMST about z.
  const double gmst = eraGmst82(ut1.jd1, ut1.jd2);
  const double c = std::cos(gmst);
  const double s = std::sin(gmst);
  const Vec r{c * r_km[0] + s * r_km[1], -s * r_km[0] + c * r_km[1], r_km[2]};
  // The velocity also loses the frame's rotation: v_ecef = R·v_teme − ω × r_ecef.
  const Vec v{c * v_km_s[0] + s * v_km_s[1] + kEarthRateRadS * r[1],
              -s * v_km_s[0] + c * v_km_s[1] - kEarthRateRadS * r[0], v_km_s[2]};

  const double lat = site.lat_deg * ERFA_DD2R;
  const double lon = site.lon_deg * ERFA_DD2R;
  double site_m[3] = {0.0, 0.0, 0.0};
  (void)eraGd2gc(ERFA_WGS84, lon, lat, site.height_m, site_m);
  const Vec rho{r[0] - site_m[0] / 1000.0, r[1] - site_m[1] / 1000.0, r[2] - site_m[2] / 1000.0};

  // East, north, up at the site (geodetic vertical).
  const double sl = std::sin(lat);
  const double cl = std::cos(lat);
  const double so = std::sin(lon);
  const double co = std::cos(lon);
  const double east = -so * rho[0] + co * rho[1];
  const double north = -sl * co * rho[0] - sl * so * rho[1] + cl * rho[2];
  const double up = cl * co * rho[0] + cl * so * rho[1] + sl * rho[2];
  const double range = std::sqrt(east * east + north * north + up * up);

  LookAngles out;
  out.range_km = range;
  out.el_deg = std::asin(up / range) * ERFA_DR2D;
  double az = std::atan2(east, north) * ERFA_DR2D;
  if (az < 0.0) az += 360.0;
  out.az_deg = az;
  // The site is fixed in this frame, so the range rate is the relative velocity along the line.
  out.range_rate_km_s = (rho[0] * v[0] + rho[1] * v[1] + rho[2] * v[2]) / range;
  return out;
}

}  // namespace azt::orbit
