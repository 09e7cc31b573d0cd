#pragma once
// The EncoderHub of the simulated antenna, as [sim] hub names it: the plain model, or the
// firmware's ELF on a simulated ATmega328P ("firmware in the loop", docs/encoder-hub.md). The
// daemon's `sim` backend and `azeltrack simulate` both take their hub from here.

#include <memory>

#include "azt/sim/plant_setup.hpp"
#include "azt/sim/simulated_hub.hpp"
#include "config/sim_config.hpp"

namespace azt::app {

/// Throws UsageError naming [sim] hub_firmware when the ELF cannot be loaded.
std::unique_ptr<sim::SimulatedHub> make_sim_hub(const sim::PlantSetup& plant,
                                                const SimHubConfig& hub);

}  // namespace azt::app
