#pragma once

#include <array>
#include <cstdint>
#include <string>

#include "azt/control/pol_target.hpp"
#include "azt/sim/radio_receiver.hpp"
#include "azt/sim/station_sim.hpp"
#include "config/mount_config.hpp"
#include "config/sky_config.hpp"

namespace azt::app {

class ConfigFile;

/// Everything `simulate` reads: the sky (sky_config.hpp), the mount ([mount.az], [mount.el],
/// [mount.pol]), the polarisation modes ([pol]),
/// the station as its controller knows it (station_setup_config.hpp) and the simulated plants
/// ([sim.az], [sim.el], [sim.pol], [sim]). The controller's settings come from the mount, never
/// from the plants. [sim] hub: what reads the simulated encoders. `model` encodes the plants'
/// counts directly; `firmware` runs the EncoderHub firmware's ELF on a simulated ATmega328P and
/// reads its frames through the daemon's decoder (docs/encoder-hub.md).
struct SimHubConfig {
  bool firmware = false;
  std::string elf;  ///< [sim] hub_firmware; empty: the build's or the package's ELF
};

/// [sim.receiver]: the simulated receiver of pointing scans (docs/calibration.md): its beam, noise
/// and reading rate, the dish (for the radio sources' antenna temperatures at the catalogue's flux
/// for flux_mhz), and the Sun's and Moon's brightness temperatures at the band. The defaults are
/// a 10 m dish at 23 cm: a 1.6° beam, the quiet Sun at about 170 000 K, the Moon at 220 K.
struct SimReceiverConfig {
  sim::ReceiverSetup receiver;
  double sun_k = 170000.0;
  double moon_k = 220.0;
  std::int64_t flux_mhz = 1296;
};

struct SimConfig {
  SkyConfig sky;
  MountConfig mount;
  sim::StationSimSetup setup;
  SimHubConfig hub;
  SimReceiverConfig receiver;
  control::PolSettings pol;  ///< [pol]: what the polarisation axis follows
};

/// [sim] hub and hub_firmware. Throws UsageError naming the key.
SimHubConfig sim_hub_from(const ConfigFile& file);

/// The simulated plants of [sim.az], [sim.el] and [sim]: the mount's rate and encoders with their
/// own imperfections, start angles, end stops (the travel's by default) and faults. Throws
/// UsageError naming the key on any invalid value.
sim::PlantSetup plant_setup_from(const ConfigFile& file, const MountConfig& mount,
                                 const control::StationSetup& station);

/// [sim.az] / [sim.el] brake and motor_heating: adds the plants' brakes and windings to `plant`
/// and returns what the controller is told of them (its brake timing and temperature trip, the
/// keys a real axis's [hardware.az] has). Throws UsageError naming the key.
std::array<sim::AxisMotorControl, 2> sim_motors_from(const ConfigFile& file,
                                                     sim::PlantSetup& plant);

/// [sim.receiver]. Throws UsageError naming the key.
SimReceiverConfig sim_receiver_from(const ConfigFile& file);

/// Throws UsageError naming the key on any missing or invalid value.
SimConfig sim_config_from(const ConfigFile& file);

}  // namespace azt::app
