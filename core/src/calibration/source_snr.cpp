#include "azt/calibration/source_snr.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>

#include "azt/calibration/noise_expectation.hpp"

namespace azt::calibration {
namespace {

/// What an SNR of nothing (or of no noise) reads as.
constexpr double kSnrLimitDb = 300.0;

double to_db(double ratio) { return 10.0 * std::log10(ratio); }

}  // namespace

double beam_coupling(double size_deg, double beamwidth_deg) {
  const double w2 = beamwidth_deg * beamwidth_deg;
  return w2 / (w2 + size_deg * size_deg);
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
  const double t_a = point_antenna_k(source.flux_jy, dish.dish_m, dish.efficiency) *
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
