#include "azt/calibration/noise_sources.hpp"

#include <array>
#include <cmath>
#include <span>
#include <string>

namespace azt::calibration {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kF107Mhz = 2800.0;              // the 10.7 cm flux's frequency
constexpr double kCasADiameterDeg = 5.0 / 60.0;  // a shell 5′ across (catalogue)
constexpr double kCygAWidthDeg = 2.0 / 60.0;     // two lobes 2′ apart (catalogue)

struct FluxPoint {
  double mhz;
  double sfu;
};

/// A quiet Sun's spectrum at the RSTN frequencies: the noon fluxes of Palehua on 1 January 2018,
/// a spotless day near the solar minimum (F10.7 ≈ 70). Only the shape is used: F10.7 scales it.
constexpr std::array<FluxPoint, 8> kQuietSun{{{245.0, 13.0},
                                              {410.0, 25.0},
                                              {610.0, 34.0},
                                              {1415.0, 46.0},
                                              {2695.0, 67.0},
                                              {4995.0, 107.0},
                                              {8800.0, 225.0},
                                              {15400.0, 518.0}}};

/// The quiet Sun at `mhz`: a power law between the two table frequencies either side of it
/// (the end pair beyond the table).
double quiet_sun_sfu(double mhz) {
  std::size_t i = 1;
  while (i + 1 < kQuietSun.size() && kQuietSun.at(i).mhz < mhz) ++i;
  const FluxPoint& a = kQuietSun.at(i - 1);
  const FluxPoint& b = kQuietSun.at(i);
  return power_law_flux(a.mhz, a.sfu, b.mhz, b.sfu, mhz);
}

/// Perley & Butler 2017 table 5: log10 S[Jy] = Σ aᵢ (log10 f[GHz])ⁱ.
double perley_butler_jy(std::span<const double> a, double freq_mhz) {
  const double x = std::log10(freq_mhz / 1000.0);
  double log_s = 0.0;
  for (auto it = a.rbegin(); it != a.rend(); ++it) log_s = log_s * x + *it;
  return std::pow(10.0, log_s);
}

constexpr std::array<double, 4> kCasA{3.3584, -0.7518, -0.035, -0.0710};
constexpr std::array<double, 5> kCygA{3.3498, -1.0022, -0.225, 0.0230, 0.0430};

}  // namespace

std::string_view to_string(NoiseSource source) {
  switch (source) {
    case NoiseSource::Sun:
      return "sun";
    case NoiseSource::Moon:
      return "moon";
    case NoiseSource::CasA:
      return "casa";
    case NoiseSource::CygA:
      return "cyga";
  }
  return "?";
}

Result<NoiseSource> parse_noise_source(std::string_view text) {
  for (NoiseSource s :
       {NoiseSource::Sun, NoiseSource::Moon, NoiseSource::CasA, NoiseSource::CygA}) {
    if (text == to_string(s)) return s;
  }
  return fail("source: must be sun, moon, casa or cyga, not \"" + std::string(text) + "\"");
}

double equivalent_gaussian_width_deg(SourceShape shape, double size_deg) {
  switch (shape) {
    case SourceShape::Point:
      return 0.0;
    case SourceShape::UniformDisc:
      return std::sqrt(std::log(2.0) / 2.0) * size_deg;
    case SourceShape::Gaussian:
      return size_deg;
  }
  return 0.0;
}

double power_law_flux(double f1_mhz, double s1, double f2_mhz, double s2, double freq_mhz) {
  const double exponent = std::log(freq_mhz / f1_mhz) / std::log(f2_mhz / f1_mhz);
  return s1 * std::pow(s2 / s1, exponent);
}

double solar_flux_at_band_sfu(double f107_sfu, double freq_mhz) {
  return f107_sfu * quiet_sun_sfu(freq_mhz) / quiet_sun_sfu(kF107Mhz);
}

double sun_radio_diameter_deg(double freq_mhz) {
  if (freq_mhz <= 1296.0) return 0.70;
  if (freq_mhz >= 10368.0) return 0.55;
  if (freq_mhz <= 2304.0) return power_law_flux(1296.0, 0.70, 2304.0, 0.65, freq_mhz);
  return power_law_flux(2304.0, 0.65, 10368.0, 0.55, freq_mhz);
}

double disc_flux_jy(double brightness_k, double diameter_deg, double freq_mhz) {
  const double radius_rad = diameter_deg * kPi / 360.0;
  const double solid_angle_sr = kPi * radius_rad * radius_rad;
  const double f_hz = freq_mhz * 1e6;
  const double w_m2_hz =
      2.0 * kBoltzmann * brightness_k * solid_angle_sr * f_hz * f_hz / (kLightMS * kLightMS);
  return w_m2_hz / kWattsPerJansky;
}

SourceAtBand sun_at_band(double flux_sfu, double freq_mhz) {
  return {flux_sfu * kJanskyPerSfu, SourceShape::UniformDisc, sun_radio_diameter_deg(freq_mhz)};
}

SourceAtBand moon_at_band(double brightness_k, double diameter_deg, double freq_mhz) {
  return {disc_flux_jy(brightness_k, diameter_deg, freq_mhz), SourceShape::UniformDisc,
          diameter_deg};
}

std::optional<SourceAtBand> radio_star_at_band(NoiseSource source, double freq_mhz) {
  switch (source) {
    case NoiseSource::Sun:
    case NoiseSource::Moon:
      return std::nullopt;
    case NoiseSource::CasA:
      return SourceAtBand{perley_butler_jy(kCasA, freq_mhz), SourceShape::UniformDisc,
                          kCasADiameterDeg};
    case NoiseSource::CygA:
      return SourceAtBand{perley_butler_jy(kCygA, freq_mhz), SourceShape::Gaussian, kCygAWidthDeg};
  }
  return std::nullopt;
}

}  // namespace azt::calibration
