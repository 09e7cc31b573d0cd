#include "azt/astro/refraction.hpp"

#include <erfa.h>
#include <erfam.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace azt::astro {
namespace {

// Below this geometric elevation the correction is faded out (linearly to zero at kFadeEndDeg):
// the formulas diverge further down and a target far below the horizon needs no refraction.
constexpr double kFadeStartDeg = -1.0;
constexpr double kFadeEndDeg = -2.0;
// Radio model blend: ITU-R P.834 (a low-elevation fit) at and below 5°, ERFA's A·tanZ + B·tan³Z
// (exact to 0.3″ against ray tracing down to 15° elevation, ERFA refco.c) at and above 15°.
constexpr double kBlendLowDeg = 5.0;
constexpr double kBlendHighDeg = 15.0;
// ITU-R P.453-14 §2: global mean reference surface refractivity N0 and scale height h0 (km).
constexpr double kReferenceN0 = 315.0;
constexpr double kReferenceScaleHeightKm = 7.35;
// Any wavelength above 100 µm selects ERFA's radio formula (refco.c).
constexpr double kRadioWavelengthUm = 1.0e5;

double deg_to_rad(double deg) { return deg * ERFA_DD2R; }

/// ERFA's A/B model is for observed zenith distance; invert it for a true one by iteration
/// (converges in a few steps: dZ/dZ_obs ≪ 1 above 15° elevation).
double ab_refraction_deg(double el_true_deg, const Atmosphere& a) {
  double refa = 0.0;
  double refb = 0.0;
  eraRefco(a.pressure_hpa, a.temperature_c, a.relative_humidity, kRadioWavelengthUm, &refa, &refb);
  const double z_true = deg_to_rad(90.0 - el_true_deg);
  double z_obs = z_true;
  for (int i = 0; i < 4; ++i) {
    const double t = std::tan(z_obs);
    z_obs = z_true - (refa * t + refb * t * t * t);
  }
  return (z_true - z_obs) * ERFA_DR2D;
}

double itu_scaled_refraction_deg(double el_true_deg, double height_m, const Atmosphere& a) {
  const double height_km = height_m / 1000.0;
  const double reference_n = kReferenceN0 * std::exp(-height_km / kReferenceScaleHeightKm);
  const double local_n = radio_refractivity(a.pressure_hpa, a.temperature_c, a.relative_humidity);
  // Low-elevation bending scales with the surface refractivity (Bean & Dutton 1966, ch. 3):
  // P.834 is fitted to the reference atmosphere, so scale it to the station's weather.
  return itu_p834_refraction_deg(el_true_deg, std::max(height_km, 0.0)) * local_n / reference_n;
}

double radio_refraction_deg(double el_true_deg, double height_m, const Atmosphere& a) {
  if (el_true_deg <= kBlendLowDeg) return itu_scaled_refraction_deg(el_true_deg, height_m, a);
  if (el_true_deg >= kBlendHighDeg) return ab_refraction_deg(el_true_deg, a);
  const double w = (el_true_deg - kBlendLowDeg) / (kBlendHighDeg - kBlendLowDeg);
  return (1.0 - w) * itu_scaled_refraction_deg(el_true_deg, height_m, a) +
         w * ab_refraction_deg(el_true_deg, a);
}

double model_refraction_deg(double el_deg, double height_m, const Atmosphere& a) {
  switch (a.model) {
    case RefractionModel::None:
      return 0.0;
    case RefractionModel::Optical:
      return saemundsson_refraction_deg(el_deg, a.pressure_hpa, a.temperature_c);
    case RefractionModel::Radio:
      return radio_refraction_deg(el_deg, height_m, a);
  }
  return 0.0;
}

}  // namespace

Result<RefractionModel> parse_refraction_model(std::string_view name) {
  if (name == "none") return RefractionModel::None;
  if (name == "optical") return RefractionModel::Optical;
  if (name == "radio") return RefractionModel::Radio;
  return fail("unknown refraction model '" + std::string(name) + "' (use radio, optical or none)");
}

std::string_view to_string(RefractionModel model) {
  switch (model) {
    case RefractionModel::None:
      return "none";
    case RefractionModel::Optical:
      return "optical";
    case RefractionModel::Radio:
      return "radio";
  }
  return "radio";
}

Result<Atmosphere> Atmosphere::make(double pressure_hpa, double temperature_c,
                                    double relative_humidity, RefractionModel model) {
  if (!std::isfinite(pressure_hpa) || pressure_hpa < 0.0 || pressure_hpa > 1200.0) {
    return fail("pressure must be 0..1200 hPa");
  }
  if (!std::isfinite(temperature_c) || temperature_c < -60.0 || temperature_c > 60.0) {
    return fail("temperature must be -60..60 °C");
  }
  if (!std::isfinite(relative_humidity) || relative_humidity < 0.0 || relative_humidity > 1.0) {
    return fail("relative humidity must be 0..1");
  }
  return Atmosphere{pressure_hpa, temperature_c, relative_humidity, model};
}

double refraction_deg(double el_geometric_deg, double height_m, const Atmosphere& atmosphere) {
  if (!std::isfinite(el_geometric_deg) || el_geometric_deg <= kFadeEndDeg) return 0.0;
  if (el_geometric_deg >= kFadeStartDeg) {
    return model_refraction_deg(el_geometric_deg, height_m, atmosphere);
  }
  const double fade = (el_geometric_deg - kFadeEndDeg) / (kFadeStartDeg - kFadeEndDeg);
  return fade * model_refraction_deg(kFadeStartDeg, height_m, atmosphere);
}

double itu_p834_refraction_deg(double el_free_space_deg, double height_km) {
  const double t = el_free_space_deg;
  const double h = height_km;
  return 1.0 / (1.728 + 0.5411 * t + 0.03723 * t * t +
                h * (0.1815 + 0.06272 * t + 0.01138 * t * t) + h * h * (0.01727 + 0.008288 * t));
}

double radio_refractivity(double pressure_hpa, double temperature_c, double relative_humidity) {
  const double t = temperature_c;
  // P.453-14 eq. (9)-(10): saturation vapour pressure over water with the enhancement factor.
  const double enhancement = 1.0 + 1e-4 * (7.2 + pressure_hpa * (0.0320 + 5.9e-6 * t * t));
  const double e_sat = enhancement * 6.1121 * std::exp((18.678 - t / 234.5) * t / (t + 257.14));
  const double e = relative_humidity * e_sat;
  const double kelvin = t + 273.15;
  // P.453-14 eq. (6): N = 77.6/T · (P + 4810·e/T).
  return 77.6 / kelvin * (pressure_hpa + 4810.0 * e / kelvin);
}

double saemundsson_refraction_deg(double el_true_deg, double pressure_hpa, double temperature_c) {
  const double h = el_true_deg;
  // Meeus eq. 16.4 in arcminutes; +0.0019279′ makes it vanish at the zenith, as Meeus suggests.
  const double r_arcmin = 1.02 / std::tan(deg_to_rad(h + 10.3 / (h + 5.11))) + 0.0019279;
  const double weather = (pressure_hpa / 1010.0) * (283.0 / (273.0 + temperature_c));
  return std::max(0.0, r_arcmin * weather / 60.0);
}

}  // namespace azt::astro
