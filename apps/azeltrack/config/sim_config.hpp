#pragma once

#include "azt/sim/station_sim.hpp"
#include "config/mount_config.hpp"
#include "config/station_config.hpp"

namespace azt::app {

class ConfigFile;

/// Everything `simulate` reads: the station and sky (station_config.hpp), the mount
/// ([mount.az], [mount.el]), the controller ([control]), the travel ([geometry]) and the
/// simulated plants ([sim.az], [sim.el], [sim]). `setup`'s controller and supervisor settings come
/// from the mount, never from the plants.
struct SimConfig {
  StationConfig station;
  MountConfig mount;
  sim::StationSimSetup setup;
};

/// Throws UsageError naming the key on any missing or invalid value.
SimConfig sim_config_from(const ConfigFile& file);

}  // namespace azt::app
