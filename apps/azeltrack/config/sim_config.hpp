#pragma once

#include "azt/sim/station_sim.hpp"
#include "config/station_config.hpp"

namespace azt::app {

class ConfigFile;

/// Everything `simulate` reads: the station and sky (station_config.hpp) plus the plants
/// ([sim.az], [sim.el], [sim]), the controller ([control]) and the travel ([geometry]).
struct SimConfig {
  StationConfig station;
  sim::StationSimSetup setup;
};

/// Throws UsageError naming the key on any missing or invalid value.
SimConfig sim_config_from(const ConfigFile& file);

}  // namespace azt::app
