#include "azt/eme/moon_conditions.hpp"

#include <cmath>

#include "azt/eme/libration.hpp"
#include "azt/eme/polarisation.hpp"
#include "azt/eme/sky_temperature.hpp"
#include "azt/util/angles.hpp"

namespace azt::eme {
namespace {}  // namespace

double separation_deg(double ra1_deg, double dec1_deg, double ra2_deg, double dec2_deg) {
  // Vincenty's formula on the sphere: accurate from arcseconds to 180°.
  const double d1 = dec1_deg * kRadPerDeg;
  const double d2 = dec2_deg * kRadPerDeg;
  const double dra = (ra2_deg - ra1_deg) * kRadPerDeg;
  const double y =
      std::hypot(std::cos(d2) * std::sin(dra),
                 std::cos(d1) * std::sin(d2) - std::sin(d1) * std::cos(d2) * std::cos(dra));
  const double x = std::sin(d1) * std::sin(d2) + std::cos(d1) * std::cos(d2) * std::cos(dra);
  return std::atan2(y, x) / kRadPerDeg;
}

double illuminated_fraction(double elongation_deg, double moon_km, double sun_km) {
  const double psi = elongation_deg * kRadPerDeg;
  const double phase = std::atan2(sun_km * std::sin(psi), moon_km - sun_km * std::cos(psi));
  return (1.0 + std::cos(phase)) / 2.0;
}

namespace {

void add_widths(const MoonInputs& in, MoonConditions& c) {
  if (!in.moon_minute_later) return;
  constexpr double kMinuteJd = 60.0 / 86400.0;
  const Libration own_now = apparent_libration(in.moon, in.tt_jd);
  const Libration own_later = apparent_libration(*in.moon_minute_later, in.tt_jd + kMinuteJd);
  c.width_hz = self_echo_width_hz(own_now, own_later, in.freq_mhz);
  if (!in.dx_moon || !in.dx_moon_minute_later) return;
  c.dx_width_hz = dx_echo_width_hz(
      own_now, own_later, apparent_libration(*in.dx_moon, in.tt_jd),
      apparent_libration(*in.dx_moon_minute_later, in.tt_jd + kMinuteJd), in.freq_mhz);
}

}  // namespace

MoonConditions moon_conditions(const MoonInputs& in) {
  MoonConditions c;
  c.parallactic_deg = parallactic_angle_deg(in.lat_deg, in.moon.az_deg, in.moon.el_geometric_deg);
  if (in.dx_lat_deg && in.dx_moon) {
    const double dx =
        parallactic_angle_deg(*in.dx_lat_deg, in.dx_moon->az_deg, in.dx_moon->el_geometric_deg);
    c.dx_dpol_deg = dpol_deg(c.parallactic_deg, dx);
    c.mnr_db = mnr_db(*c.dx_dpol_deg);
  }
  c.ecliptic_lon_deg = ecliptic_longitude_deg(in.moon.ra_deg, in.moon.dec_deg);
  c.tsky_k = tsky_k(c.ecliptic_lon_deg, in.freq_mhz);
  c.dgrd_db = dgrd_db(c.tsky_k, in.freq_mhz, in.moon.distance_km.value_or(kPerigeeKm));
  c.sun_sep_deg = separation_deg(in.moon.ra_deg, in.moon.dec_deg, in.sun.ra_deg, in.sun.dec_deg);
  c.illumination = illuminated_fraction(c.sun_sep_deg, in.moon.distance_km.value_or(kPerigeeKm),
                                        in.sun.distance_km.value_or(1.495978707e8));
  add_widths(in, c);
  return c;
}

}  // namespace azt::eme
