#pragma once
// What the simulated receiver of pointing scans hears (docs/calibration.md): the Sun and the Moon
// as discs of their brightness temperature, and every catalogue radio source with a flux at the
// band as a point. `simulate --scenario calibrate` and the daemon's `[receiver] source = "sim"`
// use the same list.

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
};

/// The Sun, the Moon and the catalogue's sources with a flux at `rx.flux_mhz`.
std::vector<SkyEmitter> sky_emitters(const SimReceiverConfig& rx);

}  // namespace azt::app
