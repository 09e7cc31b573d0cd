#include "azt/calibration/noise_expectation.hpp"

#include <cmath>
#include <limits>

namespace azt::calibration {
namespace {

constexpr double kPi = 3.14159265358979323846;

double wavelength_m(double freq_mhz) { return kLightMS / (freq_mhz * 1e6); }

bool within(double v, double lo, double hi) { return std::isfinite(v) && v > lo && v <= hi; }

Result<bool> check_station(const NoiseStation& s) {
  if (!within(s.freq_mhz, 0.0, 300000.0)) return fail("freq_mhz: must be in (0, 300000]");
  if (!within(s.dish_m, 0.0, 500.0)) return fail("dish_m: must be in (0, 500]");
  if (!within(s.efficiency, 0.0, 1.0)) return fail("efficiency: must be in (0, 1]");
  if (!within(s.tsys_k, 0.0, 100000.0)) return fail("tsys_k: must be in (0, 100000]");
  if (!(std::isfinite(s.beamwidth_deg) && s.beamwidth_deg >= 0.0 && s.beamwidth_deg <= 30.0)) {
    return fail("beamwidth_deg: must be in [0, 30] (0: estimated from the dish)");
  }
  return true;
}

}  // namespace

double estimated_beamwidth_deg(double dish_m, double freq_mhz) {
  return 70.0 * wavelength_m(freq_mhz) / dish_m;
}

double size_correction(SourceShape shape, double size_deg, double beamwidth_deg) {
  const double ratio_sq = (size_deg / beamwidth_deg) * (size_deg / beamwidth_deg);
  switch (shape) {
    case SourceShape::Point:
      return 1.0;
    case SourceShape::UniformDisc: {
      const double x_sq = std::log(2.0) * ratio_sq;
      // x²/(1 − e^(−x²)), written with expm1 so a small disc does not lose its digits.
      return x_sq > 1e-12 ? x_sq / -std::expm1(-x_sq) : 1.0;
    }
    case SourceShape::Gaussian:
      return 1.0 + ratio_sq;
  }
  return 1.0;
}

double point_antenna_k(double flux_jy, double dish_m, double efficiency) {
  const double area_m2 = kPi * dish_m * dish_m / 4.0;
  return efficiency * area_m2 * flux_jy * kWattsPerJansky / (2.0 * kBoltzmann);
}

double y_factor_db(double antenna_k, double tsys_k) {
  return 10.0 * std::log10((tsys_k + antenna_k) / tsys_k);
}

double implied_tsys_k(double y_db, double antenna_k) {
  const double y_minus_one = std::pow(10.0, y_db / 10.0) - 1.0;
  if (y_minus_one <= 0.0) return std::numeric_limits<double>::infinity();
  return antenna_k / y_minus_one;
}

double g_over_t_db(double y_db, double flux_jy, double freq_mhz, double size_factor) {
  const double y_minus_one = std::pow(10.0, y_db / 10.0) - 1.0;
  if (y_minus_one <= 0.0) return -std::numeric_limits<double>::infinity();
  const double lambda = wavelength_m(freq_mhz);
  const double s = flux_jy * kWattsPerJansky;
  return 10.0 *
         std::log10(8.0 * kPi * kBoltzmann * y_minus_one * size_factor / (s * lambda * lambda));
}

Result<NoiseExpectation> expected_noise(const NoiseStation& station, const SourceAtBand& source) {
  if (auto ok = check_station(station); !ok) return ok.error();
  if (!(std::isfinite(source.flux_jy) && source.flux_jy >= 0.0)) {
    return fail("flux: must be a finite flux of 0 or more");
  }
  NoiseExpectation e;
  e.flux_jy = source.flux_jy;
  e.beamwidth_deg = station.beamwidth_deg > 0.0
                        ? station.beamwidth_deg
                        : estimated_beamwidth_deg(station.dish_m, station.freq_mhz);
  e.size_factor = size_correction(source.shape, source.size_deg, e.beamwidth_deg);
  e.antenna_k = point_antenna_k(source.flux_jy, station.dish_m, station.efficiency) / e.size_factor;
  e.y_db = y_factor_db(e.antenna_k, station.tsys_k);
  return e;
}

}  // namespace azt::calibration
