#include "station/sky_emitters.hpp"

#include <optional>

#include "azt/astro/catalogue.hpp"
#include "azt/sim/radio_receiver.hpp"

namespace azt::app {
namespace {

constexpr double kSunSizeDeg = 0.53;   // the optical disc; the radio Sun is a little larger
constexpr double kMoonSizeDeg = 0.52;  // mean apparent diameter

std::optional<double> flux_at(const astro::RadioSource& s, std::int64_t mhz) {
  if (mhz == 2304) return s.flux_2304_jy;
  if (mhz == 10368) return s.flux_10368_jy;
  return s.flux_1296_jy;
}

}  // namespace

std::vector<SkyEmitter> sky_emitters(const SimReceiverConfig& rx) {
  const sim::SimulatedReceiver receiver(rx.receiver);
  std::vector<SkyEmitter> out;
  out.push_back({"sun", astro::Target::sun(), receiver.disc_k(rx.sun_k, kSunSizeDeg), kSunSizeDeg});
  out.push_back(
      {"moon", astro::Target::moon(), receiver.disc_k(rx.moon_k, kMoonSizeDeg), kMoonSizeDeg});
  for (const astro::RadioSource& s : astro::radio_sources()) {
    if (const auto flux = flux_at(s, rx.flux_mhz)) {
      out.push_back(
          {std::string(s.key), astro::Target::radio_source(s), receiver.point_k(*flux), 0.0});
    }
  }
  return out;
}

}  // namespace azt::app
