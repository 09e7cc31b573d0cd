#pragma once

#include <string_view>

#include "azt/util/result.hpp"

namespace azt::astro {

enum class RefractionModel {
  None,     ///< geometric elevation only
  Optical,  ///< Sæmundsson (1986) scaled for pressure and temperature, as Meeus ch. 16
  Radio,    ///< ITU-R P.834 near the horizon, ERFA A/B (radio) above, blended 5°–15°
};

Result<RefractionModel> parse_refraction_model(std::string_view name);
std::string_view to_string(RefractionModel model);

/// Surface weather at the station, used by the refraction models.
struct Atmosphere {
  double pressure_hpa = 1013.25;
  double temperature_c = 10.0;
  double relative_humidity = 0.5;  ///< 0..1
  RefractionModel model = RefractionModel::Radio;

  /// Validates: pressure 0..1200 hPa, temperature −60..+60 °C, humidity 0..1, all finite.
  static Result<Atmosphere> make(double pressure_hpa, double temperature_c,
                                 double relative_humidity, RefractionModel model);
};

/// Refraction (deg, ≥ 0, to add to the geometric elevation) for a geometric (airless) elevation,
/// station height `height_m`. Below −1° geometric elevation the correction tapers linearly to
/// zero at −2°: targets well below the horizon are not refracted.
double refraction_deg(double el_geometric_deg, double height_m, const Atmosphere& atmosphere);

/// ITU-R P.834-9 eq. (14): apparent minus free-space elevation (deg) for the ITU reference
/// atmosphere, from the free-space elevation θ0 (deg) and station altitude h (km).
double itu_p834_refraction_deg(double el_free_space_deg, double height_km);

/// ITU-R P.453-14 surface radio refractivity N (N-units) from pressure (hPa), temperature (°C)
/// and relative humidity (0..1), using the P.453 saturation vapour pressure over water.
double radio_refractivity(double pressure_hpa, double temperature_c, double relative_humidity);

/// Sæmundsson's formula (Sky & Telescope 1986; Meeus, Astronomical Algorithms eq. 16.4): true
/// altitude h (deg) → refraction (deg) at 1010 hPa and 10 °C, scaled by (P/1010)·(283/(273+T)).
double saemundsson_refraction_deg(double el_true_deg, double pressure_hpa, double temperature_c);

}  // namespace azt::astro
