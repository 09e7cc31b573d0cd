#pragma once
// What the simulated receiver of pointing scans hears (docs/calibration.md): the Sun and the Moon
// as discs of their brightness temperature, and every catalogue radio source with a flux at the
// band as a point. `simulate --scenario calibrate` and the daemon's `[receiver] source = "sim"`
// use the same list. Each has a known flux at the band: the catalogue's, or the disc's by
// Rayleigh–Jeans (the noise measurement's expected value starts from it).

#include <cstdint>
#include <string>
#include <vector>

#include "azt/astro/target.hpp"
#include "config/sim_config.hpp"

namespace azt::app {

struct SkyEmitter {
  std::string name;
  astro::Target target;
  double peak_k = 0.0;    ///< antenna temperature with the beam on it
  double size_deg = 0.0;  ///< its Gaussian-equivalent width (0: a point)
  double flux_jy = 0.0;   ///< its flux density at the band, both polarisations
};

/// The simulated Sun's and Moon's widths: Gaussians of these half-power widths.
inline constexpr double kSimSunSizeDeg =
    0.53;  // the optical disc; the radio Sun is a little larger
inline constexpr double kSimMoonSizeDeg = 0.52;  // mean apparent diameter

/// The flux of a Gaussian of peak brightness `brightness_k` and half-power width `size_deg` at
/// `mhz` (Rayleigh–Jeans, S = 2k·T·Ω·f²/c², Ω = π·θ²/(4 ln 2)).
double gaussian_disc_flux_jy(double brightness_k, double size_deg, std::int64_t mhz);

/// The Sun, the Moon and the catalogue's sources with a flux at `rx.flux_mhz`.
std::vector<SkyEmitter> sky_emitters(const SimReceiverConfig& rx);

}  // namespace azt::app
