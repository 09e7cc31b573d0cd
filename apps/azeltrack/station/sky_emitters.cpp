#include "station/sky_emitters.hpp"

#include <cmath>
#include <optional>

#include "azt/astro/catalogue.hpp"
#include "azt/sim/radio_receiver.hpp"

namespace azt::app {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kBoltzmann = 1.380649e-23;  // J/K (SI 2019, exact)
constexpr double kLightMS = 299792458.0;     // m/s (exact)
constexpr double kWattsPerJansky = 1e-26;

std::optional<double> flux_at(const astro::RadioSource& s, std::int64_t mhz) {
  if (mhz == 2304) return s.flux_2304_jy;
  if (mhz == 10368) return s.flux_10368_jy;
  return s.flux_1296_jy;
}

SkyEmitter disc(const sim::SimulatedReceiver& receiver, const char* name,
                const astro::Target& target, double brightness_k, double size_deg,
                std::int64_t mhz) {
  return {name, target, receiver.disc_k(brightness_k, size_deg), size_deg,
          gaussian_disc_flux_jy(brightness_k, size_deg, mhz)};
}

}  // namespace

double gaussian_disc_flux_jy(double brightness_k, double size_deg, std::int64_t mhz) {
  const double theta_rad = size_deg * kPi / 180.0;
  const double solid_angle_sr = kPi * theta_rad * theta_rad / (4.0 * std::log(2.0));
  const double f_hz = static_cast<double>(mhz) * 1e6;
  return 2.0 * kBoltzmann * brightness_k * solid_angle_sr * f_hz * f_hz / (kLightMS * kLightMS) /
         kWattsPerJansky;
}

std::vector<SkyEmitter> sky_emitters(const SimReceiverConfig& rx) {
  const sim::SimulatedReceiver receiver(rx.receiver);
  std::vector<SkyEmitter> out;
  out.push_back(disc(receiver, "sun", astro::Target::sun(), rx.sun_k, kSimSunSizeDeg, rx.flux_mhz));
  out.push_back(
      disc(receiver, "moon", astro::Target::moon(), rx.moon_k, kSimMoonSizeDeg, rx.flux_mhz));
  for (const astro::RadioSource& s : astro::radio_sources()) {
    if (const auto flux = flux_at(s, rx.flux_mhz)) {
      out.push_back({std::string(s.key), astro::Target::radio_source(s), receiver.point_k(*flux),
                     0.0, *flux});
    }
  }
  return out;
}

}  // namespace azt::app
