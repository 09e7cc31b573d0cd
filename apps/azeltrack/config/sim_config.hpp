#pragma once

#include <string>

#include "azt/sim/station_sim.hpp"
#include "config/mount_config.hpp"
#include "config/sky_config.hpp"

namespace azt::app {

class ConfigFile;

/// Everything `simulate` reads: the sky (sky_config.hpp), the mount ([mount.az], [mount.el]),
/// the station as its controller knows it (station_setup_config.hpp) and the simulated plants
/// ([sim.az], [sim.el], [sim]). The controller's settings come from the mount, never from the
/// plants.
/// [sim] hub: what reads the simulated encoders. `model` encodes the plants' counts directly;
/// `firmware` runs the EncoderHub firmware's ELF on a simulated ATmega328P and reads its frames
/// through the daemon's decoder (docs/encoder-hub.md).
struct SimHubConfig {
  bool firmware = false;
  std::string elf;  ///< [sim] hub_firmware; empty: firmware/encoder-hub.elf beside the program
};

struct SimConfig {
  SkyConfig sky;
  MountConfig mount;
  sim::StationSimSetup setup;
  SimHubConfig hub;
};

/// [sim] hub and hub_firmware. Throws UsageError naming the key.
SimHubConfig sim_hub_from(const ConfigFile& file);

/// The simulated plants of [sim.az], [sim.el] and [sim]: the mount's rate and encoders with their
/// own imperfections, start angles, end stops (the travel's by default) and faults. Throws
/// UsageError naming the key on any invalid value.
sim::PlantSetup plant_setup_from(const ConfigFile& file, const MountConfig& mount,
                                 const control::StationSetup& station);

/// Throws UsageError naming the key on any missing or invalid value.
SimConfig sim_config_from(const ConfigFile& file);

}  // namespace azt::app
