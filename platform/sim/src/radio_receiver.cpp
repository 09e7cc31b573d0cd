#include "azt/sim/radio_receiver.hpp"

#include <cmath>

#include "azt/calibration/pointing_model.hpp"

namespace azt::sim {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kBoltzmann = 1.380649e-23;  // J/K (SI 2019, exact)
constexpr double kJansky = 1e-26;            // W m⁻² Hz⁻¹

}  // namespace

SimulatedReceiver::SimulatedReceiver(const ReceiverSetup& setup)
    : setup_(setup), rng_(setup.seed), noise_(0.0, setup.noise_db) {}

double SimulatedReceiver::expected_db(const control::AzEl& beam,
                                      const std::vector<RadioEmitter>& sky) const {
  const double w = setup_.beamwidth_deg;
  double t = setup_.tsys_k;
  for (const RadioEmitter& e : sky) {
    const double d = calibration::separation_deg(beam, e.sky);
    const double width_sq = w * w + e.size_deg * e.size_deg;
    t += e.peak_k * std::exp(-4.0 * std::log(2.0) * d * d / width_sq);
  }
  return 10.0 * std::log10(t / setup_.tsys_k);
}

double SimulatedReceiver::read_db(const control::AzEl& beam, const std::vector<RadioEmitter>& sky) {
  return expected_db(beam, sky) + noise_(rng_);
}

double SimulatedReceiver::peak_rise_db(const RadioEmitter& source) const {
  return 10.0 * std::log10(1.0 + source.peak_k / setup_.tsys_k);
}

double SimulatedReceiver::disc_k(double brightness_k, double size_deg) const {
  const double w = setup_.beamwidth_deg;
  return brightness_k * size_deg * size_deg / (size_deg * size_deg + w * w);
}

double SimulatedReceiver::point_k(double flux_jy) const {
  const double area_m2 = kPi * setup_.dish_m * setup_.dish_m / 4.0;
  return setup_.efficiency * flux_jy * kJansky * area_m2 / (2.0 * kBoltzmann);
}

}  // namespace azt::sim
