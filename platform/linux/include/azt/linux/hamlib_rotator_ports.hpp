#pragma once
// A rotator box reached through Hamlib (a GS-232, SPID or EasyComm controller, or another
// rotctld) behind the core's ports (docs/daemon.md): it closes its own loop, so each axis is a
// setpoint drive, and its position report is each axis's sensor. The station's controller
// supervises it as it does any other drive: stale reports, stalls, runaways and jumps stop it.

#include <memory>

#include "azt/linux/hamlib_rotator.hpp"
#include "azt/ports/station_ports.hpp"

namespace azt::linux_os {

/// Azimuth setpoints go to the box as 0…360 (the convention every Hamlib backend accepts; the
/// box chooses its path), readings come back as reported. Stopping sends rot_stop. With
/// `el_fixed_deg` the station has no elevation ports and the box is always sent that elevation
/// (Hamlib's azimuth-only models ignore it).
ports::StationPorts make_hamlib_rotator_ports(std::unique_ptr<HamlibRotator> rotator,
                                              const std::string& describe,
                                              std::optional<double> el_fixed_deg = std::nullopt);

}  // namespace azt::linux_os
