#pragma once
// What an EME station reads about the Moon beside its position (docs/eme.md): the polarisation
// offset to a DX station, the sky behind the Moon and the degradation it brings, how far the
// Moon is from the Sun (Sun noise) and how much of it is lit. Computed from the places the sky
// engine already observes (azt/astro/sky.hpp), so every number is for the same instant.

#include <optional>

#include "azt/astro/sky.hpp"

namespace azt::eme {

struct MoonInputs {
  double lat_deg = 0.0;                 ///< the station's latitude
  astro::Place moon;                    ///< the Moon seen from the station (distance_km set)
  astro::Place sun;                     ///< the Sun seen from the station (distance_km set)
  std::optional<double> dx_lat_deg;     ///< a DX station, with
  std::optional<astro::Place> dx_moon;  ///< the Moon seen from there
  double freq_mhz = 144.0;
  double tt_jd = 0.0;  ///< the instant (Terrestrial Time, Julian date): the Moon's orientation
  /// The Moon a minute later from the station (and from the DX), for the echo widths.
  std::optional<astro::Place> moon_minute_later;
  std::optional<astro::Place> dx_moon_minute_later;
};

struct MoonConditions {
  double parallactic_deg = 0.0;  ///< the station's own polarisation angle (WSJT-X poloffset)
  /// Dpol: 0 for self echoes (one station at both ends); between the stations with a DX.
  double dpol_deg = 0.0;
  std::optional<double> dx_dpol_deg;  ///< with a DX station
  std::optional<double> mnr_db;       ///< with a DX station
  double ecliptic_lon_deg = 0.0;
  double tsky_k = 0.0;                ///< at freq_mhz
  double dgrd_db = 0.0;               ///< against perigee in the coldest sky (sky_temperature.hpp)
  double sun_sep_deg = 0.0;           ///< the angle between the Moon's and the Sun's centres
  double illumination = 0.0;          ///< the lit fraction of the disc, 0 (new) to 1 (full)
  std::optional<double> width_hz;     ///< self-echo spread from libration (with moon_minute_later)
  std::optional<double> dx_width_hz;  ///< DX echo spread (with both minute-later places)
};

/// Angle between two directions given as RA/Dec (degrees), stable at small and large angles.
double separation_deg(double ra1_deg, double dec1_deg, double ra2_deg, double dec2_deg);

/// The lit fraction from the Moon–Sun elongation seen by the observer and the two distances
/// (Meeus, Astronomical Algorithms, 2nd ed., eq. 48.2–48.3).
double illuminated_fraction(double elongation_deg, double moon_km, double sun_km);

MoonConditions moon_conditions(const MoonInputs& in);

}  // namespace azt::eme
