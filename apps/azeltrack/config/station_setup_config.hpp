#pragma once
// What the station's controller knows, read from the configuration: the mount
// ([mount.az], [mount.el], [mount.pol]), the controller ([control]), the travel ([geometry]) and
// the pointing corrections ([corrections]), as control::StationSetup. Every backend, the simulated
// one included, runs its controller with this alone.

#include "azt/control/station_setup.hpp"
#include "config/mount_config.hpp"

namespace azt::app {

class ConfigFile;

/// Throws UsageError naming the key on any invalid value.
control::StationSetup station_setup_from(const ConfigFile& file, const MountConfig& mount);

}  // namespace azt::app
