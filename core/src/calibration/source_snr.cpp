#include "azt/calibration/source_snr.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace azt::calibration {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kLightMPerS = 299792458.0;

/// What an SNR of nothing (or of no noise) reads as.
constexpr double kSnrLimitDb = 300.0;

double to_db(double ratio) { return 10.0 * std::log10(ratio); }

}  // namespace

double point_source_k(double flux_jy, double dish_m, double efficiency) {
  const double area_m2 = kPi * dish_m * dish_m / 4.0;
  return efficiency * area_m2 * flux_jy * kJanskyWPerM2Hz / (2.0 * kBoltzmannJPerK);
}

double beam_coupling(double size_deg, double beamwidth_deg) {
  const double w2 = beamwidth_deg * beamwidth_deg;
  return w2 / (w2 + size_deg * size_deg);
}

double disc_flux_jy(double brightness_k, double diameter_deg, double freq_hz) {
  const double radius_rad = diameter_deg * kPi / 360.0;
  const double solid_angle_sr = kPi * radius_rad * radius_rad;
  const double flux_w = 2.0 * kBoltzmannJPerK * brightness_k * solid_angle_sr * freq_hz * freq_hz /
                        (kLightMPerS * kLightMPerS);
  return flux_w / kJanskyWPerM2Hz;
}

double radiometer_noise_db(double bandwidth_hz, double integration_s) {
  return to_db(1.0 + 1.0 / std::sqrt(bandwidth_hz * integration_s));
}

SourceEstimate estimate_source(const std::string& name, double antenna_k, double size_deg,
                               const DishSetup& dish, const PointNoise& noise) {
  SourceEstimate e{name, antenna_k, 0.0, 0.0, size_deg};
  const double rise = antenna_k / dish.tsys_k;  // Y − 1
  e.rise_db = to_db(1.0 + rise);
  const double point_noise = (std::pow(10.0, noise.reading_noise_db / 10.0) - 1.0) /
                             std::sqrt(std::max(noise.readings, 1.0));
  if (!(rise > 0.0)) {
    e.snr_db = -kSnrLimitDb;
  } else {
    e.snr_db = point_noise > 0.0 ? std::min(to_db(rise / point_noise), kSnrLimitDb) : kSnrLimitDb;
  }
  return e;
}

SourceEstimate estimate_source(const SourceFlux& source, const DishSetup& dish,
                               const PointNoise& noise) {
  const double t_a = point_source_k(source.flux_jy, dish.dish_m, dish.efficiency) *
                     beam_coupling(source.size_deg, dish.beamwidth_deg);
  return estimate_source(source.name, t_a, source.size_deg, dish, noise);
}

std::vector<SourceEstimate> worth_scanning(const std::vector<SourceEstimate>& estimates,
                                           double min_snr_db) {
  std::vector<SourceEstimate> out;
  std::copy_if(estimates.begin(), estimates.end(), std::back_inserter(out),
               [min_snr_db](const SourceEstimate& e) { return e.snr_db >= min_snr_db; });
  return out;
}

}  // namespace azt::calibration
